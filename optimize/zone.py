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
    A = f.position(m.s)
    T = f.tangent(m.s)
    V = m.ds[:, None] * T
    e = T / np.linalg.norm(T, axis=-1, keepdims=True)
    D = A + design.cam_sense * cross_k(V)
    axis = -e
    n_a = rotate(axis, np.pi / 2 + limit)
    n_b = rotate(axis, -(np.pi / 2 + limit))
    lever = f.lever(m.s)
    # side t: the half-plane that shrinks when D moves outward along the lever
    a_is_t = np.einsum("ij,ij->i", n_a, lever) < 0
    n_t = np.where(a_is_t[:, None], n_a, n_b)
    n_t1 = np.where(a_is_t[:, None], n_b, n_a)
    K = design.limits.safety_factor
    ref = getattr(f, "arm", 0.0)
    D_t = D + (K - 1.0) * ref * lever
    D_t1 = D - (1.0 - 1.0 / K) * ref * lever
    normals = np.stack([n_t, n_t1], axis=1)
    apex = np.stack([D_t, D_t1], axis=1)
    offsets = np.einsum("ikj,ikj->ik", normals, apex)
    phi = design.program.starts[i] + u * design.program.phases[i].angle
    return Wedges(
        phase=np.full(len(u), i),
        phi=phi,
        normals=normals,
        offsets=offsets,
        apex=apex,
        limit=np.full(len(u), float(limit)),
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


def max_violation(
    design: CamDesign, centre: np.ndarray, *, grid: int = 192, iters: int = 48
) -> list[ViolationPeak]:
    """Local maxima over the continuum of every constraint's signed distance.

    For every constrained phase and both sides, the signed distance
    ``n(phi) . O - n(phi) . D(phi)`` is sampled on ``grid + 1`` positions, its
    local maxima (ends included) bracketed and refined by golden-section
    search (vectorized over all brackets) to ``~1e-10`` of the phase.

    Returns
    -------
    list of ViolationPeak
        Sorted by decreasing value; the first one is the largest violation
        (positive) or the smallest slack (negative).
    """
    O = np.asarray(centre, dtype=float)
    u = np.linspace(0.0, 1.0, grid + 1)
    peaks: list[ViolationPeak] = []
    gr = (np.sqrt(5.0) - 1.0) / 2.0
    for i, lim in design.constrained_phases():
        h = phase_wedges(design, i, lim, u).violation(O)  # (grid+1, 2)
        for k in (0, 1):
            y = h[:, k]
            left = np.concatenate([[-np.inf], y[:-1]])
            right = np.concatenate([y[1:], [-np.inf]])
            idx = np.nonzero((y >= left) & (y >= right))[0]
            if idx.size == 0:
                continue
            a = u[np.maximum(idx - 1, 0)]
            b = u[np.minimum(idx + 1, grid)]

            def f(x, k=k):
                return phase_wedges(design, i, lim, x).violation(O)[:, k]

            c = b - gr * (b - a)
            d = a + gr * (b - a)
            fc, fd = f(c), f(d)
            for _ in range(iters):
                go_left = fc > fd
                b = np.where(go_left, d, b)
                a = np.where(go_left, a, c)
                c_new = b - gr * (b - a)
                d_new = a + gr * (b - a)
                c_old, d_old = c, d
                c = np.where(go_left, c_new, d_old)
                d = np.where(go_left, c_old, d_new)
                fc_old, fd_old = fc, fd
                # one fresh evaluation per bracket: the other point is reused
                fresh = f(np.where(go_left, c, d))
                fc = np.where(go_left, fresh, fd_old)
                fd = np.where(go_left, fc_old, fresh)
            cand = np.stack([a, b, c, d, u[idx]])
            vals = np.stack([f(a), f(b), fc, fd, y[idx]])
            best = np.argmax(vals, axis=0)
            cols = np.arange(len(idx))
            for uu, vv in zip(cand[best, cols], vals[best, cols]):
                peaks.append(ViolationPeak(i, float(uu), k, float(vv)))
    peaks.sort(key=lambda p: -p.value)
    return peaks
