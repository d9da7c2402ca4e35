"""Seed figures not covered by ``test_seeds.py``: plan segments found by similarity, and the seeds' numbered positions.

Sources: the seeds (named and described in docs/files.md, "The seeds"); the table of every seed figure
with our value is docs/seeds.md.

* seed 000 ("Силовой анализ плоского рычажного механизма"), sections "План скоростей
  механизма" and "План ускорений механизма", phi_1 = 60 deg, omega_1 = 200 rad/s:
  segments found on the plans by the similarity of plans (свойство подобия планов)
  and the segments they come from,

  - velocity plan (mu_v = 0.4 (m/s)/mm): ab = 12 mm, as2 = 4 mm; cd = 20 mm, cs4 = 6.6 mm;
  - acceleration plan (mu_a = 50 (m/s^2)/mm): ab = 33 mm, as2 = 11 mm; cd = 18 mm, cs4 = 6 mm.

  ab and cd are read on the plan; as2 and cs4 are computed from them as 1/3 of the
  segment (l_AS2 / l_AB = 64 / 192). The values of ab (velocity) and cd (velocity) as
  speeds (4.8, 8.0 m/s) are tested in ``test_seeds.py``; here the relative velocities
  and accelerations of S2, S4 and the acceleration plan's ab, cd are.
  Tolerance: the seeds accept 5-10 % between graphical plans and analysis (seed 002,
  section 2.2: "не должны отличаться ... более чем на (5…10)%"); seed 000 reads its
  plans in whole millimetres, so a read segment also carries +-0.5 mm (a segment
  computed from it by similarity: +-0.5/3 mm). The test allows 10 % plus that reading.
* seed 003 (插床), section 二.2 step 2): position 1 = the tool's lower limit, the crank
  circle divided into 12 from it in the crank's sense, "位置5对应于滑块5处于上极限位置"
  (position 5 is the upper limit), and 5', 12' the start and end of the cut.
* seed 004, section 1.13 (program input): the reduced moments Mr and inertias J of the
  12 positions, position 1 being the dead position where the working stroke starts
  (section 1.4: "За нулевое положение принимаем крайнее положение, с которого
  начинается рабочий ход").

Units: SI for seed 000 (as the seed), mm for the machine files of seeds 003 and 004.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from cams.machine.linkage import analyse
from cams.machine.linkage.machines import OpposedTwin
from cams.machine.machinefile import load_machine
from cams.machine.timing import windows

ROOT = Path(__file__).resolve().parents[3]
SLOTTING_FILE = ROOT / "examples" / "machines" / "slotting_machine.toml"
PUMP_FILE = ROOT / "examples" / "machines" / "pump.toml"

SEED_TOL = 0.10  # seed 002, 2.2: graphical and analytic kinematics within 5-10 %

# -- seed 000 ------------------------------------------------------------------------
ENGINE = OpposedTwin(crank=0.048, rod=0.192, rod_cg=0.064, rpm=200 * 60 / (2 * np.pi))
K000 = ENGINE.kinematics(np.radians(60.0))
MU_V, MU_A = 0.4, 50.0  # seed 000's plan scales

# (quantity, seed segment in mm, plan scale, reading of the segment in mm, computed value)
SEGMENTS_000 = [
    ("V_S2A (as2 = 4 mm)", 4.0, MU_V, 0.5 / 3, np.abs(K000.S2.vel - K000.A.vel)),
    ("V_S4C (cs4 = 6.6 mm)", 6.6, MU_V, 0.5 / 3, np.abs(K000.S4.vel - K000.C.vel)),
    ("a_BA (ab = 33 mm)", 33.0, MU_A, 0.5, np.abs(K000.B.acc - K000.A.acc)),
    ("a_S2A (as2 = 11 mm)", 11.0, MU_A, 0.5 / 3, np.abs(K000.S2.acc - K000.A.acc)),
    ("a_DC (cd = 18 mm)", 18.0, MU_A, 0.5, np.abs(K000.D.acc - K000.C.acc)),
    ("a_S4C (cs4 = 6 mm)", 6.0, MU_A, 0.5 / 3, np.abs(K000.S4.acc - K000.C.acc)),
]


@pytest.mark.parametrize("name, mm, mu, reading, computed", SEGMENTS_000, ids=[r[0] for r in SEGMENTS_000])
def test_seed_000_similar_segments(name, mm, mu, reading, computed):
    """Seed 000's plan segments: within the seeds' 10 % plus the plan's reading."""
    seed = mm * mu
    assert abs(float(computed) - seed) <= SEED_TOL * seed + reading * mu


def test_seed_000_similarity_is_exact():
    """The similarity the seed uses (as2 / ab = AS2 / AB = 1/3) holds exactly for velocities and accelerations."""
    k = K000
    for P, Q, S in ((k.A, k.B, k.S2), (k.C, k.D, k.S4)):
        assert np.abs(S.vel - P.vel) == pytest.approx(np.abs(Q.vel - P.vel) / 3, rel=1e-12)
        assert np.abs(S.acc - P.acc) == pytest.approx(np.abs(Q.acc - P.acc) / 3, rel=1e-12)
        # and the image s lies on the segment ab of the plan
        assert np.abs((S.vel - P.vel) - (Q.vel - P.vel) / 3) < 1e-12 * np.abs(Q.vel)
        assert np.abs((S.acc - P.acc) - (Q.acc - P.acc) / 3) < 1e-12 * np.abs(Q.acc)


def test_seed_000_relative_acceleration_components():
    """a_BA = a^n + a^t with a^n = omega_2^2 l_AB along BA: the seed's ab^2 = an1^2 + n1b^2 (33 vs 2.4 and 32 mm)."""
    k = K000
    for P, Q, rod in ((k.A, k.B, k.rod2), (k.C, k.D, k.rod4)):
        rel = np.abs(Q.acc - P.acc)
        an, at = rod.omega**2 * 0.192, np.abs(rod.alpha) * 0.192
        assert rel == pytest.approx(np.hypot(an, at), rel=1e-12)
    # the seed's own numbers hold together to its reading: hypot(2.4, 32) = 32.1 mm vs ab = 33 mm,
    # hypot(6.6, 17) = 18.2 mm vs cd = 18 mm
    assert np.hypot(2.4, 32.0) == pytest.approx(33.0, abs=1.0)
    assert np.hypot(6.6, 17.0) == pytest.approx(18.0, abs=0.5)


# -- seed 003 ------------------------------------------------------------------------
def test_seed_003_position_5_is_the_upper_limit():
    """Seed 003: from position 1 (lower limit) the upper limit is position 5, i.e. 4 x 30 = 120 deg: K = 240/120 = 2.

    The machine file holds the typical course data (K = 2; the seed's table 1-1 is empty).
    The cut's start 5' and end 12' fall between positions 5 and 6, and 12 and 1.
    """
    spec = load_machine(SLOTTING_FILE)
    m = spec.linkage
    win = windows(m, spec.cutting)
    c = np.radians(np.arange(12) * 30.0)  # positions 1..12 as cycle angles
    y = m.output(win.frame_angle(c)).s
    assert int(np.argmin(y)) == 0 and int(np.argmax(y)) == 4  # position 1 lowest, position 5 highest
    assert np.degrees(win.working_start) == pytest.approx(120.0, abs=1e-9)  # upper limit exactly at position 5
    assert np.all(np.diff(y[:5]) > 0) and np.all(np.diff(y[4:]) < 0)  # up 1 -> 5 (return), down 5 -> 1 (cut)
    assert 120.0 < np.degrees(win.cut_start) < 150.0  # 5'
    assert 330.0 < np.degrees(win.cut_end) < 360.0  # 12'


# -- seed 004 ------------------------------------------------------------------------
MR_004 = np.array([0, 245.8, 230, 244.4, 230.6, 239.3, 227.6, 164.2, 0, 0.7, 34.3, -1.6])  # N m, section 1.13
J_004 = np.array([112, 125.4, 123.3, 125, 124, 124.1, 122.1, 117.5, 112, 147, 150, 151.9])  # kg m^2


def test_seed_004_dead_positions_are_positions_1_and_9():
    """Seed 004's tables: Mr = 0 and J at its least (112) exactly at positions 1 and 9 -- the dead positions.

    K = 2 gives a 240 deg working stroke = 8 steps of 30 deg: positions 1 -> 9 (Mr 164-246 N m),
    the idle stroke 9 -> 1 (Mr <= 34.3 N m). Our pump stops its piston and lever exactly there.
    """
    m = load_machine(PUMP_FILE).linkage
    rep = analyse(m)
    phi = rep.start + m.crank_sense * np.radians(np.arange(12) * 30.0)  # positions 1..12
    k = m.kinematics(phi, omega=m.crank_sense * 1.0)
    stopped = np.isclose(k.piston.ds, 0.0, atol=1e-9 * rep.stroke) & np.isclose(k.lever.omega, 0.0, atol=1e-12)
    assert list(np.flatnonzero(stopped)) == [0, 8]
    assert list(np.flatnonzero(MR_004 == 0)) == [0, 8]
    assert list(np.flatnonzero(J_004 == J_004.min())) == [0, 8]
    assert np.degrees(rep.working_span) == pytest.approx(240.0, abs=1e-9)
    working = np.arange(1, 8)  # positions 2..8
    idle = np.arange(9, 12)  # positions 10..12
    # the piston moves toward its working end on positions 2..8 and back on 10..12
    assert np.all(np.sign(k.piston.ds[working]) == rep.direction)
    assert np.all(np.sign(k.piston.ds[idle]) == -rep.direction)
    assert MR_004[working].min() > 150 > 40 > np.abs(MR_004[idle]).max()
