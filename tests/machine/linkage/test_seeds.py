"""The seeds' numbers, recomputed.

Sources (the seeds, named and described in docs/files.md, "The seeds"):

* seed 000 -- "Силовой анализ плоского рычажного механизма", two-cylinder engine
  mechanism: l_OA = l_OC = 0.048 m, l_AB = l_CD = 0.192 m, l_AS2 = l_CS4 = 0.064 m,
  omega_1 = 200 rad/s, phi_1 = 60 deg, OC perpendicular to OA, both pistons on the x axis
  (left and right cylinders). Its values come from velocity and acceleration plans drawn
  at mu_v = 0.4 (m/s)/mm and mu_a = 50 (m/s^2)/mm, i.e. read to about half a millimetre.
* seed 002 -- Kazan 2008 course manual, central crank-slider: stroke 0.35 m, rod 1.4 m,
  n = 120 rev/min, design position phi = 315 deg, slider right of O (F = -1); the seed
  accepts 5-10 % between its graphical and analytic results and reports <= 3 %.
  Its analytic values and all acceleration values were lost in the text (formulas were
  images); what survives is compared here.
* seed 004 -- pump with a swinging slotted lever: K = 2, H = 250 mm, O1O2 = 525 mm,
  n = 77 rev/min.
* seed 003 (插床) has no numbers: its table 1-1 of design data is empty in the text.

Units: SI as in the seeds (m, m/s, m/s^2, rad/s, rad/s^2).
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.machine.linkage import analyse
from cams.machine.linkage.machines import CrankSlider, OpposedTwin, SlottedLeverPump

SEED_TOL = 0.10  # the seeds accept 3-10 % between graphical plans and analysis

# -- seed 000 ------------------------------------------------------------------------
ENGINE = OpposedTwin(crank=0.048, rod=0.192, rod_cg=0.064, rpm=200 * 60 / (2 * np.pi))
K000 = ENGINE.kinematics(np.radians(60.0))

SEED_000 = [
    # (quantity, seed value, computed)
    ("V_A", 9.6, K000.A.speed),
    ("a_A", 1920.0, K000.A.accel),
    ("V_B", 8.8, K000.B.speed),
    ("V_D", 6.0, K000.D.speed),
    ("V_S2", 8.8, K000.S2.speed),
    ("V_S4", 7.2, K000.S4.speed),
    ("V_BA", 4.8, np.abs(K000.B.vel - K000.A.vel)),
    ("V_DC", 8.0, np.abs(K000.D.vel - K000.C.vel)),
    ("omega_2", 25.0, np.abs(K000.rod2.omega)),
    ("omega_4", 41.0, np.abs(K000.rod4.omega)),
    ("a_n_BA", 120.0, K000.rod2.omega**2 * 0.192),
    ("a_n_DC", 333.0, K000.rod4.omega**2 * 0.192),
    ("a_B", 750.0, K000.B.accel),
    ("a_D", 1800.0, K000.D.accel),
    ("a_S2", 1400.0, K000.S2.accel),
    ("a_S4", 1750.0, K000.S4.accel),
    ("a_t_BA", 1600.0, np.abs(K000.rod2.alpha) * 0.192),
    ("a_t_DC", 850.0, np.abs(K000.rod4.alpha) * 0.192),
    ("epsilon_2", 8333.0, np.abs(K000.rod2.alpha)),
    ("epsilon_4", 4427.0, np.abs(K000.rod4.alpha)),
]


@pytest.mark.parametrize("name, seed, computed", SEED_000, ids=[r[0] for r in SEED_000])
def test_seed_000_plans(name, seed, computed):
    assert float(computed) == pytest.approx(seed, rel=SEED_TOL)


def test_seed_000_stroke():
    """h = 2 l_OA = 0.096 m for both pistons."""
    assert analyse(ENGINE).stroke == pytest.approx(0.096, rel=1e-12)


def test_seed_000_pin_C_leads_A():
    """OC at -90 deg from OA would give V_D = 3.75 m/s, far from the seed's 6.0: the seed's C leads A."""
    other = OpposedTwin(crank=0.048, rod=0.192, rod_cg=0.064, phase=-np.pi / 2, rpm=ENGINE.rpm)
    assert abs(float(other.kinematics(np.radians(60.0)).D.speed) - 6.0) / 6.0 > 0.3


# -- seed 002 ------------------------------------------------------------------------
SLIDER = CrankSlider.from_stroke(0.35, 1.4, rpm=120)
K002 = SLIDER.kinematics(np.radians(315.0))
MU_V = 2.2 / 66  # seed: V_A ~ 2.2 m/s drawn as 66 mm


def test_seed_002_synthesis():
    """Formulas 1.1-1.4: l_OA = 0.175 m, x_B max 1.575 m, min 1.225 m, mean 1.4 m."""
    assert SLIDER.crank == pytest.approx(0.175, rel=1e-15)
    far, near = SLIDER.extreme_positions
    assert (far, near) == pytest.approx((1.575, 1.225), rel=1e-12)
    assert (far + near) / 2 == pytest.approx(1.4, rel=1e-12)
    assert analyse(SLIDER).stroke == pytest.approx(0.35, rel=1e-12)


def test_seed_002_velocities_at_315():
    """V_A = 12.56 * 0.175 = 2.198 m/s; plan: pb = 51 mm -> V_B = 1.7 m/s (positive), ab = 47 mm; omega_2 clockwise."""
    assert float(K002.A.speed) == pytest.approx(2.198, rel=2e-3)
    assert float(K002.B.vel.real) == pytest.approx(1.7, rel=0.03)
    v_ba = float(np.abs(K002.B.vel - K002.A.vel))
    assert v_ba == pytest.approx(47 * MU_V, rel=0.03)
    assert float(K002.rod.omega) == pytest.approx(-47 * MU_V / 1.4, rel=0.03)  # clockwise: negative


def test_seed_002_acceleration_signs_at_315():
    """a_A = omega^2 l_OA; a_B toward -x (negative); epsilon_2 clockwise (negative)."""
    assert float(K002.A.accel) == pytest.approx((4 * np.pi) ** 2 * 0.175, rel=1e-12)
    assert float(K002.B.acc.real) < 0
    assert float(K002.rod.alpha) < 0


def test_seed_002_working_stroke():
    """Slider right of O: the working stroke (away from O) runs from 180 to 360 deg of crank angle."""
    rep = analyse(SLIDER, working="forward")
    assert np.degrees([rep.start, rep.end]) == pytest.approx([180.0, 0.0], abs=1e-9)


# -- seed 004 ------------------------------------------------------------------------
def test_seed_004_synthesis():
    """theta = 60 deg, O1A = 525 * 0.5 = 262.5 mm, V_A = 8.06 * 0.262 = 2.12 m/s.

    The seed writes O2C = H * 0.5 = 125 mm; the chord of C's arc equals the stroke only
    with O2C = H / (2 sin 30 deg) = 250 mm, which the computed stroke confirms.
    """
    m = SlottedLeverPump.from_course(2.0, 250.0, 525.0, rpm=77)
    assert np.degrees(m.synthesis.swing) == pytest.approx(60.0, rel=1e-12)
    assert m.crank == pytest.approx(262.5, rel=1e-12)
    assert abs(m.omega) == pytest.approx(8.06, rel=1e-3)
    assert float(m.kinematics(np.array([0.0])).A.speed[0]) / 1000 == pytest.approx(2.12, rel=0.01)
    rep = analyse(m)
    assert rep.stroke == pytest.approx(250.0, rel=1e-12)
    assert m.lever == pytest.approx(250.0, rel=1e-12)
    assert rep.time_ratio == pytest.approx(2.0, rel=1e-12)
