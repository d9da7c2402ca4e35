"""The flat-faced follower's pipeline: sized by convexity, its profile the envelope of the face's lines.

Sizing: :func:`optimize.flat.size_flat_face` (the smallest base radius whose profile keeps its radius of curvature
at least ``min_radius``; the pressure angle is fixed by the geometry), raised to clear the bore by its hub wall
(:mod:`cams.faces.part`). The profile is
:func:`cams.profile.flat.flat_face_profile`'s, its checks :func:`cams.checks.flat.check_flat_face`'s (convexity,
a closed profile, the bore), its forces :func:`cams.dynamics.flat_forces.flat_design_forces`' (spring, contact
force with the face's sliding friction, camshaft torque, jump speed). A flat face has no zone and no R0-L trade-off.
"""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from cams.faces.base import Face
from cams.faces.result import SolveResult
from cams.model.follower import FlatRocker, FlatTranslating
from laws.errors import InputError
from optimize.flat import FlatFaceSolution

if TYPE_CHECKING:
    from cams.checks.flat import FlatCheckReport
    from cams.model.options import ProfileOptions
    from cams.profile.flat import FlatFaceProfile

__all__ = ["FlatFace", "FLAT"]


def _size_alone(design) -> SolveResult:
    """The cam of ``design`` sized by convexity alone (its floor honoured), or the chosen cam."""
    from optimize.flat import size_flat_face

    fs = size_flat_face(design)
    fo = design.follower
    return SolveResult(design=design, centre=fs.centre, R0=float(fs.R0),
                       L=float(fo.centre_distance) if isinstance(fo, FlatRocker) else None,
                       offset=float(fo.offset) if isinstance(fo, FlatTranslating) else None,
                       detail=fs, seconds=float(fs.seconds), notes=tuple(fs.notes))


class FlatFace(Face):
    """The pipeline of a flat-faced follower's cam (translating or rocker)."""

    name = "flat"
    forces_computed = True

    def size(self, design, *, method=None, objective=None) -> SolveResult:
        """The smallest base radius the convexity allows (or the floor, or the chosen ``[cam] base_radius``).

        The centre is in the frame of the flat face's reports and drawings
        (:attr:`optimize.flat.FlatFaceSolution.centre`); ``L`` is a rocker's centre distance, ``offset`` a
        translating follower's. Takes no ``method`` and no objective but ``"R0"``. With ``design.constraints =
        "all"`` (the default) a cam whose profile does not clear the bore by the hub wall is raised to the smallest
        that does (:mod:`cams.faces.part`); ``governs`` says what set the size.
        """
        self.check_method(method, "method")
        if objective not in (None, "R0"):
            raise InputError("objective", "a flat-faced follower's cam is sized by R0 (convexity); only 'R0'")
        res = _size_alone(design)
        if design.chosen:
            from cams.faces.part import chosen_bore_notes

            return replace(res, governs="chosen", notes=(*res.notes, *chosen_bore_notes(self, design, res)))
        detail = res.detail
        assert isinstance(detail, FlatFaceSolution)  # this pipeline's sizing
        floored = detail.R0_source == "limits.min_base_radius"
        res = replace(res, governs="min_base_radius" if floored else "convexity")
        from cams.faces.part import sized_to_part

        out = sized_to_part(self, design, res, _size_alone)
        if out is res:
            return out
        # the floor that sized it is the search's, not the user's
        sized = out.detail
        assert isinstance(sized, FlatFaceSolution)
        return replace(out, detail=replace(sized, R0_source="part", notes=out.notes))

    def part_checks(self, design, solution: SolveResult) -> list:
        from cams.checks.flat import flat_part_checks

        return flat_part_checks(design, solution.detail)

    def radii(self, design, solution: SolveResult) -> tuple[float, float, float, float]:
        from cams.kinematics.flat import flat_radii

        return flat_radii(design, solution.R0)

    def bore_R0(self, design) -> float | None:
        """The bore radius plus the hub wall: the profile's smallest radius is R0."""
        if design.bore_radius is None:
            return None
        return float(design.bore_radius + (design.hub_wall or 0.0))

    def table(self, design, solution: SolveResult, phi):
        from cams.profile.table import flat_table

        return flat_table(design, solution.R0, phi)

    def check_method(self, method: str | None, field: str) -> None:
        """A flat face has no zone solver: any ``method`` is refused, named by ``field``."""
        if method is not None:
            raise InputError(field, "does not apply to a flat-faced follower: its base radius follows from "
                             "convexity directly")

    def profile(self, design, solution: SolveResult, options: ProfileOptions) -> FlatFaceProfile:
        from cams.profile.flat import flat_face_profile

        return flat_face_profile(design, solution.R0, tolerance=options.tolerance, field=options.tolerance_field)

    def exact(self, design, solution: SolveResult):
        from cams.profile.exact import flat_exact

        return flat_exact(design, solution.R0)

    def checks(self, design, solution: SolveResult, profile, options: ProfileOptions) -> FlatCheckReport:
        from cams.checks.flat import check_flat_face

        if profile is None:
            profile = self.profile(design, solution, options)
        return check_flat_face(design, solution.detail, profile)

    def forces(self, design, solution: SolveResult):
        from cams.dynamics.flat_forces import flat_design_forces

        return flat_design_forces(design, float(solution.R0))

    def contact_geometry(self, design, solution: SolveResult, phi, length_unit: float):
        from cams.strength.along import flat_geometry

        return flat_geometry(design, float(solution.R0), phi, length_unit)


#: The flat-faced follower's pipeline.
FLAT = FlatFace()
