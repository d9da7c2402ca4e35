"""The design's options, typed: what is minimized and how the profile is sampled and checked.

A design file's ``[solve] objective``, ``[profile]`` table and ``[cam] bore_radius`` land here
(:func:`cams.io.designfile.design_from_dict` maps them); a design built in Python gives the same
fields. Each field is checked once, here, with the message the file's key gets. Lengths in the
design's unit (mm).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from cams.model.follower import check_length
from laws.errors import InputError, check_option

__all__ = [
    "OBJECTIVES",
    "ProfileOptions",
    "check_objective",
    "check_tolerance",
    "profile_options",
    "resolve_tolerance",
]

#: What the sizing minimizes: ``"R0"`` the base radius, ``"L"`` the centre distance (rocker only).
OBJECTIVES = ("R0", "L")


def check_tolerance(tol: object, field: str) -> float:
    """``tol`` as a float if it is a chord tolerance (a finite number > 0, length), else :class:`InputError`."""
    if isinstance(tol, bool) or not isinstance(tol, (int, float, np.integer, np.floating)) \
            or not math.isfinite(tol) or tol <= 0:
        raise InputError(field, f"chord tolerance must be a number > 0 (length unit), got {tol!r}")
    return float(tol)


def resolve_tolerance(given: float | None, override: float | None = None) -> tuple[float | None, str]:
    """The chord tolerance to use and the field a bad one is reported under.

    ``override`` (the command line's ``--tolerance``) wins over ``given``
    (the design's ``tolerance``, a file's ``[profile] tolerance``); both None
    give None: the default for the cam's size
    (:func:`cams.profile.roller.cap_tolerance`). Returns ``(tolerance, field)``;
    raises :class:`InputError` naming that field unless the tolerance is a
    number > 0.
    """
    field = "profile.tolerance" if override is None else "--tolerance"
    tol = given if override is None else override
    return (None if tol is None else check_tolerance(tol, field)), field


@dataclass(frozen=True)
class ProfileOptions:
    """How a cam's profile is sampled and checked (a file's ``[profile]`` table and ``[cam] bore_radius``).

    Attributes
    ----------
    tolerance : float or None
        Chord tolerance (largest sagitta between samples and curve), length;
        None: the default for the cam's size (:func:`cams.profile.roller.cap_tolerance`).
    min_curvature_radius : float or None
        User minimum of the working profile's radius of curvature (length).
    bore_radius : float or None
        Bore radius of the cam (length); ``None``: not checked
        (:func:`cams.profile.roller.default_bore_radius` is suggested).
    tolerance_field : str
        Where the tolerance was given (``"profile.tolerance"`` or
        ``"--tolerance"``), for the messages.
    """

    tolerance: float | None = None
    min_curvature_radius: float | None = None
    bore_radius: float | None = None
    tolerance_field: str = "profile.tolerance"

    def __post_init__(self) -> None:
        if self.tolerance is not None:
            check_tolerance(self.tolerance, self.tolerance_field)
        for value, field in ((self.min_curvature_radius, "profile.min_curvature_radius"),
                             (self.bore_radius, "cam.bore_radius")):
            if value is not None:
                check_length(field, value)


class _HasProfileFields(Protocol):
    @property
    def tolerance(self) -> float | None: ...

    @property
    def bore_radius(self) -> float | None: ...


def profile_options(design: _HasProfileFields, *, tolerance: float | None = None) -> ProfileOptions:
    """The profile settings of a design (roller or flat face), ``tolerance`` overriding its own.

    Parameters
    ----------
    design : CamDesign or FlatFaceDesign
        Its ``tolerance``, ``bore_radius`` and (roller) ``min_curvature_radius``.
    tolerance : float, optional
        Overrides the design's tolerance (the command line's ``--tolerance``).

    Raises
    ------
    InputError
        ``--tolerance`` (the override) that is not a number > 0.
    """
    tol, field = resolve_tolerance(design.tolerance, tolerance)
    return ProfileOptions(tol, getattr(design, "min_curvature_radius", None), design.bore_radius,
                          tolerance_field=field)


def check_objective(objective: object, rocker: bool) -> str:
    """``objective`` if it is one of :data:`OBJECTIVES` and fits the follower (``"L"``: rockers), else
    :class:`InputError` on ``solve.objective``."""
    check_option("solve.objective", objective, OBJECTIVES)
    if objective == "L" and not rocker:
        raise InputError("solve.objective", "'L' (least centre distance) applies to rocker followers; a "
                         "translating follower's cam is sized by R0 ('R0')")
    return str(objective)
