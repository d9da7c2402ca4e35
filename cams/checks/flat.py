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

__all__ = ["FlatCheckReport", "check_flat_face", "flat_part_checks"]


@dataclass(frozen=True, eq=False)
class FlatCheckReport(ChecksMixin):
    """The checks of a flat-face cam: convexity, a valid closed profile, the bore.

    Attributes
    ----------
    name : str
    checks : tuple of cams.checks.profile.Check
        ``convexity`` (smallest radius of curvature >= ``limits.min_radius``),
        ``profile_polygon`` (the sampled profile is a simple closed curve round
        the cam centre) and ``bore`` (only with ``[cam] bore_radius``: the exact
        smallest radius against the bore and its hub wall).
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


def flat_part_checks(design, solution) -> list[Check]:
    """The checks of a flat-face cam that need no sampled profile: convexity and (with a bore) the bore.

    Convexity compares the solution's refined smallest radius of curvature with ``limits.min_radius``; the bore
    the profile's exact smallest radius (:func:`cams.kinematics.flat.flat_radii`) with the bore and its hub wall.
    The sizing to the part (:mod:`cams.faces.part`) judges its candidates by these.

    Parameters
    ----------
    design : cams.model.design.FlatFaceDesign
    solution : optimize.flat.FlatFaceSolution
        The sized cam: its ``R0``, ``min_rho``, ``min_rho_at`` and ``rho_tolerance``.
    """
    from cams.kinematics.flat import flat_radii

    rmin = design.min_radius
    ok = solution.min_rho >= rmin - solution.rho_tolerance
    checks = [Check("convexity", bool(ok), float(solution.min_rho), solution.min_rho_at, float(rmin), "mm",
                    f"smallest radius of curvature of the profile {solution.min_rho:.6g} (limit {rmin:g})")]
    if design.bore_radius is not None:
        smallest, at, _, _ = flat_radii(design, solution.R0)
        wall = 0.0 if design.hub_wall is None else float(design.hub_wall)
        checks.append(bore_check(smallest, at, float(design.bore_radius), wall, what="profile"))
    return checks


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
    exact = flat_part_checks(design, solution)
    checks = [exact[0], polygon_check("profile_polygon", profile.work, profile.phi), *exact[1:]]
    bore = design.bore_radius if design.bore_radius is not None else default_bore_radius(profile)
    return FlatCheckReport(design.name, tuple(checks), profile, float(bore), float(design.min_radius))
