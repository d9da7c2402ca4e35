"""cams.profile.flat: envelope of the face lines, curvature, face width, minimum base radius."""

from __future__ import annotations

import numpy as np
import pytest

from cams.profile.flat import oscillating_flat_face, translating_flat_face
from laws.errors import InputError
from laws.program import Phase, Program
from optimize.flat import min_base_radius_oscillating, min_base_radius_translating

N = 72_000  # uniform samples per turn for the finite differences (the phase starts fall on the grid)


def _stroke_program():
    return Program((Phase("rise", np.pi / 2, "cycloidal"), Phase("dwell", np.pi / 6),
                    Phase("return", np.pi, "poly345"), Phase("dwell", np.pi / 3)), 10.0)


def _swing_program():
    return Program((Phase("rise", np.pi / 2, "cycloidal"), Phase("dwell", np.pi / 6),
                    Phase("return", np.pi, "poly345"), Phase("dwell", np.pi / 3)), np.radians(20))


def _rot(v, a):
    c, s = np.cos(a), np.sin(a)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def _away_from_joints(prog, phi, width=1e-3):
    """Samples farther than ``width`` (radians) from every phase joint: the jerk jumps there, which
    spoils second differences by O(step * jump)."""
    starts = np.append(prog.starts[:-1], 2 * np.pi)
    return np.min(np.abs(phi[:, None] - starts[None, :]), axis=1) > width


def _fd_rho(X, h, eps):
    """Radius of curvature (positive convex) of a closed sampled curve running round in sense -eps."""
    d1 = (np.roll(X, -1, 0) - np.roll(X, 1, 0)) / (2 * h)
    d2 = (np.roll(X, -1, 0) - 2 * X + np.roll(X, 1, 0)) / h**2
    k = -eps * (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    return 1 / k, d1


@pytest.mark.parametrize("eps", [1, -1])
def test_translating_envelope_touches_every_face_line(eps):
    prog, R0, e = _stroke_program(), 25.0, 3.0
    cam = translating_flat_face(prog, base_radius=R0, cam_sense=eps, offset=e, samples=N)
    m = prog.evaluate(cam.phi)
    O = np.array([-e, -R0])
    C = O + _rot(cam.point, eps * cam.phi)  # contact point in the fixed frame
    assert np.allclose(C[:, 1], m.s, atol=1e-10)  # on the face y = s
    assert np.allclose(C[:, 0], cam.contact, atol=1e-10)
    assert np.allclose(cam.contact, -e + eps * m.ds, atol=1e-10)
    rho, d1 = _fd_rho(cam.point, 2 * np.pi / N, eps)
    # tangent to the face: the profile's tangent turned into the fixed frame is horizontal
    t = _rot(d1, eps * cam.phi)
    assert np.max(np.abs(t[:, 1]) / np.linalg.norm(t, axis=1)) < 1e-6
    assert np.allclose(cam.rho, R0 + m.s + m.d2s, atol=1e-12)
    smooth = _away_from_joints(prog, cam.phi)
    assert np.allclose(rho[smooth], cam.rho[smooth], rtol=1e-5)
    assert np.all(cam.pressure_angle == 0)
    assert cam.face_width == pytest.approx(m.ds.max() - m.ds.min(), rel=1e-6)


def test_translating_min_base_radius():
    prog = _stroke_program()
    R0, at = min_base_radius_translating(prog, min_radius=5.0)
    cam = translating_flat_face(prog, base_radius=R0, samples=N)
    assert cam.min_rho == pytest.approx(5.0, abs=1e-9) and cam.min_rho_at == pytest.approx(at)
    assert cam.rho.min() >= 5.0 - 1e-9 and cam.convex
    dense = prog.evaluate(np.linspace(0, 2 * np.pi, 400_001))
    assert R0 == pytest.approx(5.0 - np.min(dense.s + dense.d2s), abs=1e-8)
    smaller = translating_flat_face(prog, base_radius=R0 - 0.1, samples=720)
    assert smaller.min_rho == pytest.approx(4.9, abs=1e-9)
    assert not translating_flat_face(prog, base_radius=R0 - 5.5, samples=720).convex


@pytest.mark.parametrize("f,sigma,eps", [(0.0, -1, 1), (0.0, 1, -1), (8.0, -1, 1), (-5.0, 1, -1)])
def test_oscillating_envelope_touches_every_face_line(f, sigma, eps):
    prog, L, R0 = _swing_program(), 100.0, 30.0
    cam = oscillating_flat_face(prog, centre_distance=L, base_radius=R0, face_offset=f, rise_sense=sigma,
                                cam_sense=eps, samples=N)
    psi = prog.evaluate(cam.phi).s
    a0 = sigma * np.arccos((f - R0) / L)
    m = np.stack([np.cos(a0 + sigma * psi), np.sin(a0 + sigma * psi)], axis=-1)
    O = np.array([L, 0.0])
    C = O + _rot(cam.point, eps * cam.phi)
    assert np.allclose(np.sum(m * C, axis=1), f, atol=1e-10)  # on the face line
    Jm = np.stack([-m[:, 1], m[:, 0]], axis=-1)
    # from the pivot's foot along -sigma J m: positive towards the cam, the one sign of a face's contact position
    assert np.allclose(np.sum(C * (-sigma * Jm), axis=1), cam.contact, atol=1e-10)
    assert np.all(cam.contact > 0)  # the cam centre projects on that side of the foot
    # near dwell: the face touches the base circle
    assert np.linalg.norm(cam.point[0]) == pytest.approx(R0, abs=1e-12)
    assert cam.convex
    rho, d1 = _fd_rho(cam.point, 2 * np.pi / N, eps)
    t = _rot(d1, eps * cam.phi)
    assert np.max(np.abs(np.sum(t * m, axis=1)) / np.linalg.norm(t, axis=1)) < 1e-6  # tangent to the face
    smooth = _away_from_joints(prog, cam.phi)
    assert np.allclose(rho[smooth], cam.rho[smooth], rtol=1e-5)
    # pressure angle: the face normal against the velocity of the follower's point at the contact
    JC = np.stack([-C[:, 1], C[:, 0]], axis=-1)
    cross = m[:, 0] * JC[:, 1] - m[:, 1] * JC[:, 0]
    gamma = np.arctan2(np.abs(cross), np.abs(np.sum(m * JC, axis=1)))
    assert np.allclose(cam.pressure_angle, gamma, atol=1e-12)
    if f == 0:
        assert np.all(cam.pressure_angle == 0)


def test_rocker_and_cam_turning_the_same_way_give_a_cusped_cam():
    """With this geometry the face turning with the cam makes the profile non-convex: reported, not hidden."""
    cam = oscillating_flat_face(_swing_program(), centre_distance=100.0, base_radius=30.0, rise_sense=1, cam_sense=1)
    assert not cam.convex and cam.min_rho < 0 and cam.rho.min() < 0


def test_oscillating_min_base_radius():
    prog, L = _swing_program(), 100.0
    R0, at = min_base_radius_oscillating(prog, centre_distance=L, min_radius=5.0)
    cam = oscillating_flat_face(prog, centre_distance=L, base_radius=R0, samples=N)
    assert cam.min_rho == pytest.approx(5.0, abs=1e-7) and cam.min_rho_at == pytest.approx(at)
    below = oscillating_flat_face(prog, centre_distance=L, base_radius=R0 - 0.5, samples=720)
    assert below.min_rho < 5.0


def test_flat_face_bad_input():
    prog = _stroke_program()
    for kw, field in (({"base_radius": 0.0}, "base_radius"), ({"base_radius": 10.0, "cam_sense": 0}, "cam.rotation"),
                      ({"base_radius": 10.0, "samples": 3}, "samples")):
        with pytest.raises(InputError, match=field):
            translating_flat_face(prog, **kw)
    with pytest.raises(InputError, match="min_radius"):
        min_base_radius_translating(prog, min_radius=float("nan"))
    sw = _swing_program()
    with pytest.raises(InputError, match="base_radius"):
        oscillating_flat_face(sw, centre_distance=20.0, base_radius=50.0)  # |f - R0| >= L
    with pytest.raises(InputError, match="base_radius"):
        oscillating_flat_face(sw, centre_distance=100.0, base_radius=99.0)  # past the line of centres
    with pytest.raises(InputError, match="rise_direction"):
        oscillating_flat_face(sw, centre_distance=100.0, base_radius=30.0, rise_sense=2)


@pytest.mark.parametrize("rise", ["cw", "ccw"])
@pytest.mark.parametrize("f", [0.0, 7.0, -5.0])
def test_flat_rocker_in_the_rocker_frame_of_the_model(rise, f):
    """One rocker frame: turned by ``frame_turn``, the face lies along the model's rocker (``Rocker.lever``)."""
    import tomllib

    from cams.io.designfile import design_from_dict
    from cams.model.follower import Rocker
    from optimize.flat import size_flat_face
    from tests.conftest import EXAMPLES

    d = tomllib.loads((EXAMPLES / "rocker_flat.toml").read_text(encoding="utf-8"))
    d["follower"].update(rise_direction=rise, face_offset=f)
    sol = size_flat_face(design_from_dict(d))
    fo, R0 = sol.design.follower, sol.R0
    b = sol.frame_turn
    turn = np.array([[np.cos(b), np.sin(b)], [-np.sin(b), np.cos(b)]])  # R(-b): line of centres -> rocker frame
    phi = np.linspace(0.0, 2 * np.pi, 37)
    origin, direction = sol.face_line(phi)
    psi = sol.design.program.evaluate(phi).s
    lever = Rocker(arm=1.0, sense=fo.sense).lever(psi)
    assert np.allclose(direction @ turn.T, lever, atol=1e-12)  # the face turns as the model's rocker
    J = np.array([[0.0, -1.0], [1.0, 0.0]])
    assert np.allclose(origin @ turn.T, f * fo.sense * lever @ J.T, atol=1e-12)  # the pivot's foot: f m, m = sigma J d
    O = sol.rocker_frame_centre
    assert np.allclose(O, turn @ sol.centre, atol=1e-12)
    assert O == pytest.approx([np.sqrt(fo.centre_distance**2 - (f - R0) ** 2), fo.sense * (f - R0)], abs=1e-9)
    # the face touches the base circle at the near dwell: the cam centre is R0 from it, on the side opposite m
    m0 = fo.sense * J @ np.array([1.0, 0.0])
    assert f - m0 @ O == pytest.approx(R0, abs=1e-9)
