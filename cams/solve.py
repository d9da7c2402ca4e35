"""The facade: one entry point for sizing a cam and checking it, whatever its face and laws.

``solve(design)`` hands a design of fixed laws to its face's pipeline (:func:`cams.faces.face_of`: the roller's
sizing in the allowable-centre zone, verified independently by :func:`cams.verify.pressure.check_pressure`; the
flat face's by convexity), and a design with an ``[optimize]`` table to the motion design
(:func:`cams.motion_design.design_motion`), which designs the free laws and sizes their cam through the same
pipeline. ``check_design(design)`` solves and checks the finished profile.
"""

from __future__ import annotations

import sys
import types
from typing import TYPE_CHECKING

from cams.faces import face_of
from cams.faces.base import SEARCH_CHORD
from cams.faces.result import SolveResult
from cams.faces.roller import TIE, excess, pressure_failures
from cams.model.design import OBJECTIVE_SUPERSEDED
from cams.model.options import profile_options
from laws.errors import InputError

if TYPE_CHECKING:
    from cams.model.design import Design

__all__ = ["SolveResult", "solve", "check_design", "excess", "pressure_failures", "profile_passes", "TIE",
           "SEARCH_CHORD"]


def solve(design: Design, *, method: str | None = None, objective: str | None = None) -> SolveResult:
    """Size the cam of ``design`` and verify it: the one entry point for every follower.

    Parameters
    ----------
    design : cams.model.design.Design
        Lengths in its unit, angles in radians; ``design.limits`` may fix the centre distance L (rocker) or a
        floor on R0, the follower a fixed offset (translating). A flat-faced follower's design is sized by
        convexity (:func:`optimize.flat.size_flat_face`). With ``[optimize]`` (``design.optimize``) the free
        phases' laws are designed with the cam (:mod:`cams.motion_design`).
    method : {"exact", "convex", "exhaustive"}, optional
        Overrides ``design.method`` (roller followers; refused for a flat face).
    objective : {"R0", "L"}, optional
        What to minimize when neither L nor a floor on R0 is fixed; ``"L"`` applies to rockers only. Default:
        the design file's ``[solve] objective`` (``design.objective``), else ``"R0"``.

    Returns
    -------
    SolveResult
        The cam centre (a roller's in the follower's fixed frame, :mod:`cams.model.follower`), ``R0 = |O - A0|``
        (A0 the roller centre at the near dwell), ``L = |O|`` for a rocker (pivot at the origin), the offset
        ``e = -x_O`` for a translating follower (positive: the follower's axis on the +X side of the cam centre),
        lengths in the design's unit; the face's independent check in :attr:`SolveResult.detail`.

    Raises
    ------
    InfeasibleError
        Empty zone; a fixed L outside the admissible range (the message gives the range); a floor on R0 and a
        fixed L (or a fixed offset) that cannot both hold; a minimum R0 that vanishes (set a floor).
    InputError
        An unknown method or objective; ``objective="L"`` for a translating follower.
    """
    if design.optimize is not None:
        # the laws are designed first; the method applies to the solves of the cams of fixed laws
        if objective not in (None, design.objective):
            raise InputError("solve.objective", OBJECTIVE_SUPERSEDED)
        from cams.motion_design import design_motion

        return design_motion(design, method=method)
    return face_of(design).size(design, method=method, objective=objective)


def profile_passes(result: SolveResult, *, search: bool = False) -> bool:
    """True when the cam of ``result`` can be built and its profile passes every check but the pressure angle's
    (:meth:`cams.faces.base.Face.profile_passes`: buildability without the ``[dynamics]`` checks)."""
    return face_of(result.design).profile_passes(result, search=search)


def check_design(design: Design, *, tolerance: float | None = None, method: str | None = None):
    """Solve ``design`` (:func:`solve`) and check the finished profile of its cam.

    ``tolerance`` (length) overrides the design's chord tolerance; ``method`` its ``[solve] method`` (a roller's).
    Returns the face's check report (:class:`cams.checks.profile.CheckReport` or
    :class:`cams.checks.flat.FlatCheckReport`).
    """
    opts = profile_options(design, tolerance=tolerance)  # bad options fail before solving
    result = solve(design, method=method)
    return face_of(result.design).checks(result.design, result, None, opts)


class _CallableModule(types.ModuleType):
    """``cams.solve`` is this module, and calling it calls :func:`solve`: ``cams.solve(design)`` (the package's
    lazy re-export) and ``cams.solve.solve(design)`` are one function, whichever was imported first."""

    def __call__(self, design: Design, **kwargs) -> SolveResult:
        return solve(design, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
