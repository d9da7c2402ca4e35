"""Crank-slider (seed 002): synthesis from the stroke, kinematics against independent computations."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import fsolve

from cams.machine.linkage import AssemblyError, analyse, crank_slider_crank
from cams.machine.linkage.machines import CrankSlider, OpposedTwin, SlottedLeverPump
from laws.errors import InfeasibleError, InputError
from tests.machine.linkage.conftest import assert_close, numeric_angle_derivatives, numeric_derivatives

PHI = np.linspace(0.0, 2 * np.pi, 41, endpoint=False) + 0.02


@pytest.mark.parametrize("H, rod, e", [(0.35, 1.4, 0.0), (100.0, 220.0, 30.0), (100.0, 220.0, -45.0), (40.0, 60.0, 12.0)])
@pytest.mark.parametrize("side", [1, -1])
def test_from_stroke_gives_the_stroke_and_time_ratio(H, rod, e, side):
    m = CrankSlider.from_stroke(H, rod, offset=e, slider_side=side)
    rep = analyse(m, working="slow")
    assert rep.stroke == pytest.approx(H, rel=1e-10)
    r, l = m.crank, rod
    theta = abs(np.arcsin(abs(e) / (l - r)) - np.arcsin(abs(e) / (l + r)))  # crank angle excess of the slow stroke
    assert rep.time_ratio == pytest.approx((np.pi + theta) / (np.pi - theta), rel=1e-9)
    far, near = m.extreme_positions
    assert sorted([rep.s_start, rep.s_end]) == pytest.approx(sorted([far, near]), rel=1e-12)


def test_central_synthesis_is_half_stroke():
    assert crank_slider_crank(0.35, 1.4) == 0.175


@pytest.mark.parametrize("side, e", [(1, 0.0), (-1, 0.2), (1, -0.3)])
def test_positions_match_fsolve_and_derivatives_match_numerical(side, e):
    m = CrankSlider(crank=0.5, rod=1.7, offset=e, slider_side=side, rod_cg=0.6)
    k = m.kinematics(PHI, omega=1.0)
    for j, p in enumerate(PHI):
        A = 0.5 * np.exp(1j * p)

        def loop(t):  # A + l e^{i b} = (x_B, e)
            z = A + 1.7 * np.exp(1j * t[0]) - (t[1] + 1j * e)
            return [z.real, z.imag]

        t = fsolve(loop, [k.rod.angle[j] + 0.02, k.B.x[j] + 0.01], xtol=1e-12)
        assert t[1] == pytest.approx(k.B.x[j], abs=1e-11)
    for get, st in ((lambda p: m.kinematics(p, omega=1.0).B.pos, k.B), (lambda p: m.kinematics(p, omega=1.0).S.pos, k.S)):
        d1, d2 = numeric_derivatives(get, PHI)
        assert_close(st.vel, d1, rel=1e-7)
        assert_close(st.acc, d2, rel=1e-5)
    w, a = numeric_angle_derivatives(lambda p: m.kinematics(p, omega=1.0).rod.angle, PHI)
    assert_close(k.rod.omega, w, rel=1e-7)
    assert_close(k.rod.alpha, a, rel=1e-5)


def test_central_crank_slider_closed_form():
    """Textbook closed form x_B = r cos(phi) + sqrt(l^2 - r^2 sin^2 phi) and its derivative."""
    r, l = 0.175, 1.4
    k = CrankSlider(r, l).kinematics(PHI, omega=1.0)
    assert_close(k.B.x, r * np.cos(PHI) + np.sqrt(l**2 - (r * np.sin(PHI)) ** 2), rel=1e-14)
    lam = r / l
    vx = -r * np.sin(PHI) * (1 + lam * np.cos(PHI) / np.sqrt(1 - (lam * np.sin(PHI)) ** 2))
    assert_close(k.B.vel.real, vx, rel=1e-13)


def test_transmission_minimum_of_the_central_mechanism():
    r, l = 30.0, 100.0
    rep = analyse(CrankSlider(r, l))
    assert np.degrees(rep.min_transmission) == pytest.approx(90 - np.degrees(np.arcsin(r / l)), abs=1e-6)
    assert np.degrees(rep.min_transmission_at) % 180 == pytest.approx(90.0, abs=1e-3)


def test_bad_crank_sliders():
    with pytest.raises(AssemblyError, match=r"needs l_AB > l_OA \+ \|e\| = 0.5") as ei:
        CrankSlider(crank=0.3, rod=0.45, offset=0.2)
    assert ei.value.field == "linkage.rod"
    with pytest.raises(InputError, match="linkage.crank"):
        CrankSlider(crank=0.0, rod=1.0)
    with pytest.raises(InfeasibleError, match="stroke < "):
        crank_slider_crank(250.0, 100.0, 30.0)
    with pytest.raises(InputError, match="linkage.stroke"):
        CrankSlider.from_stroke(-1.0, 1.0)


def test_opposed_twin_derivatives():
    m = OpposedTwin(0.048, 0.192, 0.064)
    k = m.kinematics(PHI, omega=1.0)
    for name in ("B", "D", "S2", "S4"):
        d1, d2 = numeric_derivatives(lambda p: getattr(m.kinematics(p, omega=1.0), name).pos, PHI)
        assert_close(getattr(k, name).vel, d1, rel=1e-7)
        assert_close(getattr(k, name).acc, d2, rel=1e-5)
    assert np.all(k.B.x > 0) and np.all(k.D.x < 0)


def test_pump_synthesis_and_derivatives():
    m = SlottedLeverPump.from_course(2.0, 250.0, 525.0)
    rep = analyse(m)
    assert rep.stroke == pytest.approx(250.0, rel=1e-10)
    assert rep.time_ratio == pytest.approx(2.0, rel=1e-10)
    assert np.degrees(rep.min_transmission) == pytest.approx(60.0, abs=1e-6)
    k = m.kinematics(PHI, omega=1.0)
    d1, d2 = numeric_derivatives(lambda p: m.kinematics(p, omega=1.0).piston.s, PHI)
    assert_close(k.piston.ds, d1, rel=1e-7)
    assert_close(k.piston.d2s, d2, rel=1e-5)
    assert_close(k.piston.s, k.C.y, rel=1e-14)
