"""Admissible centres on a circle: a fixed centre distance L (seed 3.23-3.25) or a fixed R0.

The admissible part of a circle is found by scanning the circle against a
sampled zone and refining each end of every admissible arc by root finding
(``brentq``) on the largest violation over the continuous zone. Among the
admissible points the one that minimizes a given objective is kept (for a
fixed L: the least R0, i.e. the seed's "larger x").
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from cams.model.design import CamDesign
from optimize.planar import EPS
from optimize.zone import max_violation, sample_wedges

__all__ = ["admissible_arcs", "best_on_circle", "violation_function", "crossing_seed", "round_off",
           "admissible_at_distance"]


def round_off(design: CamDesign, magnitude: float) -> float:
    """Rounding allowed on the violation ``G(O)`` of a centre whose coordinates are of size ``magnitude``.

    ``G`` compares ``n . O`` with the zone lines' offsets, of the order of
    ``|O|`` near the lines that bind and of the design's size
    (``design.scale``) otherwise; the tolerance follows both, never a fixed
    fraction of the follower's size alone.

    Parameters
    ----------
    design : CamDesign
    magnitude : float
        Size of the coordinates compared (length unit), e.g. ``|O|_1``.

    Returns
    -------
    float
        Length unit.
    """
    return EPS * (float(magnitude) + design.scale)


def violation_function(design: CamDesign, samples: int | None) -> Callable[[np.ndarray], float]:
    """Largest signed distance outside the zone: continuous (``samples=None``) or sampled.

    Parameters
    ----------
    design : CamDesign
    samples : int or None
        Steps per constrained phase of the sampled zone
        (:func:`optimize.zone.sample_wedges`); None for the continuous zone
        (:func:`optimize.zone.max_violation`).

    Returns
    -------
    callable
        ``G(O) -> float`` for a cam centre ``O`` (shape (2,), the follower's
        fixed frame of :mod:`cams.model.follower`): the largest signed distance of
        ``O`` outside the zone's half-planes, length unit; positive outside,
        <= 0 inside (minus the smallest slack).
    """
    if samples is None:
        return lambda O: max_violation(design, O)[0].value
    N, c = sample_wedges(design, samples).lines()
    return lambda O: float(np.max(N @ O - c))


def admissible_arcs(
    design: CamDesign,
    centre: np.ndarray,
    radius: float,
    *,
    samples: int | None = None,
    scan: int = 1440,
    seeds: tuple[float, ...] = (),
) -> list[tuple[float, float]]:
    """Angular intervals ``(a, b)`` (radians, a < b) of the circle inside the zone.

    The circle is ``centre + radius (cos t, sin t)``; an interval covering the
    whole circle is ``(0, 2 pi)``. Ends are refined on the continuous zone to
    ``~1e-13`` radians, on the continuous zone (``samples=None``) or on the
    zone sampled with ``samples`` steps per phase.

    ``seeds`` are angles known to be admissible (e.g. from convexity: where a
    segment between two admissible centres crosses the circle); an arc too
    narrow for the scan is found around them.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Centre of the circle in the follower's fixed frame (:mod:`cams.model.follower`),
        length unit: the rocker pivot for a fixed L, the roller centre A0 at
        the near dwell for a fixed R0.
    radius : float
        Radius of the circle, length unit.
    samples : int or None, optional
        Steps per constrained phase of the zone the ends are refined on; None:
        the continuous zone.
    scan : int, optional
        Points of the first scan round the circle.
    seeds : tuple of float, optional
        Admissible angles ``t``, radians.

    Returns
    -------
    list of (float, float)
        Intervals ``(a, b)`` of the angle ``t`` (radians, counter-clockwise from
        the frame's +X), ``a < b``; not reduced to [0, 2 pi): an arc across
        ``t = 0`` ends beyond 2 pi (or starts below 0). Empty when the circle
        misses the zone.
    """
    centre = np.asarray(centre, float)
    arcs = _scanned_arcs(design, centre, radius, samples, scan)
    G = violation_function(design, samples)
    at = lambda a: G(centre + radius * np.array([np.cos(a), np.sin(a)]))  # noqa: E731
    # a seed is admissible up to the rounding of the numbers compared (not a fraction of the follower's size)
    tol = round_off(design, float(np.abs(centre).sum()) + 2.0 * radius)
    for s in seeds:
        covered = any((s - a) % (2 * np.pi) <= (b - a) + 1e-15 for a, b in arcs)
        if covered or at(s) > tol:
            continue
        ends, reach = [], []
        for sign in (-1.0, 1.0):
            # walk away from the seed in growing steps until a point outside: the arc's end lies in the last step
            d, inner, outer = 1e-12, 0.0, None
            while outer is None and inner < 2 * np.pi:
                if at(s + sign * d) > 0:
                    outer = d
                else:
                    inner, d = d, min(4.0 * d, 2 * np.pi)
            if outer is None:  # admissible all the way round
                return [(0.0, 2 * np.pi)]
            lo, hi = sorted((s + sign * inner, s + sign * outer))
            ends.append(_refine(at, lo, hi) if at(lo) * at(hi) <= 0 else s + sign * inner)
            reach.append(inner)
        if sum(reach) >= 2 * np.pi:
            return [(0.0, 2 * np.pi)]
        arcs.append((ends[0], ends[1]))
    return arcs


def admissible_at_distance(
    design: CamDesign,
    centre: np.ndarray,
    radius: float,
    target: np.ndarray,
    distance: float,
    *,
    samples: int | None = None,
    seeds: tuple[float, ...] = (),
) -> list[np.ndarray]:
    """Admissible points of the circle (``centre``, ``radius``) at ``distance`` from ``target``.

    The crossings of the two circles, each kept when its angle lies on an
    admissible arc (:func:`admissible_arcs`, whose ends are refined on the
    zone): no tolerance on the violation. The angle's own round-off follows
    the conditioning of the crossing (two nearly concentric circles cross at
    an angle known only to ``eps * radius / |centre - target|``); a crossing
    within it of an arc's end is moved onto that end.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Centre of the circle, the follower's fixed frame, length unit (the
        rocker pivot for a fixed L).
    radius : float
        Its radius, length unit.
    target : array_like, shape (2,)
        The point the distance is measured from, same frame (the roller
        centre A0 for R0).
    distance : float
        Length unit.
    samples : int or None, optional
        As :func:`admissible_arcs`.
    seeds : tuple of float, optional
        Admissible angles on the circle, radians (see :func:`admissible_arcs`).

    Returns
    -------
    list of ndarray, shape (2,)
        Zero, one or two admissible points, same frame.
    """
    centre, target = np.asarray(centre, float), np.asarray(target, float)
    v = target - centre
    d = float(np.linalg.norm(v))
    if not d > 0:
        return []
    eps = np.finfo(float).eps
    # |centre + radius u - target| = distance  <=>  cos(t - base) = k; (r - D)(r + D) keeps the digits of r ~ D
    k = ((radius - distance) * (radius + distance) + d * d) / (2.0 * radius * d)
    dk = 8 * eps * (radius * radius + distance * distance + d * d) / (2.0 * radius * d)
    if abs(k) > 1 + dk:
        return []
    k = min(max(k, -1.0), 1.0)
    w = float(np.arccos(k))
    dt = dk / max(np.sin(w), np.sqrt(dk)) + 8 * eps * 2 * np.pi  # the angle's round-off
    base = float(np.arctan2(v[1], v[0]))
    arcs = admissible_arcs(design, centre, radius, samples=samples, seeds=seeds)
    out = []
    for t in {base + w, base - w}:
        for a, b in arcs:
            x = a + (t - a) % (2 * np.pi)  # in [a, a + 2 pi)
            if x <= b + dt:
                x = min(x, b)
            elif x >= a + 2 * np.pi - dt:
                x = a
            else:
                continue
            out.append(centre + radius * np.array([np.cos(x), np.sin(x)]))
            break
    return out


def crossing_seed(centre: np.ndarray, radius: float, inner: np.ndarray, outer: np.ndarray) -> float | None:
    """Angle where the segment from ``inner`` to ``outer`` crosses the circle.

    With both ends admissible, ``inner`` inside the circle and ``outer``
    outside, the crossing is admissible too (the zone is convex): a seed for
    :func:`admissible_arcs`.

    Parameters
    ----------
    centre : array_like, shape (2,)
        Centre of the circle, fixed frame, length unit.
    radius : float
        Its radius, length unit.
    inner, outer : ndarray, shape (2,)
        Ends of the segment, same frame: ``inner`` inside (or on) the circle,
        ``outer`` outside (or on) it.

    Returns
    -------
    float or None
        Angle ``t`` of the crossing on the circle ``centre + radius (cos t,
        sin t)``, radians in [0, 2 pi); None when the ends do not straddle the
        circle.
    """
    centre = np.asarray(centre, float)
    f = lambda s: float(np.linalg.norm(inner + s * (outer - inner) - centre) - radius)  # noqa: E731
    if f(0.0) > 0 or f(1.0) < 0:
        return None
    from laws.search import bracketed_root  # numpy's: importing scipy.optimize costs 0.3 s

    s = bracketed_root(f, 0.0, 1.0, xtol=1e-15) if f(0.0) < 0 < f(1.0) else (0.0 if f(0.0) == 0 else 1.0)
    p = inner + s * (outer - inner) - centre
    return float(np.arctan2(p[1], p[0]) % (2 * np.pi))


def _scanned_arcs(design, centre, radius, samples, scan) -> list[tuple[float, float]]:
    """Arcs found by scanning ``scan`` points against the sampled zone, ends refined."""
    t = np.linspace(0.0, 2 * np.pi, scan, endpoint=False)
    pts = centre + radius * np.stack([np.cos(t), np.sin(t)], axis=1)
    N, c = sample_wedges(design, samples or 256).lines()
    g = np.max(pts @ N.T - c, axis=1)
    G = violation_function(design, samples)
    at = lambda a: G(centre + radius * np.array([np.cos(a), np.sin(a)]))  # noqa: E731
    inside = g <= 0
    if not np.any(inside):
        return []
    if np.all(inside):
        return [(0.0, 2 * np.pi)]
    arcs = []
    k0 = int(np.argmin(inside))  # an outside point to start from
    n = len(t)
    k = k0
    for _ in range(n):
        k1 = (k + 1) % n
        if not inside[k] and inside[k1]:
            a0, a1 = t[k], t[k] + (t[k1] - t[k]) % (2 * np.pi)
            start = _refine(at, a0, a1)
            j = k1
            while inside[(j + 1) % n]:
                j = (j + 1) % n
            j1 = (j + 1) % n
            b0 = t[j] if t[j] >= start else t[j] + 2 * np.pi
            b1 = b0 + (t[j1] - t[j]) % (2 * np.pi)
            end = _refine(at, b0, b1)
            arcs.append((start, end if end > start else end + 2 * np.pi))
        k = k1
    return arcs


def _refine(at, a, b) -> float:
    """Root of the continuous violation between a and b (sign change expected)."""
    fa, fb = at(a), at(b)
    if fa * fb > 0:
        # the sampled scan and the continuum disagree at this resolution: keep the inner end
        return b if fb <= 0 else a
    from laws.search import bracketed_root  # numpy's: importing scipy.optimize costs 0.3 s

    return bracketed_root(at, a, b, xtol=1e-14, rtol=4 * np.finfo(float).eps)


def best_on_circle(
    design: CamDesign,
    centre: np.ndarray,
    radius: float,
    objective: Callable[[np.ndarray], float],
    *,
    samples: int | None = None,
    seeds: tuple[float, ...] = (),
) -> np.ndarray | None:
    """Admissible point of the circle that minimizes ``objective``; None if none.

    The objective is evaluated at the arcs' ends and on a fine grid inside each
    arc, then refined by Brent's bounded minimization (:func:`laws.search.grid_minimum`).

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Centre of the circle, the follower's fixed frame, length unit.
    radius : float
        Its radius, length unit.
    objective : callable
        ``objective(O) -> float`` of a cam centre ``O`` (shape (2,), same
        frame), to be minimized.
    samples : int or None, optional
        As :func:`admissible_arcs`: sampled zone, or None for the continuous one.
    seeds : tuple of float, optional
        Admissible angles on the circle, radians (see :func:`admissible_arcs`).

    Returns
    -------
    ndarray, shape (2,) or None
        The best admissible point of the circle (same frame), None when the
        circle misses the zone.
    """
    from laws.search import grid_minimum

    centre = np.asarray(centre, float)
    pt = lambda a: centre + radius * np.array([np.cos(a), np.sin(a)])  # noqa: E731
    best, best_val = None, np.inf
    for a, b in admissible_arcs(design, centre, radius, samples=samples, seeds=seeds):
        grid = np.linspace(a, b, 65)  # the arc's ends are samples
        x, v = grid_minimum(lambda t: objective(pt(t)), grid, [objective(pt(x)) for x in grid], xatol=1e-13)
        if v < best_val:
            best, best_val = pt(x), v
    return best
