"""The flat-faced follower's pipeline: sized by convexity, its profile the envelope of the face's lines.

Sizing: :func:`optimize.flat.size_flat_face` (the smallest base radius whose profile keeps its radius of curvature
at least ``min_radius``; the pressure angle is fixed by the geometry). The profile is
:func:`cams.profile.flat.flat_face_profile`'s, its checks :func:`cams.checks.flat.check_flat_face`'s (convexity,
a closed profile, the bore). A flat face has no zone, no R0-L trade-off, and (today) no forces: :meth:`FlatFace.forces`
refuses a ``[dynamics]`` table here, the one place.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from cams.faces.base import Face
from cams.faces.result import SolveResult
from cams.model.design import FLAT_NO_FORCES
from cams.model.follower import FlatRocker, FlatTranslating
from laws.errors import InputError

if TYPE_CHECKING:
    from cams.checks.flat import FlatCheckReport
    from cams.model.options import ProfileOptions
    from cams.profile.flat import FlatFaceProfile

__all__ = ["FlatFace", "FLAT"]


class FlatFace(Face):
    """The pipeline of a flat-faced follower's cam (translating or rocker)."""

    name = "flat"

    def size(self, design, *, method=None, objective=None) -> SolveResult:
        """The smallest base radius the convexity allows (or the floor, or the chosen ``[cam] base_radius``).

        The centre is in the frame of the flat face's reports and drawings
        (:attr:`optimize.flat.FlatFaceSolution.centre`); ``L`` is a rocker's centre distance, ``offset`` a
        translating follower's. Takes no ``method`` and no objective but ``"R0"``.
        """
        self.check_method(method, "method")
        if objective not in (None, "R0"):
            raise InputError("objective", "a flat-faced follower's cam is sized by R0 (convexity); only 'R0'")
        from optimize.flat import size_flat_face

        fs = size_flat_face(design)
        fo = design.follower
        return SolveResult(design=design, centre=fs.centre, R0=float(fs.R0),
                           L=float(fo.centre_distance) if isinstance(fo, FlatRocker) else None,
                           offset=float(fo.offset) if isinstance(fo, FlatTranslating) else None,
                           detail=fs, seconds=float(fs.seconds), notes=tuple(fs.notes))

    def check_method(self, method: str | None, field: str) -> None:
        """A flat face has no zone solver: any ``method`` is refused, named by ``field``."""
        if method is not None:
            raise InputError(field, "does not apply to a flat-faced follower: its base radius follows from "
                             "convexity directly")

    def profile(self, design, solution: SolveResult, options: ProfileOptions) -> FlatFaceProfile:
        from cams.profile.flat import flat_face_profile

        return flat_face_profile(design, solution.R0, tolerance=options.tolerance, field=options.tolerance_field)

    def checks(self, design, solution: SolveResult, profile, options: ProfileOptions) -> FlatCheckReport:
        from cams.checks.flat import check_flat_face

        if profile is None:
            profile = self.profile(design, solution, options)
        return check_flat_face(design, solution.detail, profile)

    def forces(self, design, solution: SolveResult):
        if design.dynamics is not None:
            raise InputError("dynamics", FLAT_NO_FORCES)
        return None, None


#: The flat-faced follower's pipeline.
FLAT = FlatFace()
