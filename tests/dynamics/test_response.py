"""The exact span-wise response (laws.response) against closed forms derived by hand and against solve_ivp.

Residual references, derived in the tests' docstrings: undamped, from rest, driven through the train alone (no
closing spring, ratio 1), the error ``e = x - s`` obeys ``e'' + e = -s''`` in ``tau = omega_n t``; after a rise of
``Lambda = omega_n T = 2 pi lambda`` its free vibration has the amplitude ``|int_0^Lambda s''(tau) e^(i tau) dtau|``
(Duhamel), which with ``s'' = h S''(u) / Lambda^2``, ``u = tau / Lambda``, is
``(h / Lambda) |int_0^1 S''(u) e^(i Lambda u) du|``.

* Cycloidal, ``S'' = 2 pi sin(2 pi u)``: ``int_0^1 sin(a u) e^(i b u) du = a (1 - e^(i b)) / (a^2 - b^2)`` for
  ``a = 2 pi`` (``cos a = 1, sin a = 0``), and ``|1 - e^(i b)| = 2 |sin(b / 2)|``, so the amplitude over ``h`` is
  ``8 pi^2 |sin(Omega / 2)| / (Omega |4 pi^2 - Omega^2|)``, ``Omega = Lambda``: zero at whole ``lambda >= 2``;
  at ``lambda = 1`` both vanish and the limit is ``8 pi^2 (d/2) / (2 pi 4 pi d) = 1/2``.
* 3-4-5, ``S'' = 60u - 180u^2 + 120u^3``: by parts three times with ``S''(0) = S''(1) = 0``,
  ``S'''(0) = S'''(1) = 60`` (drops out when ``e^(i Lambda) = 1``), ``S''''(1) - S''''(0) = 720`` and ``S^(5) = 720``
  (whose integral vanishes at whole ``lambda``): ``int = 720 / (i Lambda)^3``, amplitude ``720 / Lambda^4
  = 45 / (pi^4 lambda^4)``.

The oscillator's closed-form exponential, at one speed over many times and at many speeds at one time (the jump
speed's batch), is checked against scipy's Pade exponential of ``A t`` in each damping regime.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from laws.errors import InputError
from laws.polynomial import PolynomialLaw
from laws.program import Phase, Program
from laws.registry import LAWS
from laws.response import Train, phase_residuals, response, steady_state
from laws.spline import SplineLaw
from laws.table import TableLaw

BETA = np.pi / 2


def _program(law, *, beta=BETA) -> Program:
    rest = (2 * np.pi - 2 * beta) / 2
    return Program(
        (Phase("rise", beta, law), Phase("dwell", rest), Phase("return", beta, law), Phase("dwell", rest)), 1.0
    )


def _cycloidal_reference(lam: float) -> float:
    om = 2 * np.pi * lam
    if abs(lam - 1.0) < 1e-12:
        return 0.5
    return 8 * np.pi**2 * abs(np.sin(om / 2)) / (om * abs(4 * np.pi**2 - om**2))


@pytest.mark.parametrize("lam", [0.5, 1.0, 1.37, 2.0, 2.5, 3.0, 4.0, 6.25])
def test_cycloidal_residual_from_rest(lam):
    prog = _program("cycloidal")
    res = phase_residuals(prog, Train(rho=2 * np.pi * lam / BETA), steady=False)
    rise, ret = res
    assert rise[0] == 0 and ret[0] == 2
    assert rise[1] == pytest.approx(_cycloidal_reference(lam), abs=1e-9)
    assert ret[1] == pytest.approx(_cycloidal_reference(lam), abs=1e-9)
    if lam in (2.0, 3.0, 4.0):
        assert rise[1] < 1e-9
    if lam == 1.0:
        assert rise[1] == pytest.approx(0.5, abs=1e-9)


@pytest.mark.parametrize("lam", [1, 2, 3, 4, 5])
def test_345_residual_at_whole_ratios(lam):
    prog = _program("poly345")
    rise = phase_residuals(prog, Train(rho=2 * np.pi * lam / BETA), steady=False)[0]
    assert rise[1] == pytest.approx(45 / (np.pi**4 * lam**4), abs=1e-9)


def _spline() -> SplineLaw:
    return SplineLaw((0.0, 0.4, 1.0), ((0, 0, 0.1, 0.3, 0.45), (0.45, 0.6, 0.9, 1, 1)), name="sp")


def _laws():
    yield from LAWS.values()
    yield _spline()
    yield PolynomialLaw.from_boundary(start=(0, 0), end=(0, 0, 0))
    yield TableLaw((0, 0.2, 0.5, 0.7, 1), (0, 0.05, 0.5, 0.9, 1), clamped=True)


def _ivp(prog: Program, tr: Train, y0, phi_eval):
    """The train's ODE in the cam angle, integrated phase by phase with the program's own s and ds/dphi."""
    rho, r, z, f = tr.rho, tr.ratio, tr.zeta, tr.offset

    def rhs(phi, y):
        mo = prog.evaluate_phase(i, (phi - prog.starts[i]) / prog.phases[i].angle)
        return [y[1], rho**2 * (r * mo.s - y[0] - f) + 2 * z * rho * (mo.ds - y[1])]

    y = np.array([y0[0], y0[1] * rho])  # (x, dx/dphi)
    out = np.empty((2, len(phi_eval)))
    for i in range(len(prog.phases)):
        a, b = prog.starts[i], prog.starts[i + 1]
        sel = (phi_eval >= a) & (phi_eval < b)
        sol = solve_ivp(
            rhs, (a, b), y, method="DOP853", rtol=1e-11, atol=1e-13, t_eval=phi_eval[sel], dense_output=False
        )
        out[:, sel] = sol.y
        y = solve_ivp(rhs, (a, b), y, method="DOP853", rtol=1e-11, atol=1e-13).y[:, -1]
    return out, y


@pytest.mark.parametrize("zeta", [0.0, 0.07])
@pytest.mark.parametrize("law", list(_laws()), ids=lambda law: law.name)
def test_exact_against_solve_ivp(law, zeta):
    prog = _program(law, beta=1.3)
    tr = Train(rho=11.3, ratio=0.8, zeta=zeta, offset=0.05)
    y0 = np.array([0.02, -0.1])
    phi = np.linspace(0, 2 * np.pi, 301, endpoint=False)
    ref, _ = _ivp(prog, tr, y0, phi)
    got = response(prog, tr, phi, y0)
    assert np.max(np.abs(got.x - ref[0])) < 1e-8
    assert np.max(np.abs(got.dx - ref[1])) < 1e-8 * tr.rho
    # the rigid motion it carries is the program's
    mo = prog.evaluate(phi)
    assert np.max(np.abs(got.s - mo.s)) < 1e-10 and np.max(np.abs(got.ds - mo.ds)) < 1e-9
    # the acceleration is the ODE's, checked by a central difference of the exact x
    h = 1e-4
    xp, xm = response(prog, tr, phi + h, y0).x, response(prog, tr, phi - h, y0).x
    inner = (phi > 0.01) & np.all(np.abs(phi[:, None] - prog.starts[None, :]) > 2 * h, axis=1)
    fd = (xp - 2 * got.x + xm) / h**2
    assert np.max(np.abs(fd[inner] - got.d2x[inner])) < 1e-4 * max(1.0, np.max(np.abs(got.d2x)))


@pytest.mark.parametrize("law", ["cycloidal", "modified_sine", "poly4567"])
def test_steady_state_is_periodic_by_integration(law):
    prog = _program(law, beta=1.1)
    tr = Train(rho=17.7, ratio=0.9, zeta=0.03, offset=0.2)
    y0 = steady_state(prog, tr)
    _, end = _ivp(prog, tr, y0, np.array([]))
    assert end[0] == pytest.approx(y0[0], abs=1e-9)
    assert end[1] == pytest.approx(y0[1] * tr.rho, abs=1e-8 * tr.rho)


def test_undamped_resonance_has_no_steady_state():
    with pytest.raises(InputError, match="damping_ratio"):
        steady_state(_program("cycloidal"), Train(rho=12.0))


def test_damped_steady_state_forgets_the_start():
    """Lightly damped: many turns from rest approach the steady state (its residuals)."""
    prog = _program("cycloidal", beta=1.0)
    tr = Train(rho=9.4, zeta=0.05)
    y0 = steady_state(prog, tr)
    y = np.array([0.0, 0.0])
    for _ in range(40):
        _, y = _ivp(prog, tr, y, np.array([]))
        y = np.array([y[0], y[1] / tr.rho])
    assert np.allclose(y, y0, atol=1e-8)


def test_a_phase_from_rest_runs_on_into_the_next_turn():
    """The response from rest at the return's start (a phase's own figure), over the rest of the turn and on into
    the next one's rise, against solve_ivp phase by phase in that order."""
    from laws.response import rest_state

    prog = _program("modified_sine", beta=1.2)
    tr = Train(rho=13.1, ratio=0.85, zeta=0.02, offset=0.03)
    start = prog.starts[2]
    y0 = rest_state(prog, tr, 2)
    assert y0[0] == pytest.approx(0.85 * 1.0 - 0.03) and y0[1] == 0.0
    phi = start + np.linspace(0.0, 2 * np.pi, 240, endpoint=False)
    got = response(prog, tr, np.mod(phi, 2 * np.pi), y0, start=start)
    y = np.array([y0[0], 0.0])
    ref = np.empty(phi.size)
    for k, i in enumerate((2, 3, 0, 1)):
        a = prog.starts[i] + (2 * np.pi if k >= 2 else 0.0)
        b = a + prog.phases[i].angle

        def rhs(p, yy, i=i, a=a):
            mo = prog.evaluate_phase(i, (p - a) / prog.phases[i].angle)
            return [yy[1], tr.rho**2 * (tr.ratio * mo.s - yy[0] - tr.offset) + 2 * tr.zeta * tr.rho * (mo.ds - yy[1])]

        sel = (phi >= a) & (phi < b)
        sol = solve_ivp(rhs, (a, b), y, method="DOP853", rtol=1e-11, atol=1e-13, dense_output=True)
        ref[sel] = sol.sol(phi[sel])[0]
        y = sol.y[:, -1]
    assert np.max(np.abs(got.x - ref)) < 1e-8


@pytest.mark.parametrize("zeta", [0.0, 0.3, 1.0, 1.6])
def test_oscillator_against_pade_exponential(zeta):
    from scipy.linalg import expm

    from laws.response import _oscillator

    def ref(rho, t):
        return expm(np.array([[0.0, rho], [-rho, -2 * zeta * rho]]) * t)

    rhos, ts = np.array([0.7, 3.1, 12.0, 41.5]), np.array([0.0, 0.013, 0.4, 1.9])
    many_speeds = _oscillator(rhos, zeta, 0.4)
    many_times = _oscillator(3.1, zeta, ts)
    assert many_speeds.shape == many_times.shape == (4, 2, 2)
    for k in range(4):
        want = ref(rhos[k], 0.4)
        assert np.allclose(many_speeds[k], want, rtol=1e-12, atol=1e-12 * np.max(np.abs(want)))
        want = ref(3.1, ts[k])
        assert np.allclose(many_times[k], want, rtol=1e-12, atol=1e-12 * np.max(np.abs(want)))


@pytest.mark.parametrize("rho", [200.0, 300.0, 1e3, 1e4])
def test_overdamped_oscillator_where_cosh_overflows(rho):
    """Overdamped (zeta 1.6) over a turn, t = 2 pi, at speeds where cosh(w t) and sinh(w t) overflow alone (their
    product with exp(mu t) is below 1e-191, or 0): finite, and scipy's Pade exponential's to 1e-11 (exactly 0
    where both underflow)."""
    from scipy.linalg import expm

    from laws.response import _oscillator

    zeta, t = 1.6, 2 * np.pi
    with np.errstate(over="ignore"):
        assert np.isinf(np.cosh(rho * np.sqrt(zeta**2 - 1) * t))
    got = _oscillator(rho, zeta, t)
    want = expm(np.array([[0.0, rho], [-rho, -2 * zeta * rho]]) * t)
    assert np.all(np.isfinite(got))
    assert np.allclose(got, want, rtol=1e-11, atol=1e-11 * np.max(np.abs(want)))
    assert (rho < 1e3) == bool(np.all(want != 0))  # the slower two decay to a number, the faster two to 0
