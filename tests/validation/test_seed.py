"""Seed 001's own formulas (3.19-3.22, 3.26) against the product's exhaustive method.

Independent: the lines and their crossings are written literally from the
seed (``reference.seed_lines``, ``reference.seed_crossings``, the explicit
``x_C`` of 3.21 and ``y_C`` from 3.19, R0 by 3.22), with psi and psi' from the
motion program; the product builds its wedges vectorially from the instant
point D (optimize.zone), which is not imported here.

Frame mapping (documented in ``reference.seed_all_pairs``): eq. 3.19 passes
through ``D = l (1 + psi') (cos psi, -sin psi)``, so the seed's x, y are the
product's frame with ``rise_direction = "cw"`` and ``rotation = "ccw"`` (no
mirror); the admissible side of both families is ``y >= a x + b``.
``test_seed_frame_matches_reference`` pins that mapping with the reference
pressure angle, and shows the mirrored reading (y -> -y) is wrong.

Difference in the constraint sets: the seed draws one line per position
(t-t for the rise, t1-t1 for the return, or the single t1-t1 at psi = 0 under
force closure); the product bounds every limited position by both lines of
its wedge. Of the extra lines only one was found to matter: the t1-t1 line
of the rise's first position under form closure (the seed's force-closure
line), which the seed's form-closure recipe leaves out; it binds when the
rise's limit is well below the return's, or with K_C > 1
(``test_seed_form_closure_misses_the_rise_start``). With it the seed's
method reproduces the product's exhaustive result to round-off everywhere.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.solve import solve

from .designs import rocker_dict
from .reference import ReferenceZone, pressure_angles, seed_all_pairs, seed_lines

SAMPLES = 120

SEED_DESIGNS = {
    "force, cycloidal (examples/rocker_force)": rocker_dict(samples=SAMPLES),
    "form, poly345 / cycloidal, 45 / 50 deg": rocker_dict(rise=("poly345", 120.0), ret=("cycloidal", 100.0),
                                                           limit=45.0, return_limit=50.0, closure="form",
                                                           samples=SAMPLES),
    "form, harmonic / poly4567, long arm": rocker_dict(arm=260.0, swing=22.0, rise=("harmonic", 140.0),
                                                       ret=("poly4567", 110.0), limit=40.0, return_limit=55.0,
                                                       closure="form", samples=SAMPLES),
    "force, poly4567, small limit": rocker_dict(arm=80.0, swing=30.0, rise=("poly4567", 100.0), limit=30.0,
                                                samples=SAMPLES),
}


def _with_K(dd: dict, K: float) -> dict:
    return {**dd, "limits": {**dd["limits"], "safety_factor": K}}


@pytest.mark.parametrize("u", [0.0, 0.3, 0.55, 1.0])
def test_seed_frame_matches_reference(u):
    """Points on the seed's t-t / t1-t1 rays give exactly gamma = [gamma] in the product's cw/ccw frame.

    Both lines of a rise position pass through D and bound the set
    ``gamma <= [gamma]``; on the ray going into the zone (y above D) the
    reference pressure angle at that position equals the limit. The mirrored
    reading (seed's y = -product's y) gives other angles.
    """
    dd = rocker_dict(rise=("poly345", 120.0), limit=45.0)
    d = design_from_dict(dd)
    l, mu = 125.0, np.radians(45.0)
    m = d.program.evaluate_phase(0, np.array([u]))
    psi, dpsi = m.s[0], m.ds[0]
    a_t, b_t, a_t1, b_t1 = seed_lines(psi, dpsi, l, mu)
    D = l * (1 + dpsi) * np.array([np.cos(psi), -np.sin(psi)])
    assert D[1] == pytest.approx(a_t * D[0] + b_t, abs=1e-9 * l)
    assert D[1] == pytest.approx(a_t1 * D[0] + b_t1, abs=1e-9 * l)
    for a, b, sgn in ((a_t, b_t, -1.0), (a_t1, b_t1, 1.0)):
        for r in (10.0, 40.0, 90.0):
            # along the line, the direction with y increasing
            dx = sgn * r / np.hypot(1.0, a)
            P = np.array([D[0] + dx, a * (D[0] + dx) + b])
            assert P[1] > D[1]
            assert pressure_angles(d, P, 0, [u])[0] == pytest.approx(np.radians(45.0), abs=1e-8)
            mirrored = np.array([P[0], -P[1]])
            assert abs(pressure_angles(d, mirrored, 0, [u])[0] - np.radians(45.0)) > 1e-3
        # the admissible side y >= a x + b: a point above both lines is admissible at this position
    inside = D + np.array([np.sin(psi), np.cos(psi)]) * 30.0
    assert inside[1] >= a_t * inside[0] + b_t and inside[1] >= a_t1 * inside[0] + b_t1
    assert pressure_angles(d, inside, 0, [u])[0] < np.radians(45.0)


@pytest.mark.parametrize("name", list(SEED_DESIGNS))
def test_seed_all_pairs_equals_exhaustive(name):
    """Seed 3.19-3.22 (every t-t x every t1-t1, least admissible R0) == solve(method="exhaustive").

    Same positions (samples + 1 per phase, both ends). Centre and R0 agree
    to 1e-9 relative; the seed's centre also passes the reference pressure
    check at those positions (it lies on two limit lines, so gamma = [gamma]
    there to round-off).
    """
    dd = SEED_DESIGNS[name]
    d = design_from_dict(dd)
    seed = seed_all_pairs(d, SAMPLES)
    r = solve(d, method="exhaustive")
    scale = dd["follower"]["arm"]
    assert r.R0 == pytest.approx(seed.R0, rel=1e-9)
    assert np.linalg.norm(r.centre - seed.centre) <= 1e-9 * scale
    assert r.L == pytest.approx(seed.L, rel=1e-9)
    z = ReferenceZone(d, SAMPLES)
    assert z.max_excess(seed.centre[None])[0] <= 1e-8


@pytest.mark.parametrize("K", [1.2, 1.5])
@pytest.mark.parametrize("name", list(SEED_DESIGNS))
def test_seed_safety_factor_3_26(name, K):
    """Seed 3.26 (K_C moves t-t out to l(K_C + psi'), t1-t1 in to l(1/K_C + psi')) == exhaustive with K_C.

    Under form closure the comparison adds the t1-t1 line of the rise's first
    position (psi = 0, the rise's limit, 1/K_C shift) to the seed's t1-t1
    family (see ``test_seed_form_closure_misses_the_rise_start``); under force
    closure that line is the seed's own fixed t1-t1. Also: the K_C centre is
    strictly admissible for the plain limits (the shifted lines lie inside
    the zone), so the reference angle stays below [gamma], and R0 grows with K_C.
    """
    dd = _with_K(SEED_DESIGNS[name], K)
    d = design_from_dict(dd)
    seed = seed_all_pairs(d, SAMPLES, K, rise_start_t1=True)
    r = solve(d, method="exhaustive")
    scale = dd["follower"]["arm"]
    assert r.R0 == pytest.approx(seed.R0, rel=1e-9)
    assert np.linalg.norm(r.centre - seed.centre) <= 1e-9 * scale
    plain = design_from_dict(SEED_DESIGNS[name])
    assert ReferenceZone(plain, 400).max_excess(seed.centre[None])[0] < 0
    assert seed.R0 > seed_all_pairs(plain, SAMPLES).R0


def test_seed_form_closure_misses_the_rise_start():
    """The seed's form-closure recipe (t-t of the rise x t1-t1 of the return only) omits a limited position.

    The rise's first position (psi = 0, psi' = 0) is limited by the rise's
    [gamma]; its t1-t1 line is the one the seed uses under force closure. With
    a rise limit well below the return's (30 vs 60 deg) it binds: the literal
    seed centre exceeds the rise limit there (reference check, ~1.7 deg), the
    product's exhaustive centre does not, and adding that single line to the
    seed's family reproduces the product exactly. With K_C > 1 the same line
    (shifted by 1/K_C) binds in SEED_DESIGNS' long-arm design. This documents
    a gap in the seed, not in the product.
    """
    dd = rocker_dict(arm=260.0, swing=22.0, rise=("harmonic", 140.0), ret=("poly4567", 110.0), limit=30.0,
                     return_limit=60.0, closure="form", samples=SAMPLES)
    d = design_from_dict(dd)
    literal = seed_all_pairs(d, SAMPLES)
    completed = seed_all_pairs(d, SAMPLES, rise_start_t1=True)
    r = solve(d, method="exhaustive")
    z = ReferenceZone(d, SAMPLES)
    excess = z.max_excess(literal.centre[None])[0]
    assert excess > np.radians(1.0)
    # the violated position is the rise's start
    assert pressure_angles(d, literal.centre, 0, [0.0])[0] - np.radians(30.0) == pytest.approx(excess, abs=1e-9)
    assert z.max_excess(r.centre[None])[0] <= 1e-8
    assert literal.R0 < r.R0
    assert r.R0 == pytest.approx(completed.R0, rel=1e-9)
    assert np.linalg.norm(r.centre - completed.centre) <= 1e-9 * 260.0
    # K_C: the same line decides the long-arm design of SEED_DESIGNS
    dk = design_from_dict(_with_K(SEED_DESIGNS["form, harmonic / poly4567, long arm"], 1.5))
    assert seed_all_pairs(dk, SAMPLES, 1.5).R0 < solve(dk, method="exhaustive").R0 - 1.0


def test_seed_mirrored_design():
    """The mirrored seed design (rocker ccw, cam cw) gives the seed's crossing mirrored in y."""
    dd = SEED_DESIGNS["form, poly345 / cycloidal, 45 / 50 deg"]
    seed = seed_all_pairs(design_from_dict(dd), SAMPLES)
    mirrored = {**dd, "follower": {**dd["follower"], "rise_direction": "ccw"}, "cam": {"rotation": "cw"}}
    r = solve(design_from_dict(mirrored), method="exhaustive")
    assert r.R0 == pytest.approx(seed.R0, rel=1e-9)
    np.testing.assert_allclose(r.centre, seed.centre * [1, -1], atol=1e-9 * 125)
