"""The zone's wedges against the pressure-angle definition (cams.verify.pressure)."""

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.verify.pressure import pressure_angle
from optimize.zone import max_violation, phase_wedges
from tests.conftest import rocker_dict


@pytest.mark.parametrize("rise_dir", ["cw", "ccw"])
@pytest.mark.parametrize("rotation", ["cw", "ccw"])
def test_wedge_membership_equals_pressure_angle_within_limit(rise_dir, rotation):
    """A centre is inside the wedge of a position iff its pressure angle there is <= the limit."""
    d = design_from_dict(rocker_dict(follower={"rise_direction": rise_dir}, cam={"rotation": rotation}))
    lim = d.limits.pressure_angle
    u = np.linspace(0, 1, 41)
    w = phase_wedges(d, 0, lim, u)
    rng = np.random.default_rng(1)
    centres = rng.uniform(-60, 60, (400, 2)) + np.array([125.0, 0.0])
    for O in centres:
        inside = np.all(w.violation(O) <= 0, axis=1)
        gamma = pressure_angle(d, O, 0, u)
        # skip positions within round-off of the boundary
        clear = np.abs(gamma - lim) > 1e-9
        assert np.array_equal(inside[clear], (gamma <= lim)[clear])


def test_safety_factor_moves_lines_into_the_zone():
    """K_C > 1 shrinks every wedge (seed 3.26): offsets decrease along each normal."""
    base = design_from_dict(rocker_dict(limits={"closure": "form"}))
    kc = design_from_dict(rocker_dict(limits={"closure": "form", "safety_factor": 1.3}))
    u = np.linspace(0, 1, 11)
    for i in (0, 2):
        a = phase_wedges(base, i, base.limits.pressure_angle, u)
        b = phase_wedges(kc, i, kc.limits.pressure_angle, u)
        assert np.allclose(a.normals, b.normals)
        shift = a.offsets - b.offsets
        # side t moves by (K-1) l sin(gamma) along its normal, side t1 by (1-1/K) l sin(gamma)
        s = np.sin(base.limits.pressure_angle)
        assert np.allclose(shift[:, 0], 0.3 * 125 * s)
        assert np.allclose(shift[:, 1], (1 - 1 / 1.3) * 125 * s)


def test_seed_sense_instant_point_is_l_times_one_plus_psi_prime():
    """Seed 001: for opposite senses O1D = l (1 + psi')."""
    d = design_from_dict(rocker_dict())
    u = np.linspace(0, 1, 9)
    w = phase_wedges(d, 0, d.limits.pressure_angle, u)
    m = d.program.evaluate_phase(0, u)
    r = np.linalg.norm(w.apex[:, 0], axis=1)
    assert np.allclose(r, 125 * (1 + m.ds))


def test_max_violation_finds_continuous_maximum():
    """The refined peak equals a dense brute-force maximum of the same function."""
    d = design_from_dict(rocker_dict(limits={"closure": "form"}))
    O = np.array([127.0, 14.0])
    peaks = max_violation(d, O)
    best = -np.inf
    for i, lim in d.constrained_phases():
        u = np.linspace(0, 1, 200001)
        best = max(best, np.max(phase_wedges(d, i, lim, u).violation(O)))
    assert peaks[0].value == pytest.approx(best, abs=1e-9)
    assert peaks[0].value >= best - 1e-12
