"""The sampled zone as an intersection of half-planes, solved with cvxpy.

Minimum R0 is the nearest admissible point to the roller's start point A0,
minimum L the nearest to the rocker pivot, and a weighted mix minimizes
``w_R0 |O - A0| + w_L |O - O1|``; all are second-order-cone programs. The
solver's answer to a nearest-point problem is polished by the exact nearest
point of the same sampled zone (:func:`optimize.planar.nearest_point`, O(m)
per step), so that it is the sampled optimum to rounding, whatever the
solver's own accuracy at the design's magnitudes.
cvxpy is imported here only.
"""

from __future__ import annotations

import numpy as np

from cams.model.design import CamDesign
from laws.errors import InfeasibleError
from optimize.planar import EPS, nearest_point
from optimize.result import Binding, CentreSolution
from optimize.zone import sample_wedges

__all__ = ["nearest_convex", "weighted_convex", "sampling_bound"]


def _solve(design, objective, samples, half_planes):
    import cvxpy as cp

    W = sample_wedges(design, samples)
    N, c = W.lines()
    s = design.scale  # a unit for the variables, not a tolerance: the result is checked on the continuum after
    x = cp.Variable(2)
    cons = [N @ x <= c / s]
    if half_planes is not None and len(half_planes[0]):
        cons.append(np.asarray(half_planes[0]) @ x <= np.asarray(half_planes[1]) / s)
    prob = cp.Problem(cp.Minimize(objective(x, s)), cons)
    try:
        prob.solve()
    except cp.error.SolverError as e:  # pragma: no cover - solver failure is reported
        raise InfeasibleError("solve.method", f"the convex solver failed: {e}") from e
    if prob.status not in ("optimal", "optimal_inaccurate") or x.value is None:
        raise InfeasibleError("limits.pressure_angle",
                              f"no cam centre satisfies the limits (solver status: {prob.status})")
    return W, N, c, np.asarray(x.value) * s


def _binding(W, N, O, c, atol):
    h = N @ O - c
    act = np.nonzero(h >= -atol)[0]
    return tuple(Binding.of_line(W, int(k)) for k in act), act


def nearest_convex(
    design: CamDesign,
    target: np.ndarray,
    *,
    samples: int,
    half_planes: tuple[np.ndarray, np.ndarray] | None = None,
    tol: float = 1e-9,
) -> CentreSolution:
    """Admissible centre nearest to ``target`` over the sampled zone (cvxpy).

    Parameters as :func:`optimize.exhaustive.nearest_exhaustive`.
    """
    import cvxpy as cp

    T = np.asarray(target, dtype=float)
    W, N, c, O = _solve(design, lambda x, s: cp.norm(x - T / s), samples, half_planes)
    # polish: the exact nearest point of the same sampled zone (and the half_planes half-planes)
    eN = np.zeros((0, 2)) if half_planes is None else np.asarray(half_planes[0], float)
    ec = np.zeros(0) if half_planes is None else np.asarray(half_planes[1], float)
    res = nearest_point(T, np.vstack([N, eN]), np.concatenate([c, ec]))
    if res is not None:
        O = res[0]
    binding, _ = _binding(W, N, O, c, tol * _magnitude(design, T, O))
    obj = float(np.linalg.norm(O - T))
    return CentreSolution(
        centre=O, objective=obj, method="convex", samples=samples,
        binding=binding, error_bound=sampling_bound(design, O, T, obj), violation=float(np.max(N @ O - c)),
    )


def _magnitude(design: CamDesign, *points: np.ndarray) -> float:
    """Size of the numbers a signed distance compares: the points' coordinates and the design's lengths."""
    return float(design.scale + sum(np.abs(p).sum() for p in points))


def sampling_bound(design: CamDesign, O: np.ndarray, T: np.ndarray, obj: float) -> float | None:
    """Gap between the sampled optimum (a lower bound) and a feasible point of the continuum, with the rounding.

    ``obj = |O - T|`` is the sampled zone's nearest distance (a relaxation of
    the continuous zone); the point moved inside by
    :func:`optimize.bounds.push_inside` bounds the optimum from above.

    Returns
    -------
    float or None
        The gap (mm); None when no feasible point was found to bound it.
    """
    from optimize.bounds import push_inside
    from optimize.zone import max_violation

    v = max_violation(design, O)[0].value
    f = push_inside(design, O, v)
    if f is None:
        return None
    return float(abs(np.linalg.norm(f - T) - obj) + EPS * _magnitude(design, T, f))


def weighted_convex(
    design: CamDesign, points: list[np.ndarray], weights: list[float], *, samples: int
) -> CentreSolution:
    """Minimize ``sum w_k |O - P_k|`` over the sampled zone (e.g. R0 and L together)."""
    import cvxpy as cp

    pts = [np.asarray(p, float) for p in points]
    W, N, c, O = _solve(
        design, lambda x, s: sum(w * cp.norm(x - p / s) for w, p in zip(weights, pts, strict=True)), samples, None
    )
    binding, _ = _binding(W, N, O, c, 1e-6 * _magnitude(design, O))
    obj = float(sum(w * np.linalg.norm(O - p) for w, p in zip(weights, pts, strict=True)))
    return CentreSolution(centre=O, objective=obj, method="convex", samples=samples, binding=binding,
                          violation=float(np.max(N @ O - c)))
