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
at once. The inversion (:func:`cams.verify.pressure.invert`), the grid's maxima
(:func:`cams.verify.pressure.grid_peaks`) and their zoom (:func:`cams.verify.pressure.zoom`) are the per-design
check's own, called on the arrays of many designs. The kernel's margin, the turns and the distance from the cam
centre are the grid's (their margins, :data:`cams.batch.MARGIN` of R0, are far above what a grid step can hide).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

# the independent check's inversion formula, grid maxima and zoom, on arrays of many designs
from cams.verify.pressure import ZOOM_POINTS, ZOOM_STEPS, grid_peaks, invert, zoom

__all__ = ["GroupCheck", "check_group", "GRID", "JOINT", "ZOOM_POINTS", "ZOOM_STEPS"]

#: Even steps per phase of the search.
GRID = 300
#: Designs checked at once.
CHUNK = 64
#: Even steps of a dwell (its values are constant but for the profile's outline, an arc round the cam centre).
DWELL_GRID = 90
#: The pressure angle's grid maxima refined: those within this of their phase's grid maximum (radians; the grid
#: lowers a maximum by some 1e-6 at most).
NEAR = 1e-3
#: The largest turn of the pitch curve's direction at a phase joint (radians) taken as no corner: the one test of
#: a velocity jump's corner, far below the per-design path's (a turn whose cosine is below 1 - 1e-12, some
#: 1.4e-6 rad), so a batched cam has no corner by either.
JOINT = 1e-9


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
    Where every cam of a chunk (:data:`CHUNK`) has a corner (``joint`` above :data:`JOINT`), ``joint`` alone is
    computed, every other field NaN.
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
        self.floor = np.array([1e-12 * d.scale for d in designs], float)  # |W| at or below: no normal (A = O)
        lims = [dict(d.constrained_phases()) for d in designs]
        self.limits = {i: np.array([lm.get(i, np.nan) for lm in lims]) for i in range(len(designs[0].program.phases))}

    def frame(self, d: np.ndarray, s: np.ndarray):
        """The follower's geometry of designs ``d`` at ``s`` (broadcast): the roller centre ``A``, its tangent
        ``T = dA/ds`` and ``dT/ds``, components ``ax, ay, tx, ty, ux, uy`` (fixed frame)."""
        arm, sg = self.arm[d], self.sense[d]
        if self.all_rocker:
            c, sn = np.cos(sg * s), np.sin(sg * s)
            return arm * c, arm * sn, -sg * arm * sn, sg * arm * c, -arm * c, -arm * sn
        if not self.rocker.any():
            return 0.0, s, 0.0, 1.0, 0.0, 0.0
        rk = self.rocker[d]
        c, sn = np.cos(sg * s), np.sin(sg * s)
        return (
            np.where(rk, arm * c, 0.0),
            np.where(rk, arm * sn, s),
            np.where(rk, -sg * arm * sn, 0.0),
            np.where(rk, sg * arm * c, 1.0),
            np.where(rk, -arm * c, 0.0),
            np.where(rk, -arm * sn, 0.0),
        )

    def invert(self, d: np.ndarray, s: np.ndarray, ds: np.ndarray):
        """:func:`cams.verify.pressure.invert` for designs ``d`` at the motion ``s, s'`` (broadcast), and ``dT/ds``."""
        ax, ay, tx, ty, ux, uy = self.frame(d, s)
        return invert(ax, ay, tx, ty, self.O[d, 0], self.O[d, 1], ds, self.eps[d], self.floor[d]), (tx, ty, ux, uy)

    def at(self, d: np.ndarray, program, i: int, u: np.ndarray) -> dict:
        """At positions ``u`` (shape of ``d``, broadcast) of phase ``i``: ``gamma``, ``kappa``, ``p`` and the
        kernel's margin ``k`` of the working profile about the point :attr:`C` (cam frame; 0 before it is set)."""
        m = program.evaluate_phase(i, np.asarray(u, float).ravel())
        sh = np.broadcast_shapes(np.shape(d), np.shape(u))
        s, ds, d2s = (np.broadcast_to(v.reshape(np.shape(u)), sh) for v in (m.s, m.ds, m.d2s))
        eps = self.eps[d]
        v, (tx, ty, ux, uy) = self.invert(d, s, ds)
        wx, wy, nx, ny, rx, ry = v.wx, v.wy, v.nx, v.ny, v.rx, v.ry
        w2, w = v.w2, v.w
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
            "gamma": v.angle,
            "kr": kappa * rr,
            "p": p,
            "rp": np.hypot(rx, ry),  # the pitch point's distance from the cam centre
            "W": W,
            "n": (nx, ny),
            "e": (v.ex, v.ey),
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
    grid's): the independent check's :func:`cams.verify.pressure.grid_peaks` and
    :func:`cams.verify.pressure.zoom`. An undefined value (NaN) counts as +inf: as bad as can be (the design goes
    to the per-design path).
    """
    u = np.linspace(0.0, 1.0, GRID + 1)
    phases = list(grid)
    out = np.full((B, len(phases)), -np.inf)
    peaks = []
    for col, i in enumerate(phases):
        g = what(grid[i])
        g = np.where(np.isnan(g), np.inf, g)
        out[:, col] = g.max(axis=1)
        if program.phases[i].kind == "dwell":  # constant: the grid's value is the phase's
            continue
        keep = (g >= out[:, col, None] - near) & (g >= floor)
        pd, best, at, lo, hi = grid_peaks(g, u, keep)
        peaks.append((pd, np.full(len(pd), col), best, at, lo, hi))
    if not peaks:
        return out
    d, q, best, at, lo, hi = (np.concatenate(a) for a in zip(*peaks, strict=True))
    groups = [(k, i, np.flatnonzero(q == k)) for k, i in enumerate(phases)]
    groups = [(i, on, d[on, None]) for _, i, on in groups if len(on)]

    def values(x: np.ndarray) -> np.ndarray:
        gx = np.empty_like(x)
        for i, on, don in groups:
            gx[on] = what(inv.at(don, program, i, x[on]))
        return np.where(np.isnan(gx), np.inf, gx)

    best, _ = zoom(values, lo, hi, best, at, steps)
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
    # the joints first: the relative velocity's direction on both sides (a velocity jump makes a corner); a chunk
    # whose every cam has one is sent back at once (the law's velocity jumps: no centre is without a corner)
    joint = np.zeros(B)
    for i in range(len(kinds)):
        a = program.evaluate_phase(i, np.array([1.0]))
        b = program.evaluate_phase((i + 1) % len(kinds), np.array([0.0]))
        sa, sb = (np.broadcast_to(x, (B,)) for x in (a.s[0], b.s[0]))
        # the same cam angle: s continuous; the relative velocity's direction from each side's s'
        wa, _ = inv.invert(allD[:, 0], sa, a.ds[0])
        wb, _ = inv.invert(allD[:, 0], sb, b.ds[0])
        turn = np.arctan2(np.abs(wa.wx * wb.wy - wa.wy * wb.wx), wa.wx * wb.wx + wa.wy * wb.wy)
        joint = np.maximum(joint, turn)
    if (joint > JOINT).all():
        nan = np.full(B, np.nan)
        return GroupCheck(**{**{k: nan for k in GroupCheck.__dataclass_fields__}, "joint": joint})
    grid = {i: inv.at(allD, program, i, us[i][None]) for i in range(len(kinds))}
    g = _largest(inv, program, {i: grid[i] for i in moving}, lambda v: v["gamma"], B, near=NEAR)
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
