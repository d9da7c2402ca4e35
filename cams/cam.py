"""A cam design with its results computed on first use and kept.

``Cam(design)`` does no work when it is made. Asking for ``solution`` solves
the zone (once); ``tradeoff`` needs the zone but not the profile; the motion
diagrams need only the program. Every result is computed once and reused.

A flat-faced follower's design (:class:`cams.model.design.FlatFaceDesign`) has the
same attributes: ``solution`` is a :class:`optimize.flat.FlatFaceSolution`
(size from convexity), ``profile`` a :class:`cams.profile.flat.FlatFaceProfile`,
``checks`` a :class:`cams.checks.flat.FlatCheckReport`; it has no trade-off and
no forces (both None).
"""

from __future__ import annotations

from functools import cached_property

from cams.model.design import CamDesign, FlatFaceDesign

__all__ = ["Cam"]


class Cam:
    """Lazy access to everything about one design.

    Parameters
    ----------
    design : CamDesign or FlatFaceDesign
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

    def __init__(self, design: CamDesign | FlatFaceDesign, *, objective: str | None = None, method: str | None = None,
                 tolerance: float | None = None, solution=None):
        self.given = design
        self.objective = objective or getattr(design, "objective", "R0")
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
    def design(self) -> CamDesign | FlatFaceDesign:
        """The design whose cam this is: as given, or, with an ``[optimize]`` table, the design of the laws found
        (:mod:`cams.motion_design`; solved on first use)."""
        if getattr(self.given, "optimize", None) is None:
            return self.given
        return self.solution.design

    @property
    def flat(self) -> bool:
        """True for a flat-faced follower (sized by convexity)."""
        return isinstance(self.given, FlatFaceDesign)

    @classmethod
    def from_file(cls, path) -> Cam:
        """Load a design file (no computation)."""
        from cams.io.designfile import load_design

        return cls(load_design(path))

    @cached_property
    def solution(self):
        """The sized cam (:class:`cams.solve.SolveResult`), solved on first use."""
        given = self.given
        if isinstance(given, FlatFaceDesign) and given.optimize is None:  # narrowing the design's type
            from optimize.flat import size_flat_face

            return size_flat_face(given)
        from cams.solve import solve

        return solve(given, method=self.method, objective=self.objective)

    @cached_property
    def tradeoff(self):
        """The R0-L trade-off (rocker only; None for a translating follower)."""
        if isinstance(self.design, FlatFaceDesign) or self.design.follower.kind != "rocker":
            return None
        from optimize.tradeoff import tradeoff

        return tradeoff(self.design, 15)

    @cached_property
    def options(self):
        """The design's profile settings (:class:`cams.model.options.ProfileOptions`), ``tolerance`` overriding."""
        from cams.model.options import profile_options

        return profile_options(self.design, tolerance=self.tolerance)

    @cached_property
    def profile(self):
        """The sampled pitch curve and working profile(s) at the design's chord tolerance."""
        if isinstance(self.design, FlatFaceDesign):  # as self.flat, narrowing the design's type
            from cams.profile.flat import flat_face_profile

            opts = self.options
            return flat_face_profile(self.design, self.solution.R0, tolerance=opts.tolerance,
                                     field=opts.tolerance_field)
        from cams.profile.roller import build_profile

        return build_profile(self.design, self.solution.centre, tolerance=self.options.tolerance,
                             field=self.options.tolerance_field)

    @cached_property
    def checks(self):
        """Jamming, undercut, validity and bore checks of the finished profile."""
        if isinstance(self.design, FlatFaceDesign):  # as self.flat, narrowing the design's type
            from cams.checks.flat import check_flat_face

            return check_flat_face(self.design, self.solution, self.profile)
        from cams.checks.profile import check_profile

        return check_profile(self.design, self.solution.centre, options=self.options, profile=self.profile)

    @cached_property
    def _forces(self):
        """``(DesignForces or None, note or None)`` of :func:`cams.dynamics.forces.design_forces`, computed once."""
        if isinstance(self.design, FlatFaceDesign):  # as self.flat, narrowing the design's type
            return None, None
        from cams.dynamics.forces import design_forces

        return design_forces(self.design, self.solution.centre)

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
    def assessment(self):
        """Verified and buildable, with the reasons (:func:`cams.assess.assess_cam`)."""
        from cams.assess import assess_cam

        return assess_cam(self)

    def motion(self, phi):
        """Displacement and derivatives at cam angles ``phi`` (radians); no solve."""
        return self.design.program.evaluate(phi)
