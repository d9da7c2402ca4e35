"""The solvers against a brute-force grid search with the reference pressure angle.

Independent: admissibility of a candidate centre is decided only by
:class:`reference.ReferenceZone` (kinematic inversion, finite differences,
2000 steps per limited phase, no tolerance); the minimum R0 is found by
nested grids (no zone, no wedges, no instant point D, no convex solver). The
brute-force minimum can undercut the exact one only by the relaxation of
sampling 2000 positions (a few 1e-8 of the scale) and exceed it only by the
grid's resolution.

Numbers when written (length unit of the design; brute-force cell = its
final grid spacing; convex/exhaustive at 120 steps per phase; the
assertions, not these numbers, are the contract):

| design                                  | exact R0  | brute R0  | diff     | cell    | convex    | exhaustive |
|-----------------------------------------|-----------|-----------|----------|---------|-----------|------------|
| rocker force, opposite senses           | 13.240793 | 13.240810 | +1.7e-05 | 2.1e-04 | 13.240521 | 13.240521  |
| rocker force, same sense                | 12.638892 | 12.638890 | -2.8e-06 | 2.1e-04 | 12.638668 | 12.638668  |
| rocker form, opposite senses            | 15.265755 | 15.265792 | +3.7e-05 | 2.1e-04 | 15.265480 | 15.265480  |
| rocker form, same sense                 | 20.011154 | 20.011206 | +5.2e-05 | 2.1e-04 | 20.007140 | 20.007140  |
| rocker form, cam cw, long arm           | 77.999792 | 78.000317 | +5.3e-04 | 5.1e-04 | 77.997623 | 77.997623  |
| translating force, free offset          | 17.581358 | 17.581363 | +5.6e-06 | 5.1e-05 | 17.577284 | 17.577284  |
| translating form, free offset, cam cw   | 26.138008 | 26.138022 | +1.4e-05 | 5.1e-05 | 26.134373 | 26.134373  |
| translating form, centric, cam cw       | 24.290111 | 24.290111 | -2.9e-08 | 1.6e-07 | 24.288550 | 24.288550  |
| translating force, centric, cam ccw     | 30.451805 | 30.451805 | -4.0e-08 | 2.4e-07 | 30.444749 | 30.444749  |

"rocker force, same sense": the optimum lies on an edge of the zone (one
binding line); the seed's crossings alone gave 12.675563 there, the completed
all-pairs method finds the edge point.
"""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.solve import solve

from .designs import BRUTE_DESIGNS, CENTRIC_DESIGNS
from .reference import brute_force_nearest, brute_force_on_line, max_excess, max_pressure, path, spec_of

ALL = {**BRUTE_DESIGNS, **CENTRIC_DESIGNS}


@cache
def _design(name):
    return design_from_dict(ALL[name])


@cache
def _solved(name, method):
    return solve(_design(name), method=method)


@cache
def _brute(name):
    d = _design(name)
    A0 = path(spec_of(d), 0.0)
    if name in CENTRIC_DESIGNS:
        # offset 0: the centre lies on the follower's axis x = 0, below A0
        return brute_force_on_line(d, [0.0, 0.0], [0.0, -1.0], A0)
    return brute_force_nearest(d, A0)


@pytest.mark.parametrize("name", list(ALL))
def test_exact_centre_passes_reference_check(name):
    """The exact centre keeps the reference pressure angle within the limit (+1e-6 rad) on every limited phase.

    Independent of cams.verify.pressure (the product's own check): positions only,
    finite-difference tangent of the inverted pitch curve.
    """
    d = _design(name)
    r = _solved(name, "exact")
    assert max_excess(d, r.centre) <= 1e-6
    # and it is on the limit (the optimum touches the boundary), not far inside
    assert max_excess(d, r.centre) >= -1e-6


@pytest.mark.parametrize("name", list(ALL))
def test_brute_force_minimum_matches_exact(name):
    """Grid-search minimum R0 (reference admissibility) is >= exact R0 - 1e-7 scale and <= exact R0 + 4 cells.

    Lower side: no admissible centre (2000 positions per phase) is nearer to
    A0 than the exact optimum, up to the tiny relaxation of sampling. Upper
    side: the grid finds an admissible point within its resolution of it.
    """
    d = _design(name)
    r = _solved(name, "exact")
    b = _brute(name)
    assert b.distance >= r.R0 - 1e-7 * d.scale, (b.distance, r.R0)
    assert b.distance <= r.R0 + 4 * b.spacing, (b.distance, r.R0, b.spacing)
    # the centres agree within the same resolution (the optimum is unique: convex zone, strictly convex distance)
    assert np.linalg.norm(b.centre - r.centre) <= 40 * b.spacing + 1e-6 * d.scale


@pytest.mark.parametrize("name", list(ALL))
def test_exact_optimum_is_tight(name):
    """Moving the exact centre 1e-4 * scale toward A0 (smaller R0) violates the reference check.

    If the exact centre were inside the zone with slack, a smaller cam would
    exist; the reference must see the moved centre exceed the limit.
    """
    d = _design(name)
    r = _solved(name, "exact")
    A0 = path(spec_of(d), 0.0)
    toward = (A0 - r.centre) / np.linalg.norm(A0 - r.centre)
    assert max_excess(d, r.centre + 1e-4 * d.scale * toward) > 1e-7


@pytest.mark.parametrize("name", list(ALL))
def test_sampled_methods_relax(name):
    """Sampled methods see fewer positions, so their zone is larger: convex R0 <= exact R0 + error_bound.

    The exhaustive (all-pairs) method, completed with the same-side crossings
    and the feet of the perpendicular, finds the same nearest point of the
    sampled zone as the convex method, vertex or edge, and obeys the same
    bound. Both sampled centres still satisfy the reference check up to the
    sampling error (120 steps per phase, the designs' solve.samples).
    """
    d = _design(name)
    ex = _solved(name, "exact")
    cv = _solved(name, "convex")
    xh = _solved(name, "exhaustive")
    assert ex.error_bound is not None and ex.error_bound < 1e-9 * d.scale
    assert cv.R0 <= ex.R0 + ex.error_bound + 1e-12 * d.scale
    assert cv.R0 >= ex.R0 - 1e-3 * d.scale  # 120 steps: the relaxation is small
    assert xh.R0 <= ex.R0 + ex.error_bound + 1e-12 * d.scale
    assert xh.R0 == pytest.approx(cv.R0, abs=1e-9 * d.scale)
    for res in (cv, xh):
        assert max_excess(d, res.centre) <= 1e-2


@pytest.mark.parametrize("name", list(CENTRIC_DESIGNS))
def test_fixed_offset_zero_stays_on_axis(name):
    """Fixed offset 0: every method's centre lies on the follower axis (x = 0) and reports offset 0."""
    for method in ("exact", "convex", "exhaustive"):
        r = _solved(name, method)
        assert abs(r.centre[0]) <= 1e-12 * _design(name).scale
        assert r.offset == pytest.approx(0.0, abs=1e-12)
        assert r.R0 == pytest.approx(-r.centre[1], rel=1e-12)


@pytest.mark.parametrize("name", list(ALL))
def test_product_pressure_report_matches_reference(name):
    """SolveResult.pressure (the product's own check) equals the reference maxima, rise and return, to 1e-7 rad.

    Two independent computations of the same quantity: the product's analytic
    relative velocity (cams.verify.pressure) and the reference's finite differences
    of inverted positions. The return is compared under force closure too.
    """
    d = _design(name)
    r = _solved(name, "exact")
    ref = max_pressure(d, r.centre, all_phases=True)
    kinds = {i: p.kind for i, p in enumerate(d.program.phases)}
    rise = max(g for i, g in ref.items() if kinds[i] == "rise")
    ret = max(g for i, g in ref.items() if kinds[i] == "return")
    assert r.pressure.rise == pytest.approx(rise, abs=1e-7)
    assert r.pressure.ret == pytest.approx(ret, abs=1e-7)


@pytest.mark.parametrize("rise_direction", ["cw", "ccw"])
def test_empty_zone_agrees(rise_direction):
    """Swing 56 deg with a 25 deg limit: the product reports an empty zone, and no grid centre is admissible.

    The reference test at 400 steps per phase (a subset of any finer
    sampling, so it can only admit more centres) rejects every centre of a
    241 x 241 grid spanning +-8 arms round A0.
    """
    from laws.errors import InfeasibleError

    from .designs import rocker
    from .reference import ReferenceZone

    d = rocker(swing=56.0, limit=25.0, rise_direction=rise_direction, rise=("cycloidal", 170.0),
               ret=("cycloidal", 170.0), dwell=10.0)
    with pytest.raises(InfeasibleError) as exc:
        solve(d, method="exact")
    assert exc.value.field == "limits.pressure_angle"
    g = np.linspace(-8.0, 8.0, 241) * d.scale
    X, Y = np.meshgrid(125.0 + g, g)
    C = np.stack([X.ravel(), Y.ravel()], axis=1)
    assert not np.any(ReferenceZone(d, 400).admissible(C))
