"""The exact response of an elastic follower train to a cycle program: one matrix exponential per span.

Model (dimensionless; the physical one is :mod:`cams.dynamics.vibration`'s)
--------------------------------------------------------------------------
One mass ``m`` at the follower coordinate ``x`` is driven by the cam's rigid motion ``s(phi)`` (the program's
displacement, same unit and datum as ``x``) through the train: a spring ``k_t`` and a damper ``c`` between the cam
and the mass, acting on the relative displacement ``s - x`` and velocity ``s' - x'``. A closing spring ``k_s``
with preload ``F0`` at ``x = 0`` and a constant load ``P`` hold the mass towards the cam. In time ``t``::

    m x'' = k_t (s - x) + c (s' - x') - (F0 + k_s x) - P

With ``K = k_t + k_s``, ``omega_n = sqrt(K / m)``, the damping ratio against the total stiffness
``zeta = c / (2 sqrt(K m))``, the stiffness ratio ``r = k_t / K`` in (0, 1] and the static offset
``f = (F0 + P) / K`` (the program's unit), in the dimensionless time ``tau = omega_n t = rho phi`` (``phi`` the cam
angle, ``rho = omega_n / omega`` the natural frequency over the cam speed)::

    d2x/dtau2 + 2 zeta dx/dtau + x = r s + 2 zeta ds/dtau - f

and the load the cam transmits into the train, per unit of ``K`` (a length; positive: the cam pushes)::

    n = r (s - x) + 2 zeta (ds/dtau - dx/dtau)

Exactness
---------
Every piece of a library law, of a polynomial, spline or table law is a polynomial of degree ``d`` in ``u``, or
one of degree ``d <= 1`` plus a sine and a cosine of one frequency ``w``: it satisfies the linear ODE
``D^(d+1) S = 0`` or ``D^(d+1) (D^2 + w^2) S = 0``. Its derivatives ``z = (S, S', ..., S^(n-1))`` then obey
``z' = G z`` with ``G`` the ODE's companion matrix, so the augmented state ``(x, dx/dtau, z, 1)`` obeys one linear
ODE with constant coefficients over the piece, solved exactly by one matrix exponential (no quadrature). A dwell is
a constant. The cycle's periodic steady state solves ``(I - Phi) y0 = g`` for the composed affine map
``y_end = Phi y_start + g`` of ``y = (x, dx/dtau)`` over the turn.

References: the single-degree-of-freedom follower model and the residual-vibration figures of Norton, *Cam Design
and Manufacturing Handbook*, ch. 10 (dynamics of the follower train); Koster, *Vibrations of cam mechanisms* (1974).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from math import factorial

import numpy as np

from laws.base import Law
from laws.errors import InputError
from laws.modified import ModifiedCycloid, ModifiedSine, ModifiedTrapezoid
from laws.polynomial import PolynomialLaw
from laws.program import Program
from laws.spline import SplineLaw
from laws.standard import Cycloidal, Harmonic, Linear, Parabolic, Poly345, Poly4567
from laws.table import TableLaw

__all__ = [
    "Train",
    "Piece",
    "Span",
    "pieces",
    "spans",
    "cycle_map",
    "steady_state",
    "rest_state",
    "Response",
    "response",
    "grid_response",
    "grid_least_loads",
    "residual_amplitude",
    "phase_residuals",
]

PI = np.pi
_W = 4 * PI

#: Pieces of the closed-form laws: ``(u_start, u_end, polynomial degree d, frequency w or None)``.
_SHAPES: dict[type, tuple[tuple[float, float, int, float | None], ...]] = {
    Linear: ((0.0, 1.0, 1, None),),
    Parabolic: ((0.0, 0.5, 2, None), (0.5, 1.0, 2, None)),
    Harmonic: ((0.0, 1.0, 0, PI),),
    Cycloidal: ((0.0, 1.0, 1, 2 * PI),),
    ModifiedTrapezoid: (
        (0.0, 0.125, 1, _W),
        (0.125, 0.375, 2, None),
        (0.375, 0.5, 1, _W),
        (0.5, 0.625, 1, _W),
        (0.625, 0.875, 2, None),
        (0.875, 1.0, 1, _W),
    ),
    ModifiedSine: ((0.0, 0.125, 1, _W), (0.125, 0.5, 1, _W / 3), (0.5, 0.875, 1, _W / 3), (0.875, 1.0, 1, _W)),
    ModifiedCycloid: ((0.0, 0.25, 1, _W), (0.25, 0.5, 1, None), (0.5, 0.75, 1, None), (0.75, 1.0, 1, _W)),
}
_COEFFS: dict[type, tuple[float, ...]] = {
    Poly345: (0, 0, 0, 10, -15, 6),
    Poly4567: (0, 0, 0, 0, 35, -84, 70, -20),
}


def _expm(a: np.ndarray) -> np.ndarray:
    """``exp(a)`` of a square matrix or a stack of them (scipy's scaling and squaring)."""
    from scipy.linalg import expm  # here: scipy is not imported by ``import cams``

    return np.asarray(expm(a))


@dataclass(frozen=True)
class Train:
    """The follower train, dimensionless.

    Parameters
    ----------
    rho : float
        ``omega_n / omega``: natural frequency over cam speed (rad of vibration per rad of cam), > 0.
    ratio : float
        ``r = k_t / (k_t + k_s)`` in (0, 1]: 1 without a closing spring (form closure).
    zeta : float
        Damping ratio against the total stiffness, >= 0.
    offset : float
        ``f = (F0 + P) / (k_t + k_s)``: the static push of preload and load, the program's unit (towards the cam,
        i.e. against ``s``).
    """

    rho: float
    ratio: float = 1.0
    zeta: float = 0.0
    offset: float = 0.0

    def __post_init__(self) -> None:
        for key, v, ok in (
            ("rho", self.rho, lambda x: x > 0),
            ("ratio", self.ratio, lambda x: 0 < x <= 1),
            ("zeta", self.zeta, lambda x: x >= 0),
            ("offset", self.offset, lambda x: True),
        ):
            if not (isinstance(v, (int, float, np.floating)) and np.isfinite(v) and ok(v)):
                raise InputError(f"train.{key}", f"out of range: {v!r}")


def _frozen(a: np.ndarray) -> np.ndarray:
    """``a`` read-only (the cached pieces and spans are shared)."""
    a.setflags(write=False)
    return a


@dataclass(frozen=True)
class Piece:
    """A piece of a normalized law on ``[start, end]`` in ``u``: ``z = (S, ..., S^(n-1))`` obeys ``z' = G z``.

    ``generator`` is ``G`` (per unit ``u``), ``state`` is ``z`` at ``start`` (the piece's own right limit).
    """

    start: float
    end: float
    generator: np.ndarray
    state: np.ndarray

    def __post_init__(self) -> None:
        _frozen(self.generator)
        _frozen(self.state)


def _companion(d: int, w: float | None) -> np.ndarray:
    """The companion matrix of ``D^(d+1)`` or ``D^(d+1) (D^2 + w^2)``."""
    n = d + 1 if w is None else d + 3
    g = np.diag(np.ones(n - 1), 1)
    if w is not None:
        g[n - 1, n - 2] = -(w**2)  # S^(d+3) = -w^2 S^(d+1)
    return g


def _poly_pieces(coeffs, a: float, b: float, scale: float = 1.0) -> Piece:
    """A polynomial piece on ``[a, b]`` from its power coefficients in ``t = (u - a) / scale``."""
    c = np.asarray(coeffs, float)
    n = max(len(c), 1)
    z = np.array([factorial(k) * c[k] / scale**k for k in range(n)])
    return Piece(a, b, _companion(n - 1, None), z)


@lru_cache(maxsize=256)
def pieces(law: Law) -> tuple[Piece, ...]:
    """The exact pieces of a law: each a polynomial, or a polynomial plus one sinusoid.

    Parameters
    ----------
    law : Law
        A library law, a :class:`~laws.polynomial.PolynomialLaw`, :class:`~laws.spline.SplineLaw` or
        :class:`~laws.table.TableLaw`.

    Returns
    -------
    tuple of Piece
        Covering [0, 1] in order.

    Raises
    ------
    InputError
        A law of another kind (field ``law``): its pieces are not known in closed form.
    """
    kind = type(law)
    if kind in _COEFFS:
        return (_poly_pieces(_COEFFS[kind], 0.0, 1.0),)
    if isinstance(law, PolynomialLaw):
        return (_poly_pieces(law.coefficients, 0.0, 1.0),)
    if isinstance(law, SplineLaw):
        from laws.bernstein import to_power

        m = to_power(law.degree)
        b = law.breaks
        return tuple(
            _poly_pieces(m @ np.asarray(row), b[j], b[j + 1], b[j + 1] - b[j]) for j, row in enumerate(law.coefficients)
        )
    if isinstance(law, TableLaw):
        from scipy.interpolate import PPoly

        pp = PPoly.from_spline(law._spline)  # type: ignore[arg-type]
        out = []
        x = pp.x
        for j in range(len(x) - 1):
            if x[j + 1] <= x[j] or x[j + 1] <= 0.0 or x[j] >= 1.0:
                continue
            out.append(_poly_pieces(pp.c[::-1, j], float(x[j]), float(x[j + 1])))
        return tuple(out)
    if kind in _SHAPES:
        shaped = []
        for u0, u1, d, w in _SHAPES[kind]:
            g = _companion(d, w)
            n = g.shape[0]
            mid = 0.5 * (u0 + u1)  # inside the piece: no one-sided question; its state carried back exactly
            zm = law.evaluate(mid)[:n]
            shaped.append(Piece(u0, u1, g, _expm_series((g * (u0 - mid))[None])[0] @ zm))
        return tuple(shaped)
    raise InputError("law", f"the exact response knows no pieces of a {kind.__name__} law")


@dataclass(frozen=True)
class Span:
    """A stretch of the cycle over which the cam's motion ``s(phi)`` satisfies ``z' = G z`` (per radian).

    ``phase`` is its ``[[motion]]`` index, ``start``/``end`` cam angles (rad), ``state`` ``z = (s, ds/dphi, ...)`` at
    ``start``.
    """

    phase: int
    start: float
    end: float
    generator: np.ndarray
    state: np.ndarray

    def __post_init__(self) -> None:
        _frozen(self.generator)
        _frozen(self.state)


@lru_cache(maxsize=256)
def spans(program: Program) -> tuple[Span, ...]:
    """The cycle's spans: each rise or return's pieces, scaled to cam angles, and one span per dwell."""
    out = []
    for i, p in enumerate(program.phases):
        phi0 = float(program.starts[i])
        level = float(program.levels[i])
        if p.kind == "dwell":
            out.append(Span(i, phi0, phi0 + p.angle, np.zeros((1, 1)), np.array([level])))
            continue
        sh, beta = program.signed_height(i), p.angle
        for pc in pieces(program.law_of(i)):
            n = pc.state.shape[0]
            scale = beta ** -np.arange(n, dtype=float)  # d^k/dphi^k = beta^-k d^k/du^k
            g = (pc.generator * scale[:, None] / scale[None, :]) / beta
            z = sh * pc.state * scale
            z[0] += level
            if g.shape[0] == 1:  # a constant piece: give it a (zero) slope so that ds/dphi is in the state
                g, z = np.zeros((2, 2)), np.array([z[0], 0.0])
                g[0, 1] = 1.0
            out.append(Span(i, phi0 + pc.start * beta, phi0 + pc.end * beta, g, z))
    return tuple(out)


def _augmented(generator: np.ndarray, rho, *, ratio: float, zeta: float, offset: float) -> np.ndarray:
    """A span's generator per radian of cam angle for ``Y = (x, v, z, 1)``, ``v = dx/dtau``, at one speed or many.

    ``generator`` is the span's ``G`` (n x n), ``rho`` a float or an array of speeds (``omega_n / omega``);
    ``ratio, zeta, offset`` as in :class:`Train`. Shape ``shape(rho) + (n + 3, n + 3)``.
    """
    n = generator.shape[0]
    m = np.zeros((*np.shape(rho), n + 3, n + 3))
    # per radian of cam: x' = rho v, v' = rho (ratio s - x - offset) - 2 zeta rho v + 2 zeta ds/dphi
    m[..., 0, 1] = rho
    m[..., 1, 0], m[..., 1, 1] = -rho, -2 * zeta * rho
    m[..., 1, 2], m[..., 1, n + 2] = rho * ratio, -rho * offset
    if n >= 2:
        m[..., 1, 3] = 2 * zeta  # 2 zeta rho ds/dtau = 2 zeta ds/dphi
    m[..., 2 : n + 2, 2 : n + 2] = generator
    return m


def _expm_series(a: np.ndarray) -> np.ndarray:
    """``exp(a)`` of a stack of small matrices of modest norm (the forcing's generators times a span): Taylor's
    series to 18 terms after scaling by ``2^-s`` to a norm <= 1/4 (truncation below 1e-28), then ``s`` squarings."""
    a = np.asarray(a, float)
    norm = float(np.max(np.sum(np.abs(a), axis=-1))) if a.size else 0.0
    s = max(0, int(np.ceil(np.log2(norm / 0.25)))) if norm > 0.25 else 0
    x = a / 2.0**s
    eye = np.broadcast_to(np.eye(a.shape[-1]), a.shape)
    out, term = eye.copy(), eye.copy()
    for j in range(1, 19):
        term = term @ x / j
        out = out + term
    for _ in range(s):
        out = out @ out
    return out


def _oscillator(rho, zeta: float, t) -> np.ndarray:
    """``exp(A t)`` of ``A = [[0, rho], [-rho, -2 zeta rho]]`` in closed form, ``rho`` and ``t`` broadcast
    together (one speed at many ``t``, or many speeds at one ``t``): shape ``broadcast(rho, t).shape + (2, 2)``.

    ``exp(A t) = exp(mu t) (c(t) I + s(t) (A - mu I))`` with ``mu = -zeta rho`` and, for ``d = rho^2 (1 - zeta^2)``:
    ``c = cos(w t), s = sin(w t) / w`` (``w = sqrt(d)``, d > 0), ``cosh``/``sinh`` (d < 0), ``1, t`` (d = 0); the
    sign of ``d`` is that of ``1 - zeta^2`` at every ``rho > 0``.
    """
    rho, t = np.asarray(rho, float), np.asarray(t, float)
    mu = -zeta * rho
    q = 1 - zeta**2
    d = rho**2 * q
    if q > 0:
        w = np.sqrt(d)
        c, sn = np.cos(w * t), np.sin(w * t) / w
    elif q < 0:  # exp(mu t) cosh(w t) and exp(mu t) sinh(w t) / w from exp((mu -+ w) t): each factor alone overflows
        w = np.sqrt(-d)
        x = 2 * w * t
        near = np.abs(x) < 1  # e^x - 1 by expm1 there: no cancellation as w t -> 0
        em, ep = np.exp((mu - w) * t), np.exp((mu + w) * t)
        c = 0.5 * (ep + em)
        sn = np.where(near, 0.5 * em * np.expm1(np.where(near, x, 0.0)), 0.5 * (ep - em)) / w
    else:
        c = np.ones(np.broadcast_shapes(rho.shape, t.shape))
        sn = t * c
    out = np.empty((*c.shape, 2, 2))  # c I + s (A - mu I), entry by entry (overdamped: exp(mu t) already in c, s)
    out[..., 0, 0] = c - sn * mu
    out[..., 0, 1] = sn * rho
    out[..., 1, 0] = -sn * rho
    out[..., 1, 1] = c + sn * (-2 * zeta * rho - mu)
    return out if q < 0 else np.exp(mu * t)[..., None, None] * out


def _blocks(rho, zeta: float, g: np.ndarray, y: np.ndarray, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``exp(M t)``'s blocks ``(exp(A t), X(t), exp(G t))`` with ``X(t) = exp(A t) Y - Y exp(G t)`` (see
    :class:`_Flow`): ``rho`` and ``t`` broadcast as in :func:`_oscillator`, ``y`` of shape ``(2, N)`` or one per
    speed ``(k, 2, N)``, ``g`` the forcing's ``N x N`` generator."""
    t = np.asarray(t, float)
    ea = _oscillator(rho, zeta, t)
    eg = _expm_series(g * t[..., None, None])
    return ea, ea @ y - y @ eg, eg


class _Flow:
    """``exp(M t)`` of a span's augmented generator, by blocks: the oscillator's in closed form, the forcing's
    (small norm) by a matrix exponential, and the coupling ``X(t) = exp(A t) Y - Y exp(G t)`` with ``Y`` the
    solution of the Sylvester equation ``A Y - Y G = B`` -- the particular solution of the forcing plus the
    homogeneous part. Where ``A`` and ``G`` share an eigenvalue (an undamped train whose frequency is a sinusoid's
    of the law) or ``Y`` is ill-conditioned, the whole exponential is taken instead."""

    def __init__(self, span: Span, train: Train) -> None:
        from scipy.linalg import solve_sylvester

        self.m = _augmented(span.generator, train.rho, ratio=train.ratio, zeta=train.zeta, offset=train.offset)
        self.rho, self.zeta = train.rho, train.zeta
        n = self.m.shape[0]
        self.a, self.b, self.g = self.m[:2, :2], self.m[:2, 2:], self.m[2:, 2:]
        self.y: np.ndarray | None = None
        y = solve_sylvester(self.a, -self.g, self.b)
        scale = float(np.max(np.abs(self.b))) or 1.0
        if (
            np.all(np.isfinite(y))
            and np.max(np.abs(self.a @ y - y @ self.g - self.b))
            <= 1e-12 * scale * max(1.0, float(np.max(np.abs(y)))) * n
            and float(np.max(np.abs(y))) < 1e8 * scale
        ):
            self.y = y

    def __call__(self, t) -> np.ndarray:
        """``exp(M t)``, shape (N, N) for a scalar ``t``, (k, N, N) for an array."""
        scalar = np.ndim(t) == 0
        tt = np.asarray(t, float).reshape(-1)
        if self.y is None:
            out = _expm(self.m[None] * tt[:, None, None])
        else:
            out = np.zeros((tt.size, *self.m.shape))
            out[:, :2, :2], out[:, :2, 2:], out[:, 2:, 2:] = _blocks(self.rho, self.zeta, self.g, self.y, tt)
        return out[0] if scalar else out


def _start(span: Span, y: np.ndarray) -> np.ndarray:
    return np.concatenate([y, span.state, [1.0]])


def cycle_map(program: Program, train: Train) -> tuple[np.ndarray, np.ndarray, list[np.ndarray]]:
    """The turn's affine map ``y_end = Phi y_start + g`` of ``y = (x, dx/dtau)``, and each span's exponential."""
    phi, g = np.eye(2), np.zeros(2)
    exps = []
    for sp in spans(program):
        e = _Flow(sp, train)(sp.end - sp.start)
        exps.append(e)
        a, b = e[:2, :2], e[:2, 2:] @ np.concatenate([sp.state, [1.0]])
        phi, g = a @ phi, a @ g + b
    return phi, g, exps


def steady_state(program: Program, train: Train) -> np.ndarray:
    """``y0 = (x, dx/dtau)`` at cam angle 0 of the periodic steady state: ``(I - Phi) y0 = g``.

    Raises
    ------
    InputError
        An undamped train whose natural frequency is a whole multiple of the cam speed (field
        ``dynamics.damping_ratio``): ``I - Phi`` is singular and there is no periodic steady state.
    """
    phi, g, _ = cycle_map(program, train)
    a = np.eye(2) - phi
    if abs(np.linalg.det(a)) < 1e-12 * max(1.0, float(np.max(np.abs(phi)))):
        raise InputError(
            "dynamics.damping_ratio",
            "an undamped train at a whole multiple of the cam speed "
            f"(omega_n / omega = {train.rho:.6g}) has no periodic steady state: give a damping ratio > 0",
        )
    return np.linalg.solve(a, g)


def rest_state(program: Program, train: Train, i: int) -> np.ndarray:
    """``y = (x, 0)`` at rest in the static equilibrium ``x = r s - f`` at the start of phase ``i``."""
    return np.array([train.ratio * float(program.levels[i]) - train.offset, 0.0])


@dataclass(frozen=True)
class Response:
    """The train's response at cam angles ``phi`` (rad).

    ``x, dx, d2x``: the output's displacement (program unit) and its derivatives per radian of cam angle;
    ``s, ds``: the cam's rigid motion; ``load``: ``n``, the cam's push into the train per unit of the total
    stiffness (program unit; positive: compression).
    """

    phi: np.ndarray
    x: np.ndarray
    dx: np.ndarray
    d2x: np.ndarray
    s: np.ndarray
    ds: np.ndarray
    load: np.ndarray


def response(program: Program, train: Train, phi, y0: np.ndarray, *, start: float = 0.0) -> Response:
    """The response at cam angles ``phi`` from ``y0 = (x, dx/dtau)`` at ``start``.

    ``start`` must be a span's start (0, or a phase's start); angles are taken in ``[start, start + 2 pi)``
    unwrapped once (a response from a phase's start runs to the end of the turn and on into the next one).
    """
    phi = np.asarray(phi, float)
    two_pi = 2 * PI
    rel = np.mod(phi - start, two_pi) + start
    sp_all = spans(program)
    ordered = [s for s in sp_all if s.start >= start - 1e-12] + [
        Span(s.phase, s.start + two_pi, s.end + two_pi, s.generator, s.state) for s in sp_all if s.start < start - 1e-12
    ]
    rho, r, zeta, f = train.rho, train.ratio, train.zeta, train.offset
    X = np.empty((3, rel.size))
    S = np.empty((2, rel.size))
    flat = rel.ravel()
    y = np.asarray(y0, float)
    for k, sp in enumerate(ordered):
        last = k == len(ordered) - 1
        flow = _Flow(sp, train)
        sel = (flat >= sp.start - 1e-12) & ((flat < sp.end) | (last & (flat <= sp.end + 1e-12)))
        if np.any(sel):
            Y = flow(flat[sel] - sp.start) @ _start(sp, y)
            x, v, s0 = Y[:, 0], Y[:, 1], Y[:, 2]
            s1 = Y[:, 3] if sp.generator.shape[0] >= 2 else np.zeros_like(x)
            acc = r * s0 + 2 * zeta * s1 / rho - f - x - 2 * zeta * v  # d2x/dtau2
            X[:, sel] = x, rho * v, rho**2 * acc
            S[:, sel] = s0, s1
        y = (flow(sp.end - sp.start) @ _start(sp, y))[:2]
    load = _load(r, zeta, rho, S[0], S[1], X[0], X[1])
    shape = phi.shape
    return Response(phi, *(a.reshape(shape) for a in (X[0], X[1], X[2], S[0], S[1], load)))


def grid_response(program: Program, train: Train, y0: np.ndarray, samples: int) -> Response:
    """The response at ``samples`` equally spaced cam angles ``2 pi k / samples`` from ``y0`` at angle 0.

    The same exact solution as :func:`response`, faster: per span one exponential for the first sample's offset
    and one for the grid's step, applied repeatedly (the rounding grows by about one unit per step).
    """
    step = 2 * PI / samples
    phi = step * np.arange(samples)
    X = np.empty((3, samples))
    S = np.empty((2, samples))
    rho, r, zeta, f = train.rho, train.ratio, train.zeta, train.offset
    y = np.asarray(y0, float)
    for sp in spans(program):
        flow = _Flow(sp, train)
        start = _start(sp, y)
        k0 = int(np.ceil(sp.start / step - 1e-9))
        k1 = int(np.ceil(sp.end / step - 1e-9))
        if k1 > k0:
            Y = np.empty((k1 - k0, start.size))
            Y[0] = flow(phi[k0] - sp.start) @ start
            e = flow(step)
            for j in range(1, k1 - k0):
                Y[j] = e @ Y[j - 1]
            x, v, s0 = Y[:, 0], Y[:, 1], Y[:, 2]
            s1 = Y[:, 3] if sp.generator.shape[0] >= 2 else np.zeros_like(x)
            acc = r * s0 + 2 * zeta * s1 / rho - f - x - 2 * zeta * v
            X[:, k0:k1] = x, rho * v, rho**2 * acc
            S[:, k0:k1] = s0, s1
        y = (flow(sp.end - sp.start) @ start)[:2]
    load = _load(r, zeta, rho, S[0], S[1], X[0], X[1])
    return Response(phi, X[0], X[1], X[2], S[0], S[1], load)


def _load(r, zeta, rho, s, ds, x, dx):
    """The train's load ``Q`` (dimensionless, the spring's and damper's across the train): ``r (s - x) +
    2 zeta (s' - x') / rho``, ``s, s'`` the rigid motion and ``x, x'`` the output and their derivatives in the cam
    angle; the one formula of every response here."""
    return r * (s - x) + 2 * zeta * (ds - dx) / rho


def grid_least_loads(
    program: Program, rho, samples: int, *, ratio: float = 1.0, zeta: float = 0.0, offset: float = 0.0
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The steady state's least load over ``samples`` equally spaced cam angles, at many speeds at once.

    The same exact solution as :func:`steady_state` then :func:`grid_response` for each
    ``Train(rho_i, ratio, zeta, offset)``, vectorized over the speeds (the forcing's exponentials are the same at
    every speed; the Sylvester equations are solved as one batch of linear systems), so its rounding differs from
    theirs in the last digits.

    Parameters
    ----------
    program : Program
    rho : array_like
        ``omega_n / omega`` of each speed, > 0, shape (k,).
    samples : int
        Cam angles ``2 pi j / samples``, j = 0 .. samples - 1.
    ratio, zeta, offset : float
        As in :class:`Train`.

    Returns
    -------
    least : ndarray
        The least load ``n`` (program unit, per unit of the total stiffness) of each speed, shape (k,).
    size : ndarray
        The largest ``|n|`` of each speed (the scale of ``least``'s rounding).
    sure : ndarray of bool
        False where this batch cannot answer (no steady state, a Sylvester equation that is singular or
        ill-conditioned): ask :func:`steady_state` and :func:`grid_response` there.
    """
    rho = np.atleast_1d(np.asarray(rho, float))
    k = rho.size
    sure = np.ones(k, bool)
    step = 2 * PI / samples
    phi = step * np.arange(samples)
    flows = []
    for sp in spans(program):
        m = _augmented(sp.generator, rho, ratio=ratio, zeta=zeta, offset=offset)
        a, b, g = m[:, :2, :2], m[:, :2, 2:], m[0, 2:, 2:]  # the forcing's G is the same at every speed
        n = g.shape[0]
        # A Y - Y G = B, column by column: (I kron A - G^T kron I) vec(Y) = vec(B)
        big = np.kron(np.eye(n), a) - np.kron(g.T, np.eye(2))[None]
        try:
            y = np.linalg.solve(big, b.transpose(0, 2, 1).reshape(k, -1)[..., None])[..., 0]
        except np.linalg.LinAlgError:
            return np.zeros(k), np.ones(k), np.zeros(k, bool)
        y = y.reshape(k, n, 2).transpose(0, 2, 1)
        scale = np.maximum(np.max(np.abs(b), axis=(1, 2)), 1e-300)
        big_y = np.max(np.abs(y), axis=(1, 2))
        residual = np.max(np.abs(a @ y - y @ g - b), axis=(1, 2))
        sure &= np.isfinite(big_y) & (residual <= 1e-12 * scale * np.maximum(1.0, big_y) * (n + 2))
        sure &= big_y < 1e4 * scale  # well conditioned: the batch's rounding stays far below the margin it is read at
        z = np.concatenate([sp.state, [1.0]])
        ea, ec, _ = _blocks(rho, zeta, g, y, sp.end - sp.start)  # the whole span's map, taken once
        flows.append((sp, g, y, z, ea, ec @ z))

    phi_map, shift = np.broadcast_to(np.eye(2), (k, 2, 2)), np.zeros((k, 2))
    for *_, ea, push in flows:
        phi_map, shift = ea @ phi_map, (ea @ shift[..., None])[..., 0] + push
    lhs = np.eye(2) - phi_map
    det = lhs[:, 0, 0] * lhs[:, 1, 1] - lhs[:, 0, 1] * lhs[:, 1, 0]
    sure &= np.abs(det) >= 1e-9 * np.maximum(1.0, np.max(np.abs(phi_map), axis=(1, 2)))
    lhs[~sure] = np.eye(2)
    xv = np.linalg.solve(lhs, shift[..., None])[..., 0]  # (x, dx/dtau) at angle 0
    least, size = np.full(k, np.inf), np.zeros(k)
    for sp, g, y, z, e_span, push_span in flows:
        k0 = int(np.ceil(sp.start / step - 1e-9))
        k1 = int(np.ceil(sp.end / step - 1e-9))
        if k1 > k0:
            ea, ec, eg = _blocks(rho, zeta, g, y, phi[k0] - sp.start)
            sa, sc, sg = _blocks(rho, zeta, g, y, step)
            zs = np.empty((k1 - k0, z.size))
            zs[0] = eg @ z
            for j in range(1, k1 - k0):
                zs[j] = sg @ zs[j - 1]
            push = np.einsum("kij,mj->mki", sc, zs)  # the forcing's part of each step
            xs = np.empty((k1 - k0, k, 2))
            xs[0] = (ea @ xv[..., None])[..., 0] + ec @ z
            for j in range(1, k1 - k0):
                xs[j] = np.einsum("kij,kj->ki", sa, xs[j - 1]) + push[j - 1]
            s1 = zs[:, 1] if sp.generator.shape[0] >= 2 else np.zeros(k1 - k0)
            load = _load(ratio, zeta, rho, zs[:, :1], s1[:, None], xs[..., 0], rho * xs[..., 1])
            least = np.minimum(least, np.min(load, axis=0))
            size = np.maximum(size, np.max(np.abs(load), axis=0))
        xv = (e_span @ xv[..., None])[..., 0] + push_span
    return least, size, sure


def residual_amplitude(train: Train, level: float, y: np.ndarray) -> float:
    """The free vibration's amplitude about the dwell's equilibrium ``x = r level - f``, from ``y = (x, dx/dtau)``.

    With ``e = x - (r level - f)`` and ``e' = dx/dtau``: ``sqrt(e^2 + ((e' + zeta e) / sqrt(1 - zeta^2))^2)`` for
    ``zeta < 1`` (the envelope of ``A exp(-zeta tau) cos(...)`` at the phase's end; the undamped amplitude at 0);
    ``sqrt(e^2 + e'^2)`` for ``zeta >= 1`` (no oscillation: the state's size).
    """
    e = float(y[0]) - (train.ratio * level - train.offset)
    v = float(y[1])
    if train.zeta < 1:
        return float(np.hypot(e, (v + train.zeta * e) / np.sqrt(1 - train.zeta**2)))
    return float(np.hypot(e, v))


def _phase_end(program: Program, train: Train, i: int, y: np.ndarray) -> np.ndarray:
    """``y`` at the end of phase ``i`` from ``y`` at its start."""
    for sp in spans(program):
        if sp.phase == i:
            y = (_Flow(sp, train)(sp.end - sp.start) @ _start(sp, y))[:2]
    return y


def phase_residuals(
    program: Program, train: Train, y0: np.ndarray | None = None, *, steady: bool = True
) -> list[tuple[int, float, float | None]]:
    """``(phase, residual from rest, residual in the steady state)`` of every rise and return.

    Each an amplitude (:func:`residual_amplitude`) at the phase's end about the equilibrium of its end level, over
    the phase's height. ``y0`` is the steady state's start (:func:`steady_state` when None); with ``steady`` False
    the steady state is not computed and its residuals are None. The steady state's residual is about the same
    equilibrium, so it includes what the phase inherited from the phases before.
    """
    y = None
    if steady:
        y = steady_state(program, train) if y0 is None else np.asarray(y0, float)
    out: list[tuple[int, float, float | None]] = []
    for i, p in enumerate(program.phases):
        y_end = None if y is None else _phase_end(program, train, i, y)
        if p.kind != "dwell":
            h = program.height_of(i)
            end_level = float(program.levels[i]) + program.signed_height(i)
            rest = _phase_end(program, train, i, rest_state(program, train, i))
            out.append(
                (
                    i,
                    residual_amplitude(train, end_level, rest) / h,
                    None if y_end is None else residual_amplitude(train, end_level, y_end) / h,
                )
            )
        y = y_end
    return out
