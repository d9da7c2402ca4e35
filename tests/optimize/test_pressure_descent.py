"""The least pressure angle's programs built once, and its descent stopped at the certificate's own gap.

- The sparse assembly handed to the solver is the program's matrix: densified, it is the rows stacked by hand in
  the solver's order, each divided by its norm.
- The pressure rows with the ratio as a parameter are :func:`build`'s rows at that ratio (built again there),
  divided by the weights by hand: both take their coefficients from ``pressure_sides``, this checks the ratio
  and the weights as parameters (and the assembly); the coefficients themselves are checked against the
  kernel's inversion in test_pressure_rows.py.
- The estimate of the decrease still possible (:func:`_still_possible`) bounds what Dinkelbach's iteration,
  run on to its end, still gives, at every step; the descent stopped at the gap leaves no more than its share of
  the gap. (The certificate itself, value and lower bound, is checked independently in test_motion_pressure.py:
  the returned laws at 200,001 angles and a HiGHS linear program of the space rebuilt as B-splines.)
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from cams.io.designfile import load_design
from cams.model.motiondesign import MotionDesignSpec
from cams.solve import solve
from optimize.motion.conic import Assembly, Cone, ConicProgram, lower_bound
from optimize.motion.design import (
    GAP_SHARE,
    RATIO_RTOL,
    _descend,
    _lower_end,
    _Programs,
    _scales,
    _still_possible,
    _weights,
    free_phases,
    resolve_caps,
)
from optimize.motion.space import Space
from optimize.motion.translating import Request, build, form_ratio, pressure_rows, pressure_terms

ROOT = Path(__file__).resolve().parents[2]
FORCE = ROOT / "examples" / "translating_force.toml"


@pytest.fixture(scope="module")
def base() -> Request:
    """The least pressure angle's request for the force-closed example (6 spans, the 4-5-6-7 law's caps, the
    return a fixed constrained phase) at its own cam's size, as the driver makes it."""
    design = load_design(FORCE)
    held = float(solve(design).R0)
    spec = MotionDesignSpec(objective="pressure_angle", max_Ca=("poly4567",), max_Cj=("poly4567",), spans=6)
    free = free_phases(spec, design.program)
    space = Space(design.program, free, spec.degree, spec.spans, spec.continuity)
    return Request(
        space=space,
        follower="roller",
        cam_sense=design.cam_sense,
        limits=dict(design.constrained_phases()),
        caps=resolve_caps(spec, free),
        objective="pressure_angle",
        bound=100.0 * (design.scale + float(design.program.lift) + held),
        hold=held,
        length=design.scale,
    )


def _dense(asm: Assembly, data: np.ndarray) -> np.ndarray:
    M = np.zeros(asm.shape)
    ptr = np.asarray(asm.indptr)
    for j in range(asm.shape[1]):
        M[np.asarray(asm.indices[ptr[j] : ptr[j + 1]]), j] = data[ptr[j] : ptr[j + 1]]
    return M


def test_the_assembly_is_the_programs_matrix():
    """Random rows, a fixed and a ranged enforced variable, a cone: densified, the solver's matrix is the rows
    stacked by hand (equalities, the fixed variable, inequalities, the ranged one's two bounds, the cone's
    ``-(a; F)``), each equality and inequality divided by its norm; the right-hand side likewise."""
    rng = np.random.default_rng(3)
    n = 6
    G = rng.standard_normal((5, n)) * (rng.random((5, n)) < 0.5)
    G[2] = 0.0  # a zero row keeps its scale 1
    A = rng.standard_normal((2, n))
    a, F = rng.standard_normal(n), rng.standard_normal((2, n))
    lo, hi = -np.ones(n), np.ones(n)
    lo[4] = hi[4] = 0.25
    enforce = np.zeros(n, bool)
    enforce[[1, 4]] = True
    prog = ConicProgram(
        cost=rng.standard_normal(n),
        G=G,
        h=rng.standard_normal(5),
        A=A,
        b=rng.standard_normal(2),
        lo=lo,
        hi=hi,
        cones=(Cone(a, 0.5, F, np.array([0.1, -0.2])),),
        enforce=enforce,
    )
    asm = Assembly(prog)
    data, rhs, _ = asm.matrix()
    gn = [np.sqrt(sum(x * x for x in row)) or 1.0 for row in G]
    an = [np.sqrt(sum(x * x for x in row)) for row in A]
    e = np.eye(n)
    want = np.array(
        [*(A[i] / an[i] for i in range(2)), e[4], *(G[i] / gn[i] for i in range(5)), -e[1], e[1], -a, *(-F)]
    )
    want_rhs = [
        *(prog.b[i] / an[i] for i in range(2)),
        0.25,
        *(prog.h[i] / gn[i] for i in range(5)),
        1.0,
        1.0,
        0.5,
        0.1,
        -0.2,
    ]
    assert _dense(asm, data) == pytest.approx(want, rel=1e-15, abs=0)
    assert rhs == pytest.approx(want_rhs, rel=1e-15, abs=0)


def test_a_scaled_assembly_is_the_program_in_the_scaled_variables():
    """``scales``: densified, the solver's matrix is each column multiplied by its variable's scale, then each row
    divided by its norm, all by hand; the point it returns is the same program's point (a linear program with a
    unique corner, found by enumerating its vertices), in the caller's variables, and its proven lower bound is
    below that exact optimum by at most 1e-6 (the boxes up to 1e5 wide); an enforced variable's scale other than 1
    is refused."""
    from itertools import combinations

    rng = np.random.default_rng(5)
    n = 3
    G = np.vstack([rng.standard_normal((4, n)), np.eye(n), -np.eye(n)])
    h = np.concatenate([rng.random(4) + 0.5, np.full(2 * n, 40.0)])
    width = np.array([1e3, 1e5, 50.0])
    enforce = np.array([False, False, True])
    prog = ConicProgram(
        cost=rng.standard_normal(n),
        G=G,
        h=h,
        A=np.zeros((0, n)),
        b=np.zeros(0),
        lo=-width,
        hi=width,
        enforce=enforce,
    )
    scale = np.array([1e3, 1e5, 1.0])
    with pytest.raises(ValueError):
        Assembly(prog, scales=np.array([1e3, 1e5, 2.0]))
    asm = Assembly(prog, scales=scale)
    Gs = G * scale
    norms = [np.sqrt(sum(x * x for x in row)) for row in Gs]
    e = np.eye(n)
    want = np.array([*(Gs[i] / norms[i] for i in range(G.shape[0])), -e[2], e[2]])
    data, rhs, _ = asm.matrix()
    assert _dense(asm, data) == pytest.approx(want, rel=1e-15, abs=0)
    assert rhs == pytest.approx([*(h[i] / norms[i] for i in range(G.shape[0])), 50.0, 50.0], rel=1e-15, abs=0)
    best, point = np.inf, None
    for rows in combinations(range(G.shape[0]), n):  # every vertex of {G v <= h}
        M = G[list(rows)]
        if abs(np.linalg.det(M)) < 1e-9:
            continue
        v = np.linalg.solve(M, h[list(rows)])
        if np.all(G @ v <= h + 1e-9) and prog.cost @ v < best:
            best, point = float(prog.cost @ v), v
    sol = asm.solve()
    assert sol.value == pytest.approx(best, rel=1e-7, abs=1e-9)
    assert sol.v == pytest.approx(point, rel=1e-5, abs=1e-5)  # an interior point method's vertex
    # the proven bound, its residual paid at boxes of up to 1e5: below the exact optimum, by little
    assert best - 1e-6 <= lower_bound(prog, sol) <= best


@pytest.mark.parametrize("form", ["conservative", "relaxed"])
def test_the_rows_as_parameters_are_the_built_programs(base, form):
    """At two ratios and a weighting: the pressure rows with the ratio as a parameter are the program built at
    that ratio with its pressure rows divided by the weights (but in the slack's column); the solver's matrix
    assembled once and given those rows is the one assembled from that program, also with the variables' scales
    the product hands the solver (:func:`_scales`; the relaxed form's are the boxes'). (The rows' coefficients are
    the same function's, ``pressure_sides``; what differs, and is checked, is how the ratio and the weights
    enter.)"""
    rows = pressure_rows(replace(base, objective="feasibility"), form)
    asm = Assembly(rows.program, rows.pattern)
    s = _scales(base, rows.program.n, form)  # as _Programs hands them over
    scaled = Assembly(rows.program, rows.pattern, scales=s)
    assert (form == "relaxed") == bool(np.any(s[rows.pattern[1]] != 1.0))  # the parameter rows' columns scaled
    rng = np.random.default_rng(0)
    w = 0.5 + rng.random(rows.m)
    for ratio in (0.6, 0.93):
        built = build(replace(base, objective="feasibility", ratio=ratio), form)
        G, h = built.G.copy(), built.h.copy()
        G[: rows.m, :-1] /= w[:, None]
        h[: rows.m] /= w
        prog = rows.program_at(ratio, w)
        assert prog.G == pytest.approx(G, rel=1e-13, abs=1e-15)
        assert prog.h == pytest.approx(h, rel=1e-13, abs=1e-15)
        once = _dense(asm, asm.matrix(*rows.values(ratio, w))[0])
        again = Assembly(prog)
        assert once == pytest.approx(_dense(again, again.matrix()[0]), rel=1e-13, abs=1e-15)
        once = scaled.matrix(*rows.values(ratio, w))
        again = Assembly(prog, scales=s)
        data, rhs, _ = again.matrix()
        assert _dense(scaled, once[0]) == pytest.approx(_dense(again, data), rel=1e-13, abs=1e-15)
        assert once[1] == pytest.approx(rhs, rel=1e-13, abs=1e-15)


def test_pressure_rows_refuse_a_program_whose_first_rows_are_not_theirs(base, monkeypatch):
    """The assembly overwrites the program's first m rows with the pressure rows: a program built with another
    row in front of them (its last row moved first) is refused."""
    import optimize.motion.translating as translating

    built = translating._program

    def moved(*args, **kwargs):
        p = built(*args, **kwargs)
        return replace(p, G=np.roll(p.G, 1, axis=0), h=np.roll(p.h, 1))

    req = replace(base, objective="feasibility")
    pressure_rows(req, "relaxed")
    monkeypatch.setattr(translating, "_program", moved)
    with pytest.raises(AssertionError, match="first rows"):
        pressure_rows(req, "relaxed")


def test_the_decrease_still_possible_bounds_the_rest_of_the_descent(base):
    """Dinkelbach's iteration on the conservative program run on to the end (the ratio's decrease below 1e-6
    relative): at every weighted step, the estimate of the decrease still possible is at least what the steps
    after it gave (to the solver's tolerance)."""
    programs = _Programs(base, "conservative")
    ratio, weights, steps = 1.0, None, []
    for _ in range(12):
        sol = programs.solve(ratio, weights)
        got = form_ratio(base, sol.v, "conservative")
        if not got < ratio:
            break
        at = _weights(pressure_terms(base, sol.v, "conservative"))
        if weights is not None:
            steps.append((got, _still_possible(ratio, float(sol.value), at / weights, programs.rows.limit, got)))
        ratio, weights = got, at
        if len(steps) > 1 and steps[-1][1] < 1e-9:
            break
    end = ratio
    assert len(steps) >= 2
    for got, left in steps:
        assert got - end <= left + 1e-9
    assert steps[0][1] > 1e-4  # the first weighted step still had far to go: the estimate is not 0


@pytest.mark.parametrize("rtol", [RATIO_RTOL, 1e-12])
def test_the_descent_stopped_at_the_gap_leaves_less_than_its_share(base, rtol, monkeypatch):
    """The descent stopped at the certificate's gap against the same descent run to the end (1e-12: with no
    room for the relative tolerance, the stop is the gap's, its lower end proven on the way): its ratio is a
    point's own (the rows met there), above the end's by at most GAP_SHARE of the gap (ratio less the proven
    lower end) or the relative tolerance; the lower end is below the end."""
    import optimize.motion.design as design

    monkeypatch.setattr(design, "RATIO_RTOL", rtol)
    conservative, relaxed = _Programs(base, "conservative"), _Programs(base, "relaxed")
    early, sol, _, lower = _descend(base, conservative, 1.0, None, relaxed=relaxed)
    monkeypatch.setattr(design, "RATIO_RTOL", 1e-12)
    full, _, _, none = _descend(base, conservative, 1.0, None)
    assert none is None
    if rtol < RATIO_RTOL:
        assert lower is not None
    else:
        lower = _lower_end(base, relaxed, early, sol.v)
    assert form_ratio(base, sol.v, "conservative") == early
    assert full <= early + 1e-12
    assert early - full <= max(GAP_SHARE * (early - lower), rtol * early)
    assert lower < full


UNCAPPED_SPANS = 20


def _uncapped(scale: float):
    """translating_force with its rise free, the least pressure angle at UNCAPPED_SPANS spans, no caps (the
    coefficients' box declared: 1e5 on the coefficients of S^(3), which reach about 4.5e4 here), the stroke and
    the roller times ``scale``."""
    from cams.io.designfile import design_from_dict
    from cams.io.document import read_toml

    d = read_toml(FORCE)
    d["follower"]["stroke"] *= scale
    d["follower"]["roller_radius"] *= scale
    d["optimize"] = {"free": ["rise"], "objective": "pressure_angle", "spans": UNCAPPED_SPANS}
    return solve(design_from_dict(d))


@pytest.fixture(scope="module")
def uncapped():
    return _uncapped(1.0)


def test_the_uncapped_rise_proves_a_tight_true_bound(uncapped):
    """The design whose certificate proved 0 (the solver's residual, within its tolerance, paid at the declared
    box of 1e5, cost the bound 0.45): the value is the returned law's own largest ratio (kinematic inversion at
    200,001 angles); the bound is above 0 and within 0.2 % of it; an independent linear program (the space as
    B-splines, 64 samples a span, no box on the coefficients, HiGHS) has no law at the bound (least slack above
    0) and one at the value."""
    from cams.verify.pressure import pressure_angle
    from tests.optimize.test_motion_pressure import _least_slack

    o = uncapped.optimization.to_dict()
    design = uncapped.design
    g = np.abs(pressure_angle(design, uncapped.centre, 0, np.linspace(0.0, 1.0, 200_001)))
    own = g.max() / design.limits.pressure_angle
    assert o["value"] == pytest.approx(own, rel=1e-7)
    assert 0 < o["lower_bound"] <= own
    assert o["gap"] < 2e-3 and o["certified"]
    kw = {
        "held": o["held_R0"],
        "caps": None,
        "limit": design.limits.pressure_angle,
        "stroke": float(design.program.lift),
        "beta": float(design.program.phases[0].angle),
        "spans": UNCAPPED_SPANS,
    }
    assert _least_slack(o["lower_bound"], **kw) > 1e-6
    assert _least_slack(o["value"] * (1 + 1e-6), **kw) <= 1e-9


def test_the_scaled_assembly_proves_what_the_unscaled_one_cannot(uncapped):
    """The relaxed feasibility program of the uncapped design (its request as the driver makes it, at the size
    held) at 0.95 of its proven bound, solved twice, the program the same: handed over in the caller's variables,
    the solver's residual paid at the declared box (1e5) leaves a proven least slack below 0 (no proof) and far
    below the other's; over the boxes (:func:`_scales`, as the product solves it) the bound is above 0, within
    1e-6 of the solver's value."""
    o = uncapped.optimization
    design = load_design(FORCE)
    spec = MotionDesignSpec(objective="pressure_angle", free=("rise",), spans=UNCAPPED_SPANS)
    free = free_phases(spec, design.program)
    req = Request(
        space=Space(design.program, free, spec.degree, spec.spans, spec.continuity),
        follower="roller",
        cam_sense=design.cam_sense,
        limits=dict(design.constrained_phases()),
        caps=resolve_caps(spec, free),
        objective="feasibility",
        bound=100.0 * (design.scale + float(design.program.lift) + o.held_R0),
        hold=o.held_R0,
        length=design.scale,
        ratio=0.95 * o.lower_bound,
    )
    assert req.caps == {}
    prog = build(req, "relaxed")
    plain = lower_bound(prog, Assembly(prog).solve())
    sol = Assembly(prog, scales=_scales(req, prog.n, "relaxed")).solve()
    scaled = lower_bound(prog, sol)
    assert 0 < scaled <= sol.value <= scaled + 1e-6
    assert plain < 0 and plain < scaled - 0.1


def test_a_bound_of_0_is_said_beside_it(uncapped):
    """The certificate's rows and its JSON: a proven bound reads as one, ``certified`` and ``checked`` true; a
    bound of 0 (gap 1) says that nothing above 0 was proven, on the bound's row and the certificate's, instead of
    a plain "yes", and the JSON's ``certified`` is false beside ``checked`` true (it says no more than the text);
    the exit code's rule (:func:`cams.assess.assess`) still takes the checks, which pass."""
    from cams.assess import assess
    from cams.present.text import optimization_rows

    o = uncapped.optimization.to_dict()
    assert o["certified"] is True and o["checked"] is True and o["bound_proven"] is True
    rows = dict(optimization_rows(o))
    assert rows["certified"] == "yes"
    assert "none above 0" not in rows["proven lower bound"]
    zero = replace(uncapped.optimization, lower_bound=0.0, gap=1.0)
    o = zero.to_dict()
    assert o["certified"] is False and o["checked"] is True and o["bound_proven"] is False
    rows = dict(optimization_rows(o))
    assert rows["proven lower bound"].startswith("0 (ratio to the limit), gap 1 (relative): none above 0 proven")
    assert rows["certified"] == "the laws checked, no bound proven"
    held = assess(uncapped.design, replace(uncapped, optimization=zero), no_profile="not built here")
    assert held.certified is True and not any("certified" in f for f in held.failures)
    o = replace(zero, certified=False).to_dict()
    assert o["certified"] is False and o["checked"] is False
    assert dict(optimization_rows(o))["certified"] == "NO"
