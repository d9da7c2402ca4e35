"""Primitives: positions against a generic nonlinear solve, derivatives against numerical differentiation."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import fsolve

from cams.machine.linkage import (
    Angle,
    AssemblyError,
    acute_angle,
    crank,
    ground,
    on_link,
    pllp,
    plpp,
    rpp,
    rpr,
    rrp,
    rrr,
    solve_real,
)
from tests.machine.linkage.conftest import assert_close, numeric_angle_derivatives, numeric_derivatives

PHI = np.linspace(0.05, 2 * np.pi - 0.05, 37)


def test_pllp_branches_and_distances():
    c1, c2 = np.array([0j, 1 + 1j]), np.array([8 + 0j, 4 - 2j])
    for br in (1, -1):
        X, bad = pllp(c1, 5.0, 4.5, c2, branch=br)
        assert not bad.any()
        assert_close(np.abs(X - c1), np.full(2, 5.0), rel=1e-12)
        assert_close(np.abs(X - c2), np.full(2, 4.5), rel=1e-12)
        side = np.sign(np.imag(np.conj(c2 - c1) * (X - c1)))
        assert np.all(side == br)


def test_pllp_reports_unreachable():
    X, bad = pllp(np.array([0j, 0j]), 1.0, 1.0, np.array([1 + 0j, 3 + 0j]))
    assert bad.tolist() == [False, True] and np.isnan(X[1])


def test_plpp_branches():
    X, s, bad = plpp(0j, 5.0, 3j, 1 + 0j, branch=1)
    assert complex(X) == pytest.approx(4 + 3j) and float(s) == pytest.approx(4.0)
    X, s, bad = plpp(0j, 2.0, 3j, 1 + 0j)
    assert bool(bad)


def test_solve_real_and_acute_angle():
    u, w = solve_real(np.array([1 + 1j]), np.array([-1 + 2j]), np.array([3 + 0j]))
    assert_close(u * (1 + 1j) + w * (-1 + 2j), np.array([3 + 0j]), rel=1e-14)
    assert float(np.degrees(acute_angle(np.radians(100), np.radians(-100)))) == pytest.approx(20.0)


# -- a four-bar (crank + RRR) --------------------------------------------------
def fourbar(phi, omega=1.0, branch=1):
    A, _ = crank(ground(0j), 30.0, phi, omega=omega)
    D = ground(100 + 10j)
    return rrr(A, 90.0, 70.0, D, branch=branch)


@pytest.mark.parametrize("branch", [1, -1])
def test_rrr_positions_match_fsolve(branch):
    X, l1, l2 = fourbar(PHI, branch=branch)
    for k, p in enumerate(PHI):
        A = 30 * np.exp(1j * p)

        def loop(t):  # A + 90 e^{i t1} - D - 70 e^{i t2} = 0
            z = A + 90 * np.exp(1j * t[0]) - (100 + 10j) - 70 * np.exp(1j * t[1])
            return [z.real, z.imag]

        t = fsolve(loop, [l1.angle[k] + 0.05, l2.angle[k] - 0.05], xtol=1e-13)
        assert np.angle(np.exp(1j * (t[0] - l1.angle[k]))) == pytest.approx(0, abs=1e-9)
        assert np.angle(np.exp(1j * (t[1] - l2.angle[k]))) == pytest.approx(0, abs=1e-9)


@pytest.mark.parametrize("branch", [1, -1])
def test_rrr_derivatives_match_numerical(branch):
    X, l1, l2 = fourbar(PHI, branch=branch)
    d1, d2 = numeric_derivatives(lambda p: fourbar(p, branch=branch)[0].pos, PHI)
    assert_close(X.vel, d1, rel=1e-7)
    assert_close(X.acc, d2, rel=1e-5)
    for k, link in ((1, l1), (2, l2)):
        w, e = numeric_angle_derivatives(lambda p: fourbar(p, branch=branch)[k].angle, PHI)
        assert_close(link.omega, w, rel=1e-7)
        assert_close(link.alpha, e, rel=1e-5)


def test_time_derivatives_scale_with_omega():
    X1 = fourbar(PHI, omega=1.0)[0]
    Xw = fourbar(PHI, omega=-7.5)[0]
    assert_close(Xw.vel, -7.5 * X1.vel, rel=1e-12)
    assert_close(Xw.acc, 7.5**2 * X1.acc, rel=1e-12)


def test_rrr_assembly_error_names_field_and_fit():
    with pytest.raises(AssemblyError, match=r"linkage.coupler: .*d1 \+ d2 >= ") as ei:
        A, _ = crank(ground(0j), 30.0, PHI)
        rrr(A, 40.0, 40.0, ground(100 + 0j), field="linkage.coupler")
    assert ei.value.mask.any() and not ei.value.mask.all()


# -- RRP on a rotating guide: the Coriolis term ------------------------------------
def rotating_guide(phi, branch=1):
    """Slider X on a guide that turns with the crank (through the crank centre), linked to a fixed point."""
    _, g = crank(ground(0j), 1.0, 0.7 * np.sin(phi) + 0.2 * phi)  # angle only; omega below
    # guide angle th(phi) = 0.2 phi + 0.7 sin(phi): th' and th'' by hand
    guide = Angle(g.angle, 0.2 + 0.7 * np.cos(phi), -0.7 * np.sin(phi))
    c = ground(-20 + 35j)
    return rrp(c, 60.0, ground(0j), guide, branch=branch)


@pytest.mark.parametrize("branch", [1, -1])
def test_rrp_on_turning_guide_matches_numerical(branch):
    X, link, sl = rotating_guide(PHI, branch)
    d1, d2 = numeric_derivatives(lambda p: rotating_guide(p, branch)[0].pos, PHI)
    assert_close(X.vel, d1, rel=1e-7)
    assert_close(X.acc, d2, rel=1e-5)
    s1, s2 = numeric_derivatives(lambda p: rotating_guide(p, branch)[2].s, PHI)
    assert_close(sl.ds, s1, rel=1e-7)
    assert_close(sl.d2s, s2, rel=1e-5)
    w, e = numeric_angle_derivatives(lambda p: rotating_guide(p, branch)[1].angle, PHI)
    assert_close(link.omega, w, rel=1e-7)
    assert_close(link.alpha, e, rel=1e-5)


def test_rrp_unreachable_guide():
    with pytest.raises(AssemblyError, match="length >= 50"):
        rrp(ground(np.array([50j, 10j])), 20.0, ground(0j), Angle(0.0, 0.0, 0.0))


# -- RPR: guide bar with a moving pivot and an offset slot ---------------------------
def guide_bar(phi, offset):
    A, _ = crank(ground(0j), 40.0, phi)
    P, _ = crank(ground(-150 + 0j), 10.0, 2 * phi, omega=2.0)  # a moving pivot, turning twice as fast
    bar, sl = rpr(A, P, offset=offset)
    return bar, sl, A, P


@pytest.mark.parametrize("offset", [0.0, 12.0, -8.0])
def test_rpr_positions_and_derivatives(offset):
    bar, sl, A, P = guide_bar(PHI, offset)
    # position: the block lies on the slot line
    assert_close(A.pos, P.pos + (sl.s + 1j * offset) * bar.unit, rel=1e-12)
    w, e = numeric_angle_derivatives(lambda p: guide_bar(p, offset)[0].angle, PHI)
    assert_close(bar.omega, w, rel=1e-7)
    assert_close(bar.alpha, e, rel=1e-5)
    s1, s2 = numeric_derivatives(lambda p: guide_bar(p, offset)[1].s, PHI)
    assert_close(sl.ds, s1, rel=1e-7)
    assert_close(sl.d2s, s2, rel=1e-5)


def test_rpr_fsolve_positions():
    bar, sl, A, P = guide_bar(PHI, 12.0)
    for k in range(len(PHI)):
        def loop(t):
            z = P.pos[k] + (t[1] + 12j) * np.exp(1j * t[0]) - A.pos[k]
            return [z.real, z.imag]

        t = fsolve(loop, [bar.angle[k] + 0.02, sl.s[k] * 1.01], xtol=1e-13)
        assert np.angle(np.exp(1j * (t[0] - bar.angle[k]))) == pytest.approx(0, abs=1e-9)
        assert t[1] == pytest.approx(sl.s[k], rel=1e-10)


def test_rpr_block_at_pivot():
    A = ground(np.array([5 + 0j, 1 + 0j]))
    with pytest.raises(AssemblyError):
        rpr(A, ground(0j), offset=2.0)


# -- RPP (Scotch yoke, oblique slot) and rigid points ---------------------------------
def yoke(phi):
    A, cr = crank(ground(0j), 25.0, phi)
    C = on_link(ground(0j), cr, 40.0, angle=0.3)
    return rpp(C, 5 + 2j, np.radians(80), np.radians(15))


def test_rpp_derivatives():
    p, q = yoke(PHI)
    for get, sl in ((lambda x: yoke(x)[0].s, p), (lambda x: yoke(x)[1].s, q)):
        d1, d2 = numeric_derivatives(get, PHI)
        assert_close(sl.ds, d1, rel=1e-7)
        assert_close(sl.d2s, d2, rel=1e-5)


def test_rpp_parallel_slot_rejected():
    with pytest.raises(AssemblyError, match="parallel"):
        rpp(ground(1j), 0j, 0.3, 0.3 + np.pi)
