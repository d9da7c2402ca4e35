"""The checks of a flat-faced follower's cam: convexity, a valid closed profile, the bore.

The polygon and bore checks are :mod:`cams.checks.base`'s, the same as for a
roller follower's cam. Lengths in the design's unit (mm), angles in degrees
in the reports.
"""

from __future__ import annotations

from dataclasses import dataclass

from cams.checks.base import Check, ChecksMixin, bore_check, polygon_check
from cams.profile.flat import FlatFaceProfile
from cams.profile.roller import default_bore_radius

__all__ = ["FlatCheckReport", "check_flat_face"]


@dataclass(frozen=True, eq=False)
class FlatCheckReport(ChecksMixin):
    """The checks of a flat-face cam: convexity, a valid closed profile, the bore.

    Attributes
    ----------
    name : str
    checks : tuple of cams.checks.profile.Check
        ``convexity`` (smallest radius of curvature >= ``limits.min_radius``),
        ``profile_polygon`` (the sampled profile is a simple closed curve round
        the cam centre) and ``bore`` (only with ``[cam] bore_radius``).
    profile : FlatFaceProfile
    bore_radius : float
    min_radius : float
    """

    name: str
    checks: tuple
    profile: FlatFaceProfile
    bore_radius: float
    min_radius: float

    def to_dict(self) -> dict:
        """JSON-ready report: lengths in the design's unit, angles in degrees."""
        return {
            "name": self.name,
            "face": "flat",
            "passed": bool(self.passed),
            "checks": [c.to_dict() for c in self.checks],
            "min_radius": float(self.min_radius),
            "bore_radius": float(self.bore_radius),
            "R0": float(self.profile.R0),
            "points": len(self.profile),
            "tolerance": None if self.profile.tolerance is None else float(self.profile.tolerance),
        }


def check_flat_face(design, solution, profile: FlatFaceProfile) -> FlatCheckReport:
    """Check a sized flat-face cam: convexity (refined, not only at the samples), the polygon, the bore.

    Parameters
    ----------
    design : cams.model.design.FlatFaceDesign
    solution : optimize.flat.FlatFaceSolution
        The sized cam: its ``min_rho``, ``min_rho_at`` and ``rho_tolerance``.
    profile : FlatFaceProfile
        The cam sampled at the solution's base radius.
    """
    rmin = design.min_radius
    ok = solution.min_rho >= rmin - solution.rho_tolerance
    checks = [Check("convexity", bool(ok), float(solution.min_rho), solution.min_rho_at, float(rmin), "mm",
                    f"smallest radius of curvature of the profile {solution.min_rho:.6g} (limit {rmin:g})"),
              polygon_check("profile_polygon", profile.work, profile.phi)]
    bore = design.bore_radius if design.bore_radius is not None else default_bore_radius(profile)
    if design.bore_radius is not None:
        checks.append(bore_check(profile, bore, what="profile"))
    return FlatCheckReport(design.name, tuple(checks), profile, float(bore), float(rmin))
