"""Planar primitives against direct constructions."""

import numpy as np
import pytest

from optimize.planar import clip_polygon, line_crossings, nearest_point


def _unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def test_nearest_point_of_square_from_outside_corner_and_edge():
    # unit square 0 <= x, y <= 1
    N = np.array([[1.0, 0], [-1, 0], [0, 1], [0, -1]])
    c = np.array([1.0, 0, 1, 0])
    x, act = nearest_point(np.array([2.0, 3.0]), N, c, 1e-12)
    assert np.allclose(x, [1, 1]) and set(act) == {0, 2}
    x, act = nearest_point(np.array([0.25, -5.0]), N, c, 1e-12)
    assert np.allclose(x, [0.25, 0]) and list(act) == [3]
    x, act = nearest_point(np.array([0.5, 0.5]), N, c, 1e-12)
    assert np.allclose(x, [0.5, 0.5]) and len(act) == 0


def test_nearest_point_matches_dense_search_on_random_polygons():
    rng = np.random.default_rng(7)
    for _ in range(20):
        ang = np.arange(6) * np.pi / 3 + rng.uniform(-0.4, 0.4, 6)  # bounded polygon
        N = np.stack([np.cos(ang), np.sin(ang)], 1)
        c = rng.uniform(0.5, 2.0, 6)
        P = rng.uniform(-2.5, 2.5, 2)
        res = nearest_point(P, N, c, 1e-12)
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
    assert nearest_point(np.zeros(2), N, c, 1e-12) is None


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
