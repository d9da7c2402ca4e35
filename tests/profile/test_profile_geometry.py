"""cams.profile.roller: pitch curve by inversion, working profile, curvature, adaptive sampling."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString

from cams.kinematics.inversion import offset_radius, pitch_curve, pitch_phase
from cams.model.design import CamDesign
from cams.model.follower import Rocker
from cams.model.options import ProfileOptions, profile_options
from cams.profile.roller import build_profile, default_bore_radius
from laws.errors import InputError

ALL = ("rocker_force", "rocker_form", "translating_force", "translating_form_centric")

def _rot(v, a):
    c, s = np.cos(a), np.sin(a)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)

def _mirrored(design: CamDesign) -> tuple[CamDesign, np.ndarray]:
    """The same mechanism reflected so that the follower maps onto itself; the cam's sense flips.

    A rocker is reflected in the X axis (along the rocker: its sense flips too),
    a translating follower in the Y axis (its axis of motion).
    """
    f = design.follower
    if isinstance(f, Rocker):
        return design.with_(follower=Rocker(f.arm, f.roller_radius, sense=-f.sense),
                            cam_sense=-design.cam_sense), np.array([1.0, -1.0])
    return design.with_(cam_sense=-design.cam_sense), np.array([-1.0, 1.0])

@pytest.mark.parametrize("name", ALL)
def test_pitch_curve_drives_the_follower(solved, name):
    """Rotating P(phi) back by +eps phi about O reproduces the roller centre A(s(phi)) (1e-9 of arm/stroke)."""
    design, O = solved[name]
    f = design.follower
    prof = build_profile(design, O)
    phi = prof.phi
    A = _rot(prof.pitch, design.cam_sense * phi) + O
    s = design.program.evaluate(phi).s
    assert np.max(np.linalg.norm(A - f.position(s), axis=1)) < 1e-9 * design.scale
    if isinstance(f, Rocker):
        # recover the swing from the point's angle about the pivot, and the arm from its distance
        psi = f.sense * np.arctan2(A[:, 1], A[:, 0])
        assert np.max(np.abs(psi - s)) * f.arm < 1e-9 * f.arm
        assert np.max(np.abs(np.linalg.norm(A, axis=1) - f.arm)) < 1e-9 * f.arm
    else:
        assert np.max(np.abs(A[:, 0])) < 1e-9 * design.scale
        assert np.max(np.abs(A[:, 1] - s)) < 1e-9 * design.scale

@pytest.mark.parametrize("name", ["rocker_force", "translating_force"])
def test_both_senses_mirror_image(solved, name):
    """Reflecting the mechanism (cam and rocker senses flipped, O mirrored) mirrors the pitch curve."""
    design, O = solved[name]
    phi = np.linspace(0, 2 * np.pi, 721)[:-1]
    g = pitch_curve(design, O, phi)
    mirrored, M = _mirrored(design)
    gm = pitch_curve(mirrored, O * M, phi)
    assert np.allclose(gm.point, g.point * M, atol=1e-12 * design.scale)
    assert np.allclose(gm.normal, g.normal * M, atol=1e-12)
    assert np.allclose(gm.kappa, g.kappa, rtol=1e-9, atol=1e-12)

@pytest.mark.parametrize("name", ALL)
def test_working_profile_is_roller_radius_from_pitch_curve(solved, name):
    design, O = solved[name]
    prof = build_profile(design, O)
    r = design.follower.roller_radius
    assert np.allclose(np.linalg.norm(prof.work - prof.pitch, axis=1), r, atol=1e-12)
    # nearest point of the whole (densely sampled) pitch curve: no other part comes closer than r
    # (the dense polyline itself is within ~1e-6 of the curve)
    dense = pitch_curve(design, O, np.linspace(0, 2 * np.pi, 40001)).point
    d = shapely.distance(LineString(dense), shapely.points(prof.work))
    assert np.all(np.abs(d - r) < 1e-6)
    # toward the cam: the working profile lies inside the pitch curve
    assert shapely.Polygon(prof.pitch).contains(shapely.Polygon(prof.work))
    if prof.groove:
        assert np.allclose(np.linalg.norm(prof.outer - prof.pitch, axis=1), r, atol=1e-12)
        d = shapely.distance(LineString(dense), shapely.points(prof.outer))
        assert np.all(np.abs(d - r) < 1e-6)
        assert shapely.Polygon(prof.outer).contains(shapely.Polygon(prof.pitch))
    else:
        assert prof.outer is None

def _numerical_kappa(P, h):
    """Signed curvature (positive for a counter-clockwise turn) by central differences."""
    d1 = (P[2:] - P[:-2]) / (2 * h)
    d2 = (P[2:] - 2 * P[1:-1] + P[:-2]) / h**2
    return (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3

@pytest.mark.parametrize("name", ALL)
def test_analytic_curvature_matches_finite_differences(solved, name):
    design, O = solved[name]
    r = design.follower.roller_radius
    eps = design.cam_sense
    h = 1e-4
    for i in range(len(design.program.phases)):
        u = np.linspace(0.02, 0.98, 200)
        g = pitch_phase(design, O, i, u)
        phi = g.phi
        P = pitch_curve(design, O, (phi[:, None] + h * np.array([-1, 0, 1])).ravel()).point.reshape(-1, 3, 2)
        # curve runs in sense -eps: positive convex is -eps times the counter-clockwise curvature
        num = np.array([-eps * _numerical_kappa(p, h)[0] for p in P])
        assert np.allclose(g.kappa, num, rtol=1e-5, atol=1e-6 * np.abs(g.kappa).max())
        # the analytic first derivative too
        assert np.allclose(g.d1, (P[:, 2] - P[:, 0]) / (2 * h), rtol=1e-6, atol=1e-6 * design.scale)
        # the working profile's radius of curvature rho - r, numerically from offset points
        W = P - r * pitch_curve(design, O, (phi[:, None] + h * np.array([-1, 0, 1])).ravel()).normal.reshape(-1, 3, 2)
        kw = np.array([-eps * _numerical_kappa(w, h)[0] for w in W])
        rho_w = offset_radius(g.rho, -r)
        assert np.allclose(1 / rho_w, kw, rtol=1e-4, atol=1e-7)

def test_dwell_is_a_circle_with_positive_radius(solved):
    design, O = solved["rocker_force"]
    g = pitch_phase(design, O, 1, np.linspace(0, 1, 5))  # the far dwell
    radius = np.linalg.norm(g.point, axis=1)
    assert np.allclose(radius, radius[0]) and np.allclose(g.rho, radius[0])
    assert np.allclose(np.sum(g.normal * g.point, axis=1) / radius, 1.0)  # outward normal is radial

@pytest.mark.parametrize("name", ALL)
def test_samples_within_chord_tolerance_and_at_phase_starts(solved, name):
    design, O = solved[name]
    tol = 1e-3
    prof = build_profile(design, O, tolerance=tol)
    prog = design.program
    assert prof.phi[0] == 0.0 and np.all(np.diff(prof.phi) > 0)
    assert set(prog.starts[:-1]).issubset(set(prof.phi))
    # between consecutive samples, the true curves stay within tol of the chord
    nxt = np.roll(np.arange(len(prof)), -1)
    ph = prof.phase
    u0 = (prof.phi - prog.starts[ph]) / np.array([p.angle for p in prog.phases])[ph]
    u1 = np.where(nxt == 0, 1.0, np.where(ph[nxt] == ph, u0[nxt], 1.0))
    r = prof.roller_radius
    worst = 0.0
    for t in np.linspace(0.05, 0.95, 19):
        for i in range(len(prog.phases)):
            m = ph == i
            g = pitch_phase(design, O, i, u0[m] + t * (u1[m] - u0[m]))
            curves = [(g.point, prof.pitch), (g.offset(-r), prof.work)]
            if prof.groove:
                curves.append((g.offset(r), prof.outer))
            for curve, pts in curves:
                a, b = pts[m], pts[nxt][m]
                d = b - a
                dev = np.abs(d[:, 0] * (curve - a)[:, 1] - d[:, 1] * (curve - a)[:, 0]) / np.linalg.norm(d, axis=1)
                worst = max(worst, float(dev.max()))
    assert worst <= tol * (1 + 1e-6)
    assert worst > 0.2 * tol  # not wastefully dense either

def test_point_count_follows_the_tolerance(solved):
    design, O = solved["rocker_force"]
    n = [len(build_profile(design, O, tolerance=t)) for t in (1e-2, 1e-3, 1e-4)]
    assert n[0] < n[1] < n[2]
    # sagitta ~ L^2 / (8 rho): ten times tighter, about sqrt(10) times the points
    assert 2.0 < n[2] / n[1] < 4.5

def test_samples_dense_where_curvature_is_high(solved):
    design, O = solved["rocker_form"]
    prof = build_profile(design, O)
    step = np.linalg.norm(np.diff(prof.work, axis=0), axis=1)
    k = np.abs(1 / prof.rho_work[:-1])
    hi, lo = k > np.quantile(k, 0.9), k < np.quantile(k, 0.1)
    assert np.median(step[hi]) < np.median(step[lo])

def test_knife_edge_working_profile_is_the_pitch_curve(design_with, solved):
    _, O = solved["rocker_force"]
    d = design_with("rocker_force", follower={"roller_radius": 0.0})
    prof = build_profile(d, O)
    assert np.array_equal(prof.work, prof.pitch) and prof.roller_radius == 0.0

def test_linear_law_corner_gets_a_roller_arc(design_with):
    """A constant-velocity rise has a pitch-curve corner at its ends: the gap of the offset is a roller arc."""
    d = design_with("translating_force", motion=[
        {"phase": "rise", "law": "linear", "angle": 150}, {"phase": "dwell", "angle": 30},
        {"phase": "return", "law": "cycloidal", "angle": 120}, {"phase": "dwell"}])
    O = np.array([-5.0, -60.0])
    prof = build_profile(d, O, tolerance=1e-3)
    r = d.follower.roller_radius
    assert np.allclose(np.linalg.norm(prof.work - prof.pitch, axis=1), r)
    assert np.all(np.diff(prof.phi) >= 0) and prof.phi[0] == 0.0
    # consecutive working-profile points stay within a chord of tolerance-size sagitta: no gap
    step = np.linalg.norm(np.diff(np.vstack([prof.work, prof.work[:1]]), axis=0), axis=1)
    assert step.max() < 2 * np.sqrt(8 * r * 1e-3) + 1.0

def test_bad_tolerance_and_groove_without_roller(solved, design_with):
    design, O = solved["rocker_form"]
    for bad in (0.0, -1e-3, float("nan"), float("inf"), "0.1", True):
        with pytest.raises(InputError, match="tolerance"):
            build_profile(design, O, tolerance=bad)
    d = design_with("rocker_form", follower={"roller_radius": 0.0})
    with pytest.raises(InputError, match="follower.roller_radius"):
        build_profile(d, O)

def test_profile_options_from_design_file(design_with):
    d = design_with("rocker_force", profile={"tolerance": 0.01, "min_curvature_radius": 2.0}, cam={"bore_radius": 1.5})
    o = profile_options(d)
    assert o == ProfileOptions(0.01, 2.0, 1.5)
    assert profile_options(d, tolerance=0.5).tolerance == 0.5
    with pytest.raises(InputError, match="--tolerance"):
        profile_options(d, tolerance=0)
    for table, match in (({"profile": {"tolerance": -1}}, "profile.tolerance"),
                         ({"profile": {"min_curvature_radius": 0}}, "profile.min_curvature_radius"),
                         ({"cam": {"bore_radius": -2}}, "cam.bore_radius")):
        with pytest.raises(InputError, match=match):
            profile_options(design_with("rocker_force", **table))

def test_profile_arrays_are_read_only_and_bore_default(solved):
    design, O = solved["rocker_force"]
    prof = build_profile(design, O)
    with pytest.raises(ValueError):
        prof.work[0, 0] = 1.0
    assert prof.R0 == pytest.approx(np.linalg.norm(prof.pitch[0]))
    b = default_bore_radius(prof)
    assert 0 < b < prof.min_work_radius and b <= 0.3 * prof.R0
