"""The follower faces' pipelines: one :class:`~cams.faces.base.Face` per face, chosen once.

:func:`face_of` is the one place that maps a design's type to its face's pipeline (the design's type itself
follows from the file's ``follower.face`` in the loader); above it, nothing asks which face a cam has.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from cams.faces.base import Face

__all__ = ["face_of"]


def face_of(design) -> Face:
    """The pipeline of ``design``'s follower face (:class:`cams.model.design.CamDesign`: the roller's,
    :class:`cams.model.design.FlatFaceDesign`: the flat face's)."""
    from cams.model.design import FlatFaceDesign

    if isinstance(design, FlatFaceDesign):
        from cams.faces.flat import FLAT

        return FLAT
    from cams.faces.roller import ROLLER

    return ROLLER
