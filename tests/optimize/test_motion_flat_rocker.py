"""The flat-faced rocker's motion design (sequential convex programming on the envelope's convexity).

Independent references: the cam profile as the envelope of the face's lines, built by intersecting the lines
at neighbouring cam angles (no support-function formula: the lines come from the pivot, the face offset and the
swing), its radius of curvature as arc length over the turn of the normal; the rest-to-rest law of least peak
jerk (jerk +-32 on the quarters, halves: Cj = 32); finite differences of the radius of curvature.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.io.designfile import design_from_dict, load_design
from cams.io.document import read_toml
from cams.io.lawtable import law_to_table
from cams.solve import solve
from laws.errors import InputError

FLAT = "examples/rocker_flat.toml"


def envelope_radii(design, R0: float, n: int = 50_000) -> np.ndarray:
    """The profile's radius of curvature at ``n`` cam angles of the cycle, from the face's lines alone.

    Line-of-centres frame: pivot at the origin, cam centre O at (L, 0). The face is the line ``m . X = f``,
    ``m = (cos a, sin a)``, ``a = a0 + sigma psi``, the face touching the base circle at the near dwell
    (distance R0 from O: ``f - L cos a0 = R0``, ``a0`` of the rise's sign). In the cam frame (turned by
    ``-eps phi`` about O) consecutive lines meet at the profile's points; the radius of curvature is the arc
    between them over the normal's turn (negative where the profile turns the other way). The lines' crossings
    lose digits as the step shrinks (their angle is the step): 50,000 cam angles a cycle keep the radius to
    about 1e-7 of it, while the sampling's own error is of the step's square.
    """
    fo = design.follower
    L, f, sigma, eps = fo.centre_distance, fo.face_offset, fo.sense, design.cam_sense
    a0 = sigma * np.arccos((f - R0) / L)
    phi = np.linspace(0.0, 2 * np.pi, n, endpoint=False)
    a = a0 + sigma * design.program.evaluate(phi).s
    theta = a - eps * phi                           # the normal in the cam frame
    p = f - L * np.cos(a)                           # the line's distance from O: m . X = f with X = O + Y
    nx, ny = np.cos(theta), np.sin(theta)
    j = np.roll(np.arange(n), -1)
    det = nx * ny[j] - ny * nx[j]
    X = (p * ny[j] - p[j] * ny) / det
    Y = (nx * p[j] - nx[j] * p) / det
    k = np.roll(np.arange(n), -1)
    arc = np.hypot(X[k] - X, Y[k] - Y)
    turn = np.unwrap(theta)
    dtheta = (np.roll(turn, -1) - turn)[:-1]
    # each point lies between the normals k and k+1: the arc to the next over the mean turn
    sign = np.sign((X[k] - X) * -np.sin(theta[k]) + (Y[k] - Y) * np.cos(theta[k])) * np.sign(-eps)
    return (sign * arc)[:-2] / np.abs(0.5 * (dtheta[:-1] + dtheta[1:]))


@pytest.fixture(scope="module")
def designed():
    doc = read_toml(FLAT)
    doc["optimize"] = {"free": ["rise", "return"], "max_Ca": "cycloidal", "max_Cj": "cycloidal",
                       "continuity": 2, "spans": 8}
    return solve(design_from_dict(doc))


def test_envelope_radii_reproduce_the_sizing_of_todays_cam():
    """The independent radii against today's cam (cycloidal rise, 3-4-5 return): the least radius of
    curvature at its R0 is the limit, and a cam 1e-4 smaller has less."""
    d = load_design(FLAT)
    res = solve(d)
    rho = envelope_radii(d, res.R0)
    assert rho.min() == pytest.approx(d.min_radius, rel=1e-5)
    assert envelope_radii(d, res.R0 * (1 - 1e-4)).min() < d.min_radius


def test_flat_rocker_design_is_smaller_convex_and_minimal(designed):
    o = designed.optimization.to_dict()
    d = designed.design
    assert designed.verified and o["certified"] and o["method"] == "sequential convex programming"
    assert o["lower_bound"] is None and o["gap"] is None and 0 <= o["local_measure"] < 1e-3
    assert designed.R0 < 0.9 * o["reference"]["R0"] and o["value"] == designed.R0
    assert o["reference"]["R0"] == solve(load_design(FLAT)).R0     # the original laws' cam, sized alone
    assert all(b < a for a, b in zip(o["history"], o["history"][1:], strict=False))
    rho = envelope_radii(d, designed.R0)
    assert rho.min() >= d.min_radius * (1 - 1e-5)
    assert envelope_radii(d, designed.R0 * (1 - 1e-4)).min() < d.min_radius     # no smaller cam of these laws
    for i in (0, 2):
        S = d.program.law_of(i).evaluate(np.linspace(0, 1, 200_001))
        assert np.max(np.abs(S[2])) <= 2 * np.pi * (1 + 1e-9) and np.max(np.abs(S[3])) <= 4 * np.pi**2 * (1 + 1e-9)


def test_flat_rocker_law_written_out_solves_to_the_same_cam(designed):
    doc = read_toml(FLAT)
    for i in (0, 2):
        doc["motion"][i]["law"] = law_to_table(designed.design.program.law_of(i))
    assert solve(design_from_dict(doc)).R0 == designed.R0


def test_curvature_rates_are_the_radius_derivatives():
    """The linearization's rates against an independent finite difference of the envelope's radius at a dwell
    (rho = p there, p = f - L cos(a0 + sigma psi)): its rate in R0 and in psi."""
    from optimize.motion.flat_rocker import curvature_rates

    d = load_design(FLAT)
    fo = d.follower
    L, f, sigma = fo.centre_distance, fo.face_offset, fo.sense
    R0, psi = 40.0, 0.1

    def p(R, s):
        return f - L * np.cos(sigma * np.arccos((f - R) / L) + sigma * s)

    rho, g_s, _, _, g_R = curvature_rates(d, R0, np.array([psi]), np.array([0.0]), np.array([0.0]))
    e = 1e-5
    assert rho[0] == pytest.approx(p(R0, psi), rel=1e-12)
    assert g_s[0] == pytest.approx((p(R0, psi + e) - p(R0, psi - e)) / (2 * e), rel=1e-6)
    assert g_R[0] == pytest.approx((p(R0 + e, psi) - p(R0 - e, psi)) / (2 * e), rel=1e-6)


@pytest.mark.parametrize("spans", [4, 8])
def test_least_peak_jerk_is_the_bang_bang_law(spans):
    """The rise freed, its peak jerk minimized at today's R0 (C2: the jerk may jump at the knots): the least
    peak jerk of a rest-to-rest rise is 32 (jerk +32, -32, +32 on the quarters and the middle half: S(1) =
    32/32 = 1), in the space when the knots include 1/4 and 3/4; the cam at the size held stays convex."""
    doc = read_toml(FLAT)
    doc["optimize"] = {"objective": "Cj", "continuity": 2, "spans": spans}
    res = solve(design_from_dict(doc))
    o = res.optimization.to_dict()
    assert res.verified and o["certified"] and res.R0 <= o["held_R0"] * (1 + 1e-12)
    S = res.design.program.law_of(0).evaluate(np.linspace(0, 1, 200_001))
    assert o["value"] == pytest.approx(32.0, rel=1e-6) and np.max(np.abs(S[3])) >= 32.0 * (1 - 1e-9)
    assert envelope_radii(res.design, o["held_R0"]).min() >= res.design.min_radius * (1 - 1e-5)


@pytest.mark.parametrize("objective", ["L", "pressure_angle"])
def test_flat_rocker_refuses_what_does_not_apply(objective):
    doc = read_toml(FLAT)
    doc["optimize"] = {"objective": objective}
    with pytest.raises(InputError) as e:
        solve(design_from_dict(doc))
    assert e.value.field == "optimize.objective"


def test_least_peak_jerk_where_convexity_binds():
    """The return freed (3-4-5 today, whose radius of curvature sets today's R0): at that R0 the least peak jerk
    cannot reach the rest-to-rest 32, the convexity limit binds (the independent envelope at the size held
    touches it), and the jerk is below the 3-4-5's 60."""
    doc = read_toml(FLAT)
    doc["optimize"] = {"free": ["return"], "objective": "Cj", "continuity": 2, "spans": 8}
    res = solve(design_from_dict(doc))
    o = res.optimization.to_dict()
    assert res.verified and o["certified"] and res.R0 <= o["held_R0"] * (1 + 1e-12)
    rho = envelope_radii(res.design, o["held_R0"])
    assert res.design.min_radius * (1 - 1e-5) <= rho.min() <= res.design.min_radius * (1 + 1e-3)
    assert 32.0 * (1 + 1e-3) < o["value"] < 60.0
    S = res.design.program.law_of(2).evaluate(np.linspace(0, 1, 200_001))
    assert o["value"] == pytest.approx(np.max(np.abs(S[3])), rel=1e-6)


def test_curvature_rates_are_first_order_exact_on_the_rise():
    """At points of the cycloidal rise (s', s'' nonzero): the linear model rho + rates . step misses rho at
    the stepped point by the step's square (errors fall 100-fold when the step falls 10-fold), in each of s,
    s', s'' and R0."""
    from optimize.motion.flat_rocker import curvature_rates

    d = load_design(FLAT)
    u = np.linspace(0.05, 0.95, 7)
    m = d.program.evaluate_phase(0, u)
    R0 = 37.0
    rho, *g = curvature_rates(d, R0, m.s, m.ds, m.d2s)
    for k in range(4):
        errs = []
        for h in (1e-2, 1e-3):
            x = [R0, m.s, m.ds, m.d2s]
            step = h * (10.0 if k == 0 else 1.0)        # R0 in mm, the others in radians
            x[k] = x[k] + step
            got = curvature_rates(d, x[0], x[1], x[2], x[3])[0]
            rate = g[3] if k == 0 else g[k - 1]
            errs.append(np.max(np.abs(got - (rho + rate * step))))
        assert errs[1] < max(errs[0] / 50, 1e-9 * rho.max())      # (rho is nearly linear in R0)
        assert errs[0] < 1e-2 * rho.max()


def test_a_steep_designed_law_has_a_finite_jerk_peak():
    """Degree 11, C3, Ca minimized with no cap on the jerk: S''' reaches ~1.6e3, so the one-sided values 2e-9
    apart at a knot differ by ~3e-6 and the ends carry ~1e-7 of rounding; neither is a jump (the joints are
    C3 by construction): Cj is the dense peak of |S'''|, not infinite."""
    doc = read_toml(FLAT)
    doc["optimize"] = {"objective": "Ca", "degree": 11, "spans": 10}
    res = solve(design_from_dict(doc))
    (phase,) = res.optimization.phases
    S = res.design.program.law_of(0).evaluate(np.linspace(0, 1, 400_001))
    assert phase["Cj"] is not None and phase["Cj"] == pytest.approx(np.max(np.abs(S[3])), rel=1e-6)
    assert phase["Cj"] > 100
