"""The batch's sizing: the exact method's smallest cam centre for many designs of one motion program at once.

The problem is the exact method's (:mod:`optimize.exact`): the admissible centre ``O`` nearest to the roller
centre at the near dwell ``A0``, over every cam angle of every constrained phase, each position's two half-planes
``n(s) . O <= b0 + b1 s' + bt s`` of :mod:`optimize.zone` (its constants, :func:`optimize.zone.side_constants`,
per design). Every design of a group shares the program, so the law is evaluated once for all on the zone's scan
positions; the designs differ by their half-planes' constants only, and one array holds them all.

The search, in ``x = O - A0``, is an active-set exchange of at most two lines: the answer of a 2-D nearest-point
problem lies at 0, on the projection onto one line or on the crossing of two, so each step solves the problem of
the (at most) two lines active so far and the most violated one exactly, among those seven candidates, and keeps
the lines active at the new point. Each step's line is a real constraint, the kept lines define the point, so
the distance never falls and no line set repeats: the scan positions first, then the continuum's local maxima
(safeguarded Newton steps on the analytic rates of :mod:`optimize.zone`, as :func:`optimize.zone.scan_peaks`),
while any is violated. A line enters tightened by the rounding of the numbers compared (the exact method's
allowance, :data:`optimize.planar.EPS`), so the search ends on a centre with no positive signed distance at any
scan position or refined maximum (a design that does not settle in :data:`MAX_STEPS` goes to the per-design path).

The certificate: that centre is the upper bound; the same active lines, not tightened, bound the optimum from
below (a relaxation by true constraints): ``error_bound = |x| (1 + 4 EPS) - lower``, some 1e-13 of R0.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from optimize.planar import EPS
from optimize.zone import GRID, rigid_motion, scan_positions, side_constants, side_offset, side_slopes, turned

__all__ = ["BatchSizing", "size_group"]

#: The most exchange steps on the scan positions, then on the continuum.
MAX_STEPS = 80
#: Newton steps of a continuum maximum.
NEWTON = 10
#: A scan maximum this far inside its half-plane (a fraction of the design's scale) is not refined: within one
#: scan step the signed distance rises by ``|h''| dphi^2 / 8``, some 1e-5 of the scale.
FAR_INSIDE = 1e-2


@dataclass(frozen=True)
class BatchSizing:
    """The sized centres of a group (arrays over its designs).

    Attributes
    ----------
    centre : ndarray, shape (B, 2)
        Cam centres, the follower's fixed frame (length unit).
    R0 : ndarray, shape (B,)
        ``|O - A0|`` (length).
    error_bound : ndarray, shape (B,)
        ``R0`` less the lower bound of the optimum (length).
    ok : ndarray of bool, shape (B,)
        False where the search did not settle, the zone looked empty or the centre is not feasible at every
        refined maximum: those designs go to the per-design path.
    """

    centre: np.ndarray
    R0: np.ndarray
    error_bound: np.ndarray
    ok: np.ndarray


def _constants(designs, phases):
    """Per design: ``turn (B,)``, ``tau (B, 2)``, ``n0 (B, P, 2, 2)``, ``b0, b1, bt (B, P, 2)``, ``A0 (B, 2)``."""
    B, P = len(designs), len(phases)
    turn, tau, A0 = np.zeros(B), np.zeros((B, 2)), np.zeros((B, 2))
    n0 = np.zeros((B, P, 2, 2))
    b0, b1, bt = np.zeros((B, P, 2)), np.zeros((B, P, 2)), np.zeros((B, P, 2))
    for d, design in enumerate(designs):
        turn[d], tau[d] = rigid_motion(design)
        A0[d] = design.follower.position(0.0)
        for j, (_, lim) in enumerate(design.constrained_phases()):
            n, P0, Q0 = side_constants(design, lim)
            n0[d, j] = n
            b0[d, j] = np.einsum("ki,ki->k", n, P0)
            b1[d, j], bt[d, j] = n @ Q0, n @ tau[d]
    return turn, tau, n0, b0, b1, bt, A0


def _lines(turn, n0x, n0y, b0, b1, bt, s, ds):
    """Half-planes ``nx x + ny y <= off`` at motion ``s, s'`` (broadcast): :mod:`optimize.zone`'s sides."""
    a = turn * s
    nx, ny = turned(np.cos(a), np.sin(a), n0x, n0y)
    return nx, ny, side_offset(b0, b1, bt, s, ds)


def _best_of_three(lines: np.ndarray, tol: np.ndarray):
    """The exact nearest point to 0 of three half-planes per design (rows ``nx, ny, b``; ``b = +inf``: none).

    Returns ``x (B, 2)``, the active mask ``(B, 3)`` and ``found (B,)`` (False: the three have no common point).
    """
    B = len(lines)
    nx, ny, b = lines[..., 0], lines[..., 1], lines[..., 2]
    cands = [np.zeros((B, 2))]
    defs = [np.zeros((B, 3), bool)]
    for i in range(3):
        bi = np.where(np.isfinite(b[:, i]), np.minimum(b[:, i], 0.0), 0.0)
        cands.append(np.stack([bi * nx[:, i], bi * ny[:, i]], axis=1))
        m = np.zeros((B, 3), bool)
        m[:, i] = b[:, i] < 0
        defs.append(m)
    for i, k in ((0, 1), (0, 2), (1, 2)):
        det = nx[:, i] * ny[:, k] - ny[:, i] * nx[:, k]
        good = (np.abs(det) > 1e-12) & np.isfinite(b[:, i]) & np.isfinite(b[:, k])
        dd = np.where(good, det, 1.0)
        bi, bk = np.where(good, b[:, i], 0.0), np.where(good, b[:, k], 0.0)
        x = (bi * ny[:, k] - bk * ny[:, i]) / dd
        y = (nx[:, i] * bk - nx[:, k] * bi) / dd
        xy = np.stack([np.where(good, x, np.nan), np.where(good, y, np.nan)], axis=1)
        cands.append(xy)
        m = np.zeros((B, 3), bool)
        m[:, i] = m[:, k] = True
        defs.append(m)
    X = np.stack(cands, axis=1)  # (B, 7, 2)
    D = np.stack(defs, axis=1)  # (B, 7, 3): the lines a candidate lies on
    g = X[..., 0, None] * nx[:, None] + X[..., 1, None] * ny[:, None] - b[:, None]  # (B, 7, 3)
    feas = np.all((g <= tol[:, None, :]) | D, axis=2) & np.all(np.isfinite(X), axis=2)
    norm = np.where(feas, np.hypot(X[..., 0], X[..., 1]), np.inf)
    k = np.argmin(norm, axis=1)
    rows = np.arange(B)
    return X[rows, k], D[rows, k], np.isfinite(norm[rows, k])


class _Exchange:
    """The active-set exchange of every design of a group (module notes)."""

    def __init__(self, A0: np.ndarray, scale: np.ndarray):
        B = len(A0)
        self.A0, self.scale = A0, scale
        self.x = np.zeros((B, 2))
        self.active = np.full((B, 2, 3), np.inf)  # two lines (nx, ny, b in x), b = inf: none
        self.active[..., :2] = 0.0
        self.raw = self.active.copy()  # the same lines not tightened
        self.ok = np.ones(B, bool)

    def allowed(self, off: np.ndarray, rows) -> np.ndarray:
        """The rounding of a signed distance (the exact method's ``rel (|off| + 2 (|T| + |x|))``)."""
        mag = np.abs(self.A0[rows]).sum(axis=1) + np.abs(self.x[rows]).sum(axis=1)
        return EPS * (np.abs(off) + 2.0 * mag)

    def step(self, rows: np.ndarray, nx, ny, off) -> None:
        """Add the line ``nx x + ny y <= off`` (fixed frame) to designs ``rows`` and move them."""
        b = off - (nx * self.A0[rows, 0] + ny * self.A0[rows, 1])
        slack = self.allowed(off, rows)
        new = np.stack([nx, ny, b - slack], axis=1)
        lines = np.concatenate([self.active[rows], new[:, None]], axis=1)
        raw = np.concatenate([self.raw[rows], np.stack([nx, ny, b], axis=1)[:, None]], axis=1)
        tol = EPS * np.abs(np.where(np.isfinite(lines[..., 2]), lines[..., 2], 0.0))
        x, act, found = _best_of_three(lines, tol)
        self.ok[rows] &= found & (act.sum(axis=1) <= 2)
        keep = np.full((len(rows), 2, 3), np.inf)
        keep[..., :2] = 0.0
        keep_raw = keep.copy()
        for r in range(len(rows)):  # at most two True per row; the pair kept in order
            idx = np.flatnonzero(act[r])[:2]
            keep[r, : len(idx)] = lines[r, idx]
            keep_raw[r, : len(idx)] = raw[r, idx]
        self.x[rows] = np.where(found[:, None], x, self.x[rows])
        self.active[rows], self.raw[rows] = keep, keep_raw

    def lower(self) -> np.ndarray:
        """The optimum over the active lines not tightened: a lower bound of the true optimum."""
        lines = np.concatenate([self.raw, np.full((len(self.x), 1, 3), np.inf)], axis=1)
        lines[:, 2, :2] = 0.0
        tol = EPS * np.abs(np.where(np.isfinite(lines[..., 2]), lines[..., 2], 0.0))
        x, _, found = _best_of_three(lines, tol)
        return np.where(found, np.hypot(x[:, 0], x[:, 1]), 0.0)


class _OnLine:
    """The exchange of designs whose centre is held on the line ``x = x0`` (a translating follower's fixed offset).

    The problem is then one-dimensional: each half-plane bounds the centre's ``y`` from below or from above, and the
    nearest point is ``A0``'s ``y`` clamped to the tightest bounds (tightened by the rounding as in
    :class:`_Exchange`; the lower bound of the optimum from the bounds not tightened).
    """

    def __init__(self, A0: np.ndarray, scale: np.ndarray, x0: np.ndarray):
        B = len(A0)
        self.A0, self.scale, self.x0 = A0, scale, x0
        self.lo, self.hi = np.full(B, -np.inf), np.full(B, np.inf)
        self.lo_raw, self.hi_raw = self.lo.copy(), self.hi.copy()
        self.ok = np.ones(B, bool)
        self.x = np.stack([x0 - A0[:, 0], np.zeros(B)], axis=1)

    def allowed(self, off: np.ndarray, rows) -> np.ndarray:
        """As :meth:`_Exchange.allowed`."""
        mag = np.abs(self.A0[rows]).sum(axis=1) + np.abs(self.x[rows]).sum(axis=1)
        return EPS * (np.abs(off) + 2.0 * (mag if np.ndim(off) == 1 else mag[:, None]))

    def step(self, rows: np.ndarray, nx, ny, off) -> None:
        """Bound designs ``rows`` by the half-planes ``nx x + ny y <= off`` (shape (n,) or (n, L)) and move them."""
        x0 = self.x0[rows] if np.ndim(off) == 1 else self.x0[rows, None]
        c = off - nx * x0
        t = c - self.allowed(off, rows)
        flat = np.abs(ny) <= 1e-15
        safe = np.where(flat, 1.0, ny)
        below, above = ny < 0, ny > 0
        red = (lambda a: a) if np.ndim(off) == 1 else (lambda a: a.max(axis=1))
        self.ok[rows] &= ~(red(np.where(flat, -c, -np.inf)) > 0)
        self.lo[rows] = np.maximum(self.lo[rows], red(np.where(below, t / safe, -np.inf)))
        self.hi[rows] = np.minimum(self.hi[rows], -red(np.where(above, -t / safe, -np.inf)))
        self.lo_raw[rows] = np.maximum(self.lo_raw[rows], red(np.where(below, c / safe, -np.inf)))
        self.hi_raw[rows] = np.minimum(self.hi_raw[rows], -red(np.where(above, -c / safe, -np.inf)))
        self.ok[rows] &= self.lo[rows] <= self.hi[rows]
        y = np.clip(self.A0[rows, 1], self.lo[rows], self.hi[rows])
        self.x[rows, 1] = y - self.A0[rows, 1]

    def lower(self) -> np.ndarray:
        """The optimum over the bounds not tightened: a lower bound of the true optimum."""
        y = np.clip(self.A0[:, 1], self.lo_raw, self.hi_raw) - self.A0[:, 1]
        return np.hypot(self.x[:, 0], y)


def size_group(designs, phases: list[int], program) -> BatchSizing:
    """Size every design of a group (one program, the same constrained phases ``phases``), see the module.

    Parameters
    ----------
    designs : sequence of CamDesign
        Roller followers, sized by R0 with nothing fixed (no L, no floor, no chosen cam) but, for translating
        followers, the offset: all of them or none (:class:`_OnLine`).
    phases : list of int
        The program's constrained phases (:meth:`cams.model.design.CamDesign.constrained_phases`), the same for all.
    program : laws.program.Program
        Their motion program.
    """
    B = len(designs)
    turn, _, n0, b0, b1, bt, A0 = _constants(designs, phases)
    scale = np.array([d.scale for d in designs], float)
    angle = np.array([program.phases[i].angle for i in phases])
    u = scan_positions(designs[0], GRID)
    mo = np.array(
        [[getattr(m, k) for k in ("s", "ds", "d2s")] for m in (program.evaluate_phase(i, u) for i in phases)]
    )  # (P, 3, M)
    s, ds, d2s = (mo[:, k][None, :, None, :] for k in range(3))  # (1, P, 1, M)
    T = turn[:, None, None, None]
    NX, NY, OFF = _lines(T, n0[..., 0, None], n0[..., 1, None], b0[..., None], b1[..., None], bt[..., None], s, ds)
    offsets = [getattr(d.follower, "offset", None) for d in designs]
    ex: _Exchange | _OnLine
    if offsets[0] is None:
        ex = _Exchange(A0, scale)
    else:  # the fixed offset's line x = -e (optimize.sizing.offset_x): every scan position's bound at once
        ex = _OnLine(A0, scale, -np.array(offsets, float))
        ex.step(np.arange(B), *(a.reshape(B, -1) for a in (NX, NY, OFF)))
    grid = (NX, NY, OFF, T * ds, b1[..., None] * d2s + bt[..., None] * ds)
    flat = [a.reshape(B, -1) for a in (NX, NY, OFF)]
    # 1. the scan positions (the designs still moving only)
    rows = np.arange(B)
    for _ in range(MAX_STEPS):
        O = ex.x[rows] + A0[rows]
        g = flat[0][rows] * O[:, :1] + flat[1][rows] * O[:, 1:] - flat[2][rows]
        k = np.argmax(g, axis=1)
        moving = ex.ok[rows] & (g[np.arange(len(rows)), k] > 0.0)
        rows, k = rows[moving], k[moving]
        if not len(rows):
            break
        ex.step(rows, *(a[rows, k] for a in flat))
    else:
        ex.ok[rows] = False  # not settled
    # 2. the continuum: every scan maximum near its line, refined
    value = np.full(B, -np.inf)
    rows = np.arange(B)
    for _ in range(MAX_STEPS):
        O = ex.x[rows] + A0[rows]
        pk = _peaks(rows, O, grid, turn, n0, b0, b1, bt, scale, program, phases, angle, u)
        v = np.full(len(rows), -np.inf)
        best = np.zeros((len(rows), 3))
        order = np.lexsort((pk[0], pk[1]))  # by design, then value: the last of each design is its largest
        dd = pk[1][order].astype(int)
        v[dd] = pk[0][order]
        best[dd] = np.stack([pk[2][order], pk[3][order], pk[4][order]], axis=1)
        value[rows] = v
        moving = ex.ok[rows] & (v > 0.0)
        rows, best = rows[moving], best[moving]
        if not len(rows):
            break
        ex.step(rows, best[:, 0], best[:, 1], best[:, 2])
    else:
        ex.ok[rows] = False  # not settled
    R0 = np.hypot(ex.x[:, 0], ex.x[:, 1])
    ok = ex.ok & (value <= 0.0) & np.isfinite(R0)
    lower = ex.lower()
    bound = np.maximum(R0 * (1.0 + 4 * EPS) - lower, 0.0)
    return BatchSizing(centre=ex.x + A0, R0=R0, error_bound=bound, ok=ok)


def _peaks(rows, O, grid, turn, n0, b0, b1, bt, scale, program, phases, angle, u):
    """Every local maximum of every side's signed distance near its line, refined, for the designs ``rows``
    (centres ``O``): ``value, index into rows, nx, ny, off``.

    The scan: a maximum is a step where the slope turns from + to -, or an end whose slope points out; those
    within :data:`FAR_INSIDE` of the scale of their line are refined by safeguarded Newton steps on ``h' = 0``
    (the analytic ``h''``; a step leaving the bracket, or where ``h`` is not concave, is a bisection), keeping
    the largest value seen (the scan's included). ``grid`` holds the scan's half-planes ``nx, ny, off`` and the
    slope's terms ``turn s'`` and ``b1 s'' + bt s'`` (shape (B, P, 2, M) or broadcasting to it).
    """
    B = len(rows)
    NX, NY, OFF, TDS, C12 = grid
    nx, ny, off = NX[rows], NY[rows], OFF[rows]
    ox, oy = O[:, 0, None, None, None], O[:, 1, None, None, None]
    p = nx * ox + ny * oy
    h = p - off
    m = nx * oy - ny * ox
    h1 = TDS[rows] * m - C12[rows]
    scale = scale[rows]
    near = h > -FAR_INSIDE * scale[:, None, None, None]
    up, down = h1 > 0, h1 < 0
    end = np.zeros_like(up)
    end[..., 0] = down[..., 0] | (~up[..., 0] & ~down[..., 0])
    end[..., -1] = up[..., -1]
    cell = np.zeros_like(up)
    cell[..., :-1] = up[..., :-1] & down[..., 1:]
    # the scan's own values: ends and flat points exactly, and the larger end of every cell
    d_, j_, k_, i_ = np.nonzero((end | cell) & near)
    vals = h[d_, j_, k_, i_]
    first = cell[d_, j_, k_, i_]
    a = u[i_]
    bnd = u[np.minimum(i_ + 1, len(u) - 1)]
    take = first & (h[d_, j_, k_, np.minimum(i_ + 1, len(u) - 1)] > vals)
    best_u = np.where(take, bnd, a)
    best_v = np.where(take, h[d_, j_, k_, np.minimum(i_ + 1, len(u) - 1)], vals)
    ii = np.where(take, np.minimum(i_ + 1, len(u) - 1), i_)
    best = [nx[d_, j_, k_, ii], ny[d_, j_, k_, ii], off[d_, j_, k_, ii]]
    act = np.flatnonzero(first & (bnd - a > 1e-10))
    if len(act):
        d, j, k = d_[act], j_[act], k_[act]
        lo, hi = a[act].copy(), bnd[act].copy()
        x = 0.5 * (lo + hi)
        dg = rows[d]
        tn, n0x, n0y = turn[dg], n0[dg, j, k, 0], n0[dg, j, k, 1]
        c0, c1, ct = b0[dg, j, k], b1[dg, j, k], bt[dg, j, k]
        Ox, Oy, ang = O[d, 0], O[d, 1], angle[j]
        live = np.ones(len(act), bool)
        mo = np.empty((4, len(act)))
        for _ in range(NEWTON):
            for q, i in enumerate(phases):
                on = np.flatnonzero(j == q)
                if len(on):
                    e = program.evaluate_phase(i, x[on])
                    mo[:, on] = e.s, e.ds, e.d2s, e.d3s
            S, D1, D2, D3 = mo
            lx, ly, lo_off = _lines(tn, n0x, n0y, c0, c1, ct, S, D1)
            pp = lx * Ox + ly * Oy
            hx = pp - lo_off
            g1, g2 = side_slopes(tn, (Ox, Oy), lx, ly, pp, c1, ct, D1, D2, D3)
            sel = act[hx > best_v[act]]
            better = hx > best_v[act]
            best_v[sel], best_u[sel] = hx[better], x[better]
            best[0][sel], best[1][sel], best[2][sel] = lx[better], ly[better], lo_off[better]
            upx = g1 > 0
            lo, hi = np.where(upx, x, lo), np.where(upx, hi, x)
            concave = g2 < 0
            dphi = -g1 / np.where(concave, g2, -1.0)
            live &= ~(concave & (0.5 * g1 * dphi <= 1e-15 * (np.abs(pp) + np.abs(lo_off))))
            if not live.any():
                break
            xn = x + dphi / ang
            x = np.where(concave & (xn > lo) & (xn < hi), xn, 0.5 * (lo + hi))
    if not len(d_):
        return (np.full(B, -np.inf), np.arange(B), np.zeros(B), np.zeros(B), np.zeros(B))
    return best_v, d_, best[0], best[1], best[2]
