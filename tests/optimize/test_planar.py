"""Planar primitives against direct constructions."""

import numpy as np
import pytest

from laws.errors import InfeasibleError
from optimize.planar import clip_polygon, line_crossings, nearest_point


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def test_nearest_point_of_square_from_outside_corner_and_edge():
    # unit square 0 <= x, y <= 1
    N = np.array([[1.0, 0], [-1, 0], [0, 1], [0, -1]])
    c = np.array([1.0, 0, 1, 0])
    x, act = nearest_point(np.array([2.0, 3.0]), N, c)
    assert np.allclose(x, [1, 1]) and set(act) == {0, 2}
    x, act = nearest_point(np.array([0.25, -5.0]), N, c)
    assert np.allclose(x, [0.25, 0]) and list(act) == [3]
    x, act = nearest_point(np.array([0.5, 0.5]), N, c)
    assert np.allclose(x, [0.5, 0.5]) and len(act) == 0


def test_nearest_point_matches_dense_search_on_random_polygons():
    rng = np.random.default_rng(7)
    for _ in range(20):
        ang = np.arange(6) * np.pi / 3 + rng.uniform(-0.4, 0.4, 6)  # bounded polygon
        N = np.stack([np.cos(ang), np.sin(ang)], 1)
        c = rng.uniform(0.5, 2.0, 6)
        P = rng.uniform(-2.5, 2.5, 2)
        res = nearest_point(P, N, c)
        g = np.linspace(-3, 3, 301)
        X, Y = np.meshgrid(g, g)
        pts = np.stack([X.ravel(), Y.ravel()], 1)
        feas = np.all(pts @ N.T <= c, axis=1)
        if not feas.any():
            continue
        best = np.min(np.linalg.norm(pts[feas] - P, axis=1))
        d = np.linalg.norm(res[0] - P)
        assert d <= best + 1e-12 and d >= best - 0.05


def test_infeasible_returns_none():
    N = np.array([[1.0, 0], [-1, 0]])
    c = np.array([-1.0, -1.0])  # x <= -1 and x >= 1
    assert nearest_point(np.zeros(2), N, c) is None


def test_line_crossings_and_parallel():
    N1 = _unit([[1, 0], [0, 1]])
    N2 = _unit([[1, 0], [1, 1]])
    pts, ok = line_crossings(N1, np.array([1.0, 2.0]), N2, np.array([3.0, 0.0]))
    assert not ok[0, 0]
    assert np.allclose(pts[1, 1], [-2, 2])


def test_clip_polygon_triangle_area():
    N = _unit([[-1, 0], [0, -1], [1, 1]])
    c = np.array([0.0, 0.0, 1 / np.sqrt(2)])
    poly = clip_polygon(N, c, (-5, -5, 5, 5))
    x, y = poly[:, 0], poly[:, 1]
    area = 0.5 * abs(np.dot(x, np.roll(y, 1)) - np.dot(y, np.roll(x, 1)))
    assert area == pytest.approx(0.5)


# -- the dual active-set nearest point (issue 12, items 1 and 3) ------------------------------------------

from fractions import Fraction  # noqa: E402

from optimize.planar import NearestPoint  # noqa: E402


def _exact_nearest(P, N, c):
    """Nearest point by enumeration in rational arithmetic (no rounding, no tolerance): squared distance."""
    P = [Fraction(v) for v in P]
    N = [[Fraction(a), Fraction(b)] for a, b in N]
    c = [Fraction(v) for v in c]
    m = len(N)

    def feasible(x):
        return all(N[i][0] * x[0] + N[i][1] * x[1] <= c[i] for i in range(m))

    cands = [P]
    for i in range(m):
        nn = N[i][0] ** 2 + N[i][1] ** 2
        r = (N[i][0] * P[0] + N[i][1] * P[1] - c[i]) / nn
        cands.append([P[0] - r * N[i][0], P[1] - r * N[i][1]])
        for j in range(i + 1, m):
            det = N[i][0] * N[j][1] - N[i][1] * N[j][0]
            if det != 0:
                cands.append([(c[i] * N[j][1] - N[i][1] * c[j]) / det, (N[i][0] * c[j] - N[j][0] * c[i]) / det])
    d = [(x[0] - P[0]) ** 2 + (x[1] - P[1]) ** 2 for x in cands if feasible(x)]
    return min(d) if d else None


def test_nearest_point_matches_rational_enumeration_incrementally():
    """Random polygons (with parallel and repeated lines), cuts added in batches: the distance is the exact one."""
    rng = np.random.default_rng(12)
    for trial in range(300):
        m = int(rng.integers(1, 9))
        ang = rng.uniform(0, 2 * np.pi, m)
        if trial % 3 == 0:
            ang = np.round(ang * 2) / 2  # repeated and opposite normals
        N = np.stack([np.cos(ang), np.sin(ang)], 1)
        c = rng.uniform(-1, 2, m)
        P = rng.uniform(-3, 3, 2)
        q = NearestPoint(P)
        try:
            for k in range(0, m, 2):
                q.add(N[k:k + 2], c[k:k + 2])
                q.solve()
            x = q.x
        except InfeasibleError:
            x = None
        ref = _exact_nearest(P, N, c)
        if ref is None:
            assert x is None, trial
            continue
        assert x is not None, trial
        assert np.max(N @ x - c) <= 1e-13
        assert np.linalg.norm(x - P) == pytest.approx(float(ref) ** 0.5, rel=1e-12, abs=1e-13)


def test_vertex_far_from_the_origin_is_not_rejected():
    """The nearest point where two lines cross far out (coordinates ~1e6) is found: the former routine judged
    Cramer's crossing against a tolerance tied to the design's size (here 1e-13) and rejected it."""
    V = np.array([1.0e6 + 0.123456789, 2.5e6 - 0.987654321])
    a = np.array([np.cos(1.3), np.sin(1.3)])
    b = np.array([np.cos(1.3 + 1e-3), np.sin(1.3 + 1e-3)])
    w = np.array([np.cos(-0.7), np.sin(-0.7)])
    N = np.array([a, b, w])
    c = np.array([a @ V, b @ V, w @ V + 5.0])  # a third line through a farther vertex, slack at V
    P = V + 40.0 * (a + b)                     # outside both lines, V the nearest point
    x, act = nearest_point(P, N, c)
    ref = float(_exact_nearest(P, N, c)) ** 0.5
    # conditioning: the crossing moves by eps |V| / sin(1e-3) ~ 1e-6 under rounding of the data
    assert abs(np.linalg.norm(x - P) - ref) <= 4 * np.finfo(float).eps * np.abs(V).sum() / 1e-3
    assert set(act) == {0, 1}


def test_dual_certificate_kkt():
    """Multipliers >= 0 of the active lines give x - P = -N^T lam; the dual value equals dist^2 / 2."""
    rng = np.random.default_rng(3)
    for _ in range(50):
        ang = np.arange(7) * 2 * np.pi / 7 + rng.uniform(-0.3, 0.3, 7)
        N = np.stack([np.cos(ang), np.sin(ang)], 1)
        c = rng.uniform(0.5, 2.0, 7)
        q = NearestPoint(rng.uniform(-5, 5, 2))
        q.add(N, c)
        x = q.solve()
        lam = q.lam
        assert np.all(lam >= 0)
        np.testing.assert_allclose(x - q.P, -lam @ N[q.active], atol=1e-13)
        np.testing.assert_allclose(N[q.active] @ x, c[q.active], atol=1e-13)  # complementary slackness
        d2 = float((x - q.P) @ (x - q.P))
        assert q.dual_value() == pytest.approx(0.5 * d2, rel=1e-12, abs=1e-15)
        # any other lam >= 0 gives a lower value (weak duality)
        other = NearestPoint(q.P)
        other.add(N, c)
        other.active, other.lam = [0, 3], rng.uniform(0, 2, 2)
        assert other.dual_value() <= 0.5 * d2 + 1e-12


@pytest.mark.parametrize("k", [1e-3, 1.0, 1e3, 1e6])
def test_nearest_point_scales_exactly(k):
    rng = np.random.default_rng(5)
    ang = rng.uniform(0, 2 * np.pi, 200)
    N = np.stack([np.cos(ang), np.sin(ang)], 1)
    c = rng.uniform(1.0, 2.0, 200)
    P = np.array([3.0, -2.0])
    x1, act1 = nearest_point(P, N, c)
    xk, actk = nearest_point(k * P, N, k * c)
    np.testing.assert_allclose(xk / k, x1, rtol=1e-12)
    assert list(act1) == list(actk)


def test_many_cuts_cost_linear():
    """20,000 cuts: the former all-pairs routine needed m^2 crossings (3.2 GB here); now O(m) memory."""
    import tracemalloc

    rng = np.random.default_rng(9)
    m = 20_000
    ang = rng.uniform(0, 2 * np.pi, m)
    N = np.stack([np.cos(ang), np.sin(ang)], 1)
    c = rng.uniform(1.0, 2.0, m)
    tracemalloc.start()
    try:
        x, _ = nearest_point(np.array([10.0, 7.0]), N, c)
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert np.max(N @ x - c) <= 1e-13
    assert peak < 50 * m * 16


def test_lower_bound_never_exceeds_the_distance():
    """The proven lower bound (weak duality less rounding) is below the true distance at every stage of
    an incremental solve, and meets it at the end."""
    rng = np.random.default_rng(21)
    for _ in range(100):
        m = 12
        ang = rng.uniform(0, 2 * np.pi, m)
        N = np.stack([np.cos(ang), np.sin(ang)], 1)
        c = rng.uniform(0.2, 2.0, m)
        P = rng.uniform(-4, 4, 2)
        q = NearestPoint(P)
        for k in range(0, m, 3):
            q.add(N[k:k + 3], c[k:k + 3])
            q.solve()
            true = float(_exact_nearest(P, N[:k + 3], c[:k + 3])) ** 0.5
            assert q.lower_bound() <= true
            assert q.lower_bound() == pytest.approx(true, rel=1e-12, abs=1e-14)


# -- nearly parallel lines (issue 28, defect 1) -----------------------------------------------------------

from laws.errors import CamsError, SolverError  # noqa: E402

#: The two cuts on which the exact method gave up ("did not settle in 108 steps") for
#: the reproducer exact_nosettle_2178 (an independent campaign's): t-t lines 1.2e-3 rad apart, from the target T = A0.
PAIR_T = np.array([4.259996571466902, 0.0])
PAIR_N = np.array([[0.4075486535907736, 0.9131834946802025], [0.40862162338718727, 0.9127038779913338]])
PAIR_C = np.array([-4.002871822467924, -4.002871652183345]) + PAIR_N @ PAIR_T


def _residual_within_rounding(q: NearestPoint, N: np.ndarray, c: np.ndarray) -> None:
    """Every half-plane holds at ``q.x`` within its own rounding allowance (:meth:`NearestPoint.tolerances`)."""
    y = q.x - q.P
    assert np.all(N @ y - (c - N @ q.P) <= q.tolerances()), (N @ y - (c - N @ q.P), q.tolerances())


def test_nearly_parallel_pair_of_the_exact_method_settles():
    """The cuts added one after the other: the vertex is found and both lines hold within rounding (the vertex
    by Cramer's rule missed them by 1.2e-13, beyond the allowance, so the active cut was entered again, dropped
    and entered again until the cap)."""
    q = NearestPoint(PAIR_T)
    q.add(PAIR_N[:1], PAIR_C[:1])
    q.solve()
    q.add(PAIR_N[1:], PAIR_C[1:])
    x = q.solve()
    assert sorted(q.active) == [0, 1] and q.steps < 5
    _residual_within_rounding(q, PAIR_N, PAIR_C)
    ref = float(_exact_nearest(PAIR_T, PAIR_N, PAIR_C)) ** 0.5
    assert np.linalg.norm(x - PAIR_T) == pytest.approx(ref, rel=1e-14)
    assert q.lower_bound() <= ref


@pytest.mark.parametrize("k", [1e-2, 1.0, 1e3])
def test_nearly_parallel_pairs_settle_on_the_exact_distance(k):
    """Two lines from 1e-1 to 1e-13 rad apart crossing near the nearest point, added one at a time, at three unit
    scales: the method settles, every line holds within rounding, the distance is the rational enumeration's
    and the lower bound does not exceed it (the former vertex failed to settle on 1.2 % of such pairs)."""
    rng = np.random.default_rng(28)
    for trial in range(400):
        th = rng.uniform(0.0, 2 * np.pi)
        delta = 10.0 ** rng.uniform(-13.0, -1.0) * rng.choice([-1.0, 1.0])
        N = np.array([[np.cos(th), np.sin(th)], [np.cos(th + delta), np.sin(th + delta)]])
        P = k * rng.normal(size=2)
        V = P - k * rng.uniform(0.5, 2.0) * N[0] + k * 1e-3 * rng.normal(size=2)
        c = N @ V + k * 1e-9 * rng.normal(size=2)
        q = NearestPoint(P)
        q.add(N[:1], c[:1])
        q.solve()
        q.add(N[1:], c[1:])
        x = q.solve()
        _residual_within_rounding(q, N, c)
        ref = float(_exact_nearest(P, N, c)) ** 0.5
        # the distance is well conditioned (the vertex moves along the lines, across the narrow cone of normals)
        assert abs(np.linalg.norm(x - P) - ref) <= 1e-13 * (ref + np.abs(P).sum()), trial
        assert q.lower_bound() <= ref, trial


def test_an_unsettled_solve_is_a_solver_failure_not_bad_input():
    """The cap on the steps raises SolverError (the product's failure), not a CamsError (the user's)."""
    q = NearestPoint(np.array([5.0, 5.0]))
    q.add(np.array([[1.0, 0.0], [0.0, 1.0]]), np.array([1.0, 1.0]))
    with pytest.raises(SolverError, match="did not settle in 1 steps") as err:
        q.solve(max_steps=1)
    assert not isinstance(err.value, CamsError)
