"""Slotting machine (seed 003): kinematics against independent computations, synthesis by its properties."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import least_squares

from cams.machine.linkage import AssemblyError, analyse, dead_positions
from cams.machine.linkage.machines import SlottingMachine
from laws.errors import InputError
from tests.machine.linkage.conftest import assert_close, numeric_angle_derivatives, numeric_derivatives

PHI = np.linspace(0.0, 2 * np.pi, 49, endpoint=False) + 0.01

# (K, H, L_O2O3, l_BC/l_O3B, bar_side, tool_side, crank_sense): typical course data of seed 003's table
COURSES = [
    (2.0, 100.0, 150.0, 1.0, -1, 1, 1),
    (1.5, 120.0, 150.0, 0.7, -1, -1, -1),
    (1.8, 150.0, 160.0, 0.5, -1, 1, -1),
    (1.4, 100.0, 150.0, 0.8, 1, 1, 1),  # B on the crank's side, beyond the block's travel
]


@pytest.fixture(params=COURSES, ids=lambda c: f"K{c[0]}-H{c[1]}-side{c[4]}")
def machine(request):
    K, H, L, ratio, bs, ts, cs = request.param
    return SlottingMachine.from_course(K, H, L, ratio, bar_side=bs, tool_side=ts, crank_sense=cs)


def test_positions_match_least_squares(machine):
    """Loop equations O3 + s e^{i t3} = A and B + l_BC e^{i t4} = (x_yy, y_C), solved generically."""
    m = machine
    k = m.kinematics(PHI)
    for j, p in enumerate(PHI):
        A = m.crank * np.exp(1j * p)
        O3 = -m.centre_distance

        def loop(t):
            t3, s, t4, yc = t
            B = O3 + m.bar_side * m.bar * np.exp(1j * t3)
            z1 = O3 + s * np.exp(1j * t3) - A
            z2 = B + m.rod * np.exp(1j * t4) - (m.guide_x + 1j * yc)
            return [z1.real, z1.imag, z2.real, z2.imag]

        guess = [k.bar.angle[j] + 0.03, k.slide.s[j] * 1.02, k.rod.angle[j] - 0.03, k.C.y[j] + 1.0]
        sol = least_squares(loop, guess, xtol=1e-15, ftol=1e-15, gtol=1e-15)
        t3, s, t4, yc = sol.x
        assert np.max(np.abs(loop(sol.x))) < 1e-9
        assert np.angle(np.exp(1j * (t3 - k.bar.angle[j]))) == pytest.approx(0, abs=1e-9)
        assert s == pytest.approx(k.slide.s[j], rel=1e-9)
        assert yc == pytest.approx(k.C.y[j], abs=1e-8 * m.bar)


def test_derivatives_match_numerical(machine):
    m = machine
    k = m.kinematics(PHI, omega=1.0)
    for get, state in ((lambda p: m.kinematics(p, omega=1.0).C.pos, k.C), (lambda p: m.kinematics(p, omega=1.0).B.pos, k.B)):
        d1, d2 = numeric_derivatives(get, PHI)
        assert_close(state.vel, d1, rel=1e-7)
        assert_close(state.acc, d2, rel=1e-5)
    for name in ("bar", "rod"):
        w, e = numeric_angle_derivatives(lambda p: getattr(m.kinematics(p, omega=1.0), name).angle, PHI)
        assert_close(getattr(k, name).omega, w, rel=1e-7)
        assert_close(getattr(k, name).alpha, e, rel=1e-5)
    s1, s2 = numeric_derivatives(lambda p: m.kinematics(p, omega=1.0).slide.s, PHI)
    assert_close(k.slide.ds, s1, rel=1e-7)
    assert_close(k.slide.d2s, s2, rel=1e-5)


def test_coriolis_closes_the_acceleration_of_the_block(machine):
    """a_A = a_A3(on bar) + a_rel + a_Coriolis, term by term (seed 003's vector equation)."""
    k = machine.kinematics(PHI, omega=3.0)
    u, O3 = k.bar.unit, -machine.centre_distance
    r = k.A.pos - O3
    a_on_bar = (1j * k.bar.alpha - k.bar.omega**2) * r
    a_rel = k.slide.d2s * u
    a_cor = 2j * k.bar.omega * k.slide.ds * u
    assert_close(a_on_bar + a_rel + a_cor, k.A.acc, rel=1e-12)
    assert_close(np.abs(a_cor), k.coriolis, rel=1e-12)


def test_synthesis_properties(machine):
    """Computed stroke = H, time ratio = K, swing = theta; dead positions where the crank is perpendicular to the bar."""
    m, syn = machine, machine.synthesis
    rep = analyse(m)
    assert rep.stroke == pytest.approx(syn.stroke, rel=1e-10)
    assert rep.time_ratio == pytest.approx(syn.time_ratio, rel=1e-10)
    assert 2 * m.half_swing == pytest.approx(syn.swing, rel=1e-12)
    half = syn.swing / 2
    analytic = np.sort(np.mod([np.pi / 2 + half, 3 * np.pi / 2 - half], 2 * np.pi))
    assert_close(dead_positions(m), analytic, rel=1e-11, scale=1.0)
    k = m.kinematics(dead_positions(m))
    assert_close(np.real(np.conj(k.A.pos) * (k.A.pos + m.centre_distance)), np.zeros(2), rel=1e-9, scale=m.crank**2)
    assert rep.working_span > rep.return_span  # the slow stroke is the working one


def test_guide_at_middle_of_sagitta(machine):
    """y-y halves the sagitta: BC leans equally at the bar's ends and its mid-position."""
    m = machine
    mid = m.kinematics(np.array([0.0]))  # crank along +x: the bar at its mid-position
    ends = m.kinematics(dead_positions(m))
    dev_mid = abs(m.guide_x - mid.B.x[0])
    dev_end = np.abs(m.guide_x - ends.B.x)
    assert_close(dev_end, np.full(2, dev_mid), rel=1e-9, scale=m.bar)
    assert dev_mid == pytest.approx(m.synthesis.sagitta / 2, rel=1e-9)


def test_seed_layout_cuts_downward():
    """Seed 003: position 1 is the tool's lower limit; the working (cutting) stroke goes down."""
    m = SlottingMachine.from_course(2.0, 100.0, 150.0, 1.0)  # B beyond O3, crank counter-clockwise
    rep = analyse(m)
    assert rep.s_end < rep.s_start


def test_rpm_sets_time_derivatives():
    m = SlottingMachine.from_course(2.0, 100.0, 150.0, 1.0, rpm=60, crank_sense=-1)
    assert m.omega == pytest.approx(-2 * np.pi)
    k1, kw = m.kinematics(PHI, omega=1.0), m.kinematics(PHI)
    assert_close(kw.C.vel, -2 * np.pi * k1.C.vel, rel=1e-12)
    assert_close(kw.C.acc, (2 * np.pi) ** 2 * k1.C.acc, rel=1e-12)


@pytest.mark.parametrize(
    "args, field, text",
    [
        ((1.0, 100, 150, 1), "linkage.time_ratio", "K must be > 1"),
        ((0.7, 100, 150, 1), "linkage.time_ratio", "K must be > 1"),
        ((2.0, 0, 150, 1), "linkage.stroke", "> 0"),
        ((2.0, 100, -150, 1), "linkage.centre_distance", "> 0"),
        ((2.0, 100, 150, 0), "linkage.rod_ratio", "> 0"),
    ],
)
def test_bad_course_data(args, field, text):
    with pytest.raises(InputError, match=text) as ei:
        SlottingMachine.from_course(*args)
    assert ei.value.field == field


def test_bar_pin_inside_block_travel():
    with pytest.raises(InputError, match=r"inside the block's travel \[75, 225\]") as ei:
        SlottingMachine.from_course(2.0, 100.0, 150.0, 1.0, bar_side=1)
    assert ei.value.field == "linkage.bar"


def test_crank_not_shorter_than_L():
    with pytest.raises(InputError, match="shorter than the centre distance"):
        SlottingMachine(crank=160, centre_distance=150, bar=100, rod=100, guide_x=-240)


def test_rod_too_short_names_angles_and_fit():
    with pytest.raises(AssemblyError, match=r"cannot reach the guide y-y at crank angles .* needs l_BC >= 10\b") as ei:
        SlottingMachine(crank=75, centre_distance=150, bar=100, rod=5, guide_x=-240)
    assert ei.value.field == "linkage.rod"
    SlottingMachine(crank=75, centre_distance=150, bar=100, rod=10.0001, guide_x=-240)  # just fits
