"""One definition of a usable cam, shared by every command: verified and buildable.

``verified`` keeps its meaning: the independent pressure-angle check of the
solver's answer (:func:`cams.verify.pressure.check_pressure`; for a flat face, its
radius of curvature against ``limits.min_radius``). ``buildable`` says a cam
can be made and run as designed; it is false when any of these fails:

* a working profile exists: the pitch curve's base radius R0 is larger than
  the roller radius (else the working profile lies outside the pitch curve);
* form closure has a roller: a knife edge (roller radius 0) cannot run in a
  groove;
* every check of the finished profile except those of the verified side
  (:func:`cams.checks.profile.check_profile`; flat face
  :func:`cams.checks.flat.check_flat_face`): no undercut or sharp point, the
  groove's outer wall, the user's least radius of curvature, a valid closed
  profile round the cam centre, the bore given by ``[cam] bore_radius``
  inside the cam;
* the ``[dynamics]`` table, when given: the follower keeps contact, does not
  jam and meets no rigid impact (:attr:`cams.dynamics.forces.CamForces.ok`);
* the ``[contact]`` table, when given: the contact stress within the
  allowable, the film parameter at least its minimum, the bearing's life at
  least its target (:meth:`cams.strength.along.ContactCycle.failures`).

A design is usable when it is both; every command exits 1 otherwise.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.checks.base import PRESSURE_CHECKS

__all__ = ["Assessment", "assess", "assess_cam", "knife_in_groove"]


@dataclass(frozen=True)
class Assessment:
    """Whether a sized cam is verified and buildable, and why not.

    Attributes
    ----------
    verified : bool
        The independent check of the answer (pressure angle; flat face: radius
        of curvature) passes, and so do the same limits recomputed from the
        finished profile (:data:`PRESSURE_CHECKS`).
    buildable : bool
        Every condition of buildability passes (see the module).
    failures : tuple of str
        One readable line per failed condition, the not verified one first;
        empty when the cam is usable.
    short : tuple of str
        The same failures in a word or two each (for titles of pictures).
    certified : bool
        False when the exact method's bounds disagree beyond its stated error
        bound (the size is not proven minimal): the answer is not one.
    """

    verified: bool
    buildable: bool
    failures: tuple[str, ...] = ()
    short: tuple[str, ...] = ()
    certified: bool = True

    @property
    def usable(self) -> bool:
        """Certified, verified and buildable: what every command's exit code 0 means."""
        return self.certified and self.verified and self.buildable

    def title(self) -> str:
        """A picture's title line for a failing cam, e.g. ``"FAILS: undercut, bore"`` ("" when usable)."""
        return "" if self.usable else "FAILS: " + ", ".join(self.short)

    def to_dict(self) -> dict:
        """JSON-ready ``{verified, buildable, failures}``, and ``certified`` when it is false."""
        d = {"verified": bool(self.verified), "buildable": bool(self.buildable), "failures": list(self.failures)}
        if not self.certified:
            d["certified"] = False
        return d


def knife_in_groove(design) -> bool:
    """True when no profile of ``design`` can be built at any size (a knife edge in a groove: its face's
    :meth:`cams.faces.base.Face.no_profile`)."""
    from cams.faces import face_of

    return face_of(design).no_profile(design) is not None


def _dynamics_failure(forces) -> str | None:
    """Why the cam forces (:class:`cams.dynamics.forces.CamForces`) fail, or None."""
    if forces.ok:
        return None
    why = []
    if forces.contact_lost:
        why.append("the follower loses contact with the cam")
    if bool(np.any(forces.jammed)):
        why.append("the follower jams (pressure angle above the jamming limit)")
    if forces.impacts:
        why.append("rigid impacts (velocity jumps)")
    return "dynamics: " + "; ".join(why or ["the forces fail"])


def assess(design, solution, *, checks=None, forces=None, no_profile: str | None = None,
           contact=None, vibration=None) -> Assessment:
    """Assess a sized cam from its parts.

    Parameters
    ----------
    design : cams.model.design.Design
    solution : cams.faces.result.SolveResult
        Its ``verified`` is the verified side.
    checks : CheckReport or FlatCheckReport, optional
        The checks of the finished profile; None only when no profile can be
        built (a knife edge in a groove).
    forces : cams.dynamics.forces.DesignForces, optional
        The ``[dynamics]`` results (None without a ``[dynamics]`` table or where
        it does not apply).
    vibration : cams.dynamics.vibration.Vibration, optional
        The elastic train's response (``[dynamics] train_stiffness``): a loss of contact under force closure
        fails the cam, like the rigid one.
    no_profile : str, optional
        Why no profile could be built at the chord tolerance (then ``checks``
        is None and the cam is not buildable).
    contact : cams.strength.along.ContactCycle, optional
        The ``[contact]`` results: a contact stress over the allowable, a film
        parameter under its minimum or a bearing life under its target fails.

    Returns
    -------
    Assessment
    """
    from cams.faces import face_of

    face = face_of(design)
    failures: list[tuple[str, str]] = []  # (short, line)
    certified = solution.certified is not False
    if not certified:
        eb = solution.error_bound
        failures.append(("not certified", "not certified: the exact method's bounds on the size "
                         + ("do not meet (no feasible centre near it)" if eb is None else f"differ by {eb:.3g} mm")))
    opt = solution.optimization
    if opt is not None and not opt.certified:
        certified = False
        failures.append(("not certified", "motion design not certified: " + ("; ".join(opt.notes)
                                                                            or "no lower bound was proven")))
    verified = bool(solution.verified)
    if not verified:
        which = face.not_verified(solution) or ["the independent check finds a limit exceeded"]
        failures.append(("not verified", "not verified: " + "; ".join(which)))
    buildable = True

    def fail(short: str, line: str) -> None:
        nonlocal buildable
        buildable = False
        failures.append((short, line))

    for short, line in face.unbuildable(design, solution):
        fail(short, line)
    if checks is not None:
        from cams.words import check_unit, fault_words, off_by

        for c in checks.checks:
            if c.passed:
                continue
            words = fault_words(c.name)  # what a student reads, not the internal name
            if c.name in PRESSURE_CHECKS:  # the same limits recomputed from the profile: the verified side
                if verified:
                    verified = False
                    failures.insert(0, ("not verified", f"not verified: {words}: {c.message}"))
            else:
                line = f"{words}: {c.message}" if c.message else words
                # by how much, as cams check says it (a count with what it counts)
                fail(words, line + off_by(c.worst, c.limit, check_unit(c.name, c.unit)))
    elif no_profile is not None:
        fail("no profile", f"no profile: {no_profile}")
    elif face.no_profile(design) is None:
        raise ValueError("assess: the profile checks are required")
    if forces is not None:
        why = _dynamics_failure(forces.forces)
        if why is not None:
            fail("dynamics", why)
    if contact is not None:
        for short, line in contact.failures():
            fail(short, line)
    if vibration is not None:
        from cams.dynamics.vibration import vibration_failure

        why = vibration_failure(vibration)
        if why is not None:
            fail("dynamics", why)
    return Assessment(verified, buildable, tuple(f for _, f in failures), tuple(s for s, _ in failures), certified)


def assess_cam(cam) -> Assessment:
    """Assess a :class:`cams.cam.Cam`: its solution, the checks of its profile, its ``[dynamics]`` forces.

    Raises
    ------
    ProfileSizeError
        The profile cannot carry a tolerance given on the command line
        (``--tolerance``): bad input. One the design file gives makes the cam
        not buildable instead ("no profile").
    """
    from cams.model.options import OVERRIDE_FIELD
    from cams.profile.roller import ProfileSizeError

    checks, no_profile = None, None
    if cam.face.no_profile(cam.design) is None:
        try:
            checks = cam.checks
        except ProfileSizeError as e:
            if e.field == OVERRIDE_FIELD:  # the tolerance asked for on the command line: bad input, not the cam's
                raise
            no_profile = str(e)  # a valid design whose profile its own tolerance cannot carry: not buildable
    has_dynamics = cam.design.dynamics is not None  # else no forces module to import
    has_contact = cam.design.contact is not None
    return assess(cam.design, cam.solution, checks=checks, forces=cam.forces if has_dynamics else None,
                  no_profile=no_profile, contact=cam.contact if has_contact else None,
                  vibration=cam.vibration if has_dynamics else None)
