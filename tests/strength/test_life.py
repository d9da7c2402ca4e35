"""The roller bearing's life: ISO 281 at constant load, and the variable load's mean weighted by the roller's
revolutions, against a brute-force count of the roller's turns on its pin along a finely stepped pitch curve."""

from __future__ import annotations

import numpy as np
import pytest

from cams.cam import Cam
from cams.io.designfile import load_design
from cams.strength import life
from tests.conftest import EXAMPLES


def test_iso_281_at_constant_load():
    """C/P = 2 gives 2^(10/3) = 10.079 million revolutions (roller bearings' exponent 10/3)."""
    assert float(life.rating_life(2.0, 1.0)) == pytest.approx(10.0794, abs=5e-5)
    assert life.EXPONENT == 10 / 3
    # constant load: the mean is the load, whatever the weights
    assert life.mean_load([500.0, 500.0, 500.0], [1.0, 7.0, 0.5]) == pytest.approx(500.0)
    # hours: 10.079e6 revolutions at 2 roller turns per cam turn and 100 rpm
    assert life.life_hours(2.0, [1.0], [1.0], 2.0, 100.0) == pytest.approx(2 ** (10 / 3) * 1e6 / (200 * 60))


def _brute_force_turns(design, centre, phi):
    """The roller's turns relative to its pin between the fine cam angles ``phi``: along the pitch curve's chords in
    the cam frame the roller rolls (-eps chord / r), the cam turns (eps dphi) and the arm turns (its angle from the
    pivot, read off the roller centre's positions)."""
    from cams.kinematics.inversion import pitch_curve

    f, eps = design.follower, design.cam_sense
    P = pitch_curve(design, centre, phi).point
    chord = np.linalg.norm(np.diff(P, axis=0), axis=1)
    if f.kind == "rocker":  # the arm's angle about its pivot; a translating follower's pin does not turn
        A = f.position(design.program.evaluate(phi).s) - f.pivot
        beta = np.unwrap(np.arctan2(A[:, 1], A[:, 0]))
    else:
        beta = np.zeros_like(phi)
    return (-eps * chord / f.roller_radius + eps * np.diff(phi) - np.diff(beta)) / (2 * np.pi)


@pytest.mark.parametrize("name", ["translating_contact.toml", "rocker_contact.toml"])
def test_the_mean_load_is_weighted_by_the_roller_s_revolutions(name):
    cam = Cam(load_design(EXAMPLES / name))
    co = cam.contact
    fo = cam.forces.forces
    n = len(co.phi)
    fine = np.linspace(0.0, 2 * np.pi, 200 * n + 1)
    turns = np.abs(_brute_force_turns(cam.design, cam.solution.centre, fine))
    # the load over each fine step: the pipeline's sample it falls in (the rigid force is sampled at co.phi)
    k = np.minimum(((fine[:-1] + 0.5 * np.diff(fine)) / (2 * np.pi) * n + 0.5).astype(int) % n, n - 1)
    load = np.maximum(fo.contact, 0.0)[k]
    per_turn = turns.sum()
    assert co.roller_turns_per_rev == pytest.approx(per_turn, rel=1e-4)
    p = 10 / 3
    Pm = (np.sum(load**p * turns) / per_turn) ** (1 / p)
    hours = (cam.design.contact.bearing_rating / Pm) ** p * 1e6 / (per_turn * cam.design.rpm * 60)
    assert co.life_hours == pytest.approx(hours, rel=2e-3)
    # weighted by cam angle instead: 5 % off on the translating example (its load varies; the roller turns slowest
    # on the base circle); the rocker's load is nearly constant (its large working moment): the weights hardly matter
    by_angle = (
        (cam.design.contact.bearing_rating / (np.mean(load**p)) ** (1 / p)) ** p
        * 1e6
        / (per_turn * cam.design.rpm * 60)
    )
    assert abs(by_angle / hours - 1) > (0.04 if name.startswith("translating") else 0.0)


def test_a_rocker_s_arm_turns_with_the_roller():
    """On a rocker the roller's pin swings with the arm: the turns relative to the pin, not to the frame, wear the
    bearing. Over a whole turn the arm comes back (the totals agree), but over the rise they differ by the swing."""
    cam = Cam(load_design(EXAMPLES / "rocker_contact.toml"))
    fine = np.linspace(0.0, 2 * np.pi, 100001)
    steps = _brute_force_turns(cam.design, cam.solution.centre, fine)
    assert cam.contact.roller_turns_per_rev == pytest.approx(np.abs(steps).sum(), rel=1e-4)
    from cams.kinematics.inversion import pitch_curve

    P = pitch_curve(cam.design, cam.solution.centre, fine).point
    chord = np.linalg.norm(np.diff(P, axis=0), axis=1)
    frame = (
        -cam.design.cam_sense * chord / cam.design.follower.roller_radius + cam.design.cam_sense * np.diff(fine)
    ) / (2 * np.pi)
    rise = fine[:-1] < np.radians(120)
    swing = np.radians(15) / (2 * np.pi)
    assert abs(np.abs(frame[rise]).sum() - np.abs(steps[rise]).sum()) == pytest.approx(swing, rel=1e-6)
