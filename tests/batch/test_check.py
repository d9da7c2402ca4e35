"""The batch check's corner test at the phase joints (:func:`cams.batch.check.check_group`'s ``joint``, the one
test of a velocity jump's corner) against the pitch curve's one-sided directions by finite differences of its
definition ``P(phi) = R(-eps phi) (A(s(phi)) - O)``: no velocity, no normal of the inversion.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.batch import size_batch
from cams.batch.check import JOINT, GroupCheck, check_group
from cams.cam import Cam
from cams.io.designfile import design_from_dict
from tests.conftest import rocker_dict

#: The cam angle step of the one-sided differences (rad): their directions are off by some h times the
#: curvature times the length, far below the tolerance.
H = 1e-6


def _pitch(design, centre, i: int, u: float) -> np.ndarray:
    """The pitch point of phase ``i`` at its normalized position ``u`` (cam frame), from its definition."""
    prog = design.program
    s = prog.evaluate_phase(i, np.array([u])).s
    A = design.follower.position(s)[0]
    phi = prog.starts[i] + u * prog.phases[i].angle
    eps = design.cam_sense
    c, sn = np.cos(phi), np.sin(phi)
    r = A - centre
    return np.array([c * r[0] + eps * sn * r[1], -eps * sn * r[0] + c * r[1]])


def _largest_turn(design, centre) -> float:
    """The largest angle between the pitch curve's directions just before and just after a phase joint."""
    prog = design.program
    n = len(prog.phases)
    worst = 0.0
    for i in range(n):
        j = (i + 1) % n
        ha, hb = H / prog.phases[i].angle, H / prog.phases[j].angle
        before = _pitch(design, centre, i, 1.0) - _pitch(design, centre, i, 1.0 - ha)
        after = _pitch(design, centre, j, hb) - _pitch(design, centre, j, 0.0)
        cos = before @ after / (np.linalg.norm(before) * np.linalg.norm(after))
        worst = max(worst, float(np.arccos(np.clip(cos, -1.0, 1.0))))
    return worst


@pytest.fixture(scope="module")
def centres():
    """The example's sized centre and two farther out along its direction (fixed frame, mm)."""
    c = np.asarray(Cam(design_from_dict(rocker_dict())).solution.centre)
    return np.array([c, 1.1 * c, 1.25 * c])


LINEAR = [
    {"phase": "rise", "law": "linear", "angle": 120},
    {"phase": "return", "law": "cycloidal", "angle": 120},
    {"phase": "dwell"},
]


def test_a_velocity_jump_is_a_corner_of_the_size_the_pitch_curve_turns(centres):
    d = design_from_dict(rocker_dict(motion=LINEAR))
    chk = check_group([d] * len(centres), centres, d.program)
    fd = np.array([_largest_turn(d, c) for c in centres])
    assert np.all(fd > 0.05)  # a corner: the linear rise's velocity jumps at both its ends
    np.testing.assert_allclose(chk.joint, fd, atol=1e-5)
    # every cam of the chunk has a corner: sent back before the rest is checked (nothing else computed)
    others = [k for k in GroupCheck.__dataclass_fields__ if k != "joint"]
    assert all(np.isnan(getattr(chk, k)).all() for k in others)
    assert size_batch([d]) == [None]


def test_smooth_joints_have_no_corner(centres):
    d = design_from_dict(rocker_dict())
    chk = check_group([d] * len(centres), centres, d.program)
    fd = np.array([_largest_turn(d, c) for c in centres])
    assert np.all(fd < 1e-5)
    assert np.all(chk.joint <= JOINT)
    assert np.all(np.isfinite(chk.rise))  # the whole check ran


def test_a_corner_in_some_cams_of_a_chunk_sends_back_those_only(monkeypatch):
    """Only some cams of a chunk with a corner: the whole check runs (no field is NaN), so the joint test alone must
    send the cornered cam back (a chunk whose every cam has one is all NaN, rejected by every test). The check's
    own fields, one cam's ``joint`` raised to 1e-6 rad, 1000 :data:`JOINT` (a velocity jump of some 1e-6 of the
    roller's speed relative to the cam: no other test of the batch notices it)."""
    from dataclasses import replace

    import cams.batch.check

    designs = [design_from_dict(rocker_dict(limits={"pressure_angle": a})) for a in (35, 40, 45)]
    plain = size_batch(designs)
    assert all(r is not None for r in plain)
    real = cams.batch.check.check_group

    def one_corner(group, centres, program):
        chk = real(group, centres, program)
        assert len(group) == 3 and all(np.isfinite(getattr(chk, k)).all() for k in ("rise", "ret", "convex"))
        joint = chk.joint.copy()
        joint[1] = 1e-6
        assert joint[1] > JOINT and np.all(np.delete(joint, 1) <= JOINT)
        return replace(chk, joint=joint)

    monkeypatch.setattr(cams.batch.check, "check_group", one_corner)
    assert size_batch(designs) == [plain[0], None, plain[2]]
