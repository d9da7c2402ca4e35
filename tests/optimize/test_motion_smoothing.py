"""The motion design's second stage ([optimize] smoothing_slack): among the laws within the optimum's value, the
smoothest, and what the slack bought.

References: the rest-to-rest law (S' to S^(c) zero at both ends) of least integral of S^(c+1)**2 is the
polynomial of degree 2c + 1 (Euler-Lagrange: S^(2c+2) = 0 with 2c + 2 end conditions): 3u^2 - 2u^3 for C1,
the 3-4-5 law for C2, the 4-5-6-7 law for C3 (Norton, Cam Design and Manufacturing Handbook, ch. 3). The checks
here share no formula with the product's: the laws' Bernstein coefficients are turned into power form here
(binomials), differentiated and integrated exactly by numpy.polynomial, the jerk's total variation taken at the
roots of its derivative, and the cams sized again from the saved files by the exact method.
"""

from __future__ import annotations

import json
import re
from dataclasses import replace
from itertools import pairwise
from math import comb

import numpy as np
import pytest

from cams.io.designfile import design_from_dict, load_design
from cams.io.document import read_toml
from cams.model.motiondesign import MotionDesignSpec
from cams.motion_design import jerk_variation
from cams.solve import solve
from laws.errors import InputError
from laws.polynomial import PolynomialLaw
from laws.registry import get_law
from laws.standard import Poly345, Poly4567
from optimize.motion.design import design_laws
from optimize.motion.smooth import ACCEPT_RTOL, pulled_back
from optimize.motion.space import Space
from optimize.motion.translating import TIGHTEN
from tests.conftest import ROOT
from tests.inprocess import cams_cli

FORCE = str(ROOT / "examples" / "translating_force.toml")
DESIGNED = ROOT / "examples" / "translating_designed_rise.toml"


# -- independent arithmetic on law tables -----------------------------------------------------------------------

def _pieces(table: dict) -> list[tuple[float, float, np.polynomial.Polynomial]]:
    """``(a, b, P)`` per span of a spline law table, ``P(x) = S(a + x (b - a))`` in power form, x in [0, 1]."""
    out = []
    for (a, b), row in zip(pairwise(table["breaks"]), table["coefficients"], strict=True):
        p = len(row) - 1
        x = np.polynomial.Polynomial([0.0, 1.0])
        P = sum(c * comb(p, i) * x**i * (1 - x) ** (p - i) for i, c in enumerate(row))
        out.append((a, b, P))
    return out


def _integral_of_square(table: dict, r: int) -> float:
    """Integral over [0, 1] of S^(r)(u)**2, exactly (the pieces' polynomials squared and integrated)."""
    total = 0.0
    for a, b, P in _pieces(table):
        D = P.deriv(r) / (b - a) ** r
        Q = (D * D).integ()
        total += (Q(1.0) - Q(0.0)) * (b - a)
    return float(total)


def _total_variation_of_jerk(table: dict) -> float:
    """The total variation of S''' over [0, 1]: on each span, its values at the ends and at the real roots of
    S'''' inside, plus the jumps at the knots."""
    total, last = 0.0, None
    for a, b, P in _pieces(table):
        J = P.deriv(3) / (b - a) ** 3
        roots = [z.real for z in J.deriv().roots() if abs(z.imag) < 1e-12 and 0 < z.real < 1]
        xs = [0.0, *sorted(roots), 1.0]
        vals = [float(J(x)) for x in xs]
        if last is not None:
            total += abs(vals[0] - last)
        total += sum(abs(q - p) for p, q in pairwise(vals))
        last = vals[-1]
    return total


def _table(law) -> dict:
    from cams.io.lawtable import law_to_table

    t = law_to_table(law)
    assert isinstance(t, dict)
    return t


# -- known answers ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize(("continuity", "degree", "law"), [
    (1, 3, PolynomialLaw((0.0, 0.0, 3.0, -2.0))),
    (2, 7, Poly345()),
    (3, 7, Poly4567()),
])
def test_a_free_law_no_constraint_binds_on_is_the_classical_polynomial(continuity, degree, law):
    """The return of a force-closed cam: no limit, no cap, nothing the objective (R0) sees; every law of the
    space is optimal, and the smoothest is the rest-to-rest polynomial of degree 2c + 1."""
    design = load_design(FORCE)
    ld = design_laws(design, MotionDesignSpec(free=("return",), continuity=continuity, degree=degree, spans=7))
    assert ld.first is not None and ld.smoothing_note is None
    got = ld.program.law_of(2)
    u = np.linspace(0, 1, 1001)
    for k in range(continuity + 1):
        ref = law.evaluate(u)[k]
        assert np.max(np.abs(got.evaluate(u)[k] - ref)) <= 1e-5 * np.max(np.abs(ref)) + 1e-9
    # the first stage's law is one arbitrary point of the optimum: its integral is no smaller
    assert _integral_of_square(_table(got), continuity + 1) <= \
        _integral_of_square(_table(ld.first.law_of(2)), continuity + 1) * (1 + 1e-9)


@pytest.fixture(scope="module")
def roomy():
    """The designed-rise example with caps poly4567 meets with room (Ca 8, Cj 60) and a slack of 0.7: R0 may
    grow to 1.7 times the optimum's, beyond the 4-5-6-7 law's own cam (17.581358 mm)."""
    d = read_toml(DESIGNED)
    d["optimize"].update({"max_Ca": 8.0, "max_Cj": 60.0, "spans": 10, "smoothing_slack": 0.7})
    return solve(design_from_dict(d))


def test_a_slack_beyond_the_classical_laws_cam_gives_that_law_and_its_cam(roomy):
    o = roomy.optimization.to_dict()
    sm = o["smoothing"]
    poly4567_cam = solve(replace(load_design(DESIGNED), optimize=None))
    assert sm["value_before"] * 1.7 > poly4567_cam.R0 > sm["value_before"]
    u = np.linspace(0, 1, 2001)
    got = roomy.design.program.law_of(0)
    for k in range(4):
        ref = Poly4567().evaluate(u)[k]
        assert np.max(np.abs(got.evaluate(u)[k] - ref)) <= 1e-6 * np.max(np.abs(ref))
    assert roomy.R0 == pytest.approx(poly4567_cam.R0, rel=1e-7) and o["value"] == roomy.R0
    assert sm["integral_after"] == pytest.approx(100800.0, rel=1e-6)      # the 4-5-6-7 law's snap integral
    assert o["certified"] and o["lower_bound"] <= sm["value_before"]


# -- the example, checked from its saved files ------------------------------------------------------------------

def _cli(*args):
    """``cams ARGS`` in this process (tests/inprocess.py): exit code, stdout, stderr."""
    return cams_cli(*args, cwd=ROOT)


@pytest.mark.parametrize(("slack", "continuity"), [(0.0, 3), (0.01, 3), (0.01, 2)])
def test_the_smoothed_law_checked_from_the_saved_design(tmp_path, slack, continuity):
    """The designed rise (10 spans) with a slack: the saved design's cam, sized again, is within (1 + slack) of
    the first stage's law's cam, sized again from its law table; the integral the second stage minimizes (of
    S'''' for C3, of the jerk S''' for C2) is no larger; every number the report gives is the laws' own."""
    f = tmp_path / "designed.toml"
    text = re.sub(r"smoothing_slack = [^\n]*", f"smoothing_slack = {slack}",
                  DESIGNED.read_text(encoding="utf-8").replace("spans = 20", "spans = 10")
                  .replace("continuity = 3", f"continuity = {continuity}"))
    f.write_text(text, encoding="utf-8")
    out = tmp_path / "saved.toml"
    r = _cli("solve", f, "--json", "--save-design", out)
    assert r.returncode == 0, r.stderr
    o = json.loads(r.stdout)["optimize"]
    sm = o["smoothing"]
    assert sm["smoothed"] and sm["slack"] == slack and sm["derivative"] == continuity + 1

    after = solve(load_design(out))
    first_doc = read_toml(f)
    del first_doc["optimize"]
    (first_table,) = sm["first_stage_laws"]
    assert first_table.pop("phase") == 0
    first_doc["motion"][0]["law"] = first_table
    before = solve(design_from_dict(first_doc))
    assert after.verified and before.verified
    assert after.R0 == pytest.approx(sm["value_after"], rel=1e-12) and o["value"] == sm["value_after"]
    assert before.R0 == pytest.approx(sm["value_before"], rel=1e-12)
    assert after.R0 <= (1 + slack) * (1 + ACCEPT_RTOL) * before.R0
    if slack == 0.0:
        assert after.R0 == pytest.approx(before.R0, rel=ACCEPT_RTOL)
    assert o["lower_bound"] <= min(after.R0, before.R0) and o["certified"]

    saved = _table(load_design(out).program.law_of(0))
    for key, table in (("after", saved), ("before", first_table)):
        assert sm[f"integral_{key}"] == pytest.approx(_integral_of_square(table, continuity + 1), rel=1e-8)
        assert sm[f"jerk_squared_{key}"] == pytest.approx(_integral_of_square(table, 3), rel=1e-8)
        assert sm[f"jerk_variation_{key}"] == pytest.approx(_total_variation_of_jerk(table), rel=1e-6)
    assert sm["integral_after"] <= sm["integral_before"] * (1 + 1e-9)
    if slack > 0:       # what a share of 0.01 buys on this design
        assert sm["integral_after"] < 0.95 * sm["integral_before"]
        assert sm["jerk_variation_after"] < sm["jerk_variation_before"]

    r = _cli("solve", f)
    line = next(ln for ln in r.stdout.splitlines() if "smoothing (slack" in ln)
    assert f"total variation of S''' {sm['jerk_variation_before']:.1f} -> {sm['jerk_variation_after']:.1f}" in line


def test_the_report_keeps_its_keys():
    """The smoothing is reported beside the keys a motion design always had, which keep their meaning."""
    d = read_toml(FORCE)
    d["optimize"] = {"max_Ca": "poly4567", "max_Cj": "poly4567", "spans": 5}
    o = solve(design_from_dict(d)).optimization.to_dict()
    assert {"objective", "value", "lower_bound", "gap", "certified", "degree", "spans", "continuity", "pieces",
            "free", "caps", "phases", "reference", "held_R0", "floor", "method", "local_measure", "iterations",
            "history", "seconds", "notes"} < set(o)
    assert set(o["smoothing"]) == {"slack", "derivative", "smoothed", "step", "value_before", "value_after",
                                   "integral_before", "integral_after", "jerk_squared_before", "jerk_squared_after",
                                   "jerk_variation_before", "jerk_variation_after", "first_stage_laws"}
    (p,) = o["phases"]
    assert {"phase", "kind", "Cv", "Ca", "Cj", "jerk_variation", "original"} == set(p)
    assert p["original"]["jerk_variation"] == pytest.approx(273.0, rel=1e-6)


def test_the_least_pressure_angle_smoothed_within_its_share():
    """objective = "pressure_angle": the second stage at the ratio found times (1 + slack); the ratio of the
    laws returned is the independent check's, within that share of the first stage's."""
    d = read_toml(FORCE)
    d["optimize"] = {"objective": "pressure_angle", "max_Ca": "poly4567", "max_Cj": "poly4567", "spans": 5,
                     "smoothing_slack": 0.02}
    res = solve(design_from_dict(d))
    o = res.optimization.to_dict()
    sm = o["smoothing"]
    assert sm["smoothed"] and o["certified"] and res.verified
    assert o["value"] == pytest.approx(np.degrees(res.pressure.rise) / 30.0, rel=1e-9) == sm["value_after"]
    assert sm["value_before"] < sm["value_after"] <= 1.02 * (1 + ACCEPT_RTOL) * sm["value_before"]
    assert sm["integral_after"] < sm["integral_before"]


def test_a_flat_face_whose_size_the_rise_does_not_set():
    """A translating flat face sized by its fixed return's curvature: the rise's law does not change R0, so the
    whole optimum is a set and the smoothest is far smoother than the first stage's vertex at the same R0."""
    d = read_toml(str(ROOT / "examples" / "translating_flat.toml"))
    d["optimize"] = {"max_Ca": "poly4567", "max_Cj": "poly4567", "spans": 8}
    sm = solve(design_from_dict(d)).optimization.smoothing
    assert sm["value_after"] == pytest.approx(sm["value_before"], rel=1e-12)
    assert sm["integral_after"] < 0.5 * sm["integral_before"]


@pytest.mark.parametrize("scale", [1e-3, 1e3])
def test_every_unit_scale_gives_the_same_smoothing(scale):
    got = {}
    for k in (1.0, scale):
        d = read_toml(FORCE)
        d["follower"]["stroke"] *= k
        d["follower"]["roller_radius"] *= k
        d["optimize"] = {"max_Ca": "poly4567", "max_Cj": "poly4567", "spans": 6, "smoothing_slack": 0.01}
        sm = solve(design_from_dict(d)).optimization.smoothing
        got[k] = (sm["value_before"] / k, sm["value_after"] / k, sm["integral_after"], sm["jerk_variation_after"])
    assert got[scale] == pytest.approx(got[1.0], rel=1e-5)


# -- the pieces ---------------------------------------------------------------------------------------------------

@pytest.mark.parametrize(("name", "variation"), [
    ("poly4567", None),               # computed below from its polynomial
    ("poly345", 180.0),               # S''' = 60 - 360 u + 360 u^2: 60 -> -30 -> 60
    ("cycloidal", 16 * np.pi**2),     # S''' = 4 pi^2 cos(2 pi u): two full swings
    ("harmonic", None),
])
def test_jerk_variation_of_library_laws(name, variation):
    law = get_law(name)
    if name == "harmonic":                      # S'' is not 0 where it meets a dwell: the jerk is infinite
        assert jerk_variation(law) is None
        return
    if name == "poly4567":
        J = np.polynomial.Polynomial([0, 0, 0, 0, 35, -84, 70, -20]).deriv(3)
        xs = [0.0, *sorted(z.real for z in J.deriv().roots()), 1.0]
        variation = sum(abs(J(b) - J(a)) for a, b in pairwise(xs))
        assert variation == pytest.approx(273.0, rel=1e-12)
    assert jerk_variation(law) == pytest.approx(variation, rel=1e-8)


def test_pulled_back_meets_the_caps_nearest_the_second_point():
    """Two laws of one space; a cap between their Bernstein peaks: the point returned is on the segment, as far
    toward the rougher one as the cap allows (with half the caps' tightening)."""
    design = load_design(FORCE)
    space = Space(design.program, (0,), 7, 5, 3)
    n = space.size
    A, b = space.equalities(n)
    u = np.linspace(0, 1, 201)
    F = space.rows(0, 0, n, samples=u)

    def fitted(law):
        K = np.block([[F.T @ F, A.T], [A, np.zeros((A.shape[0], A.shape[0]))]])
        rhs = np.concatenate([F.T @ law.evaluate(u)[0], b])
        return space.project(np.linalg.lstsq(K, rhs, rcond=None)[0][:n])

    first, second = fitted(Poly4567()), fitted(get_law("cycloidal"))
    R = space.rows(0, 2, n)
    low, high = np.max(np.abs(R @ first)), np.max(np.abs(R @ second))
    if low > high:
        first, second, low, high = second, first, high, low
    cap = 0.5 * (low + high)
    v = pulled_back(space, {(0, 2): cap}, first, second)
    theta = float((v - first) @ (second - first) / ((second - first) @ (second - first)))
    assert np.allclose(v, first + theta * (second - first), rtol=0, atol=1e-12) and 0 < theta < 1
    assert np.max(np.abs(R @ v)) == pytest.approx(cap * (1 - TIGHTEN / 2), rel=1e-12)
    assert np.allclose(pulled_back(space, {(0, 2): 2 * high}, first, second), second, rtol=0, atol=0)


@pytest.mark.parametrize("value", [-0.01, 1.0, 2, "0.1", True, float("nan"), float("inf")])
def test_a_bad_slack_is_refused_naming_the_field(value):
    with pytest.raises(InputError) as e:
        MotionDesignSpec(smoothing_slack=value)
    assert e.value.field == "optimize.smoothing_slack"


def test_a_rockers_slack_is_refused():
    d = read_toml(str(ROOT / "examples" / "rocker_force.toml"))
    d["optimize"] = {"smoothing_slack": 0.01, "spans": 4}
    with pytest.raises(InputError) as e:
        solve(design_from_dict(d))
    assert e.value.field == "optimize.smoothing_slack"


def test_conservative_ratio_is_where_the_point_meets_the_rows():
    """The least ratio at which a point meets the conservative program's pressure rows: built at that ratio
    (times 1 + 1e-9) the rows hold at the point, at 1 - 1e-6 of it one does not."""
    from optimize.motion.conic import solve as conic_solve
    from optimize.motion.design import free_phases, resolve_caps
    from optimize.motion.translating import Request, build, conservative_ratio

    design = load_design(FORCE)
    spec = MotionDesignSpec(max_Ca=("poly4567",), max_Cj=("poly4567",), spans=4)
    free = free_phases(spec, design.program)
    space = Space(design.program, free, spec.degree, spec.spans, spec.continuity)
    req = Request(space=space, follower="roller", cam_sense=design.cam_sense, limits=dict(design.constrained_phases()),
                  caps=resolve_caps(spec, free), objective="feasibility", bound=1e4, ratio=0.9, length=design.scale,
                  hold=20.0)
    sol = conic_solve(build(req, "conservative"))
    assert sol.feasible and sol.value <= 0
    v = sol.v.copy()
    v[-1] = 0.0                                     # the rows' slack variable: the rows as they are
    rho = conservative_ratio(req, v)
    assert 0 < rho <= 0.9 * (1 + 1e-9)

    def worst(ratio: float) -> float:
        prog = build(replace(req, ratio=ratio), "conservative")
        pressure = prog.G[:, -1] != 0               # the rows that carry the slack: the pressure rows
        return float(np.max(prog.G[pressure] @ v - prog.h[pressure]))

    assert worst(rho * (1 + 1e-9)) <= 1e-12 and worst(rho * (1 - 1e-6)) > 0
