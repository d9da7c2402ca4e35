"""The design's options, typed: what is minimized and how the profile is sampled and checked.

A design file's ``[solve] objective`` and ``constraints``, ``[profile]`` table and ``[cam] bore_radius`` and
``hub_wall`` land here
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
    "CONSTRAINTS",
    "ProfileOptions",
    "check_objective",
    "check_constraints",
    "check_hub_wall",
    "check_keyway",
    "check_tolerance",
    "profile_options",
    "resolve_tolerance",
]

#: What the sizing minimizes: ``"R0"`` the base radius, ``"L"`` the centre distance (rocker only).
OBJECTIVES = ("R0", "L")
#: What the sizing keeps: ``"all"`` the pressure angle, the bore with its hub wall and the profile's checks (the
#: smallest cam that can be made), ``"pressure_angle"`` the face's own limit alone (a flat face's: convexity).
CONSTRAINTS = ("pressure_angle", "all")


def check_tolerance(tol: object, field: str) -> float:
    """``tol`` as a float if it is a chord tolerance (a finite number > 0, length), else :class:`InputError`."""
    if isinstance(tol, bool) or not isinstance(tol, (int, float, np.integer, np.floating)) \
            or not math.isfinite(tol) or tol <= 0:
        raise InputError(field, f"chord tolerance must be a number > 0 (length unit), got {tol!r}")
    return float(tol)


#: The field a tolerance given on the command line is reported under (:func:`resolve_tolerance`); a profile that
#: cannot carry it is bad input, not the cam's fault (:func:`cams.assess.assess_cam`).
OVERRIDE_FIELD = "--tolerance"


def resolve_tolerance(given: float | None, override: float | None = None) -> tuple[float | None, str]:
    """The chord tolerance to use and the field a bad one is reported under.

    ``override`` (the command line's ``--tolerance``) wins over ``given``
    (the design's ``tolerance``, a file's ``[profile] tolerance``); both None
    give None: the default for the cam's size
    (:func:`cams.profile.roller.cap_tolerance`). Returns ``(tolerance, field)``;
    raises :class:`InputError` naming that field unless the tolerance is a
    number > 0.
    """
    field = "profile.tolerance" if override is None else OVERRIDE_FIELD
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
    hub_wall : float or None
        The least material between the bore and the working profile (length, >= 0); None: the profile need only
        clear the bore (a wall of 0). Only with ``bore_radius``.
    tolerance_field : str
        Where the tolerance was given (``"profile.tolerance"`` or
        ``"--tolerance"``), for the messages.
    """

    tolerance: float | None = None
    min_curvature_radius: float | None = None
    bore_radius: float | None = None
    tolerance_field: str = "profile.tolerance"
    hub_wall: float | None = None

    def __post_init__(self) -> None:
        if self.tolerance is not None:
            check_tolerance(self.tolerance, self.tolerance_field)
        for value, field in ((self.min_curvature_radius, "profile.min_curvature_radius"),
                             (self.bore_radius, "cam.bore_radius")):
            if value is not None:
                check_length(field, value)
        check_hub_wall(self.hub_wall, self.bore_radius)

    @property
    def wall(self) -> float:
        """The hub wall the bore check asks for (length): ``hub_wall``, 0 when not given."""
        return 0.0 if self.hub_wall is None else float(self.hub_wall)


class _HasProfileFields(Protocol):
    @property
    def tolerance(self) -> float | None: ...

    @property
    def bore_radius(self) -> float | None: ...

    @property
    def hub_wall(self) -> float | None: ...


def check_hub_wall(hub_wall: object, bore_radius: float | None) -> float | None:
    """``hub_wall`` (length) if it is None or a number >= 0 given with a bore, else :class:`InputError` on
    ``cam.hub_wall``."""
    if hub_wall is None:
        return None
    if isinstance(hub_wall, bool) or not isinstance(hub_wall, (int, float, np.integer, np.floating)) \
            or not math.isfinite(hub_wall) or hub_wall < 0:
        raise InputError("cam.hub_wall", f"must be a number >= 0 (mm), got {hub_wall!r}")
    if bore_radius is None:
        raise InputError("cam.hub_wall", "is the wall between the bore and the working profile: give "
                         "cam.bore_radius too")
    return float(hub_wall)


def check_keyway(width: object, depth: object, angle: object, bore_radius: float | None) -> None:
    """Refuse a bad keyway (``[cam] keyway_width``, ``keyway_depth`` in mm, ``keyway_angle`` in radians here):
    :class:`InputError` naming the field, one line. The three are given together (the angle may be left out:
    0, on the datum), with a bore, and the keyway no wider than the bore (``width < 2 bore_radius``); how deep it
    may go against the hub wall needs the profile (:func:`cams.manufacture.keyway.check_keyway_wall`)."""
    given = {"cam.keyway_width": width, "cam.keyway_depth": depth, "cam.keyway_angle": angle}
    if all(v is None for v in given.values()):
        return
    for field, v in given.items():
        if v is None and field != "cam.keyway_angle":
            raise InputError(field, "is missing: a keyway takes keyway_width and keyway_depth (mm; keyway_angle "
                             "in degrees from the datum, default 0)")
        if v is not None and (isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating))
                              or not math.isfinite(v) or (field != "cam.keyway_angle" and v <= 0)):
            raise InputError(field, f"must be a number{'' if field == 'cam.keyway_angle' else ' > 0 (mm)'}, got "
                             f"{v!r}")
    if bore_radius is None:
        raise InputError("cam.keyway_width", "a keyway is cut in the bore: give cam.bore_radius too")
    if float(width) >= 2.0 * bore_radius:  # type: ignore[arg-type]
        raise InputError("cam.keyway_width", f"{float(width):g} mm is not narrower than the bore (diameter "  # type: ignore[arg-type]
                         f"{2.0 * bore_radius:g} mm)")


def check_constraints(constraints: object) -> str:
    """``constraints`` if it is one of :data:`CONSTRAINTS`, else :class:`InputError` on ``solve.constraints``."""
    return check_option("solve.constraints", constraints, CONSTRAINTS)


def profile_options(design: _HasProfileFields, *, tolerance: float | None = None) -> ProfileOptions:
    """The profile settings of a design (roller or flat face), ``tolerance`` overriding its own.

    Parameters
    ----------
    design : CamDesign or FlatFaceDesign
        Its ``tolerance``, ``bore_radius``, ``hub_wall`` and (roller) ``min_curvature_radius``.
    tolerance : float, optional
        Overrides the design's tolerance (the command line's ``--tolerance``).

    Raises
    ------
    InputError
        ``--tolerance`` (the override) that is not a number > 0.
    """
    tol, field = resolve_tolerance(design.tolerance, tolerance)
    return ProfileOptions(tol, getattr(design, "min_curvature_radius", None), design.bore_radius,
                          tolerance_field=field, hub_wall=design.hub_wall)


def check_objective(objective: object, rocker: bool) -> str:
    """``objective`` if it is one of :data:`OBJECTIVES` and fits the follower (``"L"``: rockers), else
    :class:`InputError` on ``solve.objective``."""
    check_option("solve.objective", objective, OBJECTIVES)
    if objective == "L" and not rocker:
        raise InputError("solve.objective", "'L' (least centre distance) applies to rocker followers; a "
                         "translating follower's cam is sized by R0 ('R0')")
    return str(objective)
