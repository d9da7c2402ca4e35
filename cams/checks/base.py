"""What every check report shares: one check's outcome, the reports' lookup, the polygon and bore checks.

Used by the roller follower's checks (:mod:`cams.checks.profile`) and the flat
face's (:mod:`cams.checks.flat`). Lengths in the design's unit (mm); angles in
degrees in the reports.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laws.units import turn_degrees

__all__ = ["Check", "ChecksMixin", "polygon_check", "bore_check", "PRESSURE_CHECKS", "finite_or_none"]

#: The checks of a profile that repeat the verified side (the pressure angle; a flat face's radius of
#: curvature against limits.min_radius), not buildability.
PRESSURE_CHECKS = ("jamming_rise", "jamming_return", "convexity")


@dataclass(frozen=True)
class Check:
    """One check's outcome.

    Attributes
    ----------
    name : str
    passed : bool
    worst : float or None
        Worst value found (unit ``unit``); ``None`` where it does not apply.
    at : float or None
        Cam angle of the worst value, radians from the program's start
        (:meth:`to_dict` gives it in degrees in [0, 360) as ``at_deg``).
    limit : float or None
        The value ``worst`` is compared with (unit ``unit``).
    unit : str
        ``"deg"``, ``"mm"`` (the design's length unit) or ``""``.
    message : str
        One readable line.
    """

    name: str
    passed: bool
    worst: float | None
    at: float | None
    limit: float | None
    unit: str
    message: str = ""

    def to_dict(self) -> dict:
        """JSON-ready ``{name, passed, worst, at_deg, limit, unit}`` (non-finite values as ``None``)."""
        return {
            "name": self.name,
            "passed": bool(self.passed),
            "worst": finite_or_none(self.worst),
            "at_deg": finite_or_none(_deg(self.at)),
            "limit": finite_or_none(self.limit),
            "unit": self.unit,
        }


def finite_or_none(x):
    """``x`` as a float, or None when it is None or not finite (for JSON)."""
    return None if x is None or not np.isfinite(x) else float(x)


class ChecksMixin:
    """``passed`` and lookup by name for a report holding ``checks`` (a tuple of :class:`Check`)."""

    checks: tuple

    @property
    def passed(self) -> bool:
        """True when every check passed."""
        return all(c.passed for c in self.checks)

    def __getitem__(self, name: str) -> Check:
        for c in self.checks:
            if c.name == name:
                return c
        raise KeyError(name)


def _deg(phi: float | None) -> float | None:
    return None if phi is None else float(turn_degrees(phi))


def polygon_check(name: str, pts: np.ndarray, phi: np.ndarray) -> Check:
    """The closed polyline ``pts`` is a valid simple polygon round the origin.

    ``worst`` is the number of self-crossings (limit 0); ``at`` the cam
    angle (radians) of the sample nearest the first crossing (or shapely's reported
    location of another defect).
    """
    import shapely
    from shapely.geometry import LinearRing, Point, Polygon

    ring = LinearRing(pts)
    poly = Polygon(ring)
    valid = bool(poly.is_valid and ring.is_simple)
    around = bool(poly.contains(Point(0.0, 0.0)))
    at = None
    crossings = 0
    msg = f"{len(pts)} points, a simple closed curve round the cam centre"
    if not valid:
        loc = None
        reason = shapely.is_valid_reason(poly)
        if not ring.is_simple:
            # noding the ring adds its crossings as new vertices
            nodes = shapely.get_coordinates(shapely.unary_union(ring))
            known = {tuple(p) for p in np.round(pts, 9)}
            extra = {tuple(p) for p in np.round(nodes, 9)} - known
            crossings = len(extra)
            loc = np.array(sorted(extra)[0]) if extra else None
        if loc is None and "[" in reason:
            try:
                loc = np.array([float(x) for x in reason[reason.index("[") + 1:reason.index("]")].split()[:2]])
            except ValueError:  # pragma: no cover - shapely's message format
                loc = None
        if loc is not None:
            at = float(phi[int(np.argmin(np.linalg.norm(pts - np.asarray(loc), axis=1)))])
        where = "" if at is None else f", the first near cam angle {_deg(at):.4f} deg"
        msg = f"{crossings} self-crossing(s){where}" if crossings else f"not a valid closed curve ({reason}){where}"
    elif not around:
        msg = "the closed curve does not surround the cam centre"
    return Check(name, valid and around, float(crossings), at, 0.0, "", msg)


def bore_check(smallest: float, at: float, bore: float, wall: float = 0.0, *, what: str = "working profile") -> Check:
    """The ``bore`` check: the profile's smallest radius clears the bore by the hub wall (lengths).

    ``smallest`` is the cam's exact smallest radius (the kernel's: :func:`cams.kinematics.inversion.
    smallest_cam_radius`, :func:`cams.kinematics.flat.flat_radii`; not the sampled polyline's) and ``at`` its cam
    angle (radians); it passes when the wall achieved, ``smallest - bore``, is at least ``wall``; the limit is
    ``bore + wall``. ``what`` names the curve in the message.
    """
    wall_text = f" + hub wall {wall:.6g} mm" if wall > 0 else ""
    return Check("bore", bool(smallest - bore >= wall), float(smallest), float(at), float(bore + wall), "mm",
                 f"{what}'s smallest radius {smallest:.6g} mm vs bore radius {bore:.6g} mm{wall_text}")
