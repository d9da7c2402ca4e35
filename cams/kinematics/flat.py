"""The flat face's envelope: the cam's profile point, its radius of curvature, the contact on the face.

A flat face's pressure angle is fixed by geometry (zero for a translating
face perpendicular to its axis and for a rocker face through its pivot), so
the cam's size is limited not by jamming but by convexity (:mod:`optimize.flat`).

Method (support function of the envelope)
-----------------------------------------
In the fixed frame the face is the line ``{X : m . X = f}`` with unit normal
``m = (cos a, sin a)`` pointing away from the cam. Its distance from the cam
centre O is ``p = f - m . O``. In the cam frame (origin O, cam at
``phi = 0``, turning with sense ``eps``) the normal's angle is
``theta = a - eps phi``. The envelope of the lines (the cam profile) and its
radius of curvature are::

    X(phi)  = p n(theta) + p_theta t(theta),   n = (cos, sin), t = (-sin, cos)
    rho     = p + p_thetatheta                 (positive: convex)
    p_theta = p' / theta',   p_thetatheta = (p'' theta' - p' theta'') / theta'^3

with primes for d/dphi. The contact point lies on the face at ``p_theta``
from the foot of the perpendicular from O, along ``t(theta)`` (``J m``).

* Translating face (frame of :class:`cams.model.follower.Translating`: Y along the
  rise, the face perpendicular to it at ``y = s``, the cam centre at
  ``O = (-e, -R0)``): ``p = R0 + s``, ``theta' = -eps``, hence
  ``rho = R0 + s + s''`` and the contact lies at ``x = -e + eps s'`` on the
  face. Convexity needs ``R0 >= rho_min - min(s + s'')``.
* Oscillating face (pivot at the origin, cam centre at ``O = (L, 0)``: the
  line-of-centres frame, see :func:`rocker_frame_turn`; the face at signed
  distance ``f`` from the pivot, turning with the rocker by ``sigma psi``):
  ``a = a0 + sigma psi``, ``p = f - L cos a``. The face touches the base
  circle at the near dwell: ``cos a0 = (f - R0) / L``, with ``a0`` on the side
  ``sigma`` so that the rise moves the face away from the cam. The contact's
  position ``c`` on the face is measured from the pivot's foot along
  ``-sigma J m``: **positive towards the cam** (the cam centre projects on
  that side of the foot), the one sign of every flat-face contact position.
  The pressure angle (between the face normal and the contact point's
  velocity) is ``atan(|f| / |c|)``: zero for a face through the pivot.

Where the follower's velocity jumps (a hard impact) the support function's
slope jumps: a jump up gives the profile a straight edge (convex), a drop a
cusp whatever the base radius (:func:`cusps`).

Angles in radians, lengths in the design's unit (mm).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

import numpy as np

from cams.model.design import FlatFaceDesign
from cams.model.follower import FlatTranslating
from laws.errors import InputError
from laws.program import Program
from laws.units import turn_degrees

__all__ = [
    "PhaseFunction",
    "curvature_radius",
    "envelope",
    "phase_minimum",
    "zoom_minimum",
    "check_cam_sense",
    "velocity_jumps",
    "cusps",
    "cusp_error",
    "translating_parts",
    "translating_cusps",
    "oscillating_setup",
    "near_dwell_angle",
    "oscillating_terms",
    "oscillating_support",
    "oscillating_parts",
    "oscillating_cusps",
    "oscillating_contact",
    "oscillating_pressure",
    "rocker_frame_turn",
    "flat_parts",
    "flat_support",
    "flat_radii",
]

#: A quantity inside one phase: ``fun(phase index, u in [0, 1]) -> array`` (one-sided at the phase's ends).
PhaseFunction = Callable[[int, np.ndarray], np.ndarray]


def phase_minimum(fun: PhaseFunction, program: Program, grid: int = 2000, tie: float = 0.0) -> tuple[float, float]:
    """Smallest ``fun(i, u)`` over the cycle and its cam angle (radians).

    Each phase is sampled on ``grid + 1`` points; outside the dwells the best
    one is refined by :func:`zoom_minimum`. A later phase's minimum must be
    smaller by more than ``tie`` (the function's unit) to replace an earlier one.
    """
    best, at = np.inf, 0.0
    for i, p in enumerate(program.phases):
        u = np.linspace(0, 1, grid + 1)
        v = fun(i, u)
        k = int(np.argmin(v))
        bu, bv = float(u[k]), float(v[k])
        if p.kind != "dwell":
            bu, bv = zoom_minimum(partial(fun, i), u[max(k - 1, 0)], u[min(k + 1, grid)], bu, bv)
        if bv < best - tie:
            best, at = bv, float(program.starts[i] + bu * p.angle)
    return best, at


def zoom_minimum(fun: Callable[[np.ndarray], np.ndarray], lo: float, hi: float, bu: float, bv: float,
                 n: int = 64, xtol: float = 1e-13) -> tuple[float, float]:
    """Smallest ``fun`` on ``[lo, hi]`` by repeated grids of ``n + 1`` points round the best one.

    ``fun`` takes an array; ``(bu, bv)`` is the best point known. Each round
    narrows the bracket ``n / 2`` times, so a handful of vectorized calls
    reach ``xtol``.
    """
    while hi - lo > xtol:
        x = np.linspace(lo, hi, n + 1)
        v = fun(x)
        k = int(np.argmin(v))
        if v[k] < bv:
            bu, bv = float(x[k]), float(v[k])
        lo, hi = x[max(k - 1, 0)], x[min(k + 1, n)]
    return bu, bv


# -- the envelope of a family of lines ---------------------------------------------------------


def curvature_radius(dtheta, d2theta, p, dp, d2p):
    """Radius of curvature ``rho = p + p_thetatheta`` of the envelope (length, positive convex).

    From the derivatives in the cam angle ``phi`` of the normal's angle
    ``theta`` (radians) and of the support function ``p`` (length).
    """
    return p + (d2p * dtheta - dp * d2theta) / dtheta**3


def envelope(theta, dtheta, d2theta, p, dp, d2p):
    """Envelope point (cam frame), radius of curvature and ``p_theta`` of a family of lines.

    Returns ``X`` (shape ``theta.shape + (2,)``, length), ``rho`` (length,
    positive convex) and ``p_theta`` (length: the contact's position on the
    line from the foot of the perpendicular from the cam centre, along
    ``t(theta)``).
    """
    if np.any(np.abs(dtheta) < 1e-12):
        raise InputError("follower", "the face turns with the cam (theta' = 0): no envelope")
    p_t = dp / dtheta
    n = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    t = np.stack([-np.sin(theta), np.cos(theta)], axis=-1)
    X = p[..., None] * n + p_t[..., None] * t
    return X, curvature_radius(dtheta, d2theta, p, dp, d2p), p_t


def check_cam_sense(cam_sense: object) -> int:
    """``cam_sense`` as +1 (counter-clockwise) or -1 (clockwise), else :class:`InputError` (``cam.rotation``)."""
    if cam_sense not in (1, -1):
        raise InputError("cam.rotation", f"cam_sense must be +1 (ccw) or -1 (cw), got {cam_sense!r}")
    return 1 if cam_sense == 1 else -1


# -- velocity jumps: a flat edge or a cusp whatever the size ----------------------------------


def velocity_jumps(program: Program) -> list[tuple[float, float, float, int]]:
    """Velocity jumps of the program: ``(phi, s' before, s' after, phase)`` for each hard impact."""
    from laws.diagnostics import find_impacts

    out = []
    for imp in find_impacts(program):
        if imp.kind != "hard":
            continue
        if imp.inside:
            after = float(program.evaluate(np.array([imp.phi + 1e-10])).ds[0])
        else:
            after = float(program.evaluate_phase(imp.phase, 0.0).ds)
        out.append((float(imp.phi), after - float(imp.size), after, int(imp.phase)))
    return out


def cusps(program: Program, p_theta: Callable[[float, float], float],
          dtheta: Callable[[float], float]) -> list[tuple[float, float, int]]:
    """The velocity jumps that give the envelope a cusp: ``(phi, jump of s', phase)``.

    Where ``s'`` jumps the support function's slope ``p_theta`` jumps: the
    profile has a straight edge (a positive jump of ``p_theta`` along
    increasing ``theta``: convex) or a cusp with a swallowtail (a negative one:
    ``rho = -inf``, whatever the base radius). ``p_theta(phi, s')`` and
    ``dtheta(s')`` give both sides at the jump.
    """
    out = []
    for phi, before, after, phase in velocity_jumps(program):
        t0, t1 = dtheta(before), dtheta(after)
        jump = (p_theta(phi, after) - p_theta(phi, before)) * np.sign(t1)
        if np.sign(t0) != np.sign(t1) or jump < 0:
            out.append((phi, after - before, phase))
    return out


def cusp_error(program: Program, found: list[tuple[float, float, int]]) -> InputError:
    """The error for a program whose velocity drops (``found``: :func:`cusps`): a cusp whatever the size."""
    phi, dv, phase = found[0]
    return InputError(f"motion[{phase}]", f"the follower's velocity jumps by {dv:.6g} per radian at "
                      f"{turn_degrees(phi):.4g} deg (a hard impact): a flat-faced follower's cam has a cusp "
                      "there whatever its base radius; use laws without velocity jumps (e.g. cycloidal, poly345)")


# -- translating -------------------------------------------------------------------------------


def translating_parts(program: Program, R0: float, eps: int = 1,
                      e: float = 0.0) -> tuple[PhaseFunction, PhaseFunction]:
    """``rho(i, u)``, ``contact(i, u)`` of the translating face inside phase ``i`` (one-sided at the ends).

    ``rho = R0 + s + s''``; ``contact = -e + eps s'``: the contact's x on the
    face (the follower's axis at x = 0), lengths.
    """
    def rho(i, u):
        m = program.evaluate_phase(i, u)
        return R0 + m.s + m.d2s

    def contact(i, u):
        return -e + eps * program.evaluate_phase(i, u).ds

    return rho, contact


def translating_cusps(program: Program, eps: int) -> list[tuple[float, float, int]]:
    """The velocity drops of a translating face's program (:func:`cusps`)."""
    return cusps(program, lambda phi, ds: -eps * ds, lambda ds: -eps)


# -- oscillating -------------------------------------------------------------------------------


def oscillating_setup(program: Program, L: float, R0: float, f: float, rise_sense: int) -> float:
    """The face normal's angle ``a0`` at the near dwell (radians, line-of-centres frame).

    ``cos a0 = (f - R0) / L`` with ``a0`` of the sign ``rise_sense``; raises
    :class:`InputError` (``base_radius``) when the face cannot touch that base
    circle or would turn past the line of centres during the rise.
    """
    if rise_sense not in (1, -1):
        raise InputError("follower.rise_direction", f"rise_sense must be +1 (ccw) or -1 (cw), got {rise_sense!r}")
    if not -1 < (f - R0) / L < 1:
        raise InputError("base_radius", f"the face cannot touch a base circle of R0 = {R0:g} (|f - R0| >= L = {L:g})")
    a0 = near_dwell_angle(L, f, R0, rise_sense)
    if abs(a0) + program.lift >= np.pi:
        raise InputError("base_radius", f"R0 = {R0:g}: the face would turn past the line of centres during the "
                         f"rise (need R0 < f + L cos(swing) = {f + L * np.cos(program.lift):.6g})")
    return float(a0)


def near_dwell_angle(L: float, f: float, R0, sigma: int):
    """The face normal's angle ``a0`` at the near dwell (radians, line-of-centres frame), unchecked:
    ``cos a0 = (f - R0) / L`` (clipped to [-1, 1]), ``a0`` of the sign ``sigma``. Arrays of R0 broadcast;
    :func:`oscillating_setup` checks that the face can touch the base circle."""
    return sigma * np.arccos(np.clip((f - np.asarray(R0, float)) / L, -1.0, 1.0))


def oscillating_terms(program: Program, L: float, f: float, sigma: int, eps: int, a0: float, phi=None,
                      phase: int | None = None, u=None):
    """The oscillating face at cam angles ``phi`` (or at ``u`` in phase ``phase``, one-sided at its ends).

    Returns ``phi, a, theta, theta', theta'', p, p', p''`` (radians, lengths;
    primes for d/dphi): ``a = a0 + sigma psi`` the face normal's angle in the
    line-of-centres frame, ``theta = a - eps phi`` in the cam frame,
    ``p = f - L cos a`` the face's distance from the cam centre.
    """
    m = program.evaluate(phi) if phase is None else program.evaluate_phase(phase, u)
    if phase is not None:
        phi = program.starts[phase] + np.asarray(u, float) * program.phases[phase].angle
    a, dth, d2th, p, dp, d2p = oscillating_support(L, f, sigma, eps, a0, m.s, m.ds, m.d2s)
    return phi, a, a - eps * phi, dth, d2th, p, dp, d2p


def oscillating_support(L: float, f: float, sigma: int, eps: int, a0, s, ds, d2s):
    """The oscillating face's normal angle and support function at swing ``s`` and its rates ``s', s''``.

    Returns ``a, theta', theta'', p, p', p''`` (radians, lengths; primes for
    d/dphi): ``a = a0 + sigma s``, ``theta' = sigma s' - eps``,
    ``theta'' = sigma s''``, ``p = f - L cos a`` and its two rates. Arrays
    broadcast; the module notes give the frame.
    """
    a = a0 + sigma * s
    sa, ca = np.sin(a), np.cos(a)
    p = f - L * ca
    dp = L * sa * sigma * ds
    d2p = L * ca * ds**2 + L * sa * sigma * d2s
    return a, sigma * ds - eps, sigma * d2s, p, dp, d2p


def oscillating_contact(L: float, sigma: int, a, p_theta):
    """The contact's position on an oscillating face (length): from the pivot's foot, positive towards the cam.

    ``c = -sigma (O . J m + p_theta)`` with ``O . J m = -L sin a``: measured
    along ``-sigma J m``, the side of the pivot's foot the cam centre
    projects on.
    """
    return -sigma * (-L * np.sin(a) + p_theta)


def oscillating_pressure(f: float, contact):
    """Pressure angle of an oscillating face (radians, >= 0): ``atan(|f| / |c|)``."""
    return np.arctan2(abs(f), np.abs(contact))


def oscillating_parts(program: Program, L: float, f: float, sigma: int, eps: int,
                      a0: float) -> tuple[PhaseFunction, PhaseFunction, PhaseFunction]:
    """``rho(i, u)``, ``contact(i, u)``, ``gamma(i, u)`` of the oscillating face inside phase ``i``.

    Lengths and radians; ``contact`` from the pivot's foot, positive towards
    the cam (:func:`oscillating_contact`).
    """
    def terms(i, u):
        return oscillating_terms(program, L, f, sigma, eps, a0, phase=i, u=u)

    def rho(i, u):
        _, _, _, t1, t2, q, q1, q2 = terms(i, u)
        return curvature_radius(t1, t2, q, q1, q2)

    def contact(i, u):
        _, a, _, t1, _, _, q1, _ = terms(i, u)
        return oscillating_contact(L, sigma, a, q1 / t1)

    def gamma(i, u):
        return oscillating_pressure(f, contact(i, u))

    return rho, contact, gamma


def oscillating_cusps(program: Program, L: float, sigma: int, eps: int, a0: float) -> list[tuple[float, float, int]]:
    """The velocity jumps that give an oscillating face's cam a cusp (:func:`cusps`)."""
    def p_theta(phi, ds):
        a = a0 + sigma * float(program.evaluate(np.array([phi])).s[0])
        return L * np.sin(a) * sigma * ds / (sigma * ds - eps)

    return cusps(program, p_theta, lambda ds: sigma * ds - eps)


def rocker_frame_turn(a0: float, sigma: int) -> float:
    """Angle (radians) from the rocker's fixed frame to the line-of-centres frame of a flat-faced rocker.

    The rocker's fixed frame (:mod:`cams.model.follower`) has X along the rocker
    at the near dwell; a flat face's rocker is the face, pointing from the
    pivot's foot towards the cam (the direction contact positions grow:
    ``-sigma J m``). The envelope is computed in the line-of-centres frame
    (pivot at the origin, cam centre at ``(L, 0)``), whose X axis is the
    rocker frame's turned by ``-beta``, ``beta = a0 - sigma 90 deg``: a point
    with line-of-centres coordinates ``x`` has rocker-frame coordinates
    ``R(-beta) x``. The cam centre in the rocker frame is
    ``L (cos beta, -sin beta) = (sqrt(L^2 - (f - R0)^2), sigma (f - R0))``.
    """
    return float(a0 - sigma * np.pi / 2)


# -- a design's flat face ------------------------------------------------------------------------


def flat_parts(design: FlatFaceDesign, R0: float) -> tuple[PhaseFunction, PhaseFunction, PhaseFunction]:
    """``rho, contact, gamma`` functions ``(phase, u) -> array`` of a flat-face design at base radius R0.

    ``design`` is a :class:`cams.model.design.FlatFaceDesign`; lengths and
    radians; ``contact`` from the follower's axis (translating, +X) or from
    the pivot's foot, positive towards the cam (rocker).
    """
    fo, prog, eps = design.follower, design.program, design.cam_sense
    if isinstance(fo, FlatTranslating):
        rho, contact = translating_parts(prog, R0, eps, fo.offset)
        return rho, contact, lambda i, u: np.zeros_like(np.asarray(u, float))
    a0 = oscillating_setup(prog, fo.centre_distance, R0, fo.face_offset, fo.sense)
    return oscillating_parts(prog, fo.centre_distance, fo.face_offset, fo.sense, eps, a0)


def flat_support(design: FlatFaceDesign, R0: float) -> PhaseFunction:
    """The face's distance from the cam centre, ``p(i, u)`` (length), of a flat-face design at base radius R0.

    The support function of the profile (module notes): ``R0 + s`` for a translating face, ``f - L cos a`` for
    an oscillating one.
    """
    fo, prog, eps = design.follower, design.program, design.cam_sense
    if isinstance(fo, FlatTranslating):
        return lambda i, u: R0 + prog.evaluate_phase(i, u).s
    L, f, sigma = fo.centre_distance, fo.face_offset, fo.sense
    a0 = oscillating_setup(prog, L, R0, f, sigma)
    return lambda i, u: oscillating_terms(prog, L, f, sigma, eps, a0, phase=i, u=u)[5]


def flat_radii(design: FlatFaceDesign, R0: float) -> tuple[float, float, float, float]:
    """The profile's smallest and largest distance from the cam centre and their cam angles.

    Every point ``X`` of the envelope has ``|X| >= X . m = p`` (``m`` the face's unit normal) and where ``p`` is
    smallest ``p_theta = 0``, so ``X = p m``: the profile's smallest radius is ``min p``, exactly. Where ``p`` is
    largest ``X = p m`` too, and a convex profile (the only kind that passes) lies inside its support lines, so
    its largest radius is ``max p``. Both are found per phase on a grid refined round the best point
    (:func:`phase_minimum`; the first such angle in the program's order wins a tie within 1e-12 of the design's
    scale).

    Returns
    -------
    smallest, smallest_at, largest, largest_at : float
        Lengths and cam angles (radians).
    """
    p = flat_support(design, R0)
    tie = 1e-12 * design.scale
    lo, lo_at = phase_minimum(p, design.program, tie=tie)
    hi, hi_at = phase_minimum(lambda i, u: -p(i, u), design.program, tie=tie)
    return float(lo), float(lo_at), float(-hi), float(hi_at)
