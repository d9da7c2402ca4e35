"""Motion design: the free phases' laws and the cam, designed together and certified.

:func:`design_motion` runs the request of a design's ``[optimize]`` table:

1. the reference: the design as given (the free phases' own laws), sized or
   checked as usual; its R0 is the size held by objectives other than R0;
2. the laws: :func:`optimize.motion.design.design_laws` solves the
   conservative program (every constraint on the Bernstein coefficients of
   every piece of every span: it holds at every cam angle) and proves a lower
   bound on the space's optimum with the relaxed one (constraints at samples);
3. the upper bound: the cam of the laws found, sized by the exact method (or
   held) and checked like any cam (the independent pressure check, the
   profile's checks); the caps are re-evaluated on the laws themselves
   (``laws.characteristics``: dense samples refined), and the squared
   objectives by Gauss-Legendre quadrature of the laws' own derivatives.

The value is the checked design's; ``gap = (value - lower_bound) / |value|``
is the certificate: no law of the space does better than ``lower_bound``. A
rocker's problem is not convex (:mod:`optimize.motion.rocker`): its design is
checked the same way, and reported with its local-optimality measure, no bound.
``certified`` is the optimum's certificate: the cam verified (its pressure angle at every cam angle, by
the independent check), the caps met by the laws themselves, and, where a bound is proven, the bound. Whether
the cam can be built and used (profile, bore, ``[dynamics]``) is the commands' one rule, ``usable``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from itertools import pairwise
from typing import TYPE_CHECKING, Any

import numpy as np

from cams.faces import face_of
from cams.faces.result import SolveResult
from cams.model.follower import Rocker, Translating
from cams.model.motiondesign import MotionCertificate
from laws.base import Law
from laws.errors import CamsError, InfeasibleError

if TYPE_CHECKING:
    from cams.faces.base import Face
    from cams.model.design import Design

__all__ = ["design_motion", "law_peaks", "integral_of_square"]


def law_peaks(law: Law) -> dict[str, float | None]:
    """``Cv``, ``Ca``, ``Cj`` of a normalized law (None where infinite: a jump where it meets a dwell)."""
    from laws.characteristics import characteristics

    ch = characteristics(law)
    return {k: (float(v) if np.isfinite(v) else None) for k, v in (("Cv", ch.cv), ("Ca", ch.ca), ("Cj", ch.cj))}


def integral_of_square(law: Law, r: int, breaks: np.ndarray, degree: int) -> float:
    """``integral_0^1 S^(r)(u)**2 du`` by Gauss-Legendre quadrature on each span (exact for the polynomial pieces).

    ``r`` up to 3 uses the law's own derivatives; ``r = 4`` differentiates
    ``S'''`` by the quadrature's exact rule for polynomials: the pieces'
    ``S''''`` as the derivative of their ``S'''`` fitted at ``degree - 2``
    Chebyshev points (exact for a polynomial of degree ``degree - 3``).
    """
    x, w = np.polynomial.legendre.leggauss(degree + 2)
    total = 0.0
    for a, b in pairwise(breaks):
        u = a + (b - a) * (x + 1) / 2
        if r <= 3:
            vals = law.evaluate(u)[r]
        else:
            q = max(degree - 3, 0)
            t = a + (b - a) * (1 - np.cos(np.pi * (np.arange(q + 1) + 0.5) / (q + 1))) / 2
            j3 = law.evaluate(t)[3]
            coef = np.polynomial.polynomial.polyfit(t - a, j3, q)
            vals = np.polynomial.polynomial.polyval(u - a, np.polynomial.polynomial.polyder(coef))
        total += float((b - a) / 2 * np.sum(w * vals**2))
    return total


def _ratio(pressure) -> float:
    """The largest ratio of pressure angle to its limit over the limited phases (the independent check's)."""
    out = []
    if pressure.rise is not None and pressure.rise_limit:
        out.append(pressure.rise / pressure.rise_limit)
    if pressure.ret is not None and pressure.return_limit:
        out.append(pressure.ret / pressure.return_limit)
    return float(max(out))


def _passing(new, sol, size_fixed: Callable[[Any], Any], face: Face):
    """The designed laws' smallest cam that passes the part's constraints (the bore and its hub wall, undercut,
    curvature): the sizing to the part's one search (:func:`cams.faces.part.size_to_part`) along the floor family
    of ``new`` from the optimum ``sol``, each floor's cam sized by ``size_fixed``. Returns the passing solution, or
    None when no cam of the family passes.
    """
    from cams.faces.part import size_to_part

    try:
        return size_to_part(face, new, sol, lambda floor: size_fixed(new.with_floor(floor)))
    except CamsError:
        return None


def design_motion(design: Design, *, method: str | None = None) -> SolveResult:
    """Design the free phases' laws of ``design`` with its cam (see the module notes).

    Parameters
    ----------
    design : cams.model.design.Design
        With ``optimize`` set.
    method : {"exact", "convex", "exhaustive"}, optional
        The method of the solves of the cams of fixed laws (a roller's; the face's pipeline refuses it for a
        flat face).

    Returns
    -------
    cams.faces.result.SolveResult
        The cam of the designed laws, its ``optimization`` holding the certificate (a
        :class:`cams.model.motiondesign.MotionCertificate`). The cams of fixed laws are sized by the pressure angle
        alone (a flat face: convexity); when the optimum of ``"R0"`` fails the part's constraints and the design
        asks for all (``constraints = "all"``), the designed laws' smallest cam that passes is returned (the
        sizing to the part, :mod:`cams.faces.part`), and a note gives the optimum that failed; the lower bound
        stays the optimum's.
    """
    from optimize.motion.design import design_laws

    spec = design.optimize
    assert spec is not None
    face = face_of(design)

    def size_fixed(d):     # by the face's own limit: the part's constraints are the fallback's below
        return face.size(d.with_(constraints="pressure_angle"), method=method)

    base = design.with_(optimize=None)
    if spec.objective == "L" and isinstance(base.follower, Rocker):
        # a rocker's least L: the cams of fixed laws are sized so too (a translating follower is refused below)
        base = replace(base, objective="L")
    try:
        reference = size_fixed(base)
    except InfeasibleError:
        reference = None
    hold = None
    sizes = spec.objective in ("R0", "L")   # the cam is sized; the other objectives hold its size
    if not sizes:
        if reference is None:
            raise InfeasibleError("optimize.objective",
                              "the cam's size is held at the original law's, but the original law admits no cam: "
                                  "choose the cam ([cam] base_radius or centre) or minimize R0")
        hold = float(reference.R0)
    ld = design_laws(base, spec, hold=hold)
    new = replace(base, program=ld.program)
    # the size held: the least pressure angle's cam sits at the program's centre (its margin keeps the fixed
    # phases' limits between the samples); the other objectives' laws are sized by the exact method, their least
    # R0 (within the size held up to the programs' sampling of the fixed phases: said if not)
    if spec.objective == "pressure_angle" and hold is not None:     # a roller's (refused for a flat face)
        if isinstance(new.follower, Rocker):     # the last accepted iterate's centre (within the size held)
            new = replace(new, centre=ld.centre, base_radius=None,
                          limits=replace(new.limits, centre_distance=None))
        else:
            x, d = ld.centre
            f = new.follower
            if isinstance(f, Translating) and f.offset is not None:
                f = replace(f, offset=None)
            new = replace(new, follower=f, centre=(x, -d), base_radius=None)
    sol = size_fixed(new)
    notes_first: list[str] = []
    if not sizes and hold is not None and spec.objective != "pressure_angle" and sol.R0 > hold * (1 + 1e-9):
        notes_first.append(f"the designed laws' least R0, {sol.R0:.6g} mm, exceeds the size held, {hold:.6g} mm "
                           "(the program saw the fixed phases at samples)")
    floor = None
    if spec.objective == "R0" and ld.free and design.constraints == "all" and not face.profile_passes(sol):
        better = _passing(new, sol, size_fixed, face)
        if reference is not None and face.profile_passes(reference) and (better is None
                                                                         or reference.R0 < better.R0):
            notes_first.append(f"the optimum, R0 = {sol.R0:.6g} mm, fails the profile's checks and the designed "
                               f"laws pass only at a larger cam: the original laws' cam (R0 = {reference.R0:.6g} "
                               "mm) is smaller and passes, and is returned")
            sol = reference
            ld = replace(ld, program=base.program)
        elif better is not None:
            notes_first.append(f"the optimum, R0 = {sol.R0:.6g} mm, fails the profile's checks (undercut, sharp "
                               f"points, the bore...): the designed laws' smallest cam that passes, R0 = "
                               f"{better.R0:.6g} mm, is returned (a floor on R0)")
            sol, floor = better, float(better.R0)

    # -- the value of the checked design, computed on the laws themselves ----------------------------------------
    obj = spec.objective
    laws_new = {i: ld.program.law_of(i) for i in ld.free}
    peaks = {i: law_peaks(law) for i, law in laws_new.items()}
    if obj == "R0":
        value = float(sol.R0)
    elif obj == "L":
        value = float(sol.L)
    elif obj == "pressure_angle":
        value = _ratio(sol.detail.pressure)
    elif obj in ("Ca", "Cj"):
        value = max(np.inf if (pk := p[obj]) is None else float(pk) for p in peaks.values())
    else:
        r = 3 if obj == "jerk_squared" else 4
        value = sum(integral_of_square(law, r, ld.space.breaks, spec.degree) for law in laws_new.values())
    notes = notes_first
    if obj == "pressure_angle":     # a roller's (refused for a flat face)
        limited = {i for i, _ in base.constrained_phases()}
        if not limited & set(ld.free):
            notes.append("no free phase has a limited pressure angle (force closure limits the rise only): the "
                         "free laws cannot lower it; free a rise")
    caps_ok = True
    names = {1: "Cv", 2: "Ca", 3: "Cj"}
    for (k, r), cap in ld.caps.items():
        got = peaks[ld.free[k]][names[r]]
        if got is None or got > cap:
            caps_ok = False
            notes.append(f"free phase {ld.free[k]}: {names[r]} = {got} exceeds its cap {cap:.6g}")
    proven = ld.lower_bound is not None     # a convex program's bound; a rocker's is a local optimum
    gap = (value - ld.lower_bound) / abs(value) if ld.lower_bound is not None and value else None
    if ld.box_binds:
        notes.append("the laws touch the space's bound on their coefficients: the lower bound holds within it")
    certified = bool(caps_ok and sol.verified and (getattr(sol, "certified", None) is not False)
                     and (gap is not None or not proven))
    original = {i: base.program.law_of(i) for i in ld.free}
    phases = []
    for i in ld.free:
        phases.append({
            "phase": i, "kind": base.program.phases[i].kind, **peaks[i],
            "original": {"law": original[i].name, **law_peaks(original[i])},
        })
    info = MotionCertificate(
        objective=obj,
        value=value,
        lower_bound=None if ld.lower_bound is None else float(ld.lower_bound),
        gap=None if gap is None else float(gap),
        certified=certified,
        degree=spec.degree,
        spans=spec.spans,
        continuity=spec.continuity,
        pieces=ld.space.pieces,
        free=tuple(ld.free),
        caps=tuple({"phase": ld.free[k], "derivative": names[r], "max": cap} for (k, r), cap in ld.caps.items()),
        phases=tuple(phases),
        reference=None if reference is None else {
            "R0": float(reference.R0),
            "L": None if reference.L is None else float(reference.L),
            "centre": {"x": float(reference.centre[0]), "y": float(reference.centre[1])},
        },
        held_R0=hold,
        floor=floor,
        method="conic" if proven else "sequential convex programming",
        local_measure=ld.local_measure,
        iterations=ld.iterations,
        history=tuple(ld.history),
        seconds=float(ld.seconds),
        notes=tuple(notes),
    )
    return replace(sol, optimization=info, notes=(*sol.notes, *notes))
