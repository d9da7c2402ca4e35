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
from optimize.motion.conic import Assembly, Cone, ConicProgram
from optimize.motion.design import (
    GAP_SHARE,
    RATIO_RTOL,
    _descend,
    _lower_end,
    _Programs,
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


@pytest.mark.parametrize("form", ["conservative", "relaxed"])
def test_the_rows_as_parameters_are_the_built_programs(base, form):
    """At two ratios and a weighting: the pressure rows with the ratio as a parameter are the program built at
    that ratio with its pressure rows divided by the weights (but in the slack's column); the solver's matrix
    assembled once and given those rows is the one assembled from that program. (The rows' coefficients are
    the same function's, ``pressure_sides``; what differs, and is checked, is how the ratio and the weights
    enter.)"""
    rows = pressure_rows(replace(base, objective="feasibility"), form)
    asm = Assembly(rows.program, rows.pattern)
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


def test_a_bound_that_proves_nothing_is_said(tmp_path):
    """translating_force with its rise free, the least pressure angle at 20 spans and no caps: the relaxed programs
    prove no ratio above 0 at the solver's accuracy. The bound 0 is true but says nothing: a note says so, beside
    the gap of 1 (either a bound above 0 is proven, or the note is there)."""
    from cams.cam import Cam
    from tests.conftest import EXAMPLES

    text = (EXAMPLES / "translating_force.toml").read_text()
    f = tmp_path / "least_pressure.toml"
    f.write_text(text + '\n[optimize]\nfree = ["rise"]\nobjective = "pressure_angle"\nspans = 20\n')
    o = Cam.from_file(f).solution.optimization
    said = any(n.startswith("no lower bound above 0 was proven") for n in o.notes)
    assert o.value > 0 and 0 <= o.lower_bound <= o.value
    assert (o.lower_bound > 0) != said
