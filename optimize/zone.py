"""The allowable-centre zone: one wedge of admissible cam centres per position.

Geometry (seed 001 eqs. 3.15-3.22)
----------------------------------
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

Each wedge is two half-planes ``n . O <= n . D`` (n unit). The pressure angle
signed positive in the cam's sense of rotation, i.e. positive where the cam
drives the follower along its rise, is ``+[gamma]`` on one edge and
``-[gamma]`` on the other: side "t" (index 0, the seed's t-t lines: the rise's)
is the ``+[gamma]`` edge, side "t1" (index 1, the seed's t1-t1 lines: the
return's under form closure, the start position's under force closure) the
``-[gamma]`` edge, whatever the senses of cam and follower, so mirror images
name their lines alike. The safety factor K_C (seed 3.26) moves D along the
lever by ``(K_C - 1) l`` for the edge whose half-plane shrinks when D moves
outward along the lever and by ``-(1 - 1/K_C) l`` for the other, shifting both
lines into the zone.

The follower as a rigid body
----------------------------
Both followers carry their geometry rigidly: at displacement ``s`` the roller
centre A, the tangent ``T = dA/ds`` and the lever are those at ``s = 0`` turned
by ``turn s`` about the origin and moved by ``tau s`` (rocker: ``turn`` = its
sense, ``tau = 0``, the origin is the pivot; translating: ``turn = 0``,
``tau`` = the unit vector of the rise). With ``V = s' T`` the wedge of a
position is therefore the wedge at ``s = 0`` with the apex term ``s'`` put in,
moved rigidly:

    n(s) = R(turn s) n0,
    D(s) = R(turn s) (P0 + s' Q0) + tau s,   P0 = A0 + k lever0,  Q0 = eps k x T0,

(``k`` the K_C shift of the side), and the signed distance of a centre O
outside a side is

    h = n . O - (b0 + b1 s' + bt s),   b0 = n0 . P0,  b1 = n0 . Q0,  bt = n0 . tau.

With ``p = n . O`` and ``m = (k x n) . O`` its derivatives along the cam angle
are (``s', s'', s'''`` from the laws)

    h'  = turn s' m - b1 s'' - bt s',
    h'' = turn (s'' m - turn s'^2 p) - b1 s''' - bt s'',

which :func:`max_violation` uses to locate the largest violation by safeguarded
Newton steps. :func:`side_constants` is the one place of the wedge geometry;
everything else here is built on these three formulas.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from cams.model.design import CamDesign
from cams.model.follower import Rocker

__all__ = ["Wedges", "wedges", "phase_wedges", "side_terms", "sample_wedges", "max_violation", "ViolationPeak",
           "ZoneTable", "zone_table", "clear_cache", "Peaks", "scan_peaks", "GRID", "rigid_motion",
           "side_constants", "scan_positions", "turned", "side_offset", "side_slopes"]

#: Even steps per phase of the violation scan (:class:`ZoneTable`).
GRID = 384
#: Half-width (in u) of the pair of scan positions put on each side of a law's breakpoint.
_BREAK_GAP = 1e-12
#: Scan steps narrower than this (in u) are not refined.
_NARROW = 1e-10


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


# -- the wedge geometry ------------------------------------------------------------------------

def rigid_motion(design: CamDesign) -> tuple[float, np.ndarray]:
    """How the follower's geometry moves with its displacement ``s``.

    Returns
    -------
    turn : float
        The geometry at ``s`` is that at ``s = 0`` turned by ``turn * s`` radians about the pivot (a rocker:
        its ``sense``, +1 counter-clockwise; a translating follower: 0).
    tau : ndarray, shape (2,)
        ... and moved by ``tau * s`` (mm): a translating follower's unit rise direction ``(0, 1)``; a rocker:
        zero.
    """
    f = design.follower
    if isinstance(f, Rocker):
        return float(f.sense), np.zeros(2)
    return 0.0, np.array([0.0, 1.0])


def side_constants(design: CamDesign, limit: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Wedge of the follower at ``s = 0``: ``n0 (2, 2)``, ``P0 (2, 2)``, ``Q0 (2,)`` (sides t, t1).

    The one place of the wedge geometry (the zone's scan and the batch sizing, :mod:`cams.batch.sizing`).

    Parameters
    ----------
    design : CamDesign
        Its follower, cam sense and K_C (``limits.safety_factor``).
    limit : float
        The pressure-angle limit of the phase, radians.

    Returns
    -------
    n0, P0, Q0 : ndarray
        ``n0[k]`` is the unit outward normal of side k, ``P0[k] + s' Q0`` its apex D (mm, with the K_C shift)
        at analogue velocity ``s'`` (mm/rad), in the fixed frame; see the module notes.
    """
    f = design.follower
    A, T, lever = (v.tolist() for v in f.frame(np.float64(0.0)))  # scalars: plain floats are quicker
    # normals: the wedge axis -e turned by +-(90 deg + limit)
    norm = math.hypot(T[0], T[1])
    ax, ay = -T[0] / norm, -T[1] / norm
    cs, sn = -math.sin(limit), math.cos(limit)
    na = (cs * ax - sn * ay, sn * ax + cs * ay)
    nb = (cs * ax + sn * ay, -sn * ax + cs * ay)
    # side t: the edge where the pressure angle, signed positive in the cam's sense, is +limit (na lies
    # at +(90 deg + limit) from the axis -e, so there n is e turned by +limit): na for a counter-clockwise cam
    n0 = np.array([na, nb] if design.cam_sense > 0 else [nb, na])
    K = design.limits.safety_factor
    ref = getattr(f, "arm", 0.0)
    # K_C: outward along the lever for the edge that shrinks so (n . lever < 0), inward for the other
    shift = [(K - 1.0) * ref if n[0] * lever[0] + n[1] * lever[1] < 0 else -(1.0 - 1.0 / K) * ref for n in n0]
    P0 = np.array([[A[0] + k * lever[0], A[1] + k * lever[1]] for k in shift])
    Q0 = np.array([-design.cam_sense * T[1], design.cam_sense * T[0]])
    return n0, P0, Q0


def turned(c: np.ndarray, s: np.ndarray, x, y) -> tuple[np.ndarray, np.ndarray]:
    """Components of the vector ``(x, y)`` turned by the angle whose cosine and sine are ``c``, ``s``."""
    return c * x - s * y, s * x + c * y


def phase_wedges(design: CamDesign, i: int, limit: float, u: np.ndarray) -> Wedges:
    """Wedges of phase ``i`` at normalized positions ``u`` (one-sided at its ends)."""
    u = np.asarray(u, dtype=float)
    m = design.program.evaluate_phase(i, u)
    turn, tau = rigid_motion(design)
    n0, P0, Q0 = side_constants(design, limit)
    c, sn = np.cos(turn * m.s)[:, None], np.sin(turn * m.s)[:, None]
    n = len(u)
    normals = np.empty((n, 2, 2))
    normals[..., 0], normals[..., 1] = turned(c, sn, n0[:, 0], n0[:, 1])
    apex = np.empty((n, 2, 2))
    dx = P0[:, 0] + m.ds[:, None] * Q0[0]
    dy = P0[:, 1] + m.ds[:, None] * Q0[1]
    ex, ey = turned(c, sn, dx, dy)
    apex[..., 0] = ex + tau[0] * m.s[:, None]
    apex[..., 1] = ey + tau[1] * m.s[:, None]
    b0 = np.einsum("ki,ki->k", n0, P0)
    offsets = side_offset(b0, n0 @ Q0, n0 @ tau, m.s[:, None], m.ds[:, None])
    p = design.program
    phi = p.starts[i] + u * p.phases[i].angle
    return Wedges(phase=np.full(n, i), phi=phi, normals=normals, offsets=offsets, apex=apex,
                  limit=np.full(n, float(limit)))


def side_terms(design: CamDesign, limit: float, s: np.ndarray, ds: np.ndarray,
               centre: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """A centre's signed distances outside both sides at positions ``(s, s')``, with their rates in ``s, s'``.

    For the motion design, which moves the law: ``h = n(s) . O - (b0 + b1 s' + bt s)`` (module notes) and
    ``dh/ds = turn m - bt`` (``m = (k x n) . O``), ``dh/ds' = -b1``.

    Parameters
    ----------
    design : CamDesign
    limit : float
        The phase's allowable pressure angle, radians.
    s, ds : ndarray, shape (n,)
        Displacement and its analogue velocity at the positions.
    centre : ndarray, shape (2,)
        Cam centre O, fixed frame.

    Returns
    -------
    h, dh_ds, dh_dds : ndarray, shape (n, 2)
        Per position and side (t, t1).
    normals : ndarray, shape (n, 2, 2)
        The sides' unit outward normals ``n(s)``: ``h`` is ``normals . O`` less a term free of ``O``.
    """
    s = np.asarray(s, dtype=float)
    ds = np.asarray(ds, dtype=float)
    turn, tau = rigid_motion(design)
    n0, P0, Q0 = side_constants(design, limit)
    c, sn = np.cos(turn * s)[:, None], np.sin(turn * s)[:, None]
    normals = np.empty((s.size, 2, 2))
    normals[..., 0], normals[..., 1] = turned(c, sn, n0[:, 0], n0[:, 1])
    b0 = np.einsum("ki,ki->k", n0, P0)
    b1, bt = n0 @ Q0, n0 @ tau
    O = np.asarray(centre, dtype=float)
    p = normals @ O
    h = p - side_offset(b0, b1, bt, s[:, None], ds[:, None])
    m = normals[..., 0] * O[1] - normals[..., 1] * O[0]
    return h, turn * m - bt, np.broadcast_to(-b1, h.shape).copy(), normals


def side_offset(b0, b1, bt, s, ds):
    """``n . D``: the offset of a side's half-plane at displacement ``s`` and analogue velocity ``ds``."""
    return b0 + b1 * ds + bt * s


def side_slopes(turn, O, nx, ny, p, b1, bt, ds, d2s, d3s=None):
    """``h'`` and, given ``s'''``, also ``h''`` along the cam angle (module notes); ``p = n . O``."""
    m = nx * O[1] - ny * O[0]
    d1 = turn * ds * m - b1 * d2s - bt * ds
    if d3s is None:
        return d1
    return d1, turn * (d2s * m - turn * ds * ds * p) - b1 * d3s - bt * d2s


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


# -- the continuous violation ------------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class ZoneTable:
    """What the violation scan needs of one design, computed once.

    Per constrained phase ``j`` (program phase ``phases[j]``) and side ``k``:
    the constants of the module notes, and the motion and the half-planes on
    the scan positions ``u``.

    Attributes
    ----------
    phases : tuple of int
        Program indices of the constrained phases.
    limit : ndarray, shape (P,)
        Their allowable pressure angles, radians.
    turn : float
        Turn of the follower per unit displacement (rocker: its sense; 0).
    n0 : ndarray, shape (P, 2, 2)
        Unit normals at ``s = 0``.
    b0, b1, bt : ndarray, shape (P, 2)
        Offset ``b0 + b1 s' + bt s`` of each side's half-plane.
    angle : ndarray, shape (P,)
        Cam angle of each phase (radians).
    sides : ndarray, shape (2 P, 6)
        Per side ``2 j + k``: ``n0x, n0y, b0, b1, bt, angle``.
    u : ndarray, shape (M,)
        Scan positions: ``grid`` even steps, geometric steps into both ends
        (laws start from rest, so a peak can sit well inside the first step)
        and a pair at each side of every law breakpoint.
    nx, ny, off : ndarray, shape (P, 2, M)
        Half-planes ``nx x + ny y <= off`` at the scan positions.
    planes : ndarray, shape (3, P * 2 * M)
        The same stacked and flattened.
    s, ds, d2s, d3s : ndarray, shape (P, 1, M)
        The motion there (per radian of cam angle).
    scale : float
        The design's length scale.
    """

    design: CamDesign
    phases: tuple[int, ...]
    limit: np.ndarray
    turn: float
    n0: np.ndarray
    b0: np.ndarray
    b1: np.ndarray
    bt: np.ndarray
    angle: np.ndarray
    sides: np.ndarray
    u: np.ndarray
    nx: np.ndarray
    ny: np.ndarray
    off: np.ndarray
    planes: np.ndarray
    s: np.ndarray
    ds: np.ndarray
    d2s: np.ndarray
    d3s: np.ndarray
    scale: float

    def motion(self, j: int, u: np.ndarray) -> tuple[np.ndarray, ...]:
        """``s, s', s'', s'''`` of constrained phase ``j`` at ``u``."""
        m = self.design.program.evaluate_phase(self.phases[j], u)
        return m.s, m.ds, m.d2s, m.d3s

    def grid_violation(self, centre: np.ndarray) -> np.ndarray:
        """Signed distances (P, 2, M) of ``centre`` outside the half-planes at the scan positions."""
        return self.nx * centre[0] + self.ny * centre[1] - self.off


@lru_cache(maxsize=8)
def _even_and_ends(grid: int) -> np.ndarray:
    """``grid`` even steps and 8 geometric steps into each end (from 1e-7 to half a step)."""
    ends = np.geomspace(1e-7, 0.5 / grid, 8)
    u = np.unique(np.concatenate([np.linspace(0.0, 1.0, grid + 1), ends, 1.0 - ends]))
    u.setflags(write=False)
    return u


def scan_positions(design: CamDesign, grid: int) -> np.ndarray:
    """Normalized positions ``u`` in [0, 1] where each constrained phase's wedges are scanned.

    ``grid`` even steps and geometric steps into each end, plus every law's breakpoints and a point just
    either side of each (a law's s'' may jump there). The same positions for every phase.
    """
    u = _even_and_ends(grid)
    found = {b for i, _ in design.constrained_phases() for b in design.program.law_of(i).breakpoints}
    if not found:
        return u
    bps = np.array(sorted(found))
    return np.unique(np.concatenate([u, bps, bps - _BREAK_GAP, bps + _BREAK_GAP]))


def zone_table(design: CamDesign, grid: int = GRID) -> ZoneTable:
    """The :class:`ZoneTable` of ``design`` with ``grid`` even steps per phase (cached per design)."""
    return _zone_table(design, int(grid))


def clear_cache() -> None:
    """Forget the cached zone tables (a benchmark times a design's first solve so)."""
    _zone_table.cache_clear()


@lru_cache(maxsize=32)
def _zone_table(design: CamDesign, grid: int) -> ZoneTable:
    phases = design.constrained_phases()
    P = len(phases)
    turn, tau = rigid_motion(design)
    n0 = np.zeros((P, 2, 2))
    b0, b1, bt = np.zeros((P, 2)), np.zeros((P, 2)), np.zeros((P, 2))
    for j, (_, lim) in enumerate(phases):
        n0[j], P0, Q0 = side_constants(design, lim)
        b0[j] = np.einsum("ki,ki->k", n0[j], P0)
        b1[j], bt[j] = n0[j] @ Q0, n0[j] @ tau
    u = scan_positions(design, grid)
    M = len(u)
    mo = np.zeros((4, P, 1, M))
    for j, (i, _) in enumerate(phases):
        m = design.program.evaluate_phase(i, u)
        mo[:, j, 0] = m.s, m.ds, m.d2s, m.d3s
    s, ds, d2s, d3s = mo
    c, sn = np.cos(turn * s), np.sin(turn * s)
    B0, B1, BT = b0[..., None], b1[..., None], bt[..., None]
    angle = np.array([design.program.phases[i].angle for i, _ in phases])
    sides = np.stack([n0[..., 0], n0[..., 1], b0, b1, bt, np.repeat(angle[:, None], 2, axis=1)], axis=-1)
    sides = sides.reshape(2 * P, 6)
    nx, ny = turned(c, sn, n0[..., 0, None], n0[..., 1, None])
    off = side_offset(B0, B1, BT, s, ds)
    return ZoneTable(
        design=design, phases=tuple(i for i, _ in phases), limit=np.array([lim for _, lim in phases], float),
        turn=turn, n0=n0, b0=b0, b1=b1, bt=bt,
        angle=angle, sides=sides, u=u, nx=nx, ny=ny, off=off, planes=np.stack([nx, ny, off]).reshape(3, -1),
        s=s, ds=ds, d2s=d2s, d3s=d3s, scale=float(design.scale),
    )


@dataclass(frozen=True)
class Peaks:
    """Local maxima of every side's signed distance over the continuum, as arrays.

    ``j`` constrained-phase index (into :attr:`ZoneTable.phases`), ``side`` 0
    (t) or 1 (t1), ``u`` position, ``value`` signed distance, and the
    half-plane ``nx x + ny y <= offset`` there.
    """

    j: np.ndarray
    side: np.ndarray
    u: np.ndarray
    value: np.ndarray
    nx: np.ndarray
    ny: np.ndarray
    offset: np.ndarray


def _refine(t: ZoneTable, O: np.ndarray, jk, i, cell, H, iters: int) -> Peaks:
    """Largest value of side ``jk`` (``2 j + k``) from the scan position ``i`` on.

    Where ``cell`` is true the slope turns from + to - between the scan
    positions ``i`` and ``i + 1``: the first point is the root of the cubic
    Hermite interpolant of the slope (from ``h'`` and ``h''`` at both ends),
    then Newton steps on ``h' = 0`` with the analytic ``h''``, safeguarded: the
    bracket shrinks by the sign of ``h'`` at every new point, and a step that
    leaves it, or one where ``h`` is not concave, is replaced by bisection.
    All brackets are stepped together (one law evaluation per phase a step); a
    bracket stops when the value still to gain, ``h'^2 / (2 |h''|)``, is below
    round-off. The largest value seen, the scan's included, is kept, so the
    result can only rise. Elsewhere the scan position ``i`` is the maximum.
    ``H`` holds the scan's ``h, h', h''``, flattened: shape (3, P * 2 * M).
    """
    turn, u = t.turn, t.u
    M = len(u)
    f0 = jk * M + i
    f1 = f0 + cell
    a, b = u[i], u[i + cell]
    (ha, da, ea), (hb, db, eb) = H[:, f0], H[:, f1]
    first = ha >= hb
    best_u, best_v = np.where(first, a, b), np.maximum(ha, hb)
    best_x, best_y, best_c = t.planes[:, np.where(first, f0, f1)]
    # a step narrower than this (the pairs around breakpoints) keeps its ends' values: a smooth
    # maximum inside would add |h''| w^2 / 8, below round-off; a corner sits at an end
    active = b - a > _NARROW
    if active.any():
        n0x, n0y, b0, b1, bt, ang = t.sides[jk].T
        # the cubic through the slopes and curvatures at both ends, in tau = (u - a) / (b - a)
        w = (b - a) * ang
        ea, eb = w * ea, w * eb
        c2 = 3.0 * (db - da) - 2.0 * ea - eb
        c3 = 2.0 * (da - db) + ea + eb
        # from the linear interpolant's root, one Newton step on the cubic
        tau = da / np.where(active, da - db, 1.0)
        q1 = ea + tau * (2.0 * c2 + 3.0 * c3 * tau)
        step = (da + tau * (ea + tau * (c2 + tau * c3))) / np.where(q1 < 0, q1, -1.0)
        tau = np.minimum(np.maximum(tau - np.where(q1 < 0, step, 0.0), 0.0), 1.0)
        x = a + (b - a) * tau
        j = jk // 2
        cuts = np.searchsorted(j, np.arange(len(t.phases) + 1)).tolist()  # candidates come sorted by phase
        mo = np.empty((4, len(a)))
        for _ in range(iters):
            for jj in range(len(t.phases)):
                lo, hi = cuts[jj], cuts[jj + 1]
                if hi > lo:
                    mo[:, lo:hi] = t.motion(jj, x[lo:hi])
            s, ds, d2s, d3s = mo
            if turn:
                nx, ny = turned(np.cos(turn * s), np.sin(turn * s), n0x, n0y)
            else:
                nx, ny = n0x, n0y
            p = nx * O[0] + ny * O[1]
            off = side_offset(b0, b1, bt, s, ds)
            hx = p - off
            d1, d2 = side_slopes(turn, O, nx, ny, p, b1, bt, ds, d2s, d3s)
            better = active & (hx > best_v)
            for dst, src in ((best_u, x), (best_v, hx), (best_x, nx), (best_y, ny), (best_c, off)):
                np.copyto(dst, src, where=better)
            up = d1 > 0
            np.copyto(a, x, where=up)
            np.copyto(b, x, where=~up)
            concave = d2 < 0
            dphi = -d1 / np.where(concave, d2, -1.0)
            # done when a Newton step would gain less than the round-off of the values it compares (|n.O|, |offset|)
            active &= ~(concave & (0.5 * d1 * dphi <= 1e-15 * (np.abs(p) + np.abs(off))))
            if not active.any():
                break
            xn = x + dphi / ang
            x = np.where(concave & (xn > a) & (xn < b), xn, 0.5 * (a + b))
    return Peaks(j=jk // 2, side=jk % 2, u=best_u, value=best_v, nx=best_x, ny=best_y, offset=best_c)


def scan_peaks(t: ZoneTable, centre: np.ndarray, *, iters: int = 8) -> Peaks:
    """Local maxima of every side's signed distance over the continuum, for the centre ``centre``.

    The signed distance and its slope are evaluated on the table's scan
    positions; a local maximum is a step where the slope turns from positive
    to negative (refined by :func:`_refine`), or a scan position that is a
    local maximum of the values where the slope is zero or, at an end, points
    outwards (exact values there).
    """
    O = np.asarray(centre, dtype=float)
    p = t.nx * O[0] + t.ny * O[1]
    h = p - t.off
    h1, h2 = side_slopes(t.turn, O, t.nx, t.ny, p, t.sides[:, 3].reshape(-1, 2, 1), t.sides[:, 4].reshape(-1, 2, 1),
                     t.ds, t.d2s, t.d3s)
    up, down = h1 > 0, h1 < 0
    point = ~up & ~down
    point[..., 0] |= down[..., 0]
    point[..., -1] |= up[..., -1]
    point[..., 1:] &= h[..., 1:] >= h[..., :-1]
    point[..., :-1] &= h[..., :-1] >= h[..., 1:]
    cell = np.zeros_like(up)
    cell[..., :-1] = up[..., :-1] & down[..., 1:]
    f = np.flatnonzero(point | cell)
    M = len(t.u)
    return _refine(t, O, f // M, f % M, cell.ravel()[f].astype(int), np.stack([h, h1, h2]).reshape(3, -1), iters)


@dataclass(frozen=True)
class ViolationPeak:
    """A local maximum of a side's signed distance over a phase."""

    phase: int
    u: float
    side: int
    value: float


def max_violation(design: CamDesign, centre: np.ndarray, *, grid: int = GRID, iters: int = 8) -> list[ViolationPeak]:
    """Local maxima over the continuum of every constraint's signed distance.

    For every constrained phase and both sides, the signed distance
    ``n(phi) . O - n(phi) . D(phi)`` and its slope are scanned on ``grid``
    even steps (plus steps into the ends and around law breakpoints); each
    local maximum is refined by safeguarded Newton steps with the analytic
    second derivative (:func:`scan_peaks`), vectorized over all peaks of all
    phases; it converges quadratically on the smooth laws.

    Returns
    -------
    list of ViolationPeak
        Sorted by decreasing value; the first one is the largest violation
        (positive) or the smallest slack (negative).
    """
    t = zone_table(design, grid)
    if not t.phases:
        return [ViolationPeak(-1, 0.0, 0, -np.inf)]
    pk = scan_peaks(t, centre, iters=iters)
    order = np.argsort(-pk.value, kind="stable")
    return [ViolationPeak(t.phases[pk.j[q]], float(pk.u[q]), int(pk.side[q]), float(pk.value[q])) for q in order]
