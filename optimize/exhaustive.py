"""The seed's all-pairs method (seed 001, formulas 3.19-3.22 and 3.26), completed.

Every t-t line (side 0 of a sampled position) is crossed with every t1-t1 line
(side 1): the seed's candidates. Read literally, the seed keeps the pair with
the largest R0, which can be the crossing of two nearly parallel lines far
outside the zone; here every candidate is ranked by the objective and the first
one that satisfies *every* sampled constraint is kept.

Those crossings are only some of the sampled zone's vertices: the nearest
admissible point to the target can also be a crossing of two lines of the same
side (two t-t lines, or two t1-t1 lines), the foot of the perpendicular from
the target on one line (the optimum on an edge), or the target itself. With
these candidates added the method returns the exact nearest point of the
sampled zone (the nearest point of a convex polygon is one of them), the same
point as :mod:`optimize.convex`, so it converges to :mod:`optimize.exact`'s
answer as the samples grow; the result states the distance from it
(``error_bound``, the gap to a point checked feasible on every cam angle).

Memory grows with the square of the samples (one candidate per pair of lines).
"""

from __future__ import annotations

import numpy as np

from cams.model.design import CamDesign
from laws.errors import InfeasibleError, InputError
from optimize.planar import line_crossings
from optimize.result import Binding, CentreSolution
from optimize.zone import sample_wedges

__all__ = ["nearest_exhaustive", "candidates", "first_admissible", "BYTES_PER_PAIR", "MAX_BYTES"]

#: Memory per candidate (coordinates, distance, masks, line indices; measured peak).
BYTES_PER_PAIR = 80
#: Largest all-pairs run started (bytes).
MAX_BYTES = 8e9


def candidates(N: np.ndarray, c: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Every point that can be the nearest point to ``target`` of ``{x : N x <= c}``.

    The lines come in pairs, two a sampled position: line ``2 i`` is the t-t
    line of position ``i``, line ``2 i + 1`` its t1-t1 line (the order of
    :meth:`optimize.zone.Wedges.lines`).

    Parameters
    ----------
    N : ndarray, shape (2 n, 2)
        Unit outward normals (fixed frame of the follower).
    c : ndarray, shape (2 n,)
        Offsets, length unit.
    target : ndarray, shape (2,)
        The point to approach, same frame and unit.

    Returns
    -------
    points : ndarray, shape (k, 2)
        In this order: the seed's crossings of every t-t line with every t1-t1
        line (3.19-3.22), the crossings of two t-t lines and of two t1-t1 lines,
        the feet of the perpendicular from ``target`` on every line, and
        ``target`` itself. Crossings of parallel lines are left out.
    lines : ndarray of int, shape (k, 2)
        The indices (into ``N``) of the lines each point lies on, ``-1`` for none.
    """
    T = np.asarray(target, dtype=float)
    m = len(N)
    idx = np.arange(m)
    pts, lines = [], []
    # the seed: every t-t line crossed with every t1-t1 line
    P, ok = line_crossings(N[0::2], c[0::2], N[1::2], c[1::2])
    i, j = np.nonzero(ok)
    pts.append(P[i, j])
    lines.append(np.stack([2 * i, 2 * j + 1], axis=1).astype(np.int32))
    # the vertices the seed does not see: two lines of the same side
    for side in (0, 1):
        P, ok = line_crossings(N[side::2], c[side::2], N[side::2], c[side::2])
        i, j = np.nonzero(np.triu(ok, k=1))
        pts.append(P[i, j])
        lines.append(np.stack([2 * i + side, 2 * j + side], axis=1).astype(np.int32))
    # the optimum on an edge: the foot of the perpendicular from the target on each line
    pts.append(T - (N @ T - c)[:, None] * N)
    lines.append(np.stack([idx, np.full(m, -1)], axis=1))
    # the target itself, when it is admissible
    pts.append(T[None])
    lines.append(np.array([[-1, -1]]))
    return np.concatenate(pts), np.concatenate(lines)


def first_admissible(points: np.ndarray, N: np.ndarray, c: np.ndarray, atol: np.ndarray) -> int | None:
    """Index of the first of ``points`` that satisfies every half-plane ``N x <= c + atol``.

    The same answer as testing the points one by one in order with
    :func:`optimize.planar.feasible_mask`, found quicker: the lines that
    rejected earlier points are tried first on the next ones (a point
    rejected by them is rejected), and only the points they let through are
    tested against every line, a few at a time.

    Parameters
    ----------
    points : ndarray, shape (k, 2)
        Candidates in their order of preference (same frame as the lines).
    N : ndarray, shape (m, 2)
        Unit outward normals.
    c : ndarray, shape (m,)
        Offsets (length unit).
    atol : ndarray, shape (k,)
        Allowed distance outside for each point (length unit).

    Returns
    -------
    int or None
        None when no point is admissible.
    """
    killers = np.zeros(0, dtype=int)
    start, chunk, batch = 0, 4096, 32
    while start < len(points):
        stop = min(len(points), start + chunk)
        rest = np.arange(start, stop)
        while len(rest):
            if len(killers):
                keep = np.all(points[rest] @ N[killers].T <= c[killers] + atol[rest, None], axis=1)
                rest = rest[keep]
            sub, rest = rest[:batch], rest[batch:]
            if not len(sub):
                break
            V = points[sub] @ N.T - c
            ok = np.all(V <= atol[sub, None], axis=1)
            if ok.any():
                return int(sub[np.argmax(ok)])
            killers = np.union1d(killers, np.argmax(V, axis=1))
        start, chunk = stop, 2 * chunk
    return None


def _by_distance(d: np.ndarray, first: int = 4096):
    """The indices of the finite ``d`` in increasing order, as successive bands of doubling size.

    The same order as a stable :func:`numpy.argsort`, without sorting the far
    candidates when a near one is admissible.
    """
    rest, k = np.flatnonzero(np.isfinite(d)), first
    while len(rest):
        # the candidates not yet yielded shrink with each band: the far ones are not scanned again
        if k < len(rest):
            dr = d[rest]
            near = dr <= np.partition(dr, k)[k]
            band, rest = rest[near], rest[~near]
        else:
            band, rest = rest, rest[:0]
        yield band[np.argsort(d[band], kind="stable")]
        k *= 2


def nearest_exhaustive(
    design: CamDesign,
    target: np.ndarray,
    *,
    samples: int,
    half_planes: tuple[np.ndarray, np.ndarray] | None = None,
    tol: float = 1e-9,
) -> CentreSolution:
    """Nearest admissible candidate to ``target``: the seed's crossings, completed.

    Parameters
    ----------
    design : CamDesign
    target : array_like, shape (2,)
        Roller centre at the near dwell (minimum R0) or rocker pivot (minimum
        L), in the follower's fixed frame (:mod:`cams.model.follower`), length unit.
    samples : int
        Steps per constrained phase (``samples + 1`` positions with both ends).
    half_planes : (N, c), optional
        Additional half-planes; a pair of opposite ones (a fixed offset line)
        is crossed with every sampled line instead, and the foot of the
        perpendicular from ``target`` on it is a candidate too.
    tol : float
        Feasibility tolerance, relative to the larger of the design's scale and
        the candidate's distance from the origin (the round-off of a crossing
        grows with its coordinates).

    Returns
    -------
    CentreSolution
        The centre, its distance to ``target`` (``objective``), the lines it
        lies on (``binding``) and ``error_bound``: the gap between this
        answer, the exact nearest point of the sampled zone (a lower bound of
        the continuous optimum), and a centre checked admissible on every cam
        angle (an upper bound), length unit; None when no such centre is found.

    Raises
    ------
    InputError
        A run that would need more than :data:`MAX_BYTES` of memory.
    InfeasibleError
        No candidate is admissible: the sampled zone is empty.
    """
    n = len(design.constrained_phases()) * (samples + 1)
    need = 2 * n * n * BYTES_PER_PAIR
    if need > MAX_BYTES:
        raise InputError(
            "solve.samples",
            f"the all-pairs method at {samples} steps per phase needs about {need / 1e9:.1f} GB (it grows with "
            f"the square of the samples; the limit is {MAX_BYTES / 1e9:.0f} GB): use fewer samples or the "
            "convex or exact method",
        )
    W = sample_wedges(design, samples)
    N_all, c_all = W.lines()
    T = np.asarray(target, dtype=float)
    if half_planes is not None and len(half_planes[0]):
        eN, ec = np.asarray(half_planes[0], float), np.asarray(half_planes[1], float)
        P, ok = line_crossings(eN[:1], ec[:1], N_all, c_all)
        k = np.nonzero(ok[0])[0]
        foot = T - (eN[0] @ T - ec[0]) * eN[0]
        pts = np.vstack([P[0][k], foot[None]])
        lines = np.concatenate([np.stack([k, np.full(len(k), -1)], axis=1), [[-1, -1]]])
        N_chk, c_chk = np.vstack([N_all, eN]), np.concatenate([c_all, ec])
        empty = InfeasibleError("follower.offset", "no admissible cam centre on the line of the fixed offset")
    else:
        pts, lines = candidates(N_all, c_all, T)
        N_chk, c_chk = N_all, c_all
        empty = InfeasibleError("limits.pressure_angle", "no cam centre satisfies the limits at the sampled "
                                "positions: the zone is empty")
    d = np.linalg.norm(pts - T, axis=1)
    best = None
    for band in _by_distance(d):
        atol = tol * np.maximum(design.scale, np.max(np.abs(pts[band]), axis=1))
        q = first_admissible(pts[band], N_chk, c_chk, atol)
        if q is not None:
            best = band[q]
            break
    if best is None:
        raise empty
    O = pts[best]
    binding = tuple(Binding.of_line(W, int(k)) for k in lines[best] if k >= 0)
    from optimize.convex import sampling_bound

    obj = float(np.linalg.norm(O - T))
    return CentreSolution(
        centre=np.asarray(O, dtype=float), objective=obj, method="exhaustive",
        samples=samples, binding=binding, error_bound=sampling_bound(design, O, T, obj),
        violation=float(np.max(W.violation(O))),
    )
