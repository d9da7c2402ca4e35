"""The allowable-centre zone: one wedge of admissible cam centres per position.

Geometry (DOMAIN.md, seed 001 eqs. 3.15-3.22)
----------------------------------------------
For a follower whose roller centre A moves with the analogue velocity
``V = dA/dphi``, the relative velocity of A with respect to a cam turning with
sense ``eps`` about a centre O is ``|w| (V - eps k x (A - O))
= |w| eps k x (O - D)`` with the instant point

    D = A + eps * k x V.

So the contact normal is parallel to D - O, pointing from O towards D (the
outward normal of the pitch curve). The pressure angle is the angle between
D - O and the direction e in which A moves on the rise; ``gamma <= [gamma]``
with the cam pushing (the physical branch) means O lies in the wedge with apex
D, axis -e and half-angle [gamma]. For a rocker D lies on the rocker line with
O1 D = l (1 - q), q = omega_rocker / omega_cam (seed: l (1 + psi')).

Each wedge is two half-planes ``n . O <= n . D`` (n unit). Side "t" is the one
whose half-plane shrinks when D moves outward along the lever (the seed's t-t
line of the rise), side "t1" the other (seed's t1-t1). The safety factor K_C
(seed 3.26) moves D along the lever by ``(K_C - 1) l`` for side t and by
``-(1 - 1/K_C) l`` for side t1, shifting both lines into the zone.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.design import CamDesign

__all__ = ["Wedges", "wedges", "phase_wedges", "sample_wedges", "max_violation", "ViolationPeak"]


def cross_k(v: np.ndarray) -> np.ndarray:
    """``k x v`` for planar vectors (last axis of size 2): (x, y) -> (-y, x)."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def rotate(v: np.ndarray, angle: np.ndarray) -> np.ndarray:
    """Rotate planar vectors ``v`` by ``angle`` (radians, counter-clockwise)."""
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


@dataclass(frozen=True)
class Wedges:
    """Constraint wedges at a set of cam positions.

    Attributes
    ----------
    phase : ndarray of int, shape (n,)
        Index of the phase in the program.
    phi : ndarray, shape (n,)
        Cam angle, radians from the start of the cycle.
    normals : ndarray, shape (n, 2, 2)
        Unit outward normals of side t (``[:, 0]``) and side t1 (``[:, 1]``).
    offsets : ndarray, shape (n, 2)
        The centre O is admissible at this position when
        ``normals[i, k] . O <= offsets[i, k]`` for both k.
    apex : ndarray, shape (n, 2, 2)
        Point D of each side (with the K_C shift), fixed frame.
    limit : ndarray, shape (n,)
        Allowable pressure angle, radians.
    """

    phase: np.ndarray
    phi: np.ndarray
    normals: np.ndarray
    offsets: np.ndarray
    apex: np.ndarray
    limit: np.ndarray

    def __len__(self) -> int:
        return len(self.phi)

    def lines(self) -> tuple[np.ndarray, np.ndarray]:
        """All half-planes as ``(N (2n, 2), c (2n,))`` with ``N O <= c``."""
        return self.normals.reshape(-1, 2), self.offsets.reshape(-1)

    def violation(self, centre: np.ndarray) -> np.ndarray:
        """Signed distance of ``centre`` outside each half-plane, shape (n, 2)."""
        return self.normals @ np.asarray(centre, dtype=float) - self.offsets


def phase_wedges(design: CamDesign, i: int, limit: float, u: np.ndarray) -> Wedges:
    """Wedges of phase ``i`` at normalized positions ``u`` (one-sided at its ends)."""
    f = design.follower
    u = np.asarray(u, dtype=float)
    m = design.program.evaluate_phase(i, u)
    A, T, lever = f.frame(m.s)
    Tx, Ty = T[:, 0], T[:, 1]
    inv = 1.0 / np.sqrt(Tx * Tx + Ty * Ty)
    # D = A + eps k x V, V = ds T
    g = design.cam_sense * m.ds
    Dx = A[:, 0] - g * Ty
    Dy = A[:, 1] + g * Tx
    # normals: the wedge axis -e turned by +-(90 deg + limit)
    cs, sn = -np.sin(limit), np.cos(limit)
    ax, ay = -Tx * inv, -Ty * inv
    nax, nay = cs * ax - sn * ay, sn * ax + cs * ay
    nbx, nby = cs * ax + sn * ay, -sn * ax + cs * ay
    lx, ly = lever[:, 0], lever[:, 1]
    # side t: the half-plane that shrinks when D moves outward along the lever
    a_is_t = (nax * lx + nay * ly) < 0
    n = len(u)
    normals = np.empty((n, 2, 2))
    normals[:, 0, 0] = np.where(a_is_t, nax, nbx)
    normals[:, 0, 1] = np.where(a_is_t, nay, nby)
    normals[:, 1, 0] = np.where(a_is_t, nbx, nax)
    normals[:, 1, 1] = np.where(a_is_t, nby, nay)
    apex = np.empty((n, 2, 2))
    K = design.limits.safety_factor
    if K != 1.0:
        ref = getattr(f, "arm", 0.0)
        kt, kt1 = (K - 1.0) * ref, -(1.0 - 1.0 / K) * ref
        apex[:, 0, 0], apex[:, 0, 1] = Dx + kt * lx, Dy + kt * ly
        apex[:, 1, 0], apex[:, 1, 1] = Dx + kt1 * lx, Dy + kt1 * ly
    else:
        apex[:, 0, 0] = apex[:, 1, 0] = Dx
        apex[:, 0, 1] = apex[:, 1, 1] = Dy
    offsets = normals[:, :, 0] * apex[:, :, 0] + normals[:, :, 1] * apex[:, :, 1]
    p = design.program.phases[i]
    phi = float(sum(q.angle for q in design.program.phases[:i])) + u * p.angle
    return Wedges(
        phase=np.full(n, i),
        phi=phi,
        normals=normals,
        offsets=offsets,
        apex=apex,
        limit=np.full(n, float(limit)),
    )


def _concat(parts: list[Wedges]) -> Wedges:
    return Wedges(*(np.concatenate([getattr(p, k) for p in parts]) for k in Wedges.__dataclass_fields__))


def wedges(design: CamDesign, positions: dict[int, np.ndarray]) -> Wedges:
    """Wedges at given normalized positions ``{phase index: u array}``."""
    limits = dict(design.constrained_phases())
    return _concat([phase_wedges(design, i, limits[i], np.asarray(u, float)) for i, u in positions.items()])


def sample_wedges(design: CamDesign, samples: int) -> Wedges:
    """Wedges at ``samples + 1`` evenly spaced positions of every constrained phase."""
    u = np.linspace(0.0, 1.0, samples + 1)
    return wedges(design, {i: u for i, _ in design.constrained_phases()})


@dataclass(frozen=True)
class ViolationPeak:
    """A local maximum of a side's signed distance over a phase."""

    phase: int
    u: float
    side: int
    value: float


def _violation_mixed(design: CamDesign, phases: list[tuple[int, float]], which: np.ndarray, u: np.ndarray,
                     O: np.ndarray) -> np.ndarray:
    """Signed distances (n, 2) at positions ``u`` of constrained phases ``phases[which]``."""
    out = np.empty((len(u), 2))
    for j, (i, lim) in enumerate(phases):
        m = which == j
        if np.any(m):
            out[m] = phase_wedges(design, i, lim, u[m]).violation(O)
    return out


def max_violation(
    design: CamDesign, centre: np.ndarray, *, grid: int = 128, iters: int = 5
) -> list[ViolationPeak]:
    """Local maxima over the continuum of every constraint's signed distance.

    For every constrained phase and both sides, the signed distance
    ``n(phi) . O - n(phi) . D(phi)`` is sampled on ``grid + 1`` positions; each
    local maximum (ends included) is refined by successive parabolic
    interpolation on a shrinking three-point stencil, vectorized over all peaks
    of all phases; it converges superlinearly on the smooth laws. The best value
    seen is kept, so refinement can only raise a peak.

    Returns
    -------
    list of ViolationPeak
        Sorted by decreasing value; the first one is the largest violation
        (positive) or the smallest slack (negative).
    """
    O = np.asarray(centre, dtype=float)
    phases = design.constrained_phases()
    if not phases:
        return [ViolationPeak(-1, 0.0, 0, -np.inf)]
    # an even grid plus geometric steps into both ends, where laws start from rest
    # and a peak can sit much closer to the end than one cell
    ends = np.geomspace(1e-7, 0.5 / grid, 8)
    u = np.unique(np.concatenate([np.linspace(0.0, 1.0, grid + 1), ends, 1.0 - ends]))
    m_u = len(u)
    gaps = np.diff(u)
    P = len(phases)
    which_g = np.repeat(np.arange(P), m_u)
    h = _violation_mixed(design, phases, which_g, np.tile(u, P), O).reshape(P, m_u, 2)
    y = np.moveaxis(h, 2, 1)  # (P, 2, grid+1)
    pad = np.full(y.shape[:2] + (1,), -np.inf)
    left = np.concatenate([pad, y[..., :-1]], axis=2)
    right = np.concatenate([y[..., 1:], pad], axis=2)
    pj, side, idx = np.nonzero((y >= left) & (y >= right))
    n = len(idx)
    rows = np.arange(n)
    best_u = u[idx]
    best_v = y[pj, side, idx]
    c = best_u.copy()
    # first stencil: the smaller neighbouring gap of each grid peak
    left_gap = np.where(idx > 0, gaps[np.maximum(idx - 1, 0)], np.inf)
    right_gap = np.where(idx < m_u - 1, gaps[np.minimum(idx, m_u - 2)], np.inf)
    step0 = np.minimum(left_gap, right_gap)
    step = step0.copy()
    for _ in range(iters):
        lo = np.clip(c - step, 0.0, 1.0)
        hi = np.clip(c + step, 0.0, 1.0)
        vv = _violation_mixed(design, phases, np.tile(pj, 3), np.concatenate([lo, c, hi]), O)
        flo, fc, fhi = vv[:n][rows, side], vv[n:2 * n][rows, side], vv[2 * n:][rows, side]
        for x, fx in ((lo, flo), (c, fc), (hi, fhi)):
            better = fx > best_v
            best_u = np.where(better, x, best_u)
            best_v = np.where(better, fx, best_v)
        # parabola through (lo, flo), (c, fc), (hi, fhi): vertex offset from c
        a1, a2 = lo - c, hi - c
        d1, d2 = flo - fc, fhi - fc
        den = a1 * a2 * (a1 - a2)
        ok = den != 0
        sden = np.where(ok, den, 1.0)
        A = np.where(ok, (d1 * a2 - d2 * a1) / sden, 0.0)
        B = np.where(ok, (d2 * a1 * a1 - d1 * a2 * a2) / sden, 0.0)
        concave = A < 0
        shift = np.where(concave, -B / (2 * np.where(concave, A, -1.0)), 0.0)
        shift = np.clip(shift, -step, step)
        c = np.where(concave, np.clip(best_u + (c + shift - best_u), 0.0, 1.0), best_u)
        step = np.clip(np.abs(shift) * 4.0, step * 1e-4, step0)
    vv = _violation_mixed(design, phases, pj, c, O)[rows, side]
    better = vv > best_v
    best_u = np.where(better, c, best_u)
    best_v = np.where(better, vv, best_v)
    order = np.argsort(-best_v, kind="stable")
    return [ViolationPeak(phases[pj[k]][0], float(best_u[k]), int(side[k]), float(best_v[k])) for k in order]
