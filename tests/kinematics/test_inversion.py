"""cams.kinematics.inversion: the kernel against numerical derivatives and independent definitions.

The reference pitch curve is the definition written out here, ``P = R(-eps phi) (A(s(phi)) - O)`` from
the follower's positions alone; its derivatives are central differences, its curvature that of the sampled
polygon through three neighbouring points, its normal the perpendicular of the chord, its pressure angle the
angle between that normal (turned back into the fixed frame) and the follower's direction of rise.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.kinematics.inversion import (
    contact_normal,
    curvature,
    curvature_rate,
    invert_at,
    invert_phase,
    offset_curvature,
    offset_radius,
    outward_normal,
    pitch_phase,
    pressure_angle,
    pressure_rate,
    rise_direction,
    smallest_cam_radius,
    to_fixed_frame,
)
from cams.model.design import CamDesign, Limits
from cams.model.follower import Rocker, Translating
from laws.program import Phase, Program
from laws.registry import get_law


def _program(lift: float) -> Program:
    return Program((Phase("rise", np.radians(120), get_law("cycloidal")), Phase("dwell", np.radians(40)),
                    Phase("return", np.radians(130), get_law("poly4567")), Phase("dwell", np.radians(70))), lift)


def _design(kind: str, follower_sense: int, cam_sense: int) -> tuple[CamDesign, np.ndarray]:
    """A rocker (arm 100, swing 20 deg) or translating follower (stroke 30, offset) and a cam centre."""
    if kind == "rocker":
        f = Rocker(100.0, 10.0, sense=follower_sense)
        d = CamDesign(f, _program(np.radians(20)), Limits(np.radians(40)), cam_sense=cam_sense)
        return d, np.array([75.0, -25.0 * follower_sense])
    d = CamDesign(Translating(8.0, offset=follower_sense * 6.0), _program(30.0), Limits(np.radians(30)),
                  cam_sense=cam_sense)
    return d, np.array([follower_sense * 6.0, -40.0])


CASES = [(k, fs, cs) for k in ("rocker", "translating") for fs in (1, -1) for cs in (1, -1)]
IDS = [f"{k}-follower{fs:+d}-cam{cs:+d}" for k, fs, cs in CASES]
H = 1e-5  # step in the normalized position u


def _reference_pitch(design: CamDesign, centre: np.ndarray, phase: int, u: np.ndarray) -> np.ndarray:
    """``R(-eps phi) (A - O)`` from the follower's positions alone (no kernel)."""
    prog = design.program
    phi = prog.starts[phase] + u * prog.phases[phase].angle
    r = design.follower.position(prog.evaluate_phase(phase, u).s) - centre
    a = -design.cam_sense * phi
    c, s = np.cos(a), np.sin(a)
    return np.stack([c * r[:, 0] - s * r[:, 1], s * r[:, 0] + c * r[:, 1]], axis=-1)


def _central(f, u: np.ndarray, angle: float, h: float = H):
    """Central difference of ``f(u)`` by the cam angle (``phi = start + u angle``)."""
    return (f(u + h) - f(u - h)) / (2 * h * angle)


def _scaled_close(got, want, rel):
    scale = np.max(np.abs(want))
    assert np.allclose(got, want, rtol=0, atol=rel * scale), np.max(np.abs(got - want)) / scale


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_pitch_point_and_derivatives_against_the_definition_and_central_differences(case):
    design, O = _design(*case)
    for i, p in enumerate(design.program.phases):
        u = np.linspace(0.02, 0.98, 49)
        inv = invert_phase(design, O, i, u, third=True)
        _scaled_close(inv.point, _reference_pitch(design, O, i, u), 1e-13)
        _scaled_close(inv.d1, _central(lambda x: _reference_pitch(design, O, i, x), u, p.angle), 1e-8)
        _scaled_close(inv.d2, _central(lambda x: invert_phase(design, O, i, x).d1, u, p.angle), 1e-8)
        _scaled_close(inv.to_cam(inv.w3), _central(lambda x: invert_phase(design, O, i, x).d2, u, p.angle), 1e-8)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_signed_curvature_is_the_sampled_polygons(case):
    """Three neighbouring points span a circle of curvature ``2 (b - a) x (c - b) / (|b - a| |c - b| |c - a|)``.

    The pitch curve runs round the cam in the sense ``-eps``, so a convex piece turns in that sense:
    ``kappa = -eps`` times the polygon's signed curvature (positive convex).
    """
    design, O = _design(*case)
    eps = design.cam_sense
    h = 1e-4
    for i in range(len(design.program.phases)):
        u = np.linspace(0.02, 0.98, 49)
        a, b, c = (_reference_pitch(design, O, i, u + d) for d in (-h, 0.0, h))
        ab, bc, ac = b - a, c - b, c - a
        menger = 2 * (ab[:, 0] * bc[:, 1] - ab[:, 1] * bc[:, 0]) / (
            np.linalg.norm(ab, axis=1) * np.linalg.norm(bc, axis=1) * np.linalg.norm(ac, axis=1))
        kappa = curvature(invert_phase(design, O, i, u))
        _scaled_close(kappa, -eps * menger, 1e-6)
        assert np.allclose(pitch_phase(design, O, i, u).kappa, kappa, rtol=0, atol=0)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_outward_normal_is_the_chords_perpendicular_away_from_the_cam(case):
    design, O = _design(*case)
    eps = design.cam_sense
    for i, p in enumerate(design.program.phases):
        u = np.linspace(0.02, 0.98, 49)
        inv = invert_phase(design, O, i, u)
        n = outward_normal(inv)
        chord = _central(lambda x: _reference_pitch(design, O, i, x), u, p.angle)
        t = chord / np.linalg.norm(chord, axis=1)[:, None]
        assert np.allclose(np.linalg.norm(n, axis=1), 1.0, atol=1e-15)
        assert np.allclose(n, eps * np.stack([-t[:, 1], t[:, 0]], axis=-1), atol=1e-8)
        if p.kind == "dwell":  # a circle about the cam centre: the normal points away from it
            P = inv.point
            assert np.allclose(n, P / np.linalg.norm(P, axis=1)[:, None], atol=1e-13)
            assert np.allclose(1 / curvature(inv), np.linalg.norm(P, axis=1), rtol=1e-13)
        # in the fixed frame: the same vector turned by R(eps phi)
        assert np.allclose(to_fixed_frame(n, np.zeros(2), eps, inv.phi), contact_normal(inv), atol=1e-15)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_pressure_angle_from_the_chords_normal_and_the_direction_of_rise(case):
    design, O = _design(*case)
    eps = design.cam_sense
    prog = design.program
    for i, p in enumerate(prog.phases):
        u = np.linspace(0.0, 1.0, 51)
        inv = invert_phase(design, O, i, u)
        uu = np.clip(u, H, 1 - H)
        chord = _central(lambda x: _reference_pitch(design, O, i, x), uu, p.angle)
        phi = prog.starts[i] + uu * p.angle
        n_cam = eps * np.stack([-chord[:, 1], chord[:, 0]], axis=-1)
        a = eps * phi
        c, s = np.cos(a), np.sin(a)
        n = np.stack([c * n_cam[:, 0] - s * n_cam[:, 1], s * n_cam[:, 0] + c * n_cam[:, 1]], axis=-1)
        T = design.follower.tangent(prog.evaluate_phase(i, uu).s)
        ref = np.arctan2(np.abs(n[:, 0] * T[:, 1] - n[:, 1] * T[:, 0]), np.sum(n * T, axis=1))
        got = pressure_angle(inv)
        inner = (u > 0) & (u < 1)
        assert np.allclose(got[inner], ref[inner], atol=1e-8)
        assert np.allclose(got, ref, atol=1e-4)  # the ends: the chord is a step inside
        assert np.all((got >= 0) & (got <= np.pi))
        T = design.follower.tangent(prog.evaluate_phase(i, u).s)
        assert np.allclose(rise_direction(inv), T / np.linalg.norm(T, axis=1)[:, None], rtol=0, atol=1e-15)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_rates_are_the_derivatives_of_the_values(case):
    design, O = _design(*case)
    for i, p in enumerate(design.program.phases):
        if p.kind == "dwell":
            continue
        u = np.linspace(0.03, 0.97, 60)
        inv = invert_phase(design, O, i, u, third=True)
        g, dg = pressure_rate(inv)
        k, dk = curvature_rate(inv)
        assert np.array_equal(g, pressure_angle(inv)) and np.array_equal(k, curvature(inv))
        num_g = _central(lambda x: pressure_angle(invert_phase(design, O, i, x)), u, p.angle, 1e-6)
        num_k = _central(lambda x: curvature(invert_phase(design, O, i, x)), u, p.angle, 1e-6)
        smooth = g > 1e-3  # |alpha| has a kink where the angle passes 0
        assert np.allclose(dg[smooth], num_g[smooth], rtol=1e-5, atol=1e-6 * np.abs(dg).max())
        assert np.allclose(dk, num_k, rtol=1e-5, atol=1e-6 * np.abs(dk).max())


def test_curvature_rate_needs_the_third_derivative():
    design, O = _design("rocker", 1, 1)
    with pytest.raises(ValueError, match="third"):
        curvature_rate(invert_phase(design, O, 0, np.array([0.5])))


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_the_cam_frame_placed_back_at_its_angle_is_the_roller_centre(case):
    """``O + R(eps phi) P(phi) = A(phi)``: the two frames of the inversion agree at every cam angle."""
    design, O = _design(*case)
    phi = np.linspace(0.0, 2 * np.pi, 97)
    inv = invert_at(design, O, phi)
    A = design.follower.position(design.program.evaluate(phi).s)
    assert np.allclose(to_fixed_frame(inv.point, O, design.cam_sense, phi), A, rtol=0, atol=1e-12 * design.scale)


def test_offset_curve_radius_and_curvature_are_reciprocal():
    kappa = np.array([0.05, -0.02, 1e-9, 0.1])
    for d in (-8.0, 8.0):
        assert np.allclose(offset_curvature(kappa, d), 1.0 / offset_radius(1.0 / kappa, d), rtol=1e-12)


@pytest.mark.parametrize("case", CASES, ids=IDS)
def test_smallest_cam_radius_against_a_dense_scan(case):
    design, O = _design(*case)
    r, at = smallest_cam_radius(design, O)
    phi = np.linspace(0.0, 2 * np.pi, 400_001)
    d = np.linalg.norm(design.follower.position(design.program.evaluate(phi).s) - O, axis=1)
    k = int(np.argmin(d))
    roller = design.follower.roller_radius
    assert d[k] - roller - 1e-9 * design.scale <= r <= d[k] - roller + 1e-12 * design.scale
    A = design.follower.position(design.program.evaluate(np.array([at])).s)[0]
    assert np.linalg.norm(A - O) - roller == pytest.approx(r, abs=1e-12 * design.scale)
