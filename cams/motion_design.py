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
A translating follower's laws are the second stage's (:mod:`optimize.motion.smooth`): the smoothest within
``(1 + smoothing_slack)`` of the first stage's value. Both stages' laws are sized and checked here; the second's
are kept when their value is within that share of the first's (to ``ACCEPT_RTOL``) and they meet the caps and the
check as well as the first's (else the first's are returned, and a note says why); the value reported is the
kept laws' own, the lower bound the first stage's. ``smoothing`` says what the slack bought.
``certified`` is the optimum's certificate: the cam verified (its pressure angle at every cam angle, by
the independent check), the caps met by the laws themselves, and, where a bound is proven, the bound. Whether
the cam can be built and used (profile, bore, ``[dynamics]``) is the commands' one rule, ``usable``.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import replace
from itertools import pairwise
from typing import TYPE_CHECKING, Any

import numpy as np

from cams.faces import face_of
from cams.faces.result import SolveResult
from cams.model.follower import Rocker, Translating
from cams.model.motiondesign import MotionCertificate
from cams.words import phase_words
from laws.base import Law
from laws.errors import CamsError, InfeasibleError
from laws.program import Program

if TYPE_CHECKING:
    from cams.faces.base import Face
    from cams.model.design import Design

__all__ = ["design_motion", "law_peaks", "integral_of_square", "jerk_variation"]


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
    Chebyshev points (exact for a polynomial of degree ``degree - 3``). The
    law is evaluated once at every span's points.
    """
    x, w = np.polynomial.legendre.leggauss(degree + 2)
    a, b = np.asarray(breaks[:-1], float), np.asarray(breaks[1:], float)
    u = a[:, None] + (b - a)[:, None] * (x[None, :] + 1) / 2
    if r <= 3:
        vals = law.evaluate(u.ravel())[r].reshape(u.shape)
    else:
        q = max(degree - 3, 0)
        cheb = (1 - np.cos(np.pi * (np.arange(q + 1) + 0.5) / (q + 1))) / 2
        t = a[:, None] + (b - a)[:, None] * cheb[None, :]
        j3 = law.evaluate(t.ravel())[3].reshape(t.shape)
        P = np.polynomial.polynomial
        vals = np.array([P.polyval(u[k] - a[k], P.polyder(P.polyfit(t[k] - a[k], j3[k], q))) for k in range(a.size)])
    return float(np.sum((b - a) / 2 * (vals**2 @ w)))


#: Points at which :func:`jerk_variation` samples S''' (the knots added).
VARIATION_SAMPLES = 100_001


def jerk_variation(law: Law, breaks: np.ndarray | None = None) -> float | None:
    """The total variation of ``S'''`` over ``u`` in [0, 1] (its jumps inside the phase included; the ends'
    steps to a neighbouring phase not). A spline's exactly: each span's ``S'''`` at its ends and at the real
    parts of its derivative's roots inside (points added never raise a sampled variation above the true one).
    Another law's sampled at :data:`VARIATION_SAMPLES` points and ``breaks``: a lower bound, within about
    ``1e-9`` relative for the library's laws. None where the jerk is infinite (``Cj`` infinite: an
    acceleration jump, or ``S''`` not 0 where the law meets a dwell)."""
    if law_peaks(law)["Cj"] is None:
        return None
    from laws.spline import SplineLaw

    if isinstance(law, SplineLaw):
        from laws.bernstein import to_power

        m = to_power(law.degree)
        total, last = 0.0, None
        for (a, b), row in zip(pairwise(law.breaks), law.coefficients, strict=True):
            jerk = np.polynomial.Polynomial(m @ np.asarray(row)).deriv(3) / (b - a) ** 3
            roots = np.real(jerk.deriv().roots()) if jerk.degree() > 1 else np.zeros(0)
            vals = jerk(np.concatenate([[0.0], np.sort(roots[(roots > 0.0) & (roots < 1.0)]), [1.0]]))
            total += float(np.sum(np.abs(np.diff(vals)))) + (0.0 if last is None else abs(float(vals[0]) - last))
            last = float(vals[-1])
        return total
    u = np.linspace(0.0, 1.0, VARIATION_SAMPLES)
    if breaks is not None:
        u = np.unique(np.concatenate([u, np.asarray(breaks, float)]))
    return float(np.sum(np.abs(np.diff(law.evaluate(u)[3]))))

#: A turn of the jerk counts when the jerk swings back by at least this share of its range (max - min) in the phase.
TURN_PROMINENCE = 0.1
#: Points at which :func:`jerk_turns` samples the jerk (the knots added).
TURN_SAMPLES = 20_001


def jerk_turns(law: Law, breaks: np.ndarray | None = None) -> int | None:
    """How many times the jerk ``S'''`` turns (from rising to falling or back) inside the phase, counting only
    swings of at least :data:`TURN_PROMINENCE` of its range; None where the jerk is infinite.

    The 3-4-5 law's jerk turns once, the 4-5-6-7 law's 3 times (up, down, up); a designed law whose jerk turns more
    often than the law it replaces rings. Sampled at :data:`TURN_SAMPLES` points and ``breaks`` (a zigzag: a
    turning point is confirmed once the jerk has moved back from it by the prominence).
    """
    if law_peaks(law)["Cj"] is None:
        return None
    u = np.linspace(0.0, 1.0, TURN_SAMPLES)
    if breaks is not None:
        u = np.unique(np.concatenate([u, np.asarray(breaks, float)]))
    j = law.evaluate(u)[3]
    tol = TURN_PROMINENCE * float(np.ptp(j))
    if not tol > 0:
        return 0
    pivot, direction, turns = float(j[0]), 0, 0
    for v in map(float, j[1:]):
        if direction == 0:
            if abs(v - pivot) > tol:  # the first swing sets the direction; the start is no turn
                direction, pivot = (1 if v > pivot else -1), v
        elif (v - pivot) * direction > 0:
            pivot = v  # still going the same way
        elif abs(v - pivot) > tol:  # moved back by the prominence: the pivot was a turn
            turns += 1
            direction, pivot = -direction, v
    return turns


def ringing_note(designed: Law, original: Law, phase: int, kind: str, breaks: np.ndarray | None) -> str | None:
    """A note when the designed law's jerk turns more often than the original law's (:func:`jerk_turns`), else None."""
    new, old = jerk_turns(designed, breaks), jerk_turns(original)
    if new is None or old is None or new <= old:
        return None
    def times(n: int) -> str:
        return {1: "once", 2: "twice"}.get(n, f"{n} times")

    return (f"{phase_words(kind, phase)}: the designed law's jerk rings: it turns {times(new)} where the original "
            f"{original.name}'s turns {times(old)} (swings over {TURN_PROMINENCE:.0%} of its range); a larger "
            "optimize.smoothing_slack, or fewer spans, smooths it at some cost in the objective")


def _objective_value(obj: str, sol, laws: dict[int, Law], peaks: dict[int, dict], breaks: np.ndarray,
                     degree: int) -> float:
    """The objective of a checked design (``sol``, its laws ``laws`` of the free phases and their ``peaks``)."""
    if obj == "R0":
        return float(sol.R0)
    if obj == "L":
        return float(sol.L)
    if obj == "pressure_angle":
        return _ratio(sol.detail.pressure)
    if obj in ("Ca", "Cj"):
        return max(np.inf if (pk := p[obj]) is None else float(pk) for p in peaks.values())
    r = 3 if obj == "jerk_squared" else 4
    return sum(integral_of_square(law, r, breaks, degree) for law in laws.values())


def _smoothness(laws: dict[int, Law], r: int, breaks: np.ndarray, degree: int) -> dict[str, float | None]:
    """The sums over the free phases of the integrals of ``S^(r)**2`` and ``S'''**2`` and of ``S'''``'s total
    variation (None when a phase's jerk is infinite)."""
    tv = [jerk_variation(law, breaks) for law in laws.values()]
    return {"integral": sum(integral_of_square(law, r, breaks, degree) for law in laws.values()),
            "jerk_squared": sum(integral_of_square(law, 3, breaks, degree) for law in laws.values()),
            "jerk_variation": None if any(t is None for t in tv) else float(sum(t for t in tv if t is not None))}


def _ratio(pressure) -> float:
    """The largest ratio of pressure angle to its limit over the limited phases (the independent check's)."""
    out = []
    if pressure.rise is not None and pressure.rise_limit:
        out.append(pressure.rise / pressure.rise_limit)
    if pressure.ret is not None and pressure.return_limit:
        out.append(pressure.ret / pressure.return_limit)
    return float(max(out))


#: The normalized peaks' names by derivative.
_PEAK_NAMES = {1: "Cv", 2: "Ca", 3: "Cj"}


def _law_table(law: Law) -> dict:
    """A spline law as a design file's law table writes it (``kind``, ``degree``, ``breaks``, ``coefficients``)."""
    from laws.spline import SplineLaw

    assert isinstance(law, SplineLaw)
    return {"kind": "spline", "degree": law.degree, "breaks": [float(x) for x in law.breaks],
            "coefficients": [[float(x) for x in row] for row in law.coefficients]}


def _passing(new, sol, size_fixed: Callable[[Any], Any], face: Face):
    """The designed laws' smallest cam that passes the part's constraints (the bore and its hub wall, undercut,
    curvature): the sizing to the part's one search (:func:`cams.faces.part.size_to_part`) along the floor family
    of ``new`` from the optimum ``sol``, each floor's cam sized by ``size_fixed``. Returns the passing solution and
    the floor (length) it was sized with, or ``(None, None)`` when no cam of the family passes.
    """
    from cams.faces.part import size_to_part

    try:
        return size_to_part(face, new, sol, lambda floor: size_fixed(new.with_floor(floor)))
    except CamsError:
        return None, None


#: Bisection steps of :func:`_checked_stages` on the way from the first stage's laws to the second's.
STEP_BISECTIONS = 10


def _blend(first: Program, second: Program, free: tuple[int, ...], step: float) -> Program:
    """``first``'s program with each free phase's spline moved ``step`` of the way to ``second``'s (the same
    knots and degree: the laws' Bernstein coefficients are linear in the space's variables)."""
    from laws.spline import SplineLaw

    laws = {}
    for i in free:
        a, b = first.law_of(i), second.law_of(i)
        assert isinstance(a, SplineLaw) and isinstance(b, SplineLaw)
        c = (1 - step) * np.asarray(a.coefficients) + step * np.asarray(b.coefficients)
        c[0, 0], c[-1, -1] = 0.0, 1.0
        laws[i] = SplineLaw(a.breaks, tuple(tuple(float(x) for x in row) for row in c), name=b.name)
    return Program(tuple(replace(p, law=laws.get(i, p.law)) for i, p in enumerate(first.phases)), first.lift)


def _checked_stages(ld, spec, placed: Callable, size_fixed: Callable, new, sol):
    """Both stages' laws checked (:mod:`optimize.motion.smooth`): ``(ld, new, sol, smoothing, notes)``.

    The second stage's laws are kept when their checked value is within ``(1 + smoothing_slack)`` of the
    first's (to ``ACCEPT_RTOL``) and they meet the caps and the check where the first's do. Otherwise (the
    programs' conservatism differs between the two laws; the solver's tolerance) the laws are taken on the
    segment between the two, as far toward the second as keeps that true, and a note says so: where the chord of
    the values crosses the limit (enough for an objective convex along the segment: R0, a peak, an integral),
    else by bisection (:data:`STEP_BISECTIONS` steps; a pressure-angle ratio is quasi-convex along it).
    ``smoothing["step"]`` is that share of the way (1: the second stage's laws).
    """
    from optimize.motion.smooth import ACCEPT_RTOL, smoothing_derivative

    obj, breaks = spec.objective, ld.space.breaks

    def evaluate(program, centre, done=None):
        new = placed(program, centre)
        try:
            s = size_fixed(new) if done is None else done
        except InfeasibleError:
            return None
        laws = {i: program.law_of(i) for i in ld.free}
        peaks = {i: law_peaks(law) for i, law in laws.items()}
        met = all((got := peaks[ld.free[k]][_PEAK_NAMES[r]]) is not None and got <= cap
                  for (k, r), cap in ld.caps.items())
        return program, centre, new, s, _objective_value(obj, s, laws, peaks, breaks, spec.degree), \
            bool(met and s.verified), laws

    first = evaluate(ld.first, ld.first_centre)
    assert first is not None
    v1, ok1 = first[4], first[5]
    limit = v1 + abs(v1) * ((1 + spec.smoothing_slack) * (1 + ACCEPT_RTOL) - 1)

    def good(e) -> bool:
        return e is not None and e[4] <= limit and (e[5] or not ok1)

    chosen, step, notes = evaluate(ld.program, ld.centre, sol), 1.0, []

    def at(t: float):
        centre = tuple((1 - t) * a + t * b for a, b in zip(ld.first_centre, ld.centre, strict=True))
        return evaluate(_blend(ld.first, ld.program, ld.free, t), centre)

    if not good(chosen):
        e2 = chosen
        lo, hi, chosen = 0.0, 1.0, first
        # first where the chord crosses the limit: enough for an objective convex along the segment
        if e2 is not None and e2[4] > limit > v1:
            t = (limit - v1) / (e2[4] - v1)
            e = at(t)
            if good(e):
                lo, hi, chosen = t, t, e
            else:
                hi = t
        for _ in range(STEP_BISECTIONS if hi > lo else 0):
            mid = 0.5 * (lo + hi)
            e = at(mid)
            if good(e):
                lo, chosen = mid, e
            else:
                hi = mid
        step = lo
        why = ("misses a cap or the check that the first stage's meet" if e2 is None or not (e2[5] or not ok1)
               else f"has the value {e2[4]:.10g}, beyond (1 + smoothing_slack) times the first stage's, {v1:.10g}")
        notes.append(f"the second stage's smoothest law {why}: the laws returned are {step:.4g} of the way from the "
                     "first stage's to it")
    program, centre, new, sol, v2, _, laws2 = chosen
    ld = replace(ld, program=program, centre=centre)
    r = smoothing_derivative(ld.space)
    laws1 = first[6]
    before, after = _smoothness(laws1, r, breaks, spec.degree), _smoothness(laws2, r, breaks, spec.degree)
    smoothing = {"slack": float(spec.smoothing_slack), "derivative": r, "smoothed": step > 0, "step": step,
                 "value_before": v1, "value_after": v2,
                 **{f"{k}_before": before[k] for k in before}, **{f"{k}_after": after[k] for k in after},
                 "first_stage_laws": [{"phase": i, **_law_table(law)} for i, law in laws1.items()]}
    return ld, new, sol, smoothing, notes


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
    t0 = time.perf_counter()  # the result's seconds: the whole motion design, its cams' sizings included
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

    def placed(program, centre):
        """The design of ``program``'s laws. The size held: the least pressure angle's cam (a roller's; refused
        for a flat face) sits at the program's centre (its margin keeps the fixed phases' limits between the
        samples); the other objectives' laws are sized by the exact method, their least R0 (within the size held
        up to the programs' sampling of the fixed phases: said if not)."""
        new = replace(base, program=program)
        if spec.objective == "pressure_angle" and hold is not None:
            if isinstance(new.follower, Rocker):     # the last accepted iterate's centre (within the size held)
                return replace(new, centre=centre, base_radius=None, limits=replace(new.limits, centre_distance=None))
            x, d = centre
            f = new.follower
            if isinstance(f, Translating) and f.offset is not None:
                f = replace(f, offset=None)
            return replace(new, follower=f, centre=(x, -d), base_radius=None)
        return new

    new = placed(ld.program, ld.centre)
    sol = size_fixed(new)
    notes_first: list[str] = []
    obj = spec.objective
    breaks = ld.space.breaks
    smoothing = None
    if ld.first is not None and ld.first_centre is not None:
        ld, new, sol, smoothing, said = _checked_stages(ld, spec, placed, size_fixed, new, sol)
        notes_first += said
    elif ld.smoothing_note is not None and spec.smoothing_slack > 0:
        notes_first.append(f"smoothing_slack: {ld.smoothing_note}")
    held_ok = True
    if not sizes and hold is not None and sol.R0 > hold * (1 + 4 * np.finfo(float).eps):
        from optimize.motion.lawrows import HOLD_RTOL

        held_ok = sol.R0 <= hold * (1 + HOLD_RTOL)
        notes_first.append(f"the designed laws' cam, R0 = {sol.R0:.10g} mm, exceeds the size held, {hold:.10g} mm, "
                           f"by {sol.R0 / hold - 1:.2g} (relative; "
                           + ("within the tolerance" if held_ok else "more than the tolerance") + f" {HOLD_RTOL:g})")
    floor = None
    if spec.objective == "R0" and ld.free and design.constraints == "all" and not face.profile_passes(sol):
        better, better_floor = _passing(new, sol, size_fixed, face)
        if reference is not None and face.profile_passes(reference) and (better is None
                                                                         or reference.R0 < better.R0):
            notes_first.append(f"the optimum, R0 = {sol.R0:.6g} mm, fails the profile's checks and the designed "
                               f"laws pass only at a larger cam: the original laws' cam (R0 = {reference.R0:.6g} "
                               "mm) is smaller and passes, and is returned")
            sol = reference
            ld = replace(ld, program=base.program)
            smoothing = None                # neither stage's laws are returned
        elif better is not None:
            notes_first.append(f"the optimum, R0 = {sol.R0:.6g} mm, fails the profile's checks (undercut, sharp "
                               f"points, the bore...): the designed laws' smallest cam that passes, R0 = "
                               f"{better.R0:.6g} mm, is returned (a floor on R0)")
            sol, floor = better, better_floor  # the floor it was sized with (a saved design solves back to it)

    # -- the value of the checked design, computed on the laws themselves ----------------------------------------
    laws_new = {i: ld.program.law_of(i) for i in ld.free}
    peaks = {i: law_peaks(law) for i, law in laws_new.items()}
    value = _objective_value(obj, sol, laws_new, peaks, breaks, spec.degree)
    notes = notes_first
    if obj == "pressure_angle":     # a roller's (refused for a flat face)
        limited = {i for i, _ in base.constrained_phases()}
        if not limited & set(ld.free):
            notes.append("no free phase has a limited pressure angle (force closure limits the rise only): the "
                         "free laws cannot lower it; free a rise")
    caps_ok = True
    names = _PEAK_NAMES
    for (k, r), cap in ld.caps.items():
        got = peaks[ld.free[k]][names[r]]
        if got is None or got > cap:
            caps_ok = False
            shown = "infinite (the derivative below it jumps)" if got is None else f"{got:.10g}"
            notes.append(f"free phase {ld.free[k]}: {names[r]} = {shown} exceeds its cap {cap:.10g}")
    proven = ld.lower_bound is not None     # a convex program's bound; a rocker's is a local optimum
    gap = (value - ld.lower_bound) / abs(value) if ld.lower_bound is not None and value else None
    if ld.box_binds:
        notes.append("the laws touch the space's bound on their coefficients: the lower bound holds within it")
    certified = bool(caps_ok and held_ok and sol.verified and (sol.certified is not False)
                     and (gap is not None or not proven))
    # every reason the certificate fails is said (the caps and the size held are said above)
    if not sol.verified:
        notes.append("the designed laws' cam is not verified: the independent check finds a limit exceeded")
    if sol.certified is False:
        notes.append("the designed laws' cam's size is not proven: the exact method's bounds disagree")
    if proven and gap is None:
        notes.append("no gap: the value is 0")
    elif proven and ld.lower_bound == 0 and value > 0:
        notes.append("no lower bound above 0 was proven (weak duality proved no smaller value impossible at the "
                     "accuracy the solver reached): the value is the checked laws' own, how near it is to the least "
                     "is not known")
    original = {i: base.program.law_of(i) for i in ld.free}
    phases = []
    for i in ld.free:
        phases.append({
            "phase": i, "kind": base.program.phases[i].kind, **peaks[i],
            "jerk_variation": jerk_variation(laws_new[i], breaks),
            "original": {"law": original[i].name, **law_peaks(original[i]),
                         "jerk_variation": jerk_variation(original[i])},
        })
        ringing = ringing_note(laws_new[i], original[i], i, base.program.phases[i].kind, breaks)
        if ringing:
            notes.append(ringing)
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
        smoothing=smoothing,
        seconds=float(ld.seconds),
        notes=tuple(notes),
    )
    return replace(sol, optimization=info, notes=(*sol.notes, *notes), seconds=time.perf_counter() - t0)
