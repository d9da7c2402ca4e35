"""The flywheel (cams.machine.flywheel): seed 004's program output, seed 003's formula, the equation of motion.

Seed 004 (pump with a swinging slotted lever, Mogilev 2006), section 1.13 "Проверка
полученных результатов при помощи программы": n = 77 rev/min, delta = 0.1, and for the
12 positions of the crank (30 deg apart, position 1 = start of the working stroke)

    Mr, N m : 0, 245.8, 230, 244.4, 230.6, 239.3, 227.6, 164.2, 0, 0.7, 34.3, 1.6
    J, kg m^2: 112, 125.4, 123.3, 125, 124, 124.1, 122.1, 117.5, 112, 147, 150, 151.9

Program output: driving moment 134.61 N m, excess work 627.36 J, flywheel 96.49 kg m^2.

What is recomputed, and how far:

* Driving moment: the mean of the 12 moments is 134.875 N m (0.2 % above the seed);
  with the twelfth moment -1.6 instead of 1.6 it is 134.608 = 134.61. The text lost
  signs elsewhere ("12-й:1.6" has lost its space as well), so the tests take -1.6.
* Flywheel from the excess work: J_F = dA / (omega_m^2 delta) gives 96.489 from 627.36,
  the seed's 96.49 -- the program uses exactly the relation of cams.machine.flywheel.
* Excess work itself: the Wittenbauer tangents on the 12 positions give dA = 519.5 J
  (J_F = 79.9 kg m^2), joining the samples by straight lines 519.8 J (79.9), by a
  periodic cubic spline 707.9 J (108.9). The seed's 627.36 J (96.49) lies between: -17 %
  and +13 % away. dA is the small difference of two large numbers here (the linkage's
  own energy 1/2 J omega^2 varies by about 1300 J over the cycle, ten times the
  flywheel's share), so how J is drawn between positions 9 (112) and 10 (147) decides
  it; the seed does not say how its program interpolates. The seed's accepted error
  between its graphical and program results (its formula 1.16.8) is lost in the text;
  seed 002 accepts 5-10 %. We state the bracket and test it, and keep the linear and
  spline values as regression values (labelled so).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from cams.machine.flywheel import flywheel, rpm_to_omega
from laws.errors import InputError

PHI12 = np.radians(np.arange(12) * 30.0)
MR_004 = np.array([0, 245.8, 230, 244.4, 230.6, 239.3, 227.6, 164.2, 0, 0.7, 34.3, -1.6])
J_004 = np.array([112, 125.4, 123.3, 125, 124, 124.1, 122.1, 117.5, 112, 147, 150, 151.9])
SEED_MD, SEED_DA, SEED_JF = 134.61, 627.36, 96.49


def test_seed_004_driving_moment():
    r = flywheel(PHI12, MR_004, J_004, rpm=77, delta=0.1)
    assert r.driving_moment == pytest.approx(SEED_MD, abs=0.005)
    # with the printed +1.6: 0.2 % above the seed
    r2 = flywheel(PHI12, np.abs(MR_004), J_004, rpm=77, delta=0.1)
    assert r2.driving_moment == pytest.approx(134.875, rel=1e-12)
    assert r2.driving_moment == pytest.approx(SEED_MD, rel=0.002)


def test_seed_004_flywheel_from_excess_work():
    """The program's J_F = dA / (omega_m^2 delta): 627.36 J -> 96.49 kg m^2."""
    w = rpm_to_omega(77)
    assert SEED_DA / (w**2 * 0.1) == pytest.approx(SEED_JF, abs=0.005)
    for how in ("linear", "spline"):
        r = flywheel(PHI12, MR_004, J_004, rpm=77, delta=0.1, interpolation=how)
        assert r.flywheel_inertia == pytest.approx(r.excess_work / (w**2 * 0.1), rel=1e-12)


def test_seed_004_excess_work_bracket():
    """The seed's dA and J_F lie between the linear and the spline joins of its 12 positions."""
    lin = flywheel(PHI12, MR_004, J_004, rpm=77, delta=0.1, interpolation="linear")
    spl = flywheel(PHI12, MR_004, J_004, rpm=77, delta=0.1, interpolation="spline")
    assert lin.excess_work < SEED_DA < spl.excess_work
    assert lin.flywheel_inertia < SEED_JF < spl.flywheel_inertia
    # regression values (ours, not the seed's)
    assert lin.excess_work == pytest.approx(519.80, abs=0.01)
    assert lin.flywheel_inertia == pytest.approx(79.945, abs=0.001)
    assert spl.excess_work == pytest.approx(707.87, abs=0.01)
    assert spl.flywheel_inertia == pytest.approx(108.872, abs=0.001)
    # Wittenbauer tangents on the 12 positions only
    w = rpm_to_omega(77)
    M13, J13 = np.append(MR_004, MR_004[0]), np.append(J_004, J_004[0])
    Ar = np.concatenate([[0.0], np.cumsum(0.5 * (M13[1:] + M13[:-1]) * np.pi / 6)])
    dE = Ar[-1] / (2 * np.pi) * np.radians(np.arange(13) * 30.0) - Ar
    dA = np.max(dE - 0.5 * J13 * (w * 1.05) ** 2) - np.min(dE - 0.5 * J13 * (w * 0.95) ** 2)
    assert dA == pytest.approx(519.52, abs=0.01)
    assert abs(lin.excess_work - dA) / dA < 1e-3


def test_seed_003_formula_for_constant_inertia():
    """Constant J: J_F = 900 dA_max / (pi^2 n^2 delta) - J, dA_max = max dE - min dE (seed 003 step 5)."""
    phi = np.radians(np.arange(0, 360, 15.0))
    Mr = np.where((phi > 1.0) & (phi < 3.5), 800.0, 20.0)
    n, d, J0 = 60.0, 0.05, 3.0
    r = flywheel(phi, Mr, J0, rpm=n, delta=d)
    seed = 900 * r.energy_range / (np.pi**2 * n**2 * d)
    assert r.flywheel_inertia == pytest.approx(seed - J0, rel=1e-12)
    assert r.achieved_delta == pytest.approx(d, rel=1e-9)


def test_analytic_sine():
    """Mr = M0 sin(phi), J const: dE = M0 (cos phi - 1), range 2 M0; omega extremes at 0 and pi."""
    phi = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    r = flywheel(phi, 50 * np.sin(phi), 0.5, rpm=120, delta=0.02, interpolation="spline")
    assert r.driving_moment == pytest.approx(0.0, abs=1e-9)
    assert r.energy_range == pytest.approx(100.0, rel=1e-9)
    w = rpm_to_omega(120)
    assert r.flywheel_inertia == pytest.approx(100 / (w**2 * 0.02) - 0.5, rel=1e-9)
    k_hi, k_lo = np.argmax(r.omega), np.argmin(r.omega)
    assert np.degrees(r.phi[k_hi]) == pytest.approx(0.0, abs=0.1) or np.degrees(r.phi[k_hi]) == pytest.approx(360.0, abs=0.1)
    assert np.degrees(r.phi[k_lo]) == pytest.approx(180.0, abs=0.1)


def _machine(phi):
    """A smooth test machine: J varies by +-40 %, Mr resists mostly in the first half turn."""
    J = 2.0 + 0.8 * np.cos(2 * phi) + 0.3 * np.sin(phi)
    dJ = -1.6 * np.sin(2 * phi) + 0.3 * np.cos(phi)
    Mr = 400.0 * np.maximum(np.sin(phi), 0.0) ** 2 + 30.0 * np.cos(3 * phi)
    return J, dJ, Mr


@pytest.mark.parametrize("delta", [0.02, 0.1])
def test_equation_of_motion_gives_delta(delta):
    """Integrate (J + J_F) omega' + 1/2 J' omega^2 = Md - Mr in time: the fluctuation is delta within 1 %."""
    phi = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    J, _, Mr = _machine(phi)
    n = 90.0
    r = flywheel(phi, Mr, J, rpm=n, delta=delta, interpolation="spline")
    Md, JF = r.driving_moment, r.flywheel_inertia

    def rhs(t, y):
        p, w = y
        Jp, dJp, Mrp = _machine(np.array(p))
        return [w, (Md - Mrp - 0.5 * dJp * w**2) / (Jp + JF)]

    w0 = float(r.omega[0])
    T = 2 * 2 * np.pi / r.omega_mean
    sol = solve_ivp(rhs, (0, T), [0.0, w0], rtol=1e-10, atol=1e-10, dense_output=True, max_step=T / 2000)
    t = np.linspace(0, T, 40001)
    p, w = sol.sol(t)
    second = p >= 2 * np.pi  # the second cycle: steady
    hi, lo = w[second].max(), w[second].min()
    got = (hi - lo) / ((hi + lo) / 2)
    assert got == pytest.approx(delta, rel=0.01)
    assert (hi + lo) / 2 == pytest.approx(r.omega_mean, rel=0.01)
    # and the speed follows the energy equation's omega(phi) all along
    assert np.max(np.abs(w[second] - np.interp(np.mod(p[second], 2 * np.pi), r.phi, r.omega))) < 1e-3 * r.omega_mean


def test_epsilon_from_equation_of_motion():
    """epsilon = d omega / dt = omega d omega / d phi."""
    phi = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    J, _, Mr = _machine(phi)
    r = flywheel(phi, Mr, J, rpm=90, delta=0.05, interpolation="spline")
    dw = np.gradient(r.omega, r.phi)
    inner = slice(5, -5)
    assert np.max(np.abs((r.omega * dw)[inner] - r.epsilon[inner])) < 1e-3 * np.max(np.abs(r.epsilon))


def test_no_flywheel_needed():
    """A large constant inertia keeps the fluctuation below delta alone: J_F = 0, needed < 0."""
    phi = np.linspace(0, 2 * np.pi, 36, endpoint=False)
    r = flywheel(phi, 10 * np.sin(phi), 1e4, rpm=100, delta=0.1)
    assert r.flywheel_inertia == 0.0 and r.needed_inertia < 0
    assert r.achieved_delta < 0.1
    assert 0.5 * (r.omega.max() + r.omega.min()) == pytest.approx(r.omega_mean, rel=1e-9)


def test_given_driving_moment():
    phi = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    Mr = 100 + 50 * np.sin(phi)
    Md = 100 + 20 * np.cos(phi)
    r = flywheel(phi, Mr, 1.0, rpm=200, delta=0.05, driving=Md, interpolation="spline")
    assert r.driving_moment == pytest.approx(100.0, rel=1e-9)
    with pytest.raises(InputError, match="flywheel.driving"):
        flywheel(phi, Mr, 1.0, rpm=200, delta=0.05, driving=Md + 1)


@pytest.mark.parametrize(
    "kw, field",
    [
        ({"delta": 0.0}, "flywheel.delta"),
        ({"delta": -0.1}, "flywheel.delta"),
        ({"delta": 1.0}, "flywheel.delta"),
        ({"rpm": 0.0}, "flywheel.rpm"),
        ({"inertia": -1.0}, "flywheel.inertia"),
        ({"phi": np.radians(np.arange(0, 361, 30.0))}, "flywheel.phi"),
        ({"phi": np.radians([0, 30, 20, 90, 120, 150, 180, 210, 240, 270, 300, 330])}, "flywheel.phi"),
        ({"resisting": np.ones(5)}, "flywheel.resisting"),
        ({"interpolation": "cubic"}, "flywheel.interpolation"),
        ({"cycle": 3 * np.pi}, "flywheel.cycle"),
        ({"cycle": 720}, "flywheel.cycle"),
    ],
)
def test_bad_input_is_one_line(kw, field):
    args = {"phi": PHI12, "resisting": MR_004, "inertia": J_004, "rpm": 77, "delta": 0.1, **kw}
    if "phi" in kw and len(kw["phi"]) != 12:
        args["resisting"], args["inertia"] = 1.0, 1.0
    with pytest.raises(InputError) as e:
        flywheel(args.pop("phi"), args.pop("resisting"), args.pop("inertia"), **args)
    assert e.value.field == field and "\n" not in str(e.value)
