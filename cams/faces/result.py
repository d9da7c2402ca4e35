"""The sized cam: one result type for every follower face.

:class:`SolveResult` holds what every sized cam has (its design, the cam centre, R0, L or the offset, the
verdicts, the notes, the motion design's certificate) and a face-specific :attr:`SolveResult.detail`: the roller's
sizing (:class:`cams.faces.roller.RollerSizing`: the binding lines, the error bound, the independent pressure-angle
check) or the flat face's (:class:`optimize.flat.FlatFaceSolution`: ``R0_min``, ``R0_source``, the face range). The
detail's attributes are read through the result too (``result.binding`` is ``result.detail.binding``), so a
caller that knows its face needs no cast; code that serves both faces reads only the common attributes.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np

if TYPE_CHECKING:
    from cams.model.design import Design
    from cams.model.motiondesign import MotionCertificate

__all__ = ["SolveResult", "SizingDetail"]


class SizingDetail(Protocol):
    """What a face's sizing adds to :class:`SolveResult` (one implementation per face)."""

    @property
    def verified(self) -> bool:
        """The face's independent check of the answer (the roller: the pressure angle; flat: convexity)."""
        ...

    def to_dict(self, result: SolveResult) -> dict:
        """The result's JSON report (lengths in the design's unit, angles in degrees), in the face's key order,
        with the cam's exact ``smallest_cam_radius`` and ``largest_cam_radius`` and their ``*_at_deg`` (the same
        numbers as :meth:`cams.faces.base.Face.radii`)."""
        ...


@dataclass(frozen=True)
class SolveResult:
    """A sized (or chosen) cam of fixed laws, whatever its follower's face.

    Attributes
    ----------
    design : cams.model.design.Design
        The design whose cam this is (with ``[optimize]``: the designed laws' design).
    centre : ndarray, shape (2,)
        Cam centre (length). A roller: in the follower's fixed frame (:mod:`cams.model.follower`); a flat face:
        in the frame of its reports and drawings (:attr:`optimize.flat.FlatFaceSolution.centre`).
    R0 : float
        Base radius (length): cam centre to the roller centre at the near dwell (a roller's pitch curve), or to
        the face at the near dwell (a flat face).
    L : float or None
        Centre distance, cam centre to rocker pivot (rockers; None for a translating follower).
    offset : float or None
        Offset of the follower's axis (translating followers; None for a rocker).
    detail : SizingDetail
        What only the face's sizing has (see the module).
    seconds : float
        Time of the sizing (s); with ``[optimize]``, of the whole motion design (its laws and their cam).
    notes : tuple of str
    certified : bool or None
        The size's certificate: False when the exact method's proven lower bound and its feasible upper bound
        disagree beyond the stated accuracy; None where no bound is stated.
    optimization : MotionCertificate or None
        The motion design's certificate (a design with ``[optimize]``), else None.
    governs : str or None
        What set the size: ``"pressure_angle"`` (a roller's limit), ``"convexity"`` (a flat face's),
        ``"min_base_radius"`` (the user's floor), ``"bore"``, ``"undercut"`` or ``"curvature"`` (the part's
        constraints, :mod:`cams.faces.part`), ``"chosen"`` (the designer's cam); None where not said.
    pressure_angle_R0 : float or None
        The R0 the pressure angle alone asks for (length; a roller's: the zone's minimum, or the least at a fixed
        L or offset, with no floor), beside the answer so that the price of the other constraints shows; None for
        a flat face (its pressure angle does not size it: ``R0_min`` is its convexity's) and a chosen cam.
    """

    design: Design
    centre: np.ndarray
    R0: float
    L: float | None
    offset: float | None
    detail: SizingDetail
    seconds: float
    notes: tuple[str, ...] = field(default_factory=tuple)
    certified: bool | None = None
    optimization: MotionCertificate | None = None
    governs: str | None = None
    pressure_angle_R0: float | None = None

    def __getattr__(self, name: str) -> Any:
        # the face's own attributes, read through the result (only called when the common ones have no such name)
        if name == "detail" or name.startswith("__"):
            raise AttributeError(name)
        return getattr(self.detail, name)

    @property
    def verified(self) -> bool:
        """True when the face's independent check finds every limit respected."""
        return bool(self.detail.verified)

    @property
    def face(self) -> str:
        """The follower's face, ``"roller"`` or ``"flat"`` (a label: :attr:`cams.model.design.Design.face`)."""
        return self.design.face

    def to_dict(self) -> dict:
        """JSON-ready report: lengths in the design's unit, angles in degrees (the face's keys, the part's, then
        ``optimize`` with a motion design).

        The part's keys, every face alike: ``governs``, ``pressure_angle_R0``; ``smallest_cam_radius`` and
        ``largest_cam_radius`` (the cam's exact smallest and largest radius, the blank's radius, with
        ``*_at_deg``); ``bore_radius`` (given, or None), ``hub_wall`` (the wall achieved: the smallest radius less
        the bore, None without a bore) and ``hub_wall_required``; ``rpm`` (the cam speed, rev/min, or None);
        ``peaks`` (the follower's velocity, acceleration and jerk, :func:`cams.kinematics.peaks.motion_peaks`: at
        ``[cam] rpm``, else per radian of cam angle).
        """
        from cams.kinematics.peaks import motion_peaks

        design = self.design
        face = self.detail.to_dict(self)
        small = face["smallest_cam_radius"]
        bore = design.bore_radius
        part = {
            "governs": self.governs,
            "pressure_angle_R0": None if self.pressure_angle_R0 is None else float(self.pressure_angle_R0),
            **{k: face.pop(k) for k in ("smallest_cam_radius", "smallest_cam_radius_at_deg", "largest_cam_radius",
                                        "largest_cam_radius_at_deg")},
            "bore_radius": None if bore is None else float(bore),
            "hub_wall": None if bore is None else float(small - bore),
            "hub_wall_required": None if bore is None else float(design.hub_wall or 0.0),
            "rpm": None if design.rpm is None else float(design.rpm),
            "peaks": motion_peaks(design.program, rocker=design.follower.kind == "rocker",
                                  rpm=design.rpm).to_dict(),
        }
        d: dict = {}
        for k, v in face.items():   # the part's keys right after R0
            d[k] = v
            if k == "R0":
                d.update(part)
        d["notes"] = list(self.notes)
        if self.optimization is not None:
            d["optimize"] = self.optimization.to_dict()
        return d
