"""Reference computations that share none of the product's formulas.

Nothing here imports :mod:`optimize.zone`, :mod:`optimize.planar` or
:mod:`cams.verify.pressure`. Only the motion program (``laws``, the lift ``s(phi)``
of a phase) and the design's data (arm, senses, limits, read from the object
built by :mod:`cams.io.designfile`) are taken from the product.

The pressure angle is computed from positions only, by kinematic inversion:

1. the roller-centre path in the fixed frame, ``A(s)``, written here from the
   frame definitions (rocker: pivot O1 at the origin, X along the rocker at
   the near dwell, CCW positive, ``A = l (cos(sigma psi), sin(sigma psi))``
   with ``sigma = +1`` for a counter-clockwise rise; translating: origin at
   A0, Y along the rise, ``A = (0, s)``);
2. the position of the roller centre on the cam (the pitch curve) at cam
   angle ``phi``: ``P(phi) = Rot(-eps phi) (A(s(phi)) - O)``, ``eps`` the
   cam's sense (+1 CCW);
3. the pitch-curve tangent by a 4th-order finite difference of ``P`` over
   ``phi`` (central inside the phase, one-sided at the phase ends, so that
   the stencil never leaves the phase: the constraint of a phase uses the
   one-sided limits at its ends; one-sided also next to a piecewise law's
   breakpoints, ``Law.breakpoints``, where a higher derivative jumps), turned
   back to the fixed frame by ``Rot(eps phi)``;
4. the outward normal: ``P`` winds once round O in the sense ``-eps`` (the
   cam turns ``+eps``), so the region bounded by the pitch curve lies to the
   right of the direction of travel for ``eps = +1`` and to the left for
   ``eps = -1``; the outward normal is the tangent turned by ``eps * 90 deg``;
5. the force on the roller: the outward normal on a rise (the cam pushes the
   roller away), the inward normal on a form-closed return (the other groove
   wall pushes it back);
6. the roller centre's velocity direction: central difference of the fixed
   path over its own parameter (``A(s + d) - A(s - d)``, exact for a line and
   for a circle's chord), oriented with the phase (increasing ``s`` on a
   rise, decreasing on a return). Taking it along the path, not over
   ``phi``, keeps it defined where ``ds/dphi = 0`` (phase ends);
7. ``gamma = angle(force, velocity)`` in [0, pi]; above 90 deg the cam would
   pull instead of push (wrong branch).

Many centres at once: the finite difference is linear in O, so for fixed
positions ``t_cam(O) = a - B O`` with ``a = sum w_j Rot(-eps phi_j) A_j / h``
and ``B = sum w_j Rot(-eps phi_j) / h``; ``cos gamma = t_cam . q / |t_cam|``
with ``q = sigma Rot(-eps phi - eps 90 deg) v``. :class:`ReferenceZone`
evaluates that; a test checks it against :func:`pressure_angles` point by
point.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import minimize_scalar

__all__ = [
    "Spec", "spec_of", "path", "pressure_angles", "max_pressure", "ReferenceZone",
    "brute_force_nearest", "brute_force_on_line", "seed_lines", "seed_crossings", "seed_all_pairs", "max_excess",
]

#: Cam-angle step of the pitch-curve finite difference, radians.
H_PHI = 2e-4
#: Path-parameter step of the velocity-direction difference (relative to the lift).
D_PATH = 1e-4

# 4th-order first-derivative stencils (offsets in steps, weights / step)
_CENTRAL = (np.array([-2, -1, 1, 2]), np.array([1.0, -8.0, 8.0, -1.0]) / 12.0)
_FORWARD = (np.array([0, 1, 2, 3, 4]), np.array([-25.0, 48.0, -36.0, 16.0, -3.0]) / 12.0)
_BACKWARD = (-_FORWARD[0], -_FORWARD[1])


@dataclass(frozen=True)
class Spec:
    """The data of a design, read off the product's design object."""

    kind: str               # "rocker" | "translating"
    arm: float              # rocker arm (0 for translating)
    sigma: int              # rocker's sense on the rise, +1 CCW
    eps: int                # cam's sense, +1 CCW
    program: object         # laws.program.Program
    closure: str
    rise_limit: float
    return_limit: float
    scale: float

    def constrained(self) -> list[tuple[int, float, int]]:
        """(phase index, limit, +1 rise / -1 return) of the limited phases."""
        out = []
        for i, p in enumerate(self.program.phases):
            if p.kind == "rise":
                out.append((i, self.rise_limit, 1))
            elif p.kind == "return" and self.closure == "form":
                out.append((i, self.return_limit, -1))
        return out


def spec_of(design) -> Spec:
    """Read the data of a :class:`cams.model.design.CamDesign` (no formulas)."""
    f = design.follower
    lim = design.limits
    ret = lim.pressure_angle if lim.return_pressure_angle is None else lim.return_pressure_angle
    if f.kind == "rocker":
        return Spec("rocker", float(f.arm), int(f.sense), int(design.cam_sense), design.program,
                    lim.closure, float(lim.pressure_angle), float(ret), float(f.arm))
    return Spec("translating", 0.0, 1, int(design.cam_sense), design.program,
                lim.closure, float(lim.pressure_angle), float(ret), float(design.program.lift))


def path(spec: Spec, s) -> np.ndarray:
    """Roller centre in the fixed frame at displacement ``s``; shape ``s.shape + (2,)``."""
    s = np.asarray(s, dtype=float)
    if spec.kind == "rocker":
        th = spec.sigma * s
        return spec.arm * np.stack([np.cos(th), np.sin(th)], axis=-1)
    return np.stack([np.zeros_like(s), s], axis=-1)


def _rot(v: np.ndarray, a) -> np.ndarray:
    """Rotate planar vectors by angles ``a`` (CCW)."""
    c, s = np.cos(a), np.sin(a)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def _stencils(u: np.ndarray, hu: float, breaks=()):
    """Per position: offsets (K, 5) in steps and weights (K, 5); padded with zero weights.

    Central where the stencil fits inside the phase without straddling one of
    the law's ``breaks`` (where a piecewise law's pieces meet and a higher
    derivative jumps, which would spoil the difference's order); otherwise
    one-sided, away from the end or break.
    """
    K = len(u)
    off = np.zeros((K, 5))
    w = np.zeros((K, 5))
    central = (u - 2 * hu >= 0) & (u + 2 * hu <= 1)
    fwd_ok = u + 4 * hu <= 1
    for b in breaks:
        central &= ~((u - 2 * hu < b) & (u + 2 * hu > b))
        fwd_ok &= ~((u < b) & (u + 4 * hu > b))
    fwd = ~central & fwd_ok
    bwd = ~central & ~fwd
    off[central, :4], w[central, :4] = _CENTRAL
    off[fwd], w[fwd] = _FORWARD
    off[bwd], w[bwd] = _BACKWARD
    return off, w


@dataclass(frozen=True)
class _Positions:
    phi: np.ndarray        # (K,) cam angle
    s: np.ndarray          # (K,) displacement
    phi_j: np.ndarray      # (K, 5) stencil cam angles
    A_j: np.ndarray        # (K, 5, 2) stencil roller centres (fixed frame)
    w: np.ndarray          # (K, 5) weights / h
    v: np.ndarray          # (K, 2) unit velocity direction
    sigma: np.ndarray      # (K,) +1 rise, -1 return
    limit: np.ndarray      # (K,)


def _positions(spec: Spec, phase: int, u, kind_sign: int, limit: float) -> _Positions:
    prog = spec.program
    p = prog.phases[phase]
    u = np.atleast_1d(np.asarray(u, dtype=float))
    start = prog.starts[phase]
    hu = H_PHI / p.angle
    off, w = _stencils(u, hu, tuple(getattr(p.law, "breakpoints", ())))
    uj = np.clip(u[:, None] + off * hu, 0.0, 1.0)
    phi_j = start + uj * p.angle
    s_j = prog.evaluate_phase(phase, uj).s
    A_j = path(spec, s_j)
    s = prog.evaluate_phase(phase, u).s
    d = D_PATH * (1.0 if spec.kind == "rocker" else spec.scale)
    dv = kind_sign * (path(spec, s + d) - path(spec, s - d))
    v = dv / np.linalg.norm(dv, axis=-1, keepdims=True)
    K = len(u)
    return _Positions(start + u * p.angle, s, phi_j, A_j, w / H_PHI, v,
                      np.full(K, float(kind_sign)), np.full(K, float(limit)))


def pressure_angles(design, centre, phase: int, u) -> np.ndarray:
    """Reference pressure angle (radians, [0, pi]) in ``phase`` at normalized ``u``.

    Literal version, one centre: invert the stencil's roller centres about
    ``centre``, difference them, turn the tangent back, take the outward
    normal, the force and the velocity direction, and the angle between them.
    """
    spec = spec_of(design)
    kind = spec.program.phases[phase].kind
    if kind == "dwell":
        raise ValueError("a dwell has no pressure angle to limit")
    sign = 1 if kind == "rise" else -1
    lim = spec.rise_limit if sign > 0 else spec.return_limit
    P = _positions(spec, phase, u, sign, lim)
    O = np.asarray(centre, dtype=float)
    eps = spec.eps
    inverted = _rot(P.A_j - O, -eps * P.phi_j)                       # pitch-curve points
    t_cam = np.einsum("kj,kjd->kd", P.w, inverted)                   # d P / d phi
    t_fix = _rot(t_cam, eps * P.phi)                                 # back to the fixed frame
    n_out = _rot(t_fix, eps * np.pi / 2)                             # outward normal
    force = P.sigma[:, None] * n_out                                 # rise: outward, return: inward
    c = np.sum(force * P.v, axis=-1) / np.linalg.norm(force, axis=-1)
    return np.arccos(np.clip(c, -1.0, 1.0))


def max_pressure(design, centre, *, n: int = 2000, all_phases: bool = False, peaks: int = 8) -> dict[int, float]:
    """Largest reference pressure angle of every limited phase: {phase: radians}.

    ``n + 1`` evenly spaced positions per phase; each of the ``peaks`` highest
    local maxima (phase ends included) refined by a bounded scalar search
    between its neighbours (the highest sample alone would miss a second peak
    that the sampling lowered). ``all_phases``: every rise
    and return, limited or not (a force-closed return: the cam's outward
    normal against the roller's returning velocity, the same angle).
    """
    spec = spec_of(design)
    out = {}
    u = np.linspace(0.0, 1.0, n + 1)
    if all_phases:
        phases = [i for i, p in enumerate(spec.program.phases) if p.kind != "dwell"]
    else:
        phases = [i for i, _, _ in spec.constrained()]
    for i in phases:
        g = pressure_angles(design, centre, i, u)
        best = float(np.max(g))
        local = np.flatnonzero((g >= np.r_[-1.0, g[:-1]]) & (g >= np.r_[g[1:], -1.0]))
        for k in local[np.argsort(-g[local])][:peaks]:
            lo, hi = u[max(k - 1, 0)], u[min(k + 1, n)]
            r = minimize_scalar(lambda x: -float(pressure_angles(design, centre, i, [x])[0]),
                                bounds=(lo, hi), method="bounded", options={"xatol": 1e-12})
            best = max(best, float(-r.fun))
        out[i] = best
    return out


def max_excess(design, centre, *, n: int = 2000) -> float:
    """Largest ``gamma - limit`` over the limited phases (radians; <= 0 admissible)."""
    spec = spec_of(design)
    lims = {i: lim for i, lim, _ in spec.constrained()}
    return max(g - lims[i] for i, g in max_pressure(design, centre, n=n).items())


class ReferenceZone:
    """The reference admissibility test for many centres at fixed positions.

    Parameters
    ----------
    design : CamDesign
    n : int
        Steps per limited phase (``n + 1`` positions, both ends included).
    """

    def __init__(self, design, n: int = 2000):
        self.design = design
        self.n = int(n)
        spec = self.spec = spec_of(design)
        u = np.linspace(0.0, 1.0, n + 1)
        parts = [_positions(spec, i, u, sg, lim) for i, lim, sg in spec.constrained()]
        cat = lambda name: np.concatenate([getattr(p, name) for p in parts])  # noqa: E731
        phi, phi_j, A_j, w, v = cat("phi"), cat("phi_j"), cat("A_j"), cat("w"), cat("v")
        sigma, self.limit = cat("sigma"), cat("limit")
        eps = spec.eps
        self.a = np.einsum("kj,kjd->kd", w, _rot(A_j, -eps * phi_j))
        self.Bc = np.sum(w * np.cos(-eps * phi_j), axis=1)
        self.Bs = np.sum(w * np.sin(-eps * phi_j), axis=1)
        self.q = sigma[:, None] * _rot(v, -eps * phi - eps * np.pi / 2)
        self.cos_lim = np.cos(self.limit)

    def cos_gamma(self, centres: np.ndarray) -> np.ndarray:
        """cos of the reference pressure angle, shape (M, K) for centres (M, 2)."""
        O = np.atleast_2d(np.asarray(centres, dtype=float))
        ox, oy = O[:, 0:1], O[:, 1:2]
        tx = self.a[None, :, 0] - (self.Bc * ox - self.Bs * oy)
        ty = self.a[None, :, 1] - (self.Bs * ox + self.Bc * oy)
        return (tx * self.q[:, 0] + ty * self.q[:, 1]) / np.hypot(tx, ty)

    def admissible(self, centres: np.ndarray, *, chunk: int = 32, prefilter: ReferenceZone | None = None
                   ) -> np.ndarray:
        """True where every position has gamma <= its limit (strictly, no tolerance).

        ``prefilter``: a zone whose positions are a subset of this one's (``n``
        dividing this ``n``); centres it rejects are rejected without the full
        test (same answer, less work).
        """
        O = np.atleast_2d(np.asarray(centres, dtype=float))
        out = np.zeros(len(O), dtype=bool)
        todo = np.arange(len(O))
        if prefilter is not None:
            if self.n % prefilter.n or prefilter.spec != self.spec:
                raise ValueError("the prefilter's positions must be a subset of this zone's")
            todo = todo[prefilter.admissible(O, chunk=chunk)]
        # cos(gamma) >= cos(limit) with cos(limit) > 0, i.e. t.q >= 0 and (t.q)^2 >= cos^2 |t|^2:
        # the same test as cos_gamma(O) >= cos_lim without square roots and divisions
        ax, ay, qx, qy, Bc, Bs = self.a[:, 0], self.a[:, 1], self.q[:, 0], self.q[:, 1], self.Bc, self.Bs
        c2 = self.cos_lim**2
        for k in range(0, len(todo), chunk):
            idx = todo[k:k + chunk]
            ox, oy = O[idx, 0:1], O[idx, 1:2]
            tx = ax - (Bc * ox - Bs * oy)
            ty = ay - (Bs * ox + Bc * oy)
            dot = tx * qx
            dot += ty * qy
            n2 = tx * tx
            n2 += ty * ty
            n2 *= c2
            out[idx] = np.all((dot >= 0) & (dot * dot >= n2), axis=1)
        return out

    def max_excess(self, centres: np.ndarray, *, chunk: int = 256) -> np.ndarray:
        """Largest ``gamma - limit`` over the positions, per centre (radians)."""
        O = np.atleast_2d(np.asarray(centres, dtype=float))
        out = np.empty(len(O))
        for k in range(0, len(O), chunk):
            g = np.arccos(np.clip(self.cos_gamma(O[k:k + chunk]), -1.0, 1.0))
            out[k:k + chunk] = np.max(g - self.limit, axis=1)
        return out


@dataclass(frozen=True)
class BruteResult:
    centre: np.ndarray
    distance: float
    spacing: float
    evaluated: int


def brute_force_nearest(design, target, *, n: int = 2000, half: float | None = None,
                        points: int = 61, final: float = 2e-6) -> BruteResult:
    """Admissible centre nearest to ``target`` by grid search with the reference test.

    A square grid of ``points**2`` centres round ``target`` (half-width
    ``half``, default 4 scales), then grids of the same size round the best
    admissible point, each ``half`` = 6 cells of the previous one (a factor 5
    finer), until the cell is below ``final * scale``. Early levels use 400
    steps per phase, the last three ``n``.
    """
    spec = spec_of(design)
    scale = spec.scale
    T = np.asarray(target, dtype=float)
    coarse, dense = ReferenceZone(design, 400), ReferenceZone(design, n)
    pre = coarse if n % 400 == 0 else None
    half = 4.0 * scale if half is None else half
    g = np.linspace(-1.0, 1.0, points)
    centre = T
    evaluated = 0
    # how many levels until the cell is below final * scale
    cell = 2 * half / (points - 1)
    levels = 1
    while cell > final * scale:
        cell *= 12.0 / (points - 1)
        levels += 1
    best = None
    last_cell = cell
    for lev in range(levels):
        X, Y = np.meshgrid(centre[0] + half * g, centre[1] + half * g)
        C = np.stack([X.ravel(), Y.ravel()], axis=1)
        ok = dense.admissible(C, prefilter=pre) if lev >= levels - 3 else coarse.admissible(C)
        evaluated += len(C)
        if not np.any(ok):
            raise AssertionError(f"brute force: no admissible centre on the grid of level {lev}")
        d = np.linalg.norm(C[ok] - T, axis=1)
        k = int(np.argmin(d))
        best = C[ok][k]
        if lev == 0 and np.max(np.abs(best - T)) >= half * (1 - 1e-12):
            raise AssertionError("brute force: best point on the first grid's edge, enlarge it")
        last_cell = 2 * half / (points - 1)
        centre = best
        half = 6 * last_cell
    return BruteResult(best, float(np.linalg.norm(best - T)), float(last_cell), evaluated)


def brute_force_on_line(design, point, direction, target, *, n: int = 2000, span: float | None = None,
                        points: int = 401, final: float = 1e-7) -> BruteResult:
    """Admissible point of the line ``point + t direction`` nearest to ``target`` (1-D grids)."""
    spec = spec_of(design)
    scale = spec.scale
    p0 = np.asarray(point, float)
    dvec = np.asarray(direction, float) / np.linalg.norm(direction)
    T = np.asarray(target, float)
    zone = ReferenceZone(design, n)
    t0 = float(np.dot(T - p0, dvec))
    half = 10.0 * scale if span is None else span
    g = np.linspace(-1.0, 1.0, points)
    best = None
    evaluated = 0
    cell = np.inf
    while True:
        ts = t0 + half * g
        C = p0 + ts[:, None] * dvec
        ok = zone.admissible(C)
        evaluated += len(C)
        if not np.any(ok):
            raise AssertionError("brute force on the line: no admissible point")
        d = np.linalg.norm(C[ok] - T, axis=1)
        k = int(np.argmin(d))
        best = C[ok][k]
        cell = 2 * half / (points - 1)
        if cell <= final * scale:
            break
        t0 = float(np.dot(best - p0, dvec))
        half = 4 * cell
    return BruteResult(best, float(np.linalg.norm(best - T)), cell, evaluated)


# --- the seed's formulas 3.19-3.22 and 3.26 (seed 001), taken literally -------------

def seed_lines(psi, dpsi, l: float, mu: float, K: float = 1.0):
    """Seed lines as ``y = a x + b`` for positions (psi, psi').

    Returns ``(a_t, b_t, a_t1, b_t1)``:
    t-t   (3.19 / 3.26): ``y = l (K + psi') (tan b cos psi - sin psi) - x tan b``, ``b = mu + psi``;
    t1-t1 (3.20 / 3.26): ``y = x tan b - l (1/K + psi') (tan b cos psi + sin psi)``, ``b = mu - psi``.
    """
    psi = np.asarray(psi, float)
    dpsi = np.asarray(dpsi, float)
    bi = mu + psi
    bj = mu - psi
    a_t = -np.tan(bi)
    b_t = l * (K + dpsi) * (np.tan(bi) * np.cos(psi) - np.sin(psi))
    a_t1 = np.tan(bj)
    b_t1 = -l * (1.0 / K + dpsi) * (np.tan(bj) * np.cos(psi) + np.sin(psi))
    return a_t, b_t, a_t1, b_t1


def seed_crossings(psi_i, dpsi_i, mu_i: float, psi_j, dpsi_j, mu_j: float, l: float, K: float = 1.0):
    """Every t-t line (rise position i) crossed with every t1-t1 line (position j).

    ``x_C`` by 3.21 (3.26 with K_C), ``y_C`` by the right side of 3.19 at
    ``x_C``, ``R0`` by 3.22 with ``A = (l, 0)``; shapes (len(i), len(j)).
    ``mu_i`` and ``mu_j`` are the transmission angles ``90 deg - [gamma]`` of
    the rise and of the return (they may differ under form closure).
    """
    psi_i, dpsi_i = np.asarray(psi_i, float)[:, None], np.asarray(dpsi_i, float)[:, None]
    psi_j, dpsi_j = np.asarray(psi_j, float)[None, :], np.asarray(dpsi_j, float)[None, :]
    mu_j = np.broadcast_to(np.asarray(mu_j, float), psi_j.shape[1:])[None, :]
    tbi, tbj = np.tan(mu_i + psi_i), np.tan(mu_j - psi_j)
    x = l * ((K + dpsi_i) * (tbi * np.cos(psi_i) - np.sin(psi_i))
             + (1.0 / K + dpsi_j) * (tbj * np.cos(psi_j) + np.sin(psi_j))) / (tbi + tbj)
    y = l * (K + dpsi_i) * (tbi * np.cos(psi_i) - np.sin(psi_i)) - x * tbi
    R0 = np.sqrt((x - l) ** 2 + y**2)
    return x, y, R0


@dataclass(frozen=True)
class SeedResult:
    centre: np.ndarray
    R0: float
    L: float
    pair: tuple[int, int]
    lines: tuple[np.ndarray, ...]


def seed_all_pairs(design, samples: int, K: float = 1.0, *, rise_start_t1: bool = False,
                   tol: float = 1e-9) -> SeedResult:
    """The seed's all-pairs method (3.19-3.22, 3.26) for the seed's senses.

    Positions: ``samples + 1`` per phase, both ends included (as the product).
    t-t lines at every rise position, t1-t1 lines at every return position
    (form closure) or the single t1-t1 at psi = 0 (force closure). Every
    crossing is a candidate; kept: the least R0 among those on the admissible
    side of *every* line (within ``tol * l``).

    ``rise_start_t1``: under form closure, add to the t1-t1 family the line of
    the rise's first position (psi = 0, psi' = 0, the rise's limit) - the
    seed's force-closure line, which the seed's form-closure recipe leaves out
    although that position is limited too (it matters when the rise's limit
    is below the return's and K_C > 1).

    Admissible side. Eq. 3.19 passes through ``D = l (1 + psi') (cos psi,
    -sin psi)`` (put ``x = x_D`` into it), so in the seed's coordinates the
    rocker end turns towards -y on the rise: the product's frame with
    ``rise_direction = "cw"``, no mirror. The centre must lie within
    ``[gamma]`` of the direction opposite to A's velocity, i.e. on the rays
    from D towards ``(sin psi, cos psi)`` +- ``[gamma]``; t-t (slope
    ``-tan(mu + psi)``) and t1-t1 (slope ``tan(mu - psi)``) are those rays'
    lines and the admissible side of both is ``y >= a x + b``. The seed's
    words ("admissible left of t-t, right of t1-t1") agree with this when its
    figure shows the same right-handed frame turned by 180 degrees (pivot on
    the right, x to the left, y downwards; the rocker end then visibly turns
    clockwise): visual left is +x, and ``y >= a x + b`` is the +x side of a
    falling line (t-t) and the -x side of a rising one (t1-t1). The side is
    also checked against the reference pressure angle in the tests.
    """
    spec = spec_of(design)
    if not (spec.kind == "rocker" and spec.sigma == -1 and spec.eps == 1):
        raise ValueError("the seed's formulas are written for a rocker turning cw on the rise, cam ccw")
    prog = spec.program
    l = spec.arm
    u = np.linspace(0.0, 1.0, samples + 1)

    def motion(kind):
        ms = [prog.evaluate_phase(i, u) for i, p in enumerate(prog.phases) if p.kind == kind]
        return np.concatenate([m.s for m in ms]), np.concatenate([m.ds for m in ms])

    psi_i, dpsi_i = motion("rise")
    mu_i = np.pi / 2 - spec.rise_limit
    if spec.closure == "form":
        psi_j, dpsi_j = motion("return")
        mu_j = np.full(len(psi_j), np.pi / 2 - spec.return_limit)
        if rise_start_t1:
            psi_j, dpsi_j, mu_j = np.r_[psi_j, 0.0], np.r_[dpsi_j, 0.0], np.r_[mu_j, mu_i]
    else:
        psi_j, dpsi_j, mu_j = np.zeros(1), np.zeros(1), np.full(1, mu_i)
    a_t, b_t, _, _ = seed_lines(psi_i, dpsi_i, l, mu_i, K)
    _, _, a_t1, b_t1 = seed_lines(psi_j, dpsi_j, l, mu_j, K)
    x, y, R0 = seed_crossings(psi_i, dpsi_i, mu_i, psi_j, dpsi_j, mu_j, l, K)
    a = np.concatenate([a_t, a_t1])
    b = np.concatenate([b_t, b_t1])
    flat = np.argsort(R0, axis=None)
    X, Y = x.ravel()[flat], y.ravel()[flat]
    for k in range(0, len(flat), 512):
        xs, ys = X[k:k + 512], Y[k:k + 512]
        ok = np.all(ys[:, None] >= a[None, :] * xs[:, None] + b[None, :] - tol * l, axis=1)
        if np.any(ok):
            m = k + int(np.argmax(ok))
            i, j = np.unravel_index(flat[m], R0.shape)
            C = np.array([X[m], Y[m]])
            return SeedResult(C, float(R0[i, j]), float(np.hypot(*C)), (int(i), int(j)), (a_t, b_t, a_t1, b_t1))
    raise AssertionError("seed all-pairs: no admissible crossing")
