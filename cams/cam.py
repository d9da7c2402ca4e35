"""A cam design with its results computed on first use and kept.

``Cam(design)`` does no work when it is made. Asking for ``solution`` solves
the zone (once); ``tradeoff`` needs the zone but not the profile; the motion
diagrams need only the program. Every result is computed once and reused.

The follower's face is chosen once (:attr:`Cam.face`, :func:`cams.faces.face_of`); each property below is one
call of the face's pipeline (:class:`cams.faces.base.Face`): a flat face's ``profile`` is a
:class:`cams.profile.flat.FlatFaceProfile`, its ``checks`` a :class:`cams.checks.flat.FlatCheckReport`, and it has
no trade-off and no forces.
"""

from __future__ import annotations

from functools import cached_property
from typing import TYPE_CHECKING

from cams.faces import face_of

if TYPE_CHECKING:
    from cams.faces.base import Face
    from cams.faces.result import SolveResult
    from cams.model.design import Design
    from cams.model.options import ProfileOptions

__all__ = ["Cam"]


class Cam:
    """Lazy access to everything about one design.

    Parameters
    ----------
    design : cams.model.design.Design
    objective : {"R0", "L"}, optional
        What to minimize; default from the design file's ``[solve] objective``.
    method : {"exact", "convex", "exhaustive"}, optional
        Overrides the design's ``[solve] method`` (roller followers).
    tolerance : float, optional
        Chord tolerance of the profile (length), overriding ``[profile] tolerance``.
    solution : SolveResult, optional
        A solution already found for ``design`` (e.g. by a machine's timing):
        taken as the cam's, not solved again.
    """

    def __init__(self, design: Design, *, objective: str | None = None, method: str | None = None,
                 tolerance: float | None = None, solution: SolveResult | None = None):
        self.given = design
        self.face: Face = face_of(design)
        self.objective = objective or design.objective
        self.method = method
        self.tolerance = tolerance
        if solution is not None:
            self.__dict__["solution"] = solution  # what the cached property would hold

    def computed(self, name: str):
        """The lazy attribute ``name`` if it has been computed, else None (computes nothing).

        E.g. ``computed("checks")`` after :attr:`assessment`: None when no
        profile could be built (a knife edge in a groove, a tolerance the
        profile cannot carry).
        """
        return self.__dict__.get(name)

    @property
    def design(self) -> Design:
        """The design whose cam this is: as given, or, with an ``[optimize]`` table, the design of the laws found
        (:mod:`cams.motion_design`; solved on first use)."""
        return self.given if self.given.optimize is None else self.solution.design

    @classmethod
    def from_file(cls, path) -> Cam:
        """Load a design file (no computation)."""
        from cams.io.designfile import load_design

        return cls(load_design(path))

    @cached_property
    def solution(self) -> SolveResult:
        """The sized cam (:class:`cams.faces.result.SolveResult`), solved on first use (:func:`cams.solve.solve`)."""
        from cams.solve import solve

        return solve(self.given, method=self.method, objective=self.objective)

    @cached_property
    def tradeoff(self):
        """The R0-L trade-off (a rocker roller's; None for other followers)."""
        return self.face.tradeoff(self.design)

    @cached_property
    def options(self) -> ProfileOptions:
        """The design's profile settings (:class:`cams.model.options.ProfileOptions`), ``tolerance`` overriding."""
        from cams.model.options import profile_options

        return profile_options(self.design, tolerance=self.tolerance)

    @cached_property
    def profile(self):
        """The sampled working profile (a roller's pitch curve too) at the design's chord tolerance."""
        return self.face.profile(self.design, self.solution, self.options)

    @cached_property
    def checks(self):
        """The checks of the finished profile: jamming, undercut, validity, the bore (the face's)."""
        return self.face.checks(self.design, self.solution, self.profile, self.options)

    @cached_property
    def _forces(self):
        """``(DesignForces or None, note or None)`` of the face's forces stage, computed once."""
        return self.face.forces(self.design, self.solution)

    @property
    def forces(self):
        """Spring, contact force, torque and jump speed (:class:`cams.dynamics.forces.DesignForces`).

        ``None`` without a ``[dynamics]`` table, for a form-closed cam or
        without a cam speed (see :func:`cams.dynamics.forces.design_forces`).
        """
        return self._forces[0]

    @property
    def forces_note(self) -> str | None:
        """Why there are no forces where a ``[dynamics]`` table asks for them (form closure, no rpm), else None."""
        return self._forces[1]

    @cached_property
    def _contact(self):
        """``(ContactCycle or None, note or None)`` of the face's contact stage, computed once."""
        c = self.design.contact
        elastic = c is not None and c.force_model == "elastic"
        return self.face.contact(self.design, self.solution, self.forces, self.vibration if elastic else None)

    @property
    def contact(self):
        """The contact along the cycle (:class:`cams.strength.along.ContactCycle`): stresses, film, life; None
        without a ``[contact]`` table or without forces (:attr:`contact_note` says why)."""
        return self._contact[0]

    @property
    def contact_note(self) -> str | None:
        """Why there is no contact stress where ``[contact]`` asks for it, else None."""
        return self._contact[1]

    @cached_property
    def vibration(self):
        """The elastic follower train's response (:class:`cams.dynamics.vibration.Vibration`); None without
        ``[dynamics] train_stiffness``."""
        spec = self.design.dynamics
        if spec is None or spec.dynamics.train_stiffness is None:
            return None
        return self.face.vibration(self.design, self.solution, self.forces)

    @cached_property
    def assessment(self):
        """Verified and buildable, with the reasons (:func:`cams.assess.assess_cam`)."""
        from cams.assess import assess_cam

        return assess_cam(self)

    def motion(self, phi):
        """Displacement and derivatives at cam angles ``phi`` (radians); no solve."""
        return self.design.program.evaluate(phi)
