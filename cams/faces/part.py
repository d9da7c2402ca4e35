"""Sizing to the part: the smallest cam that can be made, one search for every face and for the motion design.

A cam sized by its pressure angle alone (a flat face: by its convexity) may be one nobody can make: its working
profile may not clear the shaft's bore, the roller may undercut it, its curvature may be sharper than asked for.
:func:`size_to_part` finds the smallest cam of the **floor family** that meets every constraint:

* the floor family: for each floor ``F`` on R0 at or above the pressure-angle minimum, the cam the face's own
  sizing returns with ``limits.min_base_radius = F`` (a roller: the centre on the circle of radius F about the
  roller centre at the near dwell with the largest margin to the zone's edges; on the circle of radius L about the
  pivot when L is fixed; on the offset's line when the offset is fixed; a flat face: R0 = F);
* the constraints, judged on exact extrema (:meth:`cams.faces.base.Face.part_checks`: refined on the kernel's
  analytic rates, never the sampled polyline's): the pressure angle within its limits (the independent check,
  :attr:`cams.faces.result.SolveResult.verified`, and its recomputation), the working profile's smallest radius at
  least the bore radius plus the hub wall (``bore``), no undercut and a working profile at all (``undercut``), the
  least radius of curvature asked for (``curvature``), a flat face's convexity (``convexity``), and with a
  ``[contact]`` table's allowable stress the largest Hertz pressure along the cycle within it
  (``contact_stress``, :meth:`cams.faces.base.Face.contact_check`: the cam's forces and contact computed).

The search: from the pressure-angle minimum the floor jumps to the least R0 whose base circle clears the bore by
the wall (:meth:`cams.faces.base.Face.bore_R0`: no smaller cam can, since the roller centre's path passes the
base circle) and then rises by factors of :data:`GROWTH` until a cam passes; the bracket between the last failing
floor and the passing one is narrowed by regula falsi (Illinois) on the smallest margin, to :data:`RTOL` of R0, and
the passing end is returned. Its certificate: the cam at ``R0 (1 - BELOW)`` on the same family is judged and
fails (if it passed, the search narrows again below it); the constraint it fails is the one that **governs**.

Monotonicity. Along the floor family the bore's margin grows with R0 wherever the roller's nearest approach to the
cam centre is on the base circle (the smallest radius is then ``R0 - r`` exactly: every translating roller, whose
roller centre only moves away from the centre, every flat face, whose smallest radius is R0, and the rockers
whose rise carries the roller away from the centre at once); a flat translating face's convexity margin is
``R0 + min(s + s'') - min_radius``, increasing. Elsewhere (the undercut and curvature margins, a rocker that
swings in, a fixed L's family) passing was found monotone on every example and on random designs
(``tests/faces/test_part_sizing.py`` scans each family densely), but it is not proven: the search does not rely on
it beyond the step of :data:`GROWTH` (a passing window narrower than that between two failing floors could be
missed), and the answer's minimality is certified locally, at ``R0 (1 - BELOW)``, in every case.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from laws.errors import CamsError, InfeasibleError
from laws.units import turn_degrees

if TYPE_CHECKING:
    from cams.checks.base import Check
    from cams.faces.base import Face
    from cams.faces.result import SolveResult

__all__ = ["Verdict", "judge", "size_to_part", "sized_to_part", "chosen_bore_notes", "GOVERNS", "GROWTH", "RTOL",
           "BELOW"]

#: The floor's factor between the candidates of the upward scan.
GROWTH = 1.25
#: The bracket's relative width at which the search stops (of R0).
RTOL = 1e-11
#: The certificate's step below the answer: the cam at ``R0 (1 - BELOW)`` on the family fails.
BELOW = 1e-6
#: The most candidates of the upward scan (``GROWTH ** 200`` is about 1e19).
MAX_STEPS = 200

#: The constraint each check (or each unbuildable reason of a face) stands for, as ``governs`` names it.
GOVERNS = {"jamming_rise": "pressure_angle", "jamming_return": "pressure_angle", "bore": "bore",
           "undercut": "undercut", "undercut_outer": "undercut", "no working profile": "undercut",
           "min_curvature_radius": "curvature", "convexity": "convexity", "contact_stress": "contact_stress"}
#: The checks whose worst value 0 is a corner of the pitch curve at a phase joint (a velocity jump): radius 0 at
#: every size, so no cam of the family passes them (:func:`cams.checks.profile.curvature_extremes`).
SIZELESS = ("undercut", "undercut_outer")
#: The design file's field that asks for each constraint (for the error when no cam of the family meets it).
FIELDS = {"pressure_angle": "limits.pressure_angle", "bore": "cam.bore_radius", "undercut": "follower.roller_radius",
          "curvature": "profile.min_curvature_radius", "convexity": "limits.min_radius",
          "contact_stress": "contact.allowable_stress"}
#: Notes of the face's sizing that the answer does not keep: a floor raised (the search's is not the user's) and
#: the base cam's failures (the answer passes).
_STALE_NOTES = ("R0 raised to the constructive floor", "R0 raised to limits.min_base_radius", "not buildable:",
                "rise pressure angle", "return pressure angle")


@dataclass(frozen=True)
class Verdict:
    """How one cam of the family fares against the constraints.

    Attributes
    ----------
    failing : tuple of str
        The constraints it fails (``governs`` words, in the checks' order, each once); empty when it passes.
    margin : float
        The smallest margin of its length checks (worst value less the limit, length; negative when failing,
        ``-inf`` when a check without a length margin fails): the search's interpolation variable.
    checks : tuple of Check
        The checks it was judged by (:meth:`cams.faces.base.Face.part_checks`).
    """

    failing: tuple[str, ...]
    margin: float
    checks: tuple[Check, ...]

    @property
    def passed(self) -> bool:
        """True when every constraint is met."""
        return not self.failing

    def failed_check(self, name: str) -> Check | None:
        """The first failed check that stands for constraint ``name``, or None."""
        return next((c for c in self.checks if not c.passed and GOVERNS.get(c.name) == name), None)


def judge(face: Face, design, solution: SolveResult) -> Verdict:
    """Judge the cam of ``solution`` (a cam of ``design``'s family) against every constraint of the part.

    The pressure angle by the independent check (``solution.verified``) and the face's checks on exact extrema
    (:meth:`cams.faces.base.Face.part_checks`); a cam with no working profile (R0 not above the roller) fails the
    roller's (``undercut``).
    """
    checks = tuple(face.part_checks(design, solution))
    stress = face.contact_check(design, solution)
    if stress is not None:
        checks = (*checks, stress)
    failing: list[str] = []
    margin = np.inf
    if not solution.verified:
        failing.append("pressure_angle")
    for short, _ in face.unbuildable(design, solution):
        failing.append(GOVERNS.get(short, short))
    for c in checks:
        if c.unit == "mm" and c.worst is not None and c.limit is not None and not np.isnan(c.worst - c.limit):
            margin = min(margin, float(c.worst - c.limit))
        if not c.passed:
            failing.append(GOVERNS.get(c.name, c.name))
    if failing and not margin < 0:      # no length margin says by how much: the search bisects there
        margin = -np.inf
    return Verdict(tuple(dict.fromkeys(failing)), float(margin), checks)


class _Family:
    """The floor family of one design: its cams by floor, each sized and judged once."""

    def __init__(self, face: Face, design, size_at: Callable[[float], SolveResult]):
        self.face, self.design, self.size_at = face, design, size_at
        self.failing: dict[float, Verdict] = {}     # the floors judged failing, with their verdicts

    def at(self, F: float) -> tuple[SolveResult, Verdict]:
        """The cam at floor ``F`` and its verdict (raises :class:`laws.errors.CamsError` beyond the family)."""
        cand = self.size_at(F)
        v = judge(self.face, self.design, cand)
        if not v.passed:
            self.failing[F] = v
        return cand, v


#: The contact stress's stall: a growth step of the floor that lowers the largest Hertz pressure by less than this
#: fraction of itself, the stress alone failing, ends the upward scan (no larger cam will meet it: the pressure
#: tends to the roller's own, ``sqrt(w E* / (pi r))``, as the cam's curvature flattens). A heuristic stop, said so.
STALL = 1e-3


def _stress_levels_off(before: Verdict, now: Verdict) -> bool:
    """True when only the contact stress fails at both floors and the later's largest pressure is within
    :data:`STALL` of the earlier's (or above it)."""
    if before.failing != ("contact_stress",) or now.failing != ("contact_stress",):
        return False
    a, b = before.failed_check("contact_stress"), now.failed_check("contact_stress")
    if a is None or b is None or a.worst is None or b.worst is None:
        return False
    return bool(b.worst > a.worst * (1.0 - STALL))


def _end_of_family(fam: _Family, lo: float, hi: float, last: tuple[SolveResult, Verdict]):
    """The family ends between ``lo`` (a cam, failing) and ``hi`` (none): a passing cam before the end, or None.

    Bisects the end (to :data:`RTOL`), judging every cam met; returns ``(F, cam, verdict)`` of the first passing
    one, else ``(F_end, cam, verdict)`` of the last cam with ``verdict.passed`` False.
    """
    end = (lo, *last)
    while hi - lo > RTOL * hi:
        mid = 0.5 * (lo + hi)
        try:
            cand, v = fam.at(mid)
        except CamsError:
            hi = mid
            continue
        if v.passed:
            return mid, cand, v
        lo, end = mid, (mid, cand, v)
    return end


def _no_cam(fam: _Family, base: SolveResult, F: float, cand: SolveResult, v: Verdict, why: str) -> InfeasibleError:
    """The error of a family none of whose cams meets the constraints (``v``: the verdict of its last, at ``F``)."""
    name = v.failing[0]
    field = FIELDS.get(name, name)
    c = v.failed_check(name)
    wall = float(fam.design.hub_wall or 0.0)
    if name == "bore" and c is not None and c.worst is not None and c.limit is not None and c.worst >= c.limit - wall:
        field = "cam.hub_wall"      # the bore alone is cleared: the wall is what no cam gives
    said = f": {c.message}" if c is not None else ""
    return InfeasibleError(field, f"no cam of this design meets it: along the floor family from R0 = "
                           f"{base.R0:.6g} mm ({_start(base.governs)}) to {F:.6g} mm ({why}) every "
                           f"cam fails the {_words(name)}; at the largest{said}")


def _words(name: str | None) -> str:
    """A constraint's name in words (``pressure_angle``: pressure angle)."""
    return (name or "size").replace("_", " ")


def _start(governs: str | None) -> str:
    """Where the family's search starts, in words: the base cam's ``governs``."""
    return "the floor limits.min_base_radius" if governs == "min_base_radius" else f"the {_words(governs)}'s minimum"


def _narrow(fam: _Family, lo: float, g_lo: float, hi: float, g_hi: float, best: tuple[SolveResult, Verdict]):
    """Narrow the bracket ``[lo, hi]`` (``lo`` failing, ``hi`` passing; ``g_*`` their margins) to :data:`RTOL`.

    Regula falsi on the smallest margin (Illinois: an end kept twice in a row has its margin halved), its point
    kept a quarter of the tolerance inside the bracket (a root at an end, as a bore cleared exactly at the
    least R0 its base circle allows, closes the bracket in one step), a bisection every fourth step and wherever
    the margins give no point. Returns ``(hi, cam, verdict)`` of the passing end.
    """
    kept, step = 0, 0
    while hi - lo > RTOL * hi:
        step += 1
        x = np.nan
        if step % 4 and np.isfinite(g_lo) and np.isfinite(g_hi) and g_hi > g_lo:
            x = hi - g_hi * (hi - lo) / (g_hi - g_lo)
        pad = 0.25 * RTOL * hi
        if np.isfinite(x):      # within the bracket, a step short of each end: a root at an end closes it next
            x = min(max(x, lo + pad), hi - pad)
        else:
            x = 0.5 * (lo + hi)
        cand, v = fam.at(x)
        if v.passed:
            hi, g_hi, best = x, v.margin, (cand, v)
            if kept == 1:
                g_lo *= 0.5
            kept = 1
        else:
            lo, g_lo = x, v.margin
            if kept == -1:
                g_hi *= 0.5
            kept = -1
    return hi, best[0], best[1]


def _sampled_valid(fam: _Family, hi: float, base: SolveResult) -> tuple[float, SolveResult, str]:
    """The family's smallest cam above ``hi`` whose sampled profile also passes (a valid closed curve round the
    centre: :meth:`cams.faces.base.Face.profile_passes`), where the exact extrema pass but the polygon does not (a
    cam just clear of its roller, its smallest radius near 0). The floor rises from ``hi`` by steps of ``BELOW``
    doubling, then a bisection to 1e-9 of R0; returns ``(floor, cam, why)``.

    Raises
    ------
    InfeasibleError
        The family ends first (``follower.roller_radius``).
    """
    def ok(F: float):
        try:
            cand, v = fam.at(F)
        except CamsError:
            return None, False
        return cand, v.passed and fam.face.profile_passes(cand)

    lo, step, F = hi, BELOW, hi
    for _ in range(60):
        F = hi * (1 + step)
        cand, good = ok(F)
        if cand is None:
            raise InfeasibleError("follower.roller_radius", f"no cam of this design meets it: its sampled working "
                                  f"profile crosses itself from R0 = {hi:.6g} mm to the family's end")
        if good:
            break
        lo, step = F, 2 * step
    else:       # pragma: no cover - a crossing 2**60 times BELOW wide
        raise InfeasibleError("follower.roller_radius", "no cam of this design meets it: its sampled working "
                              f"profile crosses itself from R0 = {hi:.6g} mm up")
    while F - lo > 1e-9 * F:
        mid = 0.5 * (lo + F)
        c2, good = ok(mid)
        if good:
            F, cand = mid, c2
        else:
            lo = mid
    return F, cand, f" (below it the sampled working profile crosses itself; its exact extrema pass from {hi:.6g} mm)"


def size_to_part(face: Face, design, base: SolveResult,
                 size_at: Callable[[float], SolveResult]) -> tuple[SolveResult, float | None]:
    """The smallest cam of ``design``'s floor family that meets every constraint of the part (see the module).

    Parameters
    ----------
    face : cams.faces.base.Face
        The design's pipeline: its :meth:`~cams.faces.base.Face.part_checks`, ``unbuildable`` and ``bore_R0``.
    design : cams.model.design.Design
        The design whose constraints (bore, hub wall, the profile's limits) are met.
    base : SolveResult
        The cam sized by the pressure angle alone (a flat face: convexity; a user's floor included), with its
        ``governs`` and ``pressure_angle_R0``: returned as it is when it passes (or fails its own limit alone: a
        sampled method's cam that exceeds it between samples is reported so, not raised; or has a corner, a
        velocity jump's, that no size clears: a note says so).
    size_at : callable
        ``size_at(F)``: the family's cam at floor ``F`` (length), sized by the pressure angle alone; it raises
        :class:`laws.errors.CamsError` where the family has no cam.

    Returns
    -------
    SolveResult
        The passing cam (``design`` as its design), its ``governs`` the constraint the cam at
        ``R0 (1 - BELOW)`` fails, its ``pressure_angle_R0`` the base's, and a note.
    float or None
        The floor it was sized with (length; a design saved with it solves back to it), None for ``base``.

    Raises
    ------
    InfeasibleError
        No cam of the family meets the constraints (the family ends: a fixed L or a flat rocker bounds R0; or no
        cam up to ``GROWTH ** MAX_STEPS`` times the minimum does): the field that asks for the constraint the
        largest cam fails (``cam.bore_radius``, ``cam.hub_wall``, ``follower.roller_radius``...).
    """
    fam = _Family(face, design, size_at)
    v0 = judge(face, design, base)
    if not set(v0.failing) - {"pressure_angle"}:   # a cam that fails only its own limit (a sampled method's) stays
        return base, None
    corner = next((c for c in v0.checks if c.name in SIZELESS and not c.passed and c.worst == 0.0), None)
    if corner is not None:      # a corner of the pitch curve (a velocity jump): radius 0 at every size
        return replace(base, notes=(*base.notes, f"not sized to the part: the pitch curve has a corner (a velocity "
                                    f"jump) at cam angle {turn_degrees(corner.at or 0.0):.4f} deg, radius of "
                                    "curvature 0 at every size, which no larger cam clears; use a law without "
                                    "velocity jumps")), None
    lo, g_lo = float(base.R0), v0.margin
    fam.failing[lo] = v0
    least = face.bore_R0(design)
    F = least if least is not None and least > lo * (1 + RTOL) else lo * GROWTH
    last = (base, v0)
    found = None
    for _ in range(MAX_STEPS):
        try:
            cand, v = fam.at(F)
        except CamsError as e:
            F_end, cand_end, v_end = _end_of_family(fam, lo, F, last)
            if v_end.passed:
                found = (F_end, cand_end, v_end)
                break
            raise _no_cam(fam, base, F_end, cand_end, v_end, "the largest R0 the family admits") from e
        if v.passed:
            found = (F, cand, v)
            break
        if _stress_levels_off(last[1], v):
            raise _no_cam(fam, base, F, cand, v, "where the largest Hertz pressure levels off: it falls by less "
                          f"than {STALL:g} of itself as R0 grows by {GROWTH:g}, bounded by the roller's own radius")
        lo, g_lo, last = F, v.margin, (cand, v)
        F *= GROWTH
    if found is None:
        raise _no_cam(fam, base, lo, *last, f"{GROWTH:g}^{MAX_STEPS} times the minimum")
    hi, cand, v = found
    certified = False
    for _ in range(8):     # the certificate: the cam just below fails (else narrow again below it)
        hi, cand, v = _narrow(fam, lo, g_lo, hi, v.margin, (cand, v))
        below = hi * (1 - BELOW)
        cb, vb = fam.at(below) if below > base.R0 else (base, v0)
        if not vb.passed:
            certified = True
            break
        lo = max(f for f in fam.failing if f < below)
        hi, cand, v, g_lo = below, cb, vb, -np.inf
    if not certified:       # pragma: no cover - passing found not monotone eight times over at 1e-6 of R0
        vb = fam.failing[max(f for f in fam.failing if f < hi)]
    governs = vb.failing[0]
    c = vb.failed_check(governs)
    why = f" ({c.message})" if c is not None else ""
    if not face.profile_passes(cand):       # the sampled profile crosses itself where exact extrema pass
        hi, cand, why = _sampled_valid(fam, hi, base)
        governs = "undercut"
    notes = [n for n in base.notes if not n.startswith(_STALE_NOTES)]
    notes.append(f"sized to the part: R0 raised from {base.R0:.6g} mm ({_start(base.governs)}) "
                 f"to {cand.R0:.6g} mm, the smallest cam of the floor family that meets every constraint; the "
                 f"{_words(governs)} governs: at R0 (1 - {BELOW:g}) it fails{why}"
                 + ("" if certified else "; NOT certified minimal: passing is not monotone along the family here"))
    if design.bore_radius is None:
        smallest = face.radii(design, cand)[0]
        notes.append(f"no [cam] bore_radius: nothing keeps material round the cam centre, whose own smallest radius "
                     f"is {smallest:.6g} mm; give the shaft's bore (and a hub_wall) to size a cam that can be mounted")
    return replace(cand, design=design, governs=governs, pressure_angle_R0=base.pressure_angle_R0,
                   notes=tuple(notes)), hi


def sized_to_part(face: Face, design, base: SolveResult, size_alone: Callable[[Any], SolveResult]) -> SolveResult:
    """A pipeline's size stage's last step: ``base`` (``design``'s cam sized by the face's own limit) or, when it
    fails the part's constraints and ``design.constraints`` is ``"all"``, the smallest cam of its floor family
    that meets them (:func:`size_to_part`; ``size_alone(d)`` sizes a design ``d`` by the face's own limit, its
    time added). A chosen cam, and a design of which no profile can be built, are returned as they are."""
    if design.constraints != "all" or design.chosen or face.no_profile(design) is not None:
        return base
    t0 = time.perf_counter()
    alone = design.with_(constraints="pressure_angle")
    out, floor = size_to_part(face, design, base, lambda F: size_alone(alone.with_floor(F)))
    return out if floor is None else replace(out, seconds=base.seconds + time.perf_counter() - t0)


def chosen_bore_notes(face: Face, design, solution: SolveResult) -> list[str]:
    """For a chosen cam whose working profile does not clear the bore by the hub wall: the least R0 that fits.

    That is the design without its chosen cam (:meth:`cams.model.design.Design.unchosen`: a rocker's L and a
    translating follower's offset kept where they fixed it) sized with every constraint (``constraints = "all"``).
    Returns one note, or none when the bore is cleared (or not given, or no profile can be built).

    Raises
    ------
    InfeasibleError
        No cam of the design (L or the offset held as the chosen cam fixed them) clears the bore by the wall: the
        bore (``cam.bore_radius``) or the wall (``cam.hub_wall``) contradicts the design.
    """
    bore = design.bore_radius
    if bore is None or face.no_profile(design) is not None:
        return []
    smallest = face.radii(design, solution)[0]
    wall = float(design.hub_wall or 0.0)
    if smallest - bore >= wall:
        return []
    wall_text = f" by the hub wall {wall:.6g} mm" if wall > 0 else ""
    said = f"the chosen cam's smallest radius {smallest:.6g} mm does not clear the bore radius {bore:.6g} mm{wall_text}"
    try:
        fits = face.size(design.unchosen().with_(constraints="all"))
    except InfeasibleError as e:
        if e.field in ("cam.bore_radius", "cam.hub_wall"):     # no cam of it can: the bore contradicts the design
            raise InfeasibleError(e.field, f"{said}, and {str(e)[len(e.field) + 2:]}") from None
        return [f"bore: {said}; no cam of this design meets its limits ({e})"]
    except CamsError as e:
        return [f"bore: {said}; no cam of this design meets its limits ({e})"]
    return [f"bore: {said}; the least R0 that fits is {fits.R0:.6g} mm (this design sized without the chosen cam, "
            f"governs: {fits.governs})"]
