"""The batch's independent check: the pressure angle, the pitch curve's curvature and the working profile's shape
of many sized cams at once, by kinematic inversion (no zone, no instant point D).

As :mod:`cams.verify.pressure` does for one design: the roller centre ``A(s)`` and its tangent ``T = dA/ds`` come
from the follower's own geometry (rocker: ``A = arm (cos sense s, sin sense s)``; translating: ``A = (0, s)``);
its velocity relative to the cam, per radian, is ``W = s' T - eps k x (A - O)``; the pitch curve's outward normal
is ``n = eps k x W / |W|`` and the pressure angle ``gamma = arccos(n . T / |T|)``. The pitch curve in the cam's
frame is ``P = R(-eps phi) (A - O)``, so ``P' = R W`` and ``P'' = R (W' - eps k x W)`` with
``W' = s'' T + s'^2 dT/ds - eps s' k x T``: its curvature, positive where convex (the curve runs round the cam
centre in the sense ``-eps``), is ``kappa = -eps (W x W' - eps |W|^2) / |W|^3``.

The working profile (the pitch curve offset by the roller radius ``r`` towards the cam) is judged without a
polyline. Where ``kappa r < 1`` its tangent turns as the pitch curve's (``W_work' = (1 - kappa r) P'``), so it
is star-shaped about a point ``C`` (a simple closed curve, and so is its polyline at a chord far below the
margin) when ``C`` lies inside every one of its tangent lines: ``(W_work - C) . n > 0``; ``C`` is the centroid of
its outline on the grid, and the cam centre is inside when the outline turns once round it. That stands for what
the per-design path judges on the 1 um polyline (no self-crossing, the centre inside). The groove's outer wall
(offset outwards) needs ``-kappa r < 1``; it lies outside the inner wall along the same normals, star-shaped about
the same point (``(W_out - C) . n`` is larger by ``2 r``).

Every largest value is found on a grid per phase and the local maxima of the grid (the ends included) that can
matter are refined by zooming into their bracket of two steps, tenfold a step, as the per-design check does (the
pressure angle's to the last digits; the curvature's to a thousandth of a step); all designs, phases and maxima
at once. The kernel's margin, the turns and the distance from the cam centre are the grid's (their margins,
:data:`cams.batch.MARGIN` of R0, are far above what a grid step can hide).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from cams.verify.pressure import ZOOM_POINTS, ZOOM_STEPS  # the independent check's zoom, the same

__all__ = ["GroupCheck", "check_group", "GRID", "ZOOM_POINTS", "ZOOM_STEPS"]

#: Even steps per phase of the search.
GRID = 300
#: Designs checked at once.
CHUNK = 64
#: Even steps of a dwell (its values are constant but for the profile's outline, an arc round the cam centre).
DWELL_GRID = 90
#: The pressure angle's grid maxima refined: those within this of their phase's grid maximum (radians; the grid
#: lowers a maximum by some 1e-6 at most).
NEAR = 1e-3


@dataclass(frozen=True)
class GroupCheck:
    """Extremes of the sized cams of a group (arrays over its designs).

    ``rise``/``ret``: the largest pressure angle over the rise/return phases (radians; NaN: no such phase);
    ``excess``: the largest excess of a constrained phase's over its limit (radians; -inf: none); ``convex`` and
    ``concave``: the largest curvature and minus curvature of the pitch curve times the roller radius (refined
    where above a half); ``kernel``: the working profile's smallest distance inside its tangent lines seen from its
    outline's centroid (length, on the grid); ``turns``: its turns round the cam centre and ``step`` the largest
    angle a grid step sweeps there (radians); ``reach``: its smallest distance from the cam centre (length, on the
    grid); ``joint``: the largest turn of the pitch curve's direction at a phase joint (radians); ``largest``: the
    cam's largest radius (the pitch curve's, refined, less the roller; a groove's outer wall: plus), length.
    """

    rise: np.ndarray
    ret: np.ndarray
    excess: np.ndarray
    convex: np.ndarray
    concave: np.ndarray
    kernel: np.ndarray
    turns: np.ndarray
    step: np.ndarray
    reach: np.ndarray
    joint: np.ndarray
    largest: np.ndarray


class _Inversion:
    """The follower geometry of every design of a group, and the inverted motion at given positions."""

    def __init__(self, designs, centres: np.ndarray):
        from cams.model.follower import Rocker

        f = [d.follower for d in designs]
        self.rocker = np.array([isinstance(x, Rocker) for x in f])
        self.all_rocker = bool(self.rocker.all())
        self.arm = np.array([getattr(x, "arm", 0.0) for x in f], float)
        self.sense = np.array([getattr(x, "sense", 1) for x in f], float)
        self.eps = np.array([d.cam_sense for d in designs], float)
        self.O = np.asarray(centres, float)
        self.roller = np.array([x.roller_radius for x in f], float)
        self.C = np.zeros_like(self.O)
        self.factor = np.array([d.limits.safety_factor for d in designs], float)
        lims = [dict(d.constrained_phases()) for d in designs]
        self.limits = {i: np.array([lm.get(i, np.nan) for lm in lims]) for i in range(len(designs[0].program.phases))}

    def at(self, d: np.ndarray, program, i: int, u: np.ndarray) -> dict:
        """At positions ``u`` (shape of ``d``, broadcast) of phase ``i``: ``gamma``, ``kappa``, ``p`` and the
        kernel's margin ``k`` of the working profile about the point :attr:`C` (cam frame; 0 before it is set)."""
        m = program.evaluate_phase(i, np.asarray(u, float).ravel())
        sh = np.broadcast_shapes(np.shape(d), np.shape(u))
        s, ds, d2s = (np.broadcast_to(v.reshape(np.shape(u)), sh) for v in (m.s, m.ds, m.d2s))
        arm, sg, eps = self.arm[d], self.sense[d], self.eps[d]
        if self.all_rocker:
            c, sn = np.cos(sg * s), np.sin(sg * s)
            ax, ay, tx, ty, ux, uy = arm * c, arm * sn, -sg * arm * sn, sg * arm * c, -arm * c, -arm * sn
        elif not self.rocker.any():
            ax, ay, tx, ty, ux, uy = 0.0, s, 0.0, 1.0, 0.0, 0.0
        else:
            rk = self.rocker[d]
            c, sn = np.cos(sg * s), np.sin(sg * s)
            ax = np.where(rk, arm * c, 0.0)
            ay = np.where(rk, arm * sn, s)
            tx = np.where(rk, -sg * arm * sn, 0.0)
            ty = np.where(rk, sg * arm * c, 1.0)
            ux = np.where(rk, -arm * c, 0.0)  # dT/ds
            uy = np.where(rk, -arm * sn, 0.0)
        rx, ry = ax - self.O[d, 0], ay - self.O[d, 1]
        wx, wy = ds * tx + eps * ry, ds * ty - eps * rx
        w2 = wx * wx + wy * wy
        w = np.sqrt(w2)
        nx, ny = -eps * wy / w, eps * wx / w
        t = np.hypot(tx, ty)
        gamma = np.arccos(np.clip((nx * tx + ny * ty) / t, -1.0, 1.0))
        vx = d2s * tx + ds * ds * ux + eps * ds * ty
        vy = d2s * ty + ds * ds * uy - eps * ds * tx
        kappa = -eps * (wx * vy - wy * vx - eps * w2) / (w2 * w)
        p = rx * nx + ry * ny
        # the working profile's point, the cam's frame: R(-eps phi) (A - O - r n)
        phi = program.starts[i] + np.asarray(u, float) * program.phases[i].angle
        cp, sp = np.cos(phi), eps * np.sin(phi)
        rr = self.roller[d]
        qx, qy = rx - rr * nx, ry - rr * ny
        W = (cp * qx + sp * qy, -sp * qx + cp * qy)
        return {
            "gamma": gamma,
            "kr": kappa * rr,
            "p": p,
            "rp": np.hypot(rx, ry),  # the pitch point's distance from the cam centre
            "W": W,
            "n": (nx, ny),
            "e": (tx / t, ty / t),
            "s": s,
            "d": np.broadcast_to(d, np.shape(s)),
            "i": i,
        }

    def safety(self, v: dict) -> np.ndarray:
        """The safety factor's excess at the values ``v`` of :meth:`at` (:func:`cams.verify.safety.safety_terms`:
        the larger of its two moved lines' ``outside / reach``, the sine of the angle's excess; -inf where it does
        not apply, K_C = 1 or a translating follower)."""
        from cams.verify.safety import safety_terms

        d, i = v["d"], v["i"]
        K, arm, sg = self.factor[d], self.arm[d], self.sense[d]
        lim = self.limits[i][d]
        on = (K > 1.0) & self.rocker[d] & np.isfinite(lim)
        lx, ly = np.cos(sg * v["s"]), np.sin(sg * v["s"])  # the rocker line, pivot at the origin
        (nx, ny), (ex, ey) = v["n"], v["e"]
        # its arm, factor and limit broadcast with the positions (per design here)
        per: dict[str, Any] = {
            "arm": np.where(on, arm, 1.0),
            "factor": np.where(on, K, 1.0),
            "limit": np.where(on, lim, 0.5),
        }
        outside, reach, _ = safety_terms(self.O[d, 0], self.O[d, 1], nx, ny, ex, ey, lx, ly, **per)
        with np.errstate(divide="ignore", invalid="ignore"):
            x = np.where(reach > 0.0, outside / np.where(reach > 0.0, reach, 1.0), outside).max(axis=-1)
        return np.where(on, np.where(np.isnan(x), np.inf, x), -np.inf)

    def kernel(self, v: dict, program, i: int, u: np.ndarray) -> np.ndarray:
        """The working profile's margin inside its tangent lines seen from :attr:`C` (cam frame), at the values
        ``v`` of :meth:`at` for all designs: ``(W - C) . n_cam = (A - O - r n - R(eps phi) C) . n``."""
        phi = program.starts[i] + u * program.phases[i].angle
        eps = self.eps[:, None]
        cp, sp = np.cos(phi), eps * np.sin(phi)
        cx, cy = self.C[:, 0, None], self.C[:, 1, None]
        nx, ny = v["n"]
        return v["p"] - self.roller[:, None] - ((cp * cx - sp * cy) * nx + (sp * cx + cp * cy) * ny)


def _peaks_of(g: np.ndarray, keep: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The grid's local maxima (ends included; the first of a plateau) of the rows of ``g`` where ``keep`` holds."""
    low = np.full((len(g), 1), -np.inf)
    left, right = np.hstack([low, g[:, :-1]]), np.hstack([g[:, 1:], low])
    d, j = np.nonzero((g > left) & (g >= right) & keep)
    return d, j


def _largest(
    inv: _Inversion,
    program,
    grid: dict,
    what,
    B: int,
    *,
    near: float = np.inf,
    floor: float = -np.inf,
    steps: int = ZOOM_STEPS,
):
    """Largest of ``what(values of _Inversion.at)`` over each phase of ``grid`` for each design: ``(B, phases)``.

    ``grid`` holds the values on the grid per phase; the local maxima of a moving phase's grid within ``near`` of
    its phase's grid maximum and at least ``floor`` are refined by ``steps`` zoom steps (the others are the
    grid's).
    """
    u = np.linspace(0.0, 1.0, GRID + 1)
    phases = list(grid)
    out = np.full((B, len(phases)), -np.inf)
    rows: list[np.ndarray] = []
    cols: list[np.ndarray] = []
    los: list[np.ndarray] = []
    his: list[np.ndarray] = []
    bests: list[np.ndarray] = []
    for col, i in enumerate(phases):
        g = what(grid[i])
        g = np.where(np.isnan(g), np.inf, g)  # undefined: as bad as can be (the design goes to the per-design path)
        out[:, col] = g.max(axis=1)
        if program.phases[i].kind == "dwell":  # constant: the grid's value is the phase's
            continue
        keep = (g >= out[:, col, None] - near) & (g >= floor)
        pd, j = _peaks_of(g, keep)
        rows.append(pd)
        cols.append(np.full(len(pd), col))
        los.append(u[np.maximum(j - 1, 0)])
        his.append(u[np.minimum(j + 1, GRID)])
        bests.append(g[pd, j])
    if not rows:
        return out
    d, q, lo, hi, best = (np.concatenate(a) for a in (rows, cols, los, his, bests))
    t = np.linspace(0.0, 1.0, ZOOM_POINTS)
    r = np.arange(len(d))
    for _ in range(steps):
        x = lo[:, None] + (hi - lo)[:, None] * t
        gx = np.empty_like(x)
        for k, i in enumerate(phases):
            on = np.flatnonzero(q == k)
            if len(on):
                gx[on] = what(inv.at(d[on, None], program, i, x[on]))
        gx = np.where(np.isnan(gx), np.inf, gx)
        jx = np.argmax(gx, axis=1)
        best = np.maximum(best, gx[r, jx])
        lo, hi = x[r, np.maximum(jx - 1, 0)], x[r, np.minimum(jx + 1, ZOOM_POINTS - 1)]
    np.maximum.at(out, (d, q), best)
    return out


def _winding(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Turns of the closed polyline ``(x, y)`` (rows) round the origin, and its largest step's angle (radians)."""
    a = np.arctan2(y, x)
    da = np.diff(np.hstack([a, a[:, :1]]), axis=1)
    da = (da + np.pi) % (2 * np.pi) - np.pi
    return da.sum(axis=1) / (2 * np.pi), np.abs(da).max(axis=1)


def check_group(designs, centres: np.ndarray, program) -> GroupCheck:
    """The extremes of the cams of ``designs`` (one program) centred at ``centres`` (fixed frame, shape (B, 2)).

    In chunks of :data:`CHUNK` designs (arrays that stay in the processor's cache).
    """
    parts = [_check(designs[a : a + CHUNK], centres[a : a + CHUNK], program) for a in range(0, len(designs), CHUNK)]
    return GroupCheck(*(np.concatenate([getattr(p, k) for p in parts]) for k in GroupCheck.__dataclass_fields__))


def _check(designs, centres: np.ndarray, program) -> GroupCheck:
    """:func:`check_group` of one chunk."""
    B = len(designs)
    inv = _Inversion(designs, centres)
    kinds = [p.kind for p in program.phases]
    moving = [i for i, k in enumerate(kinds) if k != "dwell"]
    us = {i: np.linspace(0.0, 1.0, (DWELL_GRID if k == "dwell" else GRID) + 1) for i, k in enumerate(kinds)}
    allD = np.arange(B)[:, None]
    grid = {i: inv.at(allD, program, i, us[i][None]) for i in range(len(kinds))}
    g = _largest(inv, program, {i: grid[i] for i in moving}, lambda v: v["gamma"], B, near=NEAR)
    every = list(grid)
    rise = np.full(B, np.nan)
    ret = np.full(B, np.nan)
    excess = np.full(B, -np.inf)
    for q, i in enumerate(moving):
        col = g[:, q]
        if kinds[i] == "rise":
            rise = np.fmax(rise, col)
        else:
            ret = np.fmax(ret, col)
        excess = np.maximum(excess, col - np.where(np.isnan(inv.limits[i]), np.inf, inv.limits[i]))
    # the safety factor K_C of a rocker (seed 3.26): the independent check's moved lines, over the constrained phases
    if (inv.factor > 1.0).any():
        limited = {i: grid[i] for i in moving if np.isfinite(inv.limits[i]).any()}
        sf = _largest(inv, program, limited, inv.safety, B, near=NEAR) if limited else np.full((B, 1), -np.inf)
        excess = np.maximum(excess, sf.max(axis=1))
    # the curvature times the roller, refined where above a half (farther from 1 the grid's value tells enough)
    # (to a thousandth of a step: the test is against 1 - MARGIN, not to the last digit)
    convex = _largest(inv, program, grid, lambda v: v["kr"], B, floor=0.5, steps=3).max(axis=1)
    concave = _largest(inv, program, grid, lambda v: -v["kr"], B, floor=0.5, steps=3).max(axis=1)
    # the working profile: star-shaped about the centroid of its outline, and round the cam centre (on the grid)
    wx = np.hstack([grid[i]["W"][0][:, :-1] for i in grid])
    wy = np.hstack([grid[i]["W"][1][:, :-1] for i in grid])
    turns, step = _winding(wx, wy)
    ax, ay = np.roll(wx, -1, axis=1), np.roll(wy, -1, axis=1)
    cr = wx * ay - ax * wy
    area = 0.5 * cr.sum(axis=1)
    inv.C = np.stack([((wx + ax) * cr).sum(axis=1), ((wy + ay) * cr).sum(axis=1)], axis=1) / (6.0 * area[:, None])
    kernel = np.min([inv.kernel(grid[i], program, i, us[i]).min(axis=1) for i in grid], axis=0)
    reach = np.hypot(wx, wy).min(axis=1)
    # the blank: the pitch curve's largest radius (the normal is radial there), less the roller (a groove's outer
    # wall: plus), refined like the pressure angle's maxima
    pitch = _largest(inv, program, grid, lambda v: v["rp"], B).max(axis=1)
    groove = np.array([d.limits.closure == "form" for d in designs])
    largest = pitch + np.where(groove, inv.roller, -inv.roller)
    # the joints: the relative velocity's direction on both sides (a velocity jump makes a corner)
    joint = np.zeros(B)
    allD = np.arange(B)
    for i in every:
        a = program.evaluate_phase(i, np.array([1.0]))
        b = program.evaluate_phase((i + 1) % len(kinds), np.array([0.0]))
        sa, sb = (np.broadcast_to(x, (B,)) for x in (a.s[0], b.s[0]))
        # the same cam angle: s continuous; the relative velocity's direction from each side's s'
        wa = _velocity(inv, allD, sa, a.ds[0])
        wb = _velocity(inv, allD, sb, b.ds[0])
        turn = np.arctan2(np.abs(wa[0] * wb[1] - wa[1] * wb[0]), wa[0] * wb[0] + wa[1] * wb[1])
        joint = np.maximum(joint, turn)
    return GroupCheck(
        rise=rise,
        ret=ret,
        excess=excess,
        convex=convex,
        concave=concave,
        kernel=kernel,
        turns=turns,
        step=step,
        reach=reach,
        joint=joint,
        largest=largest,
    )


def _velocity(inv: _Inversion, d, s, ds):
    """The roller centre's velocity relative to the cam (fixed frame, per radian) at ``s, s'``."""
    rk, arm, sg, eps = inv.rocker[d], inv.arm[d], inv.sense[d], inv.eps[d]
    c, sn = np.cos(sg * s), np.sin(sg * s)
    ax, ay = np.where(rk, arm * c, 0.0), np.where(rk, arm * sn, s)
    tx, ty = np.where(rk, -sg * arm * sn, 0.0), np.where(rk, sg * arm * c, 1.0)
    rx, ry = ax - inv.O[d, 0], ay - inv.O[d, 1]
    return ds * tx + eps * ry, ds * ty - eps * rx
