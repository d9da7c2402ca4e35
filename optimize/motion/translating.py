"""The translating followers' programs: the law's coefficients and the cam's centre in one convex program.

Roller (or knife edge). In the follower's frame (origin at the roller centre
at the near dwell, Y along the rise) the cam centre is ``(x, -d)``, the offset
``e = -x`` and ``R0 = || (x, d) ||``. The pressure angle ``gamma`` at cam angle
``phi`` obeys ``tan gamma = (s' + eps x) / (d + s)`` with ``eps`` the cam's
sense (+1 counter-clockwise; the same as ``(s' - eps e) / (d + s)``; tested
against the kernel's inversion). A limit ``[gamma]`` on a phase is therefore::

    |s'(phi) + eps x| <= tan[gamma] (d + s(phi))

two inequalities linear in the law's coefficients and in ``(x, d)``; the
smallest ``R0`` is a second-order cone program.

Flat face (perpendicular to the axis). The profile's radius of curvature is
``R0 + s + s''`` (analogues per radian), so convexity with a least radius
``rho`` is ``R0 + s + s'' >= rho``: linear, and the smallest ``R0`` a linear
program.

Both are built in two forms from the same rows (:class:`optimize.motion.space.Space`):
``"conservative"``, every constraint on the Bernstein coefficients of every
piece of every span (it holds at every cam angle), and ``"relaxed"``, every
constraint at sample points only (its optimum is a lower bound of the space's).
The variables: the free phases' coefficients, then the geometry (``x, d`` or
``R0``), then an epigraph variable ``t``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from laws.program import Program
from optimize.motion.conic import Cone, ConicProgram
from optimize.motion.space import Space

__all__ = ["Request", "build", "Sides", "pressure_sides", "PressureRows", "pressure_rows", "conservative_ratio",
           "form_ratio", "pressure_terms", "SAMPLES_PER_SPAN",
           "FIXED_SAMPLES", "TIGHTEN", "S_MARGIN"]
#: Sample points per span of the relaxation (ends included).
SAMPLES_PER_SPAN = 17
#: Sample points of a fixed (not free) constrained phase.
FIXED_SAMPLES = 400
#: Relative tightening of the caps in the conservative program: room for the solver's feasibility tolerance
#: (Clarabel's default, 1e-8 on the scaled rows) and for the projection onto the joints' equalities; the caps
#: are then checked on the laws themselves.
TIGHTEN = 1e-7
#: How far the normalized S may leave [0, 1] (the follower its stroke): a margin that keeps the bounds of a law
#: that touches 0 or 1 over a whole span (every library law does at its ends) from binding degenerately.
S_MARGIN = 5e-7


@dataclass(frozen=True)
class Request:
    """What one program asks.

    Parameters
    ----------
    space : Space
    follower : {"roller", "flat"}
    cam_sense : int
        +1 counter-clockwise.
    limits : dict of int to float
        Constrained phases (roller) and their pressure-angle limits, radians.
    caps : dict of (int, int) to float
        ``(k, r)`` -> cap on ``|S_k^(r)|`` (free phase ``k``, derivative ``r``).
    objective : str
        ``"R0"``, ``"Ca"``, ``"Cj"``, ``"jerk_squared"``, ``"snap_squared"`` or
        ``"feasibility"`` (minimize the largest slack of the pressure rows,
        length; for the least pressure angle's iteration).
    ratio : float
        The pressure limits are ``ratio * limit`` (1 but in the least pressure angle's iteration).
    centre : (float, float) or None
        A fixed cam centre ``(x, d)`` (roller) or ``(R0, 0)`` (flat).
    x_fixed : float or None
        A fixed ``x = -e`` (roller, ``follower.offset``).
    hold : float or None
        ``R0`` at most this (the cam's size held), length.
    bound : float
        The box on the geometry and ``t`` (length), generous.
    min_radius : float
        Flat face: the least radius of curvature, length.
    length : float
        The program's unit of length (the design's scale): every length above is divided by it, so that the
        program, its tolerances and its bound do not depend on the design's unit; the caller multiplies the
        geometry and a length objective back.
    """

    space: Space
    follower: str
    cam_sense: int
    limits: dict[int, float]
    caps: dict[tuple[int, int], float]
    objective: str
    bound: float
    ratio: float = 1.0
    centre: tuple[float, float] | None = None
    x_fixed: float | None = None
    hold: float | None = None
    min_radius: float = 0.0
    length: float = 1.0


def _fixed_motion(program: Program, i: int, count: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    m = program.evaluate_phase(i, np.linspace(0.0, 1.0, count))
    return m.s, m.ds, m.d2s


@dataclass(frozen=True)
class Sides:
    """One limited phase's pressure rows (roller): ``s' + eps x`` and ``d + s`` at each of the phase's points,
    linear in the program's variables ``v`` (:func:`build`'s: the laws', then ``x = v[nc]``, ``d = v[nc + 1]``,
    ``t``), lengths over the request's ``length``, ``s'`` per radian.

    The points are the Bernstein coefficients of every piece (``"conservative"``) or the samples (``"relaxed"``)
    of a free phase, :data:`FIXED_SAMPLES` positions of a fixed one. At each::

        s' = ds0 + slope_scale (slope @ v),   s = s0 + level_scale (level @ v)

    a free phase's ``slope`` and ``level`` the rows of ``S'`` (its coefficients elevated to the degree of
    ``S``'s) and of ``S`` (:meth:`optimize.motion.space.Space.rows`), ``slope_scale = sh / beta``,
    ``level_scale = sh``, ``ds0 = 0`` and ``s0 = lev`` (:meth:`~optimize.motion.space.Space.phase_scale`); a
    fixed phase's ``slope`` and ``level`` None, ``ds0`` and ``s0`` its law's values. The phase's rows at ratio
    ``r`` are ``sign (s' + eps x) <= tan(r limit) (d + s)``, for each sign.

    Made by :func:`pressure_sides` alone; :func:`build` (:meth:`rows`), :func:`pressure_rows` (:meth:`matrices`)
    and :func:`pressure_terms` (:meth:`at`) combine them, each in the order of operations it has always used (the
    least pressure angle's iteration is sensitive to the last bit of its rows on some designs).

    Attributes
    ----------
    nc : int
        The laws' variables (``x``'s column).
    eps : float
        The cam's sense, +1 counter-clockwise.
    limit : float
        The phase's pressure-angle limit, radians.
    ds0, s0 : ndarray, shape (points,)
    slope, level : ndarray, shape (points, nc + 3), or None
    slope_scale, level_scale : float
    """

    nc: int
    eps: float
    limit: float
    ds0: np.ndarray
    s0: np.ndarray
    slope: np.ndarray | None = None
    level: np.ndarray | None = None
    slope_scale: float = 0.0
    level_scale: float = 0.0

    def rows(self, sign: float, T: float) -> tuple[np.ndarray, np.ndarray]:
        """:func:`build`'s rows ``sign (s' + eps x) - T (d + s) <= 0`` (``T = tan(ratio limit)``): ``(G, h)``."""
        nc = self.nc
        if self.slope is None or self.level is None:
            rows = np.zeros((self.s0.size, nc + 3))
            rhs = T * self.s0 - sign * self.ds0
        else:
            rows = sign * self.slope_scale * self.slope - T * self.level_scale * self.level
            rhs = T * self.s0
        rows[:, nc] = sign * self.eps
        rows[:, nc + 1] = -T
        return rows, rhs

    def matrices(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """``(top, top0, bottom, bottom0)``: ``top @ v + top0 = s' + eps x`` and ``bottom @ v + bottom0 = d + s``
        (:class:`PressureRows`'s sides)."""
        nc = self.nc
        if self.slope is None or self.level is None:
            top, bottom = np.zeros((self.s0.size, nc + 3)), np.zeros((self.s0.size, nc + 3))
        else:
            top, bottom = self.slope_scale * self.slope, self.level_scale * self.level
        top[:, nc] = self.eps
        bottom[:, nc + 1] = 1.0
        return top, self.ds0, bottom, self.s0

    def at(self, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(s' + eps x, d + s)`` at ``v``."""
        ds, s = self.ds0, self.s0
        if self.slope is not None and self.level is not None:
            ds = self.slope_scale * (self.slope @ v)        # ds0 is 0
            s = s + self.level_scale * (self.level @ v)
        return ds + self.eps * float(v[self.nc]), float(v[self.nc + 1]) + s


def pressure_sides(req: Request, form: str) -> list[Sides]:
    """The pressure rows of ``req`` (roller) in ``form``, per limited phase in ``req.limits``' order
    (:class:`Sides`): the one place their coefficients are made.

    A free phase of height ``sh``, angle ``beta`` and start ``lev`` has ``s = lev + sh S`` and
    ``s' = sh S' / beta``; a fixed phase's ``s`` and ``s'`` are its law's values at :data:`FIXED_SAMPLES`
    positions.
    """
    sp = req.space
    nc = sp.size
    n = nc + 3                      # the laws' variables, x, d, t
    samples = _form_samples(sp, form)
    index = {i: k for k, i in enumerate(sp.free)}
    ell = float(req.length)
    eps = float(req.cam_sense)
    out = []
    for i, limit in req.limits.items():
        if i in index:
            k = index[i]
            sh, beta, lev = sp.phase_scale(i)
            level = sp.rows(k, 0, n, samples=samples)
            slope = sp.rows(k, 1, n, samples=samples, elevate=True)
            out.append(Sides(nc=nc, eps=eps, limit=float(limit), ds0=np.zeros(level.shape[0]),
                             s0=np.full(level.shape[0], lev / ell), slope=slope, level=level,
                             slope_scale=sh / ell / beta, level_scale=sh / ell))
        else:
            s, ds, _ = _fixed_motion(sp.program, i, FIXED_SAMPLES)
            out.append(Sides(nc=nc, eps=eps, limit=float(limit), ds0=ds / ell, s0=s / ell))
    return out


def build(req: Request, form: str) -> ConicProgram:
    """The program of ``req`` in ``form`` ``"conservative"`` or ``"relaxed"`` (see the module notes)."""
    return _program(req, form, None if req.follower == "flat" else pressure_sides(req, form))


def _program(req: Request, form: str, sides: list[Sides] | None) -> ConicProgram:
    """:func:`build` with the pressure rows' sides given (:func:`pressure_sides`; None for a flat face)."""
    sp = req.space
    nc = sp.size
    flat = req.follower == "flat"
    ng = 1 if flat else 2           # (R0) or (x, d)
    n = nc + ng + 1
    it = n - 1                      # the epigraph variable t
    samples = _form_samples(sp, form)
    tight = 1.0 - TIGHTEN if form == "conservative" else 1.0
    G: list[np.ndarray] = []
    h: list[np.ndarray] = []
    cost = np.zeros(n)
    cones: list[Cone] = []
    index = {i: k for k, i in enumerate(sp.free)}
    slack = req.objective == "feasibility"
    ell = float(req.length)

    def scaled(i: int) -> tuple[float, float, float]:
        sh, beta, lev = sp.phase_scale(i)
        return sh / ell, beta, lev / ell

    def fixed(i: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        s, ds, d2s = _fixed_motion(sp.program, i, FIXED_SAMPLES)
        return s / ell, ds / ell, d2s / ell

    rho = req.min_radius / ell

    def add(rows: np.ndarray, rhs: np.ndarray, *, pressure: bool = False) -> None:
        if slack and pressure:
            rows = rows.copy()
            rows[:, it] -= 1.0
        G.append(rows)
        h.append(np.broadcast_to(rhs, rows.shape[:1]).astype(float))

    # -- the follower's geometric constraint on every constrained phase --------------------------------------
    phases = sp.program.phases
    if flat:
        for i in range(len(phases)):
            # R0 + s + s'' >= rho  ->  -R0 - sh S - sh/beta^2 S'' <= lev - rho
            if i in index:
                k = index[i]
                sh, beta, lev = scaled(i)
                r0 = sp.rows(k, 0, n, samples=samples)
                r2 = sp.rows(k, 2, n, samples=samples, elevate=True)
                rows = -sh * r0 - sh / beta**2 * r2
                rows[:, nc] = -1.0
                add(rows, np.full(rows.shape[0], lev - rho))
            else:
                s, _, s2 = fixed(i)
                rows = np.zeros((s.size, n))
                rows[:, nc] = -1.0
                add(rows, s + s2 - rho)
    else:
        for side in sides or ():
            T = float(np.tan(req.ratio * side.limit))
            for sign in (1.0, -1.0):
                add(*side.rows(sign, T), pressure=True)     # sign (s' + eps x) - T (d + s) <= 0

    # -- caps on the free phases' normalized derivatives; S within [0, 1] (the follower within its stroke) -------
    for (k, r), cap in req.caps.items():
        rows = sp.rows(k, r, n, samples=samples)
        add(np.vstack([rows, -rows]), np.full(2 * rows.shape[0], cap * tight))
    for k in range(len(sp.free)):
        rows = sp.rows(k, 0, n, samples=samples)
        m = rows.shape[0]
        add(np.vstack([rows, -rows]), np.concatenate([np.full(m, 1 + S_MARGIN), np.full(m, S_MARGIN)]))

    # -- the objective ---------------------------------------------------------------------------------------
    obj = req.objective
    if obj == "R0":
        if flat:
            cost[nc] = 1.0
        else:
            cost[it] = 1.0
            F = np.zeros((2, n))
            F[0, nc], F[1, nc + 1] = 1.0, 1.0
            a = np.zeros(n)
            a[it] = 1.0
            cones.append(Cone(a, 0.0, F, np.zeros(2)))
    elif obj in ("Ca", "Cj"):
        r = 2 if obj == "Ca" else 3
        cost[it] = 1.0
        for k in range(len(sp.free)):
            rows = sp.rows(k, r, n, samples=samples)
            rows = np.vstack([rows, -rows])
            rows[:, it] = -1.0
            add(rows, np.zeros(rows.shape[0]))
    elif obj in ("jerk_squared", "snap_squared"):
        r = 3 if obj == "jerk_squared" else 4
        cost[it] = 1.0
        F = np.vstack([sp.integral_factor(k, r, n) for k in range(len(sp.free))])
        a = np.zeros(n)
        a[it] = 1.0
        cones.append(Cone(a, 0.0, F, np.zeros(F.shape[0])))
    elif obj == "feasibility":
        cost[it] = 1.0
    else:
        raise ValueError(obj)

    # -- the cam's size held ---------------------------------------------------------------------------------
    if req.hold is not None and not flat:
        F = np.zeros((2, n))
        F[0, nc], F[1, nc + 1] = 1.0, 1.0
        cones.append(Cone(np.zeros(n), float(req.hold) / ell * tight, F, np.zeros(2)))  # within it after rounding

    # -- the box -----------------------------------------------------------------------------------------------
    B = req.bound / ell
    hi = np.concatenate([sp.bounds(req.caps), np.zeros(ng + 1)])
    lo = -hi
    if flat:
        lo[nc], hi[nc] = 0.0, B
        if req.centre is not None:
            lo[nc] = hi[nc] = req.centre[0] / ell
        elif req.hold is not None:
            lo[nc] = hi[nc] = req.hold / ell
    else:
        lo[nc], hi[nc] = -B, B
        lo[nc + 1], hi[nc + 1] = 0.0, B
        if req.centre is not None:
            lo[nc] = hi[nc] = req.centre[0] / ell
            lo[nc + 1] = hi[nc + 1] = req.centre[1] / ell
        elif req.x_fixed is not None:
            lo[nc] = hi[nc] = req.x_fixed / ell
    if slack:
        lo[it], hi[it] = -B, B                  # the pressure rows' slack (length)
    elif obj == "R0":
        lo[it], hi[it] = (0.0, 0.0) if flat else (0.0, B)   # a flat face's R0 is a variable itself: t unused
    else:
        lo[it], hi[it] = 0.0, 1e6               # a normalized peak or the root of an integral
    A, b = sp.equalities(n)
    enforce = np.zeros(n, bool)
    enforce[nc:] = True             # the geometry and t; the coefficients' box is declared, not handed over
    return ConicProgram(cost=cost, G=np.vstack(G) if G else np.zeros((0, n)), h=np.concatenate(h) if h else
                        np.zeros(0), A=A, b=b, lo=lo, hi=hi, cones=tuple(cones), enforce=enforce)


@dataclass(frozen=True)
class PressureRows:
    """The pressure rows of :func:`build`'s feasibility program (roller) with the ratio as a parameter.

    Row ``i`` (in :func:`build`'s order: per limited phase, the sign +1 rows, then the sign -1 rows) at ratio
    ``r`` is ``U_i v + u0_i - tan(r limit_i) (W_i v + c_i) <= t``: ``U v + u0`` is ``sign (s' + eps x)`` and
    ``W v + c`` is ``d + s`` (lengths over ``req.length``), ``t`` the program's last variable.

    Attributes
    ----------
    program : ConicProgram
        :func:`build`'s feasibility program; its first ``m`` rows of ``G`` are these (at the request's ratio).
    U, W : ndarray, shape (m, n)
        The rows' two sides (the column of ``t`` zero).
    u0, c : ndarray, shape (m,)
    limit : ndarray, shape (m,)
        Each row's pressure-angle limit, radians.
    pattern : (ndarray, ndarray)
        The rows' possible nonzeros ``(row, column)``, row-major, ``t``'s column included: the pattern of
        :class:`optimize.motion.conic.Assembly`.
    """

    program: ConicProgram
    U: np.ndarray
    W: np.ndarray
    u0: np.ndarray
    c: np.ndarray
    limit: np.ndarray
    pattern: tuple[np.ndarray, np.ndarray]

    @property
    def m(self) -> int:
        return int(self.c.size)

    def values(self, ratio: float, weights: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """The rows at ``ratio``, each divided by its positive weight (``weights``, ``m``; none: 1) but in
        ``t``'s column: their values on :attr:`pattern` and their right-hand sides."""
        T = np.tan(ratio * self.limit)
        w = np.ones(self.m) if weights is None else weights
        r, k = self.pattern
        vals = (self.U[r, k] - T[r] * self.W[r, k]) / w[r]
        vals[k == self.U.shape[1] - 1] = -1.0
        return vals, (T * self.c - self.u0) / w

    def program_at(self, ratio: float, weights: np.ndarray | None = None) -> ConicProgram:
        """The whole program at ``ratio``, its rows weighted (dense, as :func:`build` gives it)."""
        vals, rhs = self.values(ratio, weights)
        G, h = self.program.G.copy(), self.program.h.copy()
        G[:self.m] = 0.0
        G[self.pattern] = vals
        h[:self.m] = rhs
        return replace(self.program, G=G, h=h)


def pressure_rows(req: Request, form: str) -> PressureRows:
    """The feasibility program of ``req`` in ``form`` with its pressure rows' two sides (:class:`PressureRows`),
    built once for every ratio (roller, objective ``"feasibility"``)."""
    if req.follower == "flat" or req.objective != "feasibility":
        raise ValueError("the pressure rows of a roller's feasibility program")
    sides = pressure_sides(req, form)
    prog = _program(req, form, sides)
    n = prog.n
    U, W, u0, c, lim = [], [], [], [], []
    for side in sides:
        top, top0, bottom, bottom0 = side.matrices()
        for sign in (1.0, -1.0):
            U.append(sign * top)
            u0.append(sign * top0)
            W.append(bottom)
            c.append(bottom0)
            lim.append(np.full(top0.size, side.limit))
    Um, Wm = np.vstack(U), np.vstack(W)
    m = Um.shape[0]  # the slack's column is -1 on the pressure rows alone: they must be the program's first m rows
    if not (np.all(prog.G[:m, n - 1] == -1.0) and (m == prog.G.shape[0] or prog.G[m, n - 1] == 0.0)):
        raise AssertionError("the pressure rows are not the feasibility program's first rows")
    nz = (Um != 0) | (Wm != 0)
    nz[:, n - 1] = True
    rr, kk = np.nonzero(nz)
    return PressureRows(program=prog, U=Um, W=Wm, u0=np.concatenate(u0), c=np.concatenate(c),
                        limit=np.concatenate(lim), pattern=(rr, kk))


def pressure_terms(req: Request, v: np.ndarray,
                   form: str = "conservative") -> list[tuple[np.ndarray, np.ndarray, float]]:
    """The two sides of :func:`build`'s pressure rows at ``v`` (roller): per limited phase, in the rows' order,
    ``(|s' + eps x|, d + s, limit)`` on the Bernstein coefficients of every piece (``"conservative"``) or at the
    samples (``"relaxed"``) of a free phase, at the samples of a fixed one (lengths over ``req.length``;
    :func:`pressure_sides` at ``v``).

    A row of ``build`` at ratio ``r`` is ``sign (s' + eps x) <= tan(r limit) (d + s)``, for each sign."""
    out = []
    for side in pressure_sides(req, form):
        top, bottom = side.at(v)
        out.append((np.abs(top), bottom, side.limit))
    return out


def form_ratio(req: Request, v: np.ndarray, form: str = "conservative") -> float:
    """The least ratio of the pressure-angle limits at which ``v`` meets the pressure rows of :func:`build`'s
    program in ``form`` (roller; the laws' variables, then ``x, d`` over ``req.length``).

    The least ``T = tan(ratio * limit)`` of each row is the ratio of its two sides (:func:`pressure_terms`).
    ``inf`` when some ``d + s`` is not positive where ``s' + eps x`` is not 0.
    """
    worst = 0.0
    for top, bottom, limit in pressure_terms(req, v, form):
        if np.any((bottom <= 0) & (top > 0)):
            return float("inf")
        need = np.max(np.where(bottom > 0, top / np.where(bottom > 0, bottom, 1.0), 0.0))
        worst = max(worst, float(np.arctan(need)) / limit)
    return worst


def conservative_ratio(req: Request, v: np.ndarray) -> float:
    """:func:`form_ratio` of the ``"conservative"`` program: the least ratio at which ``v`` meets its rows, which
    hold at every cam angle (a free phase's on the Bernstein coefficients of every piece, a fixed one's at its
    samples)."""
    return form_ratio(req, v, "conservative")


def _form_samples(sp: Space, form: str) -> np.ndarray | None:
    """The points of a free phase's rows in ``form``: None (the Bernstein coefficients of every piece,
    ``"conservative"``) or the relaxation's samples (normalized, ``"relaxed"``)."""
    if form == "conservative":
        return None
    if form != "relaxed":
        raise ValueError(form)
    return np.linspace(0.0, 1.0, (SAMPLES_PER_SPAN - 1) * sp.spans + 1)
