"""The seed's all-pairs method (seed 001, formulas 3.19-3.22 and 3.26), done right.

Every t-t line (side 0 of a sampled position) is crossed with every t1-t1 line
(side 1); the crossings are ranked by the objective and the first one that
satisfies *every* sampled constraint is kept. Read literally, the seed keeps the
pair with the largest R0, which can be the crossing of two nearly parallel
lines far outside the zone; checking each candidate against all constraints
keeps the zone's apex instead. The method only finds vertices of the sampled
zone: where the nearest admissible point lies on an edge, :mod:`optimize.convex`
and :mod:`optimize.exact` find a smaller cam. Memory grows with the square of
the samples (one crossing per pair).
"""

from __future__ import annotations

import numpy as np

from cams.design import CamDesign
from laws.errors import InfeasibleError, InputError
from optimize.planar import feasible_mask, line_crossings
from optimize.result import Binding, CentreSolution
from optimize.zone import sample_wedges

__all__ = ["nearest_exhaustive", "BYTES_PER_PAIR", "MAX_BYTES"]

#: Memory per crossing of a t-t and a t1-t1 line (coordinates, distance, mask, sort index; measured peak).
BYTES_PER_PAIR = 64
#: Largest all-pairs run started (bytes).
MAX_BYTES = 8e9


def nearest_exhaustive(
    design: CamDesign,
    target: np.ndarray,
    *,
    samples: int,
    extra: tuple[np.ndarray, np.ndarray] | None = None,
    tol: float = 1e-9,
) -> CentreSolution:
    """Best admissible crossing of a t-t and a t1-t1 line, nearest to ``target``.

    Parameters
    ----------
    design : CamDesign
    target : array_like, shape (2,)
        Roller centre at the near dwell (minimum R0) or rocker pivot (minimum L).
    samples : int
        Steps per constrained phase (``samples + 1`` positions with both ends).
    extra : (N, c), optional
        Additional half-planes; a pair of opposite ones (a fixed offset line)
        is crossed with every sampled line instead.
    tol : float
        Feasibility tolerance relative to the design's scale.
    """
    m = len(design.constrained_phases()) * (samples + 1)
    need = m * m * BYTES_PER_PAIR
    if need > MAX_BYTES:
        raise InputError(
            "solve.samples",
            f"the all-pairs method at {samples} steps per phase needs about {need / 1e9:.1f} GB (it grows with "
            f"the square of the samples; the limit is {MAX_BYTES / 1e9:.0f} GB): use fewer samples or the "
            "convex or exact method",
        )
    W = sample_wedges(design, samples)
    scale = design.scale
    atol = tol * scale
    N_all, c_all = W.lines()
    T = np.asarray(target, dtype=float)
    if extra is not None and len(extra[0]):
        eN, ec = np.asarray(extra[0], float), np.asarray(extra[1], float)
        pts, ok = line_crossings(eN[:1], ec[:1], N_all, c_all)
        cand = pts[0][ok[0]]
        pair_i = np.nonzero(ok[0])[0]
        N_chk, c_chk = np.vstack([N_all, eN]), np.concatenate([c_all, ec])
        d = np.linalg.norm(cand - T, axis=1)
        order = np.argsort(d)
        feas = feasible_mask(cand[order], N_chk, c_chk, atol)
        if not np.any(feas):
            raise InfeasibleError("follower.offset", "no admissible cam centre on the line of the fixed offset")
        k = order[np.argmax(feas)]
        binding = (Binding.of_line(W, pair_i[k]),)
        O = cand[k]
    else:
        pts, ok = line_crossings(W.normals[:, 0], W.offsets[:, 0], W.normals[:, 1], W.offsets[:, 1])
        d = np.where(ok, np.linalg.norm(pts - T, axis=-1), np.inf)
        flat = np.argsort(d, axis=None)
        flat = flat[np.isfinite(d.ravel()[flat])]
        pts2 = pts.reshape(-1, 2)
        O = None
        chunk = 256
        for start in range(0, len(flat), chunk):
            idx = flat[start : start + chunk]
            feas = feasible_mask(pts2[idx], N_all, c_all, atol)
            if np.any(feas):
                k = idx[np.argmax(feas)]
                O = pts2[k]
                i, j = np.unravel_index(k, d.shape)
                binding = (
                    Binding(int(W.phase[i]), float(W.phi[i]), 0),
                    Binding(int(W.phase[j]), float(W.phi[j]), 1),
                )
                break
        if O is None:
            raise InfeasibleError("limits.pressure_angle", "no crossing of t-t and t1-t1 lines is admissible: the zone is empty")
    viol = float(np.max(W.violation(O)))
    return CentreSolution(
        centre=np.asarray(O, dtype=float), objective=float(np.linalg.norm(O - T)), method="exhaustive",
        samples=samples, binding=binding, error_bound=None, violation=viol,
    )
