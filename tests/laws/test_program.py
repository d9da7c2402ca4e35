"""Cycle programs: properties of any valid program, bad input, and regressions."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from laws.errors import InputError
from laws.polynomial import PolynomialLaw
from laws.program import TWO_PI, Phase, Program, wrap_angle
from laws.registry import LAWS, get_law

LAW_NAMES = sorted(LAWS)


@st.composite
def programs(draw):
    """Any valid program: the lift in 1-3 rises and 1-3 returns, dwells anywhere, angles summing to 360 deg."""
    lift = draw(st.floats(0.1, 50.0))

    def parts():
        n = draw(st.integers(1, 3))
        w = np.array(draw(st.lists(st.floats(0.2, 1.0), min_size=n, max_size=n)))
        return list(w / w.sum() * lift)

    kinds = [("rise", h) for h in parts()] + [("return", h) for h in parts()]
    seq = []
    for kind, h in kinds:
        seq.append((kind, h))
        if draw(st.booleans()):
            seq.append(("dwell", None))
    weights = np.array(draw(st.lists(st.floats(0.05, 1.0), min_size=len(seq), max_size=len(seq))))
    angles = weights / weights.sum() * TWO_PI
    phases = []
    for (kind, h), a in zip(seq, angles, strict=True):
        law = None if kind == "dwell" else get_law(draw(st.sampled_from(LAW_NAMES)))
        phases.append(Phase(kind, float(a), law, None if kind == "dwell" else float(h)))
    return Program(tuple(phases), lift=lift)


def smooth_points(p: Program, n: int = 240, margin: float = 1e-4) -> np.ndarray:
    """Cam angles away from the joints and from the laws' internal breakpoints."""
    phi = (np.arange(n) + 0.37) * TWO_PI / n
    marks = list(p.starts)
    for i, ph in enumerate(p.phases):
        if ph.law is not None:
            marks += [p.starts[i] + b * ph.angle for b in ph.law.breakpoints]
    d = np.min(np.abs(phi[:, None] - np.asarray(marks)[None, :]), axis=1)
    return phi[d > margin]


PROFILE = settings.get_profile("laws")


@settings(PROFILE)
@given(p=programs())
def test_displacement_within_lift(p):
    m = p.evaluate(np.linspace(-TWO_PI, 2 * TWO_PI, 1501))
    assert np.all(m.s >= -1e-12 * p.lift)
    assert np.all(m.s <= p.lift * (1 + 1e-12))
    assert m.s.max() == pytest.approx(p.lift, rel=1e-2)  # the lift is reached (sampled)


@settings(PROFILE)
@given(p=programs(), turns=st.integers(-3, 3))
def test_periodic(p, turns):
    phi = smooth_points(p)
    a, b = p.evaluate(phi), p.evaluate(phi + turns * TWO_PI)
    tol = 1e-9 * p.lift
    np.testing.assert_allclose(b.s, a.s, atol=tol)
    np.testing.assert_allclose(b.ds, a.ds, atol=tol * 1e3)
    # s is continuous everywhere, joints included
    np.testing.assert_allclose(p.evaluate(p.starts).s, p.evaluate(p.starts + TWO_PI).s, atol=tol)


@settings(PROFILE)
@given(p=programs())
def test_derivatives_consistent_with_finite_differences(p):
    phi = smooth_points(p)
    h = 1e-6
    m = p.evaluate(phi)
    up, dn = p.evaluate(phi + h), p.evaluate(phi - h)
    beta = min(ph.angle for ph in p.phases)
    v_ref, a_ref = p.lift / beta, p.lift / beta**2
    np.testing.assert_allclose((up.s - dn.s) / (2 * h), m.ds, atol=1e-5 * v_ref)
    np.testing.assert_allclose((up.ds - dn.ds) / (2 * h), m.d2s, atol=1e-5 * a_ref)


def test_continuity_of_s_at_joints():
    p = Program(
        (Phase("rise", 2.0, get_law("poly345"), 3.0), Phase("dwell", 1.0), Phase("rise", 1.0, get_law("cycloidal"), 2.0),
         Phase("return", TWO_PI - 4.0, get_law("modified_sine"))),
        lift=5.0,
    )
    for i in range(len(p.phases)):
        end = p.evaluate_phase(i - 1, 1.0).s if i else p.evaluate_phase(len(p.phases) - 1, 1.0).s
        assert float(p.evaluate_phase(i, 0.0).s) == pytest.approx(float(end), abs=1e-12)


def test_wrap_of_tiny_negative_angle():
    # regression: np.mod(-1e-17, 2 pi) == 2 pi exactly, and the program used to
    # treat that angle as 2 pi past the start of phase 0 (clipped to its end),
    # returning the top of the rise (s = lift) instead of 0
    p = Program((Phase("rise", math.pi, get_law("cycloidal")), Phase("return", math.pi, get_law("cycloidal"))), lift=2.0)
    assert float(wrap_angle(-1e-17)) == 0.0
    m = p.evaluate(np.array([-1e-17, 0.0]))
    assert m.s.tolist() == [0.0, 0.0]
    assert p.phase_of(-1e-17) == 0


@settings(PROFILE)
@given(p=programs(), turns=st.integers(-3, 3))
def test_locate_lands_in_the_phase_that_contains_the_angle(p, turns):
    # definition, checked phase by phase: the phase i with start_i <= x < start_i + angle_i (x the angle in the
    # turn, the starts a running sum of the angles written out here), and within = x - start_i, so that
    # start_i + within + turns * 2 pi is the angle asked for
    x = np.concatenate([np.linspace(0.0, TWO_PI, 97, endpoint=False), [1e-3, TWO_PI - 1e-3]])
    idx, within = p.locate(x + turns * TWO_PI)
    assert idx.shape == within.shape == x.shape
    start = 0.0
    for i, ph in enumerate(p.phases):
        inside = (x >= start + 1e-9) & (x < start + ph.angle - 1e-9)
        assert np.all(idx[inside] == i)
        np.testing.assert_allclose(within[inside], x[inside] - start, rtol=0, atol=1e-12)
        start += ph.angle
    assert np.all((within >= -1e-12) & (within <= np.array([ph.angle for ph in p.phases])[idx] + 1e-12))


def test_locate_at_a_joint_is_the_later_phase():
    p = Program(
        (Phase("rise", 2.0, "cycloidal"), Phase("dwell", 1.0), Phase("return", TWO_PI - 3.0, "cycloidal")), lift=1.0
    )
    idx, within = p.locate(np.array([0.0, 2.0, 3.0, TWO_PI, -1e-17]))
    assert idx.tolist() == [0, 1, 2, 0, 0]
    assert within.tolist() == [0.0, 0.0, 0.0, 0.0, 0.0]
    i, w = p.locate(2.5)  # a scalar gives scalars
    assert (int(i), float(w)) == (1, 0.5)


def test_scalar_and_array_shapes():
    p = Program((Phase("rise", math.pi, "cycloidal"), Phase("return", math.pi, "cycloidal")), lift=1.0)
    assert p.evaluate(0.3).s.shape == ()
    assert p.evaluate(np.zeros((2, 3))).d3s.shape == (2, 3)


def test_law_names_resolved():
    p = Program((Phase("rise", math.pi, "modified_sine"), Phase("return", math.pi, "poly345")), lift=1.0)
    assert p.phases[0].law is get_law("modified_sine")
    assert p.phases[1].law is get_law("poly345")


def test_user_law_in_program():
    law = PolynomialLaw.from_boundary(start=(0, 0), end=(0, 0))
    p = Program((Phase("rise", math.pi, law), Phase("return", math.pi, "poly345")), lift=1.0)
    np.testing.assert_allclose(p.evaluate(1.0).s, get_law("poly345").evaluate(1 / math.pi)[0])


def test_time_derivatives():
    p = Program((Phase("rise", math.pi, "cycloidal"), Phase("return", math.pi, "cycloidal")), lift=1.0)
    m = p.evaluate(math.pi / 2)
    v, a, j = m.time_derivatives(60.0)  # 1 rev/s: omega = 2 pi rad/s
    assert float(v) == pytest.approx(float(m.ds) * TWO_PI)
    assert float(a) == pytest.approx(float(m.d2s) * TWO_PI**2)
    with pytest.raises(InputError) as e:
        m.time_derivatives(0.0)
    assert e.value.field == "cam.rpm"


def _prog(*phases, lift=1.0):
    return Program(tuple(phases), lift=lift)


R, D = math.radians, None


@pytest.mark.parametrize(
    "build, field, match",
    [
        (lambda: _prog(Phase("rise", R(180), get_law("cycloidal")), Phase("dwell", 0.0),
                       Phase("return", R(180), get_law("cycloidal"))), "motion[1].angle", "> 0"),
        (lambda: _prog(Phase("rise", R(180), get_law("cycloidal")), Phase("return", -R(10), get_law("cycloidal")),
                       Phase("dwell", R(190))), "motion[1].angle", "> 0"),
        (lambda: _prog(Phase("rise", R(180), get_law("cycloidal")), Phase("return", R(170), get_law("cycloidal"))),
         "motion", "sum to 360"),
        (lambda: _prog(Phase("rise", R(180), "bogus"), Phase("return", R(180), "cycloidal")),
         "motion[0].law", "unknown law 'bogus'"),
        (lambda: _prog(Phase("rise", R(180)), Phase("return", R(180), "cycloidal")), "motion[0].law", "needs a law"),
        (lambda: _prog(Phase("rise", R(180), 3.0), Phase("return", R(180), "cycloidal")), "motion[0].law", "law"),
        (lambda: _prog(Phase("lift", R(180), "cycloidal"), Phase("return", R(180), "cycloidal")),
         "motion[0].phase", "rise, dwell, return"),
        (lambda: _prog(Phase("rise", "abc", "cycloidal"), Phase("return", R(180), "cycloidal")),
         "motion[0].angle", "> 0"),
        (lambda: _prog(Phase("rise", R(180), "cycloidal"), Phase("return", R(180), "cycloidal"), lift=0.0),
         "lift", "positive"),
        (lambda: _prog(Phase("rise", R(180), "cycloidal"), Phase("return", R(180), "cycloidal"), lift="1"),
         "lift", "positive"),
        (lambda: _prog(Phase("rise", R(180), "cycloidal", 2.0), Phase("return", R(180), "cycloidal")),
         "motion[0].height", "lift"),
        (lambda: _prog(Phase("rise", R(180), "cycloidal"), Phase("return", R(180), "cycloidal", 0.5)),
         "motion", "return to 0"),
        (lambda: _prog(Phase("return", R(180), "cycloidal"), Phase("rise", R(180), "cycloidal")),
         "motion[0]", "outside"),
        (lambda: _prog(), "motion", "at least one phase"),
        (lambda: _prog(Phase("rise", R(180), "cycloidal"), ("return", R(180), "cycloidal")), "motion[1]", "Phase"),
    ],
)
def test_bad_input_names_the_field(build, field, match):
    with pytest.raises(InputError, match=match) as e:
        build()
    assert e.value.field == field
    assert str(e.value).startswith(field + ":")


def test_unknown_law_lists_the_valid_names():
    with pytest.raises(InputError) as e:
        get_law("cycloid", "motion[2].law")
    assert e.value.field == "motion[2].law"
    assert "modified_trapezoid" in str(e.value) and "cycloidal" in str(e.value)


def test_non_monotone_table_in_program_input():
    from laws.table import TableLaw

    with pytest.raises(InputError) as e:
        TableLaw([0, 0.6, 0.3, 1], [0, 0.5, 0.4, 1], clamped=True)
    assert e.value.field == "table.u"


def test_program_is_immutable():
    p = Program((Phase("rise", math.pi, "cycloidal"), Phase("return", math.pi, "cycloidal")), lift=1.0)
    with pytest.raises(AttributeError):
        p.lift = 2.0
