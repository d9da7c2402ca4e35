"""The motion each exported curve gives, read back from the drawing: ``cams profile``'s ``export_motion``.

A drawing (DXF, SVG) is read back (:mod:`cams.manufacture.readback`: whatever curve it holds -- a
polyline, arcs, a spline) and the design's follower is put in contact with it (:mod:`cams.kinematics.exported`).
:func:`export_entry` gives the JSON entry, :func:`coarsest_tolerance` searches the coarsest tolerance whose export
keeps the acceleration error within a share of the law's peak.

Lengths mm, a rocker's angles degrees (the entry), shares as fractions (0.05 is 5 %).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from cams.kinematics.exported import Arc, Element, ExportMotion, Line, export_motion
from laws.errors import InputError

__all__ = [
    "check_share",
    "curve_kind",
    "export_entry",
    "measure",
    "coarsest_tolerance",
    "Trial",
    "MOTION_FORMATS",
    "SEARCH_STEPS",
    "REFINE_STEPS",
]

#: The written formats whose curve is read back and followed (a CSV holds points, not a curve).
MOTION_FORMATS = ("dxf", "svg")
#: Tolerances tried per decade, from the coarsest accepted down (:func:`coarsest_tolerance`).
SEARCH_STEPS = 2
#: Bisections (in the tolerance's logarithm) between the last tolerance that failed and the first that met.
REFINE_STEPS = 4


def check_share(share: object, field: str = "--max-accel-error") -> float:
    """``share`` as a float > 0 (a share of the law's peak acceleration: 0.05 is 5 %), else :class:`InputError`."""
    try:
        v = float(share)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        v = float("nan")
    if not (np.isfinite(v) and v > 0):
        raise InputError(field, f"must be a share of the peak acceleration > 0 (0.05 is 5 %), got {share!r}")
    return v


def curve_kind(elements: list[Element]) -> str:
    """``"polyline"`` (lines only), ``"arcs"`` (arcs, with lines or not) or ``"spline"`` (spline pieces)."""
    if all(isinstance(e, Line) for e in elements):
        return "polyline"
    if all(isinstance(e, Line | Arc) for e in elements):
        return "arcs"
    return "spline"


def measure(design, solution, path: str | os.PathLike, field: str) -> tuple[list[Element], ExportMotion]:
    """Read the curve of a written drawing back and the motion it gives (:func:`cams.kinematics.exported.
    export_motion`; ``solution``'s centre for a roller, its R0 for a flat face)."""
    from cams.manufacture.readback import read_profile

    elements = read_profile(path, field)
    return elements, export_motion(design, elements, centre=solution.centre, R0=solution.R0)


def export_entry(fmt: str, tolerance: float, elements: list[Element], motion: ExportMotion) -> dict:
    """The JSON entry of one written curve: ``format``, ``curve``, ``tolerance`` (mm), ``elements``, ``max_ds``
    (mm, a rocker's deg), ``max_dv`` (mm/rad, deg/rad), ``max_da`` (mm/rad², deg/rad²), ``max_da_ratio`` (share of
    the law's peak acceleration)."""
    return {"format": fmt, "curve": curve_kind(elements), "tolerance": float(tolerance), **motion.to_dict()}


def _share(ratio: float) -> str:
    return f"{100 * ratio:.4g} %" if np.isfinite(ratio) else "unbounded (a knife edge on a corner)"


@dataclass(frozen=True)
class Trial:
    """One tolerance tried by :func:`coarsest_tolerance`.

    Attributes
    ----------
    tolerance : float
        The chord tolerance (mm).
    ratio : float
        The acceleration error's share of the law's peak (``inf``: unbounded).
    elements : int
        The drawing's elements at that tolerance.
    """

    tolerance: float
    ratio: float
    elements: int


def coarsest_tolerance(
    evaluate: Callable[[float], Trial],
    coarsest: float,
    finest: float,
    share: float,
    *,
    curve: str,
    field: str = "--max-accel-error",
) -> Trial:
    """The coarsest tolerance whose export keeps the acceleration error within ``share`` of the law's peak.

    Tolerances from ``coarsest`` down to ``finest`` are tried, :data:`SEARCH_STEPS` a decade; between the last
    that failed and the first that meets, :data:`REFINE_STEPS` bisections of the logarithm keep the coarsest that
    meets. ``evaluate(tolerance)`` exports at that tolerance and measures.

    Raises
    ------
    InputError
        ``field``: no tolerance tried meets the share; the message gives the finest's error.
    """
    share = check_share(share, field)
    n = max(1, int(np.ceil(SEARCH_STEPS * np.log10(coarsest / finest))))
    tried = np.geomspace(coarsest, finest, n + 1)
    last_bad = None
    for t in tried:
        trial = evaluate(float(t))
        if trial.ratio <= share:
            break
        last_bad = trial
    else:
        why = (
            ": the roller rounds each vertex, so a polyline's acceleration error does not fall with the tolerance"
            if curve == "polyline"
            else ""
        )
        assert last_bad is not None
        raise InputError(
            field,
            f"no {curve} export keeps the acceleration error within {100 * share:.4g} % of the "
            f"law's peak: at the finest tolerance tried, {last_bad.tolerance:.3g} mm "
            f"({last_bad.elements} elements), it is {_share(last_bad.ratio)}{why}",
        )
    good = trial
    if last_bad is not None:
        lo, hi = np.log(good.tolerance), np.log(last_bad.tolerance)
        for _ in range(REFINE_STEPS):
            mid = evaluate(float(np.exp(0.5 * (lo + hi))))
            if mid.ratio <= share:
                good, lo = mid, np.log(mid.tolerance)
            else:
                hi = np.log(mid.tolerance)
    return good
