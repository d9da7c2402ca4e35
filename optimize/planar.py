"""Exact planar primitives: nearest point of a polygon given by half-planes, clipping.

All functions take half-planes as ``N (m, 2)`` unit normals and ``c (m,)``
offsets meaning ``N @ x <= c``.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

__all__ = ["nearest_point", "line_crossings", "clip_polygon", "feasible_mask"]


def feasible_mask(points: np.ndarray, N: np.ndarray, c: np.ndarray, tol: float) -> np.ndarray:
    """True for the points that satisfy every half-plane ``N x <= c`` within ``tol``.

    Parameters
    ----------
    points : ndarray, shape (k, 2)
        Points in the frame of the half-planes (for the solvers: cam centres
        in the follower's fixed frame, :mod:`cams.follower`; length unit).
    N : ndarray, shape (m, 2)
        Unit normals, pointing out of the half-planes.
    c : ndarray, shape (m,)
        Offsets (length unit): ``N x - c`` is the signed distance outside.
    tol : float
        Allowed distance outside (length unit), >= 0.

    Returns
    -------
    ndarray of bool, shape (k,)
        True where ``N x <= c + tol`` holds for every half-plane (all True
        when ``m = 0``).
    """
    if len(N) == 0:
        return np.ones(len(points), dtype=bool)
    return np.all(points @ N.T <= c + tol, axis=1)


def line_crossings(N1, c1, N2, c2) -> tuple[np.ndarray, np.ndarray]:
    """Crossings of lines ``N1[i] x = c1[i]`` with ``N2[j] x = c2[j]``, all pairs.

    Parameters
    ----------
    N1 : ndarray, shape (n1, 2)
        Normals of the first lines (unit length not needed).
    c1 : ndarray, shape (n1,)
        Their offsets.
    N2 : ndarray, shape (n2, 2)
        Normals of the second lines.
    c2 : ndarray, shape (n2,)
        Their offsets.

    Returns
    -------
    points : ndarray, shape (n1, n2, 2)
    ok : ndarray of bool, shape (n1, n2)
        False where the lines are parallel (no unique crossing).
    """
    a, b = N1[:, None, 0], N1[:, None, 1]
    cc, d = N2[None, :, 0], N2[None, :, 1]
    det = a * d - b * cc
    ok = np.abs(det) > 1e-12
    sdet = np.where(ok, det, 1.0)
    x = (c1[:, None] * d - b * c2[None, :]) / sdet
    y = (a * c2[None, :] - cc * c1[:, None]) / sdet
    return np.stack([x, y], axis=-1), ok


@lru_cache(maxsize=128)
def _pairs(m: int) -> np.ndarray:
    """Flat indices ``i * m + j`` of the line pairs ``i < j``, in :func:`numpy.triu_indices` order."""
    iu, ju = np.triu_indices(m, k=1)
    return iu * m + ju


def nearest_point(P: np.ndarray, N: np.ndarray, c: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray] | None:
    """Exact nearest point to ``P`` of ``{x : N x <= c}`` (planar, small m).

    The nearest point is ``P`` itself, the foot of ``P`` on one line, or the
    crossing of two lines (as :func:`line_crossings`); the feasible candidate
    closest to ``P`` is it. Costs O(m^3) and is meant for the few lines of an
    active-set method.

    Parameters
    ----------
    P : array_like, shape (2,)
        The point to approach (for the solvers: the target of the objective,
        fixed frame, length unit).
    N : ndarray, shape (m, 2)
        Unit normals of the half-planes (the feet of ``P`` assume unit length).
    c : ndarray, shape (m,)
        Offsets, length unit.
    tol : float
        Feasibility and activity tolerance, length unit.

    Returns
    -------
    (x, active) or None
        The point and the indices of the half-planes active there (within
        ``tol``); ``None`` when the half-planes have no common point.
    """
    P = np.asarray(P, dtype=float)
    m = len(N)
    if m == 0:
        return P.copy(), np.zeros(0, int)
    r = N @ P - c
    if (r <= tol).all():
        return P.copy(), np.flatnonzero(np.abs(r) <= tol)
    a, b = N[:, 0], N[:, 1]
    # all pairs as (m, m) arrays, then the pairs i < j whose lines cross
    pair = _pairs(m)
    det = (a[:, None] * b - b[:, None] * a).ravel()[pair]
    ok = np.abs(det) > 1e-12
    pair, det = pair[ok], det[ok]
    X = np.empty((m + len(pair), 2))
    X[:m] = P - r[:, None] * N
    X[m:, 0] = (c[:, None] * b - b[:, None] * c).ravel()[pair] / det
    X[m:, 1] = (a[:, None] * c - a * c[:, None]).ravel()[pair] / det
    feas = (X @ N.T <= c + tol).all(axis=1)
    if not feas.any():
        return None
    X = X[feas]
    d = X - P
    x = X[np.argmin(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1])]
    return x, np.flatnonzero(np.abs(N @ x - c) <= tol)


def clip_polygon(N: np.ndarray, c: np.ndarray, box: tuple[float, float, float, float]) -> np.ndarray:
    """Convex polygon ``{x : N x <= c}`` clipped to ``box = (xmin, ymin, xmax, ymax)``.

    Sutherland-Hodgman against each half-plane in turn.

    Parameters
    ----------
    N : ndarray, shape (m, 2)
        Outward normals of the half-planes.
    c : ndarray, shape (m,)
        Their offsets.
    box : (xmin, ymin, xmax, ymax)
        The clipping rectangle, in the frame and unit of the half-planes.

    Returns
    -------
    ndarray, shape (k, 2)
        The vertices counter-clockwise, shape (0, 2) when the intersection is
        empty.
    """
    x0, y0, x1, y1 = box
    poly = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]], dtype=float)
    for n, cc in zip(N, c):
        if len(poly) == 0:
            break
        s = poly @ n - cc
        inside = s <= 0
        if np.all(inside):
            continue
        out = []
        m = len(poly)
        for j in range(m):
            p, q = poly[j], poly[(j + 1) % m]
            sp, sq = s[j], s[(j + 1) % m]
            if sp <= 0:
                out.append(p)
            if (sp <= 0) != (sq <= 0):
                t = sp / (sp - sq)
                out.append(p + t * (q - p))
        poly = np.array(out) if out else np.zeros((0, 2))
    return poly
