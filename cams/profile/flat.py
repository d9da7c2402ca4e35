"""Flat-faced followers: profile as the envelope of the face lines, size from convexity.

A flat face's pressure angle is fixed by geometry (zero for a translating
face perpendicular to its axis and for a rocker face through its pivot), so
the cam's size is limited not by jamming but by convexity: the profile's
radius of curvature must stay above a minimum ``rho_min > 0`` everywhere, and
the face must be wide enough for the contact point's travel.

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
from the foot of the perpendicular from O.

* Translating face (frame of :class:`cams.model.follower.Translating`: Y along the
  rise, the face perpendicular to it at ``y = s``, the cam centre at
  ``O = (-e, -R0)``): ``p = R0 + s``, ``theta' = -eps``, hence
  ``rho = R0 + s + s''`` and the contact lies at ``x = -e + eps s'`` on the
  face. Convexity needs ``R0 >= rho_min - min(s + s'')``.
* Oscillating face (pivot at the origin, cam centre at ``O = (L, 0)``, the
  face at signed distance ``f`` from the pivot, turning with the rocker by
  ``sigma psi``): ``a = a0 + sigma psi``, ``p = f - L cos a``. The face
  touches the base circle at the near dwell: ``cos a0 = (f - R0) / L``, with
  ``a0`` on the side ``sigma`` so that the rise moves the face away from the
  cam. The pressure angle (between the face normal and the contact point's
  velocity) is ``atan(|f| / |c|)`` with ``c`` the contact's position along the
  face from the pivot's foot: zero for a face through the pivot.

Where the follower's velocity jumps (a hard impact) the support function's
slope jumps: a jump up gives the profile a straight edge (convex), a drop a
cusp whatever the base radius (``min_rho = -inf``; the minimum-radius
functions refuse such a program).

Design files
------------
``[follower] face = "flat"`` makes :func:`cams.io.designfile.design_from_dict`
return a :class:`cams.model.design.FlatFaceDesign` (followers :class:`FlatTranslating`,
:class:`FlatRocker`); :func:`size_flat_face` sizes it (base radius, face
travel, pressure angle: :class:`FlatFaceSolution`), :func:`flat_face_profile`
samples the cam within a chord tolerance and :func:`check_flat_face` checks it.
For the rocker the design reports contact positions along the face from the
pivot's foot, positive towards the cam (``-sigma`` times ``contact`` here).

Angles in radians, lengths in the design's unit (mm).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from cams.checks.profile import ChecksMixin
from laws.errors import InputError
from laws.program import Program

if TYPE_CHECKING:  # the design's module imports this one's followers
    from cams.model.design import FlatFaceDesign

__all__ = [
    "FlatFaceProfile",
    "translating_flat_face",
    "oscillating_flat_face",
    "min_base_radius_translating",
    "min_base_radius_oscillating",
    "FlatTranslating",
    "FlatRocker",
    "FlatFaceSolution",
    "FlatCheckReport",
    "flat_face_cam",
    "flat_face_profile",
    "size_flat_face",
    "check_flat_face",
]


@dataclass(frozen=True, eq=False)
class FlatFaceProfile:
    """A flat-faced follower's cam, sampled.

    Attributes
    ----------
    phi : ndarray, shape (n,)
        Cam angles, radians (the phase starts among them).
    point : ndarray, shape (n, 2)
        Cam profile (envelope of the face lines), cam frame, length unit.
    rho : ndarray, shape (n,)
        Radius of curvature of the profile, positive convex.
    contact : ndarray, shape (n,)
        Contact point's position along the face, length: from the follower's
        axis (translating, +X positive) or from the foot of the perpendicular
        from the pivot (oscillating, along ``J m``).
    pressure_angle : ndarray, shape (n,)
        Radians.
    base_radius : float
        R0: distance from the cam centre to the face at the near dwell.
    min_rho, min_rho_at : float
        Smallest radius of curvature over the cycle (refined, not only at the
        samples) and the cam angle where it occurs (radians).
    """

    phi: np.ndarray
    point: np.ndarray
    rho: np.ndarray
    contact: np.ndarray
    pressure_angle: np.ndarray
    base_radius: float
    min_rho: float
    min_rho_at: float
    name: str = "cam"
    tolerance: float | None = None

    # the attributes cams.io.export reads (a flat face has no pitch curve and no groove)
    pitch = None
    outer = None
    roller_radius = 0.0
    groove = False

    def __len__(self) -> int:
        return len(self.phi)

    @property
    def work(self) -> np.ndarray:
        """The cam profile (``point``), under the name :mod:`cams.io.export` uses."""
        return self.point

    @property
    def R0(self) -> float:
        """The base radius (``base_radius``), under the name :mod:`cams.io.export` uses."""
        return self.base_radius

    @property
    def min_work_radius(self) -> float:
        """Smallest distance of the sampled profile from the cam centre (length)."""
        return float(np.min(np.linalg.norm(self.point, axis=1)))

    @property
    def face_range(self) -> tuple[float, float]:
        """Smallest and largest contact position on the face (length)."""
        return float(np.min(self.contact)), float(np.max(self.contact))

    @property
    def face_width(self) -> float:
        """Face width the contact travels over (length), without margins."""
        lo, hi = self.face_range
        return hi - lo

    @property
    def convex(self) -> bool:
        """True when the profile is convex everywhere (``min_rho > 0``)."""
        return bool(self.min_rho > 0)


def _grid(program: Program, samples: int) -> np.ndarray:
    """Cam angles: ``samples`` uniform steps over the turn plus every phase start."""
    if not (isinstance(samples, (int, np.integer)) and samples >= 8):
        raise InputError("samples", f"must be an integer >= 8, got {samples!r}")
    uniform = np.linspace(0, 2 * np.pi, samples + 1)[:-1]
    starts = program.starts[:-1]
    near = np.min(np.abs(uniform[:, None] - starts[None, :]), axis=1) < 1e-9
    return np.unique(np.concatenate([uniform[~near], starts]))  # a start replaces a uniform point next to it


def _phase_min(fun, program: Program, grid: int = 2000) -> tuple[float, float]:
    """Smallest ``fun(i, u)`` over the cycle (per phase, grid + zooming search) and its cam angle."""
    best, at = np.inf, 0.0
    for i, p in enumerate(program.phases):
        u = np.linspace(0, 1, grid + 1)
        v = fun(i, u)
        k = int(np.argmin(v))
        bu, bv = float(u[k]), float(v[k])
        if p.kind != "dwell":
            bu, bv = _zoom_min(lambda x: fun(i, x), u[max(k - 1, 0)], u[min(k + 1, grid)], bu, bv)
        if bv < best:
            best, at = bv, float(program.starts[i] + bu * p.angle)
    return best, at


def _zoom_min(fun, lo: float, hi: float, bu: float, bv: float, n: int = 64, xtol: float = 1e-13):
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


def _illinois(fun, a: float, b: float, fa: float, fb: float, xtol: float) -> float:
    """A root of ``fun`` in ``[a, b]`` with ``fa < 0 <= fb`` (Illinois false position); the admissible end."""
    side = 0
    for _ in range(200):
        if abs(b - a) <= xtol:
            break
        c = b - fb * (b - a) / (fb - fa)
        if not (min(a, b) < c < max(a, b)):
            c = 0.5 * (a + b)
        fc = fun(c)
        if fc >= 0:
            b, fb = c, fc
            if side == 1:
                fa *= 0.5
            side = 1
        else:
            a, fa = c, fc
            if side == -1:
                fb *= 0.5
            side = -1
    return b


def _rho(dtheta, d2theta, p, dp, d2p):
    """Radius of curvature ``rho = p + p_thetatheta`` of the envelope, from derivatives in ``phi``."""
    return p + (d2p * dtheta - dp * d2theta) / dtheta**3


def _envelope(theta, dtheta, d2theta, p, dp, d2p):
    """Envelope point (cam frame), radius of curvature and ``p_theta`` of a family of lines."""
    if np.any(np.abs(dtheta) < 1e-12):
        raise InputError("follower", "the face turns with the cam (theta' = 0): no envelope")
    p_t = dp / dtheta
    n = np.stack([np.cos(theta), np.sin(theta)], axis=-1)
    t = np.stack([-np.sin(theta), np.cos(theta)], axis=-1)
    X = p[..., None] * n + p_t[..., None] * t
    return X, _rho(dtheta, d2theta, p, dp, d2p), p_t


def _check_cam_sense(cam_sense) -> int:
    if cam_sense not in (1, -1):
        raise InputError("cam.rotation", f"cam_sense must be +1 (ccw) or -1 (cw), got {cam_sense!r}")
    return int(cam_sense)


def _check_length(field: str, v, *, positive=True) -> float:
    ok = isinstance(v, (int, float, np.floating)) and not isinstance(v, bool) and np.isfinite(v)
    if not ok or (positive and v <= 0):
        raise InputError(field, f"must be a number{' > 0' if positive else ''}, got {v!r}")
    return float(v)


# -- velocity jumps: a flat edge or a cusp whatever the size ----------------------------------


def _velocity_jumps(program: Program) -> list[tuple[float, float, float, int]]:
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


def _cusps(program: Program, p_theta, dtheta) -> list[tuple[float, float, int]]:
    """The velocity jumps that give the envelope a cusp: ``(phi, jump of s', phase)``.

    Where ``s'`` jumps the support function's slope ``p_theta`` jumps: the
    profile has a straight edge (a positive jump of ``p_theta`` along
    increasing ``theta``: convex) or a cusp with a swallowtail (a negative one:
    ``rho = -inf``, whatever the base radius). ``p_theta(phi, s')`` and
    ``dtheta(s')`` give both sides at the jump.
    """
    out = []
    for phi, before, after, phase in _velocity_jumps(program):
        t0, t1 = dtheta(before), dtheta(after)
        jump = (p_theta(phi, after) - p_theta(phi, before)) * np.sign(t1)
        if np.sign(t0) != np.sign(t1) or jump < 0:
            out.append((phi, after - before, phase))
    return out


def _cusp_error(program: Program, cusps) -> InputError:
    phi, dv, phase = cusps[0]
    return InputError(f"motion[{phase}]", f"the follower's velocity jumps by {dv:.6g} per radian at "
                      f"{np.degrees(phi) % 360:.4g} deg (a hard impact): a flat-faced follower's cam has a cusp "
                      "there whatever its base radius; use laws without velocity jumps (e.g. cycloidal, poly345)")


# -- translating -------------------------------------------------------------------------------


def _translating_parts(program: Program, R0: float, eps: int = 1, e: float = 0.0):
    """``rho(i, u)``, ``contact(i, u)`` of the translating face inside phase ``i`` (one-sided at the ends)."""
    def rho(i, u):
        m = program.evaluate_phase(i, u)
        return R0 + m.s + m.d2s

    def contact(i, u):
        return -e + eps * program.evaluate_phase(i, u).ds

    return rho, contact


def _translating_cusps(program: Program, eps: int):
    return _cusps(program, lambda phi, ds: -eps * ds, lambda ds: -eps)


def translating_flat_face(program: Program, *, base_radius: float, cam_sense: int = 1, offset: float = 0.0,
                          samples: int = 1440) -> FlatFaceProfile:
    """Cam of a translating flat-faced follower (face perpendicular to the axis).

    Parameters
    ----------
    program : Program
        Lift is the stroke (length).
    base_radius : float
        R0, cam centre to the face at the near dwell (length, > 0).
    cam_sense : {+1, -1}
        Cam's sense of rotation, +1 counter-clockwise.
    offset : float
        Axis offset e (positive: axis on the +X side of the cam centre); it
        shifts the contact positions on the face, not the profile.
    samples : int
        Uniform steps per turn (phase starts are added).

    Returns
    -------
    FlatFaceProfile
        ``rho = R0 + s + s''``; pressure angle 0; ``contact`` is the contact
        point's x in the follower frame (the axis at x = 0). A drop of the
        follower's velocity (a hard impact) gives the profile a cusp:
        ``min_rho = -inf`` there.

    Examples
    --------
    >>> import numpy as np
    >>> from laws.program import Phase, Program
    >>> prog = Program((Phase("rise", np.pi / 2, "cycloidal"), Phase("return", 1.5 * np.pi, "cycloidal")), 10.0)
    >>> cam = translating_flat_face(prog, base_radius=30.0)
    >>> round(cam.min_rho, 4), round(cam.face_width, 4)
    (13.5737, 16.9765)
    """
    R0 = _check_length("base_radius", base_radius)
    eps = _check_cam_sense(cam_sense)
    e = _check_length("follower.offset", offset, positive=False)
    phi = _grid(program, samples)
    m = program.evaluate(phi)
    theta = np.pi / 2 - eps * phi
    X, rho, p_t = _envelope(theta, np.full_like(phi, -eps), np.zeros_like(phi), R0 + m.s, m.ds, m.d2s)
    contact = -e - p_t  # fixed-frame x of the contact: O_x + p_theta * (J m)_x, J m = (-1, 0)
    lo, at = _phase_min(_translating_parts(program, R0)[0], program)
    cusps = _translating_cusps(program, eps)
    if cusps:
        lo, at = -np.inf, cusps[0][0]
    return FlatFaceProfile(phi, X, rho, contact, np.zeros_like(phi), R0, lo, at)


def min_base_radius_translating(program: Program, *, min_radius: float = 0.0) -> tuple[float, float]:
    """Smallest R0 of a translating flat-faced follower's cam with ``rho >= min_radius``.

    ``R0 = min_radius - min(s + s'')`` over the cycle (found per phase by grid
    and bounded search), at least 0.

    Returns
    -------
    R0 : float
        Length.
    at : float
        Cam angle (radians) of the binding position.

    Raises
    ------
    InputError
        Field ``motion[i]``: the follower's velocity drops somewhere (a cusp
        whatever the base radius).
    """
    rmin = _check_length("min_radius", min_radius, positive=False)
    cusps = _translating_cusps(program, 1)  # the same for either sense of rotation
    if cusps:
        raise _cusp_error(program, cusps)
    v, at = _phase_min(_translating_parts(program, 0.0)[0], program)
    return max(rmin - v, 0.0), at


# -- oscillating -------------------------------------------------------------------------------


def _oscillating_setup(program, L, R0, f, rise_sense):
    if rise_sense not in (1, -1):
        raise InputError("follower.rise_direction", f"rise_sense must be +1 (ccw) or -1 (cw), got {rise_sense!r}")
    c0 = (f - R0) / L
    if not -1 < c0 < 1:
        raise InputError("base_radius", f"the face cannot touch a base circle of R0 = {R0:g} (|f - R0| >= L = {L:g})")
    a0 = rise_sense * np.arccos(c0)
    if abs(a0) + program.lift >= np.pi:
        raise InputError("base_radius", f"R0 = {R0:g}: the face would turn past the line of centres during the "
                         f"rise (need R0 < f + L cos(swing) = {f + L * np.cos(program.lift):.6g})")
    return a0


def _oscillating_terms(program, L, f, sigma, eps, a0, phi=None, phase=None, u=None):
    m = program.evaluate(phi) if phase is None else program.evaluate_phase(phase, u)
    if phase is not None:
        phi = program.starts[phase] + np.asarray(u, float) * program.phases[phase].angle
    a = a0 + sigma * m.s
    sa, ca = np.sin(a), np.cos(a)
    p = f - L * ca
    dp = L * sa * sigma * m.ds
    d2p = L * ca * m.ds**2 + L * sa * sigma * m.d2s
    theta = a - eps * phi
    dth = sigma * m.ds - eps
    d2th = sigma * m.d2s
    return phi, a, theta, dth, d2th, p, dp, d2p


def _oscillating_parts(program: Program, L: float, f: float, sigma: int, eps: int, a0: float):
    """``rho(i, u)``, ``contact(i, u)``, ``gamma(i, u)`` of the oscillating face inside phase ``i``."""
    def terms(i, u):
        return _oscillating_terms(program, L, f, sigma, eps, a0, phase=i, u=u)

    def rho(i, u):
        _, _, _, t1, t2, q, q1, q2 = terms(i, u)
        return _rho(t1, t2, q, q1, q2)

    def contact(i, u):
        _, a, _, t1, _, _, q1, _ = terms(i, u)
        return -L * np.sin(a) + q1 / t1

    def gamma(i, u):
        return np.arctan2(abs(f), np.abs(contact(i, u)))

    return rho, contact, gamma


def _oscillating_cusps(program: Program, L: float, sigma: int, eps: int, a0: float):
    def p_theta(phi, ds):
        a = a0 + sigma * float(program.evaluate(np.array([phi])).s[0])
        return L * np.sin(a) * sigma * ds / (sigma * ds - eps)

    return _cusps(program, p_theta, lambda ds: sigma * ds - eps)


def oscillating_flat_face(program: Program, *, centre_distance: float, base_radius: float, face_offset: float = 0.0,
                          rise_sense: int = -1, cam_sense: int = 1, samples: int = 1440) -> FlatFaceProfile:
    """Cam of an oscillating (rocker) flat-faced follower.

    Parameters
    ----------
    program : Program
        Lift is the swing (radians).
    centre_distance : float
        L, pivot to cam centre (length); the cam centre is at ``(L, 0)``.
    base_radius : float
        R0, cam centre to the face at the near dwell (length).
    face_offset : float
        Signed distance f of the face line from the pivot (length, along the
        face's outward normal); 0: the face passes through the pivot.
    rise_sense : {+1, -1}
        Rocker's sense of rotation on the rise (+1 counter-clockwise).
    cam_sense : {+1, -1}
        Cam's sense of rotation.
    samples : int
        Uniform steps per turn (phase starts are added).

    Returns
    -------
    FlatFaceProfile
        ``contact`` measured along ``J m`` from the pivot's foot on the face.
        A velocity jump that gives a cusp makes ``min_rho = -inf``.

    Raises
    ------
    InputError
        Non-positive lengths; a base circle the face cannot touch; a face that
        would turn past the line of centres; a face turning with the cam.
    """
    L = _check_length("centre_distance", centre_distance)
    R0 = _check_length("base_radius", base_radius)
    f = _check_length("face_offset", face_offset, positive=False)
    eps = _check_cam_sense(cam_sense)
    a0 = _oscillating_setup(program, L, R0, f, rise_sense)
    phi = _grid(program, samples)
    phi, a, theta, dth, d2th, p, dp, d2p = _oscillating_terms(program, L, f, rise_sense, eps, a0, phi=phi)
    X, rho, p_t = _envelope(theta, dth, d2th, p, dp, d2p)
    contact = -L * np.sin(a) + p_t  # O . J m + p_theta
    gamma = np.arctan2(abs(f), np.abs(contact))
    lo, at = _phase_min(_oscillating_parts(program, L, f, rise_sense, eps, a0)[0], program)
    cusps = _oscillating_cusps(program, L, rise_sense, eps, a0)
    if cusps:
        lo, at = -np.inf, cusps[0][0]
    return FlatFaceProfile(phi, X, rho, contact, gamma, R0, lo, at)


def _oscillating_scan(program: Program, L: float, f: float, sigma: int, eps: int, R0: np.ndarray,
                      grid: int = 2000, block: int = 20):
    """Smallest radius of curvature on a fixed grid (``grid + 1`` positions a phase), ``block`` R0 at a time.

    Yields ``(index, minimum)`` in the order of ``R0``.
    """
    u = np.linspace(0, 1, grid + 1)
    parts = [program.evaluate_phase(i, u) for i, p in enumerate(program.phases) if p.kind != "dwell"]
    # a dwell's profile is an arc of radius p = f - L cos(a): its smallest value is at one of the levels
    levels = np.unique(program.levels)
    s, ds, d2s = (np.concatenate([getattr(m, k) for m in parts] + [z])[None, :]
                  for k, z in (("s", levels), ("ds", 0 * levels), ("d2s", 0 * levels)))
    dth = sigma * ds - eps
    for k0 in range(0, len(R0), block):
        a = sigma * np.arccos((f - R0[k0:k0 + block]) / L)[:, None] + sigma * s
        sa, ca = np.sin(a), np.cos(a)
        with np.errstate(divide="ignore", invalid="ignore"):
            rho = _rho(dth, sigma * d2s, f - L * ca, L * sa * sigma * ds, L * ca * ds**2 + L * sa * sigma * d2s)
        rho = np.where(np.isfinite(rho), rho, -np.inf).min(axis=1)
        yield from zip(range(k0, k0 + len(rho)), rho)


def min_base_radius_oscillating(program: Program, *, centre_distance: float, face_offset: float = 0.0,
                                rise_sense: int = -1, cam_sense: int = 1, min_radius: float = 0.0,
                                scan: int = 200) -> tuple[float, float]:
    """Smallest R0 of an oscillating flat-faced follower's cam with ``rho >= min_radius``.

    R0 ranges over ``(0, f + L cos(swing))`` (beyond, the face would turn past
    the line of centres); the smallest radius of curvature is scanned over
    ``scan`` values of R0 (on a fixed grid of cam angles, all at once) and the
    first admissible one refined by root finding on the refined minimum.

    Returns
    -------
    R0 : float
        Length.
    at : float
        Cam angle (radians) of the binding position.

    Raises
    ------
    InputError
        No R0 in the range gives a convex enough profile (field
        ``min_radius``); a velocity jump that gives a cusp whatever the size
        (field ``motion[i]``).
    """
    L = _check_length("centre_distance", centre_distance)
    f = _check_length("face_offset", face_offset, positive=False)
    rmin = _check_length("min_radius", min_radius, positive=False)
    eps = _check_cam_sense(cam_sense)
    if rise_sense not in (1, -1):
        raise InputError("follower.rise_direction", f"rise_sense must be +1 (ccw) or -1 (cw), got {rise_sense!r}")
    hi = f + L * np.cos(program.lift)
    lo = max(f - L, 0.0)
    if hi <= lo + 1e-12 * L:
        # the face's far position must stay on the cam's side of the centre: f + L cos(swing) > 0 (f < L here)
        largest = np.degrees(np.arccos(np.clip(-f / L, -1.0, 1.0)))
        need = -L * np.cos(program.lift)
        need = 0.0 if abs(need) < 1e-9 * L else need
        raise InputError("swing", f"a flat face at {f:g} from the pivot with L = {L:g} turns at most {largest:.6g} "
                         f"degrees before its line passes the cam centre (swing {np.degrees(program.lift):g}); reduce "
                         f"the swing or give a face_offset above {need:.6g}")
    grid = lo + (hi - lo) * (np.arange(1, scan + 1) / (scan + 1))
    a_mid = _oscillating_setup(program, L, grid[scan // 2], f, rise_sense)
    cusps = _oscillating_cusps(program, L, rise_sense, eps, a_mid)
    if cusps:
        raise _cusp_error(program, cusps)

    def margin(R0):
        # the smallest radius of curvature at R0, as oscillating_flat_face finds it, without building the profile
        a0 = _oscillating_setup(program, L, R0, f, rise_sense)
        cusps = _oscillating_cusps(program, L, rise_sense, eps, a0)
        if cusps:
            return -np.inf, cusps[0][0]
        lo, at = _phase_min(_oscillating_parts(program, L, f, rise_sense, eps, a0)[0], program)
        return lo - rmin, at

    # the grid minimum is at least the true one: the first R0 admissible on the grid is where to start
    for k, coarse in _oscillating_scan(program, L, f, rise_sense, eps, grid):
        if coarse < rmin:
            continue
        g, at = margin(grid[k])
        if g < 0:
            continue
        if k == 0:
            return float(grid[0]), at
        # grid[k - 1] is not admissible: its grid minimum, an upper bound of the true one, is below, or
        # (an earlier k of the loop) its true minimum is
        R = _illinois(lambda x: margin(x)[0], grid[k - 1], grid[k], margin(grid[k - 1])[0], g, 1e-12 * L)
        return float(R), margin(R)[1]
    raise InputError("min_radius", f"no base radius below {hi:.6g} gives a radius of curvature >= {rmin:g}")


# -- flat-faced followers in design files --------------------------------------------------------


@dataclass(frozen=True)
class FlatTranslating:
    """Translating follower with a flat face perpendicular to its axis (design files' ``face = "flat"``).

    Parameters
    ----------
    offset : float
        Axis offset e (length; positive: the axis on the +X side of the cam
        centre). It moves the contact along the face, not the profile.
    stroke_scale : float
        The stroke, the characteristic length for relative tolerances.
    """

    offset: float = 0.0
    stroke_scale: float = 1.0

    kind = "translating"
    face = "flat"

    def __post_init__(self):
        _check_length("follower.offset", self.offset, positive=False)
        _check_length("follower.stroke", self.stroke_scale)

    @property
    def scale(self) -> float:
        """Characteristic length (the stroke)."""
        return self.stroke_scale


@dataclass(frozen=True)
class FlatRocker:
    """Oscillating follower with a flat face (design files' ``face = "flat"``).

    Parameters
    ----------
    centre_distance : float
        L, pivot to cam centre (length).
    face_offset : float
        Signed distance f from the pivot to the face line (length), positive
        when the pivot lies on the cam's side of the face; 0: the face passes
        through the pivot.
    sense : {+1, -1}
        Rocker's sense of rotation during the rise, +1 counter-clockwise.
    """

    centre_distance: float
    face_offset: float = 0.0
    sense: int = -1

    kind = "rocker"
    face = "flat"

    def __post_init__(self):
        _check_length("follower.centre_distance", self.centre_distance)
        _check_length("follower.face_offset", self.face_offset, positive=False)
        if self.sense not in (1, -1):
            raise InputError("follower.rise_direction", "must be 'cw' or 'ccw'")

    @property
    def scale(self) -> float:
        """Characteristic length (the centre distance L)."""
        return self.centre_distance


#: Names the design file gives the API's fields, for error messages.
_FILE_FIELDS = {"centre_distance": "follower.centre_distance", "face_offset": "follower.face_offset",
                "min_radius": "limits.min_radius", "follower.offset": "follower.offset", "swing": "follower.swing",
                "base_radius": "cam.base_radius"}


def _renamed(e: InputError, field: str | None = None) -> InputError:
    """``e`` with its field named as in a design file (``field`` overrides)."""
    msg = str(e)[len(e.field) + 2:] if e.field else str(e)
    new = field or _FILE_FIELDS.get(e.field, e.field)
    return InputError(new, msg)


def _parts(design, R0: float):
    """``rho, contact, gamma`` functions ``(phase, u) -> array`` of a flat-face design at base radius R0."""
    fo, prog, eps = design.follower, design.program, design.cam_sense
    if fo.kind == "translating":
        rho, contact = _translating_parts(prog, R0, eps, fo.offset)
        return rho, contact, lambda i, u: np.zeros_like(np.asarray(u, float))
    a0 = _oscillating_setup(prog, fo.centre_distance, R0, fo.face_offset, fo.sense)
    rho, contact, gamma = _oscillating_parts(prog, fo.centre_distance, fo.face_offset, fo.sense, eps, a0)
    # along -sigma J m: positive towards the cam (the cam centre projects on that side of the pivot's foot)
    return rho, lambda i, u: -fo.sense * contact(i, u), gamma


def flat_face_cam(design, base_radius: float, *, samples: int = 1440) -> FlatFaceProfile:
    """The sampled cam of a flat-face design (:class:`cams.model.design.FlatFaceDesign`) at a base radius."""
    fo = design.follower
    if fo.kind == "translating":
        cam = translating_flat_face(design.program, base_radius=base_radius, cam_sense=design.cam_sense,
                                    offset=fo.offset, samples=samples)
    else:
        cam = oscillating_flat_face(design.program, centre_distance=fo.centre_distance, base_radius=base_radius,
                                    face_offset=fo.face_offset, rise_sense=fo.sense, cam_sense=design.cam_sense,
                                    samples=samples)
    return replace(cam, name=design.name)


#: Fewest samples per turn of an exported flat-face profile, and the most.
MIN_SAMPLES, MAX_SAMPLES = 360, 2_000_000


def flat_face_profile(design, base_radius: float, *, tolerance: float | None = None,
                      field: str = "profile.tolerance") -> FlatFaceProfile:
    """The cam sampled uniformly in cam angle, every chord within ``tolerance`` of the profile.

    A chord spanning a turn ``dtheta`` of the face's normal on an arc of
    radius rho is ``rho dtheta**2 / 8`` from it; the number of samples makes
    the largest such sagitta (estimated on 720 samples) at most ``tolerance``.
    Straight edges (where the follower's velocity jumps up) are exact. The
    tolerance is at most 5 % of the base radius (:func:`cams.profile.roller.cap_tolerance`;
    None: 1e-3, 0.1 % of the base radius when that is under 1 mm).
    """
    from cams.profile.roller import cap_tolerance

    tolerance = cap_tolerance(tolerance, base_radius, field)
    coarse = flat_face_cam(design, base_radius, samples=720)
    dtheta = np.ones_like(coarse.phi)
    if design.follower.kind == "rocker":
        dtheta = np.abs(design.follower.sense * design.program.evaluate(coarse.phi).ds - design.cam_sense)
    worst = float(np.max(np.abs(coarse.rho) * dtheta**2))
    n = int(np.ceil(2 * np.pi * np.sqrt(worst / (8 * tolerance))))
    if n > MAX_SAMPLES:
        raise InputError(field, f"a chord tolerance of {tolerance:g} needs {n} points a turn, more than "
                         f"{MAX_SAMPLES}; use a larger tolerance")
    return replace(flat_face_cam(design, base_radius, samples=max(n, MIN_SAMPLES)), tolerance=float(tolerance))


def _deg(phi) -> float | None:
    return None if phi is None or not np.isfinite(phi) else float(np.degrees(phi) % 360.0)


@dataclass(frozen=True, eq=False)
class FlatFaceSolution:
    """A sized flat-face cam: base radius, face travel and pressure angle.

    Lengths in the design's unit, angles in radians.

    Attributes
    ----------
    design : cams.model.design.FlatFaceDesign
    R0 : float
        The base radius used: the convexity minimum ``R0_min``, or the floor
        ``limits.min_base_radius`` when larger, or the file's
        ``cam.base_radius``.
    R0_min : float or None
        Smallest base radius with ``rho >= min_radius`` everywhere (None when
        no base radius reaches it and ``cam.base_radius`` was given).
    R0_source : {"convexity", "limits.min_base_radius", "cam.base_radius"}
    binding_at : float or None
        Cam angle where rho is smallest at ``R0_min``.
    min_rho, min_rho_at : float
        Smallest radius of curvature at ``R0`` and its cam angle.
    face_range : (float, float)
        Smallest and largest contact position on the face: from the follower's
        axis (translating, +X) or from the foot of the perpendicular from the
        pivot (rocker, along the face, positive towards the cam; the API's
        ``FlatFaceProfile.contact`` is along ``J m``, this is ``-sigma`` times it).
    face_range_at : (float, float)
        Their cam angles.
    pressure_range : (float, float)
        Smallest and largest pressure angle over the cycle (fixed by the
        geometry: 0 for a translating face and for a rocker face through its
        pivot).
    pressure_max_at : float
    seconds : float
    notes : tuple of str
    """

    design: FlatFaceDesign
    R0: float
    R0_min: float | None
    R0_source: str
    binding_at: float | None
    min_rho: float
    min_rho_at: float
    face_range: tuple[float, float]
    face_range_at: tuple[float, float]
    pressure_range: tuple[float, float]
    pressure_max_at: float
    seconds: float
    notes: tuple[str, ...] = ()

    @property
    def centre(self) -> np.ndarray:
        """Cam centre in the follower's fixed frame: ``(-e, -R0)`` (translating) or ``(L, 0)`` (rocker)."""
        fo = self.design.follower
        if fo.kind == "translating":
            return np.array([0.0 - fo.offset, -self.R0]) + 0.0  # + 0.0: no -0.0 in reports
        return np.array([fo.centre_distance, 0.0])

    @property
    def face_width(self) -> float:
        """Length of face the contact travels over (no margins)."""
        return float(self.face_range[1] - self.face_range[0])

    @property
    def face_width_centred(self) -> float | None:
        """Translating: width of a face centred on the follower's axis, ``2 max(|lo|, |hi|)``; rocker: None."""
        if self.design.follower.kind != "translating":
            return None
        return float(2 * max(abs(self.face_range[0]), abs(self.face_range[1])))

    def face_line(self, phi) -> tuple[np.ndarray, np.ndarray]:
        """The face in the follower's fixed frame at cam angles ``phi``: ``(origin, direction)``.

        Points of the face are ``origin + c * direction`` with ``c`` measured as
        ``face_range`` (from the axis, or from the pivot's foot); shapes
        ``phi.shape + (2,)``.
        """
        fo, prog = self.design.follower, self.design.program
        s = prog.evaluate(np.asarray(phi, dtype=float)).s
        if fo.kind == "translating":
            origin = np.stack([np.zeros_like(s), s], axis=-1)
            return origin, np.stack([np.ones_like(s), np.zeros_like(s)], axis=-1)
        a = _oscillating_setup(prog, fo.centre_distance, self.R0, fo.face_offset, fo.sense) + fo.sense * s
        m = np.stack([np.cos(a), np.sin(a)], axis=-1)
        return fo.face_offset * m, -fo.sense * np.stack([-m[..., 1], m[..., 0]], axis=-1)

    def curves(self, n: int = 721) -> dict:
        """Radius of curvature, contact position and pressure angle against the cam angle.

        Each phase is sampled with both ends (one-sided values), the phases
        separated by NaN: keys ``phi``, ``rho``, ``contact``, ``pressure``
        (radians, lengths), for pictures.
        """
        prog = self.design.program
        funs = _parts(self.design, self.R0)
        out = {k: [] for k in ("phi", "rho", "contact", "pressure")}
        for i, p in enumerate(prog.phases):
            u = np.linspace(0.0, 1.0, max(int(n * p.angle / (2 * np.pi)), 8))
            vals = [prog.starts[i] + u * p.angle] + [np.broadcast_to(f(i, u), u.shape) for f in funs]
            for k, v in zip(out, vals):
                out[k] += [v, [np.nan]]
        return {k: np.concatenate(v) for k, v in out.items()}

    @property
    def rho_tolerance(self) -> float:
        """Round-off allowed on ``min_rho`` (length unit).

        ``rho`` sums terms of the size of R0 (and of L for a rocker): where the
        convexity binds, ``s''`` is about ``-R0``, so a cam far larger than its
        follower (tiny rise angles) loses ``eps * R0`` on ``rho``. The
        tolerance follows those magnitudes, not the follower's size alone.
        """
        L = float(getattr(self.design.follower, "centre_distance", 0.0))
        size = abs(self.R0) + abs(L) + abs(self.design.min_radius)
        return 1e-9 * self.design.scale + 64 * np.finfo(float).eps * size

    @property
    def verified(self) -> bool:
        """True when the profile at R0 is convex enough: ``min_rho >= min_radius`` (to :attr:`rho_tolerance`)."""
        return bool(self.min_rho >= self.design.min_radius - self.rho_tolerance)

    def to_dict(self) -> dict:
        """JSON-ready report: lengths in the design's unit, angles in degrees."""
        fo = self.design.follower
        lo, hi = self.face_range
        deg = lambda x: None if x is None else float(np.degrees(x))  # noqa: E731
        return {
            "name": self.design.name,
            "follower": fo.kind,
            "face": "flat",
            "R0": float(self.R0),
            "R0_min": None if self.R0_min is None else float(self.R0_min),
            "R0_source": self.R0_source,
            "binding_deg": _deg(self.binding_at),
            "min_radius": float(self.design.min_radius),
            "min_rho": float(self.min_rho),
            "min_rho_at_deg": _deg(self.min_rho_at),
            "L": float(fo.centre_distance) if fo.kind == "rocker" else None,
            "face_offset": float(fo.face_offset) if fo.kind == "rocker" else None,
            "offset": float(fo.offset) if fo.kind == "translating" else None,
            "centre": {"x": float(self.centre[0]), "y": float(self.centre[1])},
            "face_range": {"from": float(lo), "to": float(hi),
                           "from_at_deg": _deg(self.face_range_at[0]), "to_at_deg": _deg(self.face_range_at[1])},
            "face_width": self.face_width,
            "face_width_centred": self.face_width_centred,
            "pressure_angle": {"min": deg(self.pressure_range[0]), "max": deg(self.pressure_range[1]),
                               "max_at_deg": _deg(self.pressure_max_at)},
            "verified": self.verified,
            "seconds": float(self.seconds),
            "notes": list(self.notes),
        }


def size_flat_face(design) -> FlatFaceSolution:
    """Size the cam of a flat-face design (:class:`cams.model.design.FlatFaceDesign`).

    The base radius is the convexity minimum (:func:`min_base_radius_translating`,
    :func:`min_base_radius_oscillating` with ``design.min_radius``), raised to
    ``design.min_base_radius`` when that is larger, or ``design.base_radius``
    when given. At that radius the smallest radius of curvature, the extreme
    contact positions on the face and the pressure angle's range are located
    per phase (grid and bounded search).

    Raises
    ------
    InputError
        Fields named as in the design file: ``limits.min_radius`` (no base
        radius is convex enough), ``motion[i]`` (a velocity drop: a cusp
        whatever the size), ``cam.base_radius`` (outside what the face can touch).
    """
    import time

    t0 = time.perf_counter()
    fo, prog, rmin = design.follower, design.program, design.min_radius
    notes = []
    R0_min = bind = None
    try:
        if fo.kind == "translating":
            R0_min, bind = min_base_radius_translating(prog, min_radius=rmin)
        else:
            R0_min, bind = min_base_radius_oscillating(
                prog, centre_distance=fo.centre_distance, face_offset=fo.face_offset, rise_sense=fo.sense,
                cam_sense=design.cam_sense, min_radius=rmin)
    except InputError as e:
        if e.field == "min_radius":
            hint = ("a longer follower.centre_distance, a smaller swing, longer rise or return angles, the other "
                    "follower.rise_direction or a smaller limits.min_radius may help")
            e = _renamed(e, "limits.min_radius")
            if design.base_radius is None:
                raise InputError("limits.min_radius", f"{str(e)[len('limits.min_radius: '):]}; {hint}") from None
            notes.append(f"no base radius reaches the limit: {str(e)}")
        else:
            raise _renamed(e) from None
    if design.base_radius is not None:
        R0, source = float(design.base_radius), "cam.base_radius"
        if R0_min is not None:
            notes.append(f"R0 is cam.base_radius = {R0:g} mm; the smallest convex enough is {R0_min:.6g} mm")
    elif design.min_base_radius is not None and design.min_base_radius > R0_min:
        R0, source = float(design.min_base_radius), "limits.min_base_radius"
        notes.append(f"R0 raised to limits.min_base_radius = {R0:g} (convexity needs {R0_min:.6g})")
    else:
        R0, source = R0_min, "convexity"
        if R0 <= 0:
            raise InputError("limits.min_radius", f"{rmin:g} is met by any base radius (s + s'' >= min_radius "
                             "everywhere); give limits.min_base_radius or cam.base_radius")
    try:
        rho, contact, gamma = _parts(design, R0)
    except InputError as e:
        raise _renamed(e, source if e.field == "base_radius" else None) from None
    lo_rho, lo_rho_at = _phase_min(rho, prog)
    lo, lo_at = _phase_min(contact, prog)
    hi, hi_at = _phase_min(lambda i, u: -contact(i, u), prog)
    if fo.kind == "translating":
        g = (0.0, 0.0, 0.0)
    else:
        gmin, _ = _phase_min(gamma, prog)
        gmax, gat = _phase_min(lambda i, u: -gamma(i, u), prog)
        g = (gmin, -gmax, gat)
        if lo < 0 < -hi:
            notes.append("the contact passes the foot of the perpendicular from the pivot: the face must reach "
                         "both sides of it")
    return FlatFaceSolution(
        design=design, R0=float(R0), R0_min=None if R0_min is None else float(R0_min), R0_source=source,
        binding_at=bind, min_rho=float(lo_rho), min_rho_at=float(lo_rho_at), face_range=(float(lo), float(-hi)),
        face_range_at=(float(lo_at), float(hi_at)), pressure_range=(float(g[0]), float(g[1])),
        pressure_max_at=float(g[2]), seconds=time.perf_counter() - t0, notes=tuple(notes))


@dataclass(frozen=True, eq=False)
class FlatCheckReport(ChecksMixin):
    """The checks of a flat-face cam: convexity, a valid closed profile, the bore.

    Attributes
    ----------
    name : str
    checks : tuple of cams.checks.profile.Check
        ``convexity`` (smallest radius of curvature >= ``limits.min_radius``),
        ``profile_polygon`` (the sampled profile is a simple closed curve round
        the cam centre) and ``bore`` (only with ``[cam] bore_radius``).
    profile : FlatFaceProfile
    bore_radius : float
    min_radius : float
    """

    name: str
    checks: tuple
    profile: FlatFaceProfile
    bore_radius: float
    min_radius: float

    def to_dict(self) -> dict:
        """JSON-ready report: lengths in the design's unit, angles in degrees."""
        return {
            "name": self.name,
            "face": "flat",
            "passed": bool(self.passed),
            "checks": [c.to_dict() for c in self.checks],
            "min_radius": float(self.min_radius),
            "bore_radius": float(self.bore_radius),
            "R0": float(self.profile.R0),
            "points": len(self.profile),
            "tolerance": float(self.profile.tolerance),
        }


def check_flat_face(design, solution: FlatFaceSolution, profile: FlatFaceProfile) -> FlatCheckReport:
    """Check a sized flat-face cam: convexity (refined, not only at the samples), the polygon, the bore."""
    from cams.checks.profile import Check, _polygon_check
    from cams.profile.roller import default_bore_radius

    rmin = design.min_radius
    ok = solution.min_rho >= rmin - solution.rho_tolerance
    checks = [Check("convexity", bool(ok), float(solution.min_rho), _deg(solution.min_rho_at), float(rmin), "mm",
                    f"smallest radius of curvature of the profile {solution.min_rho:.6g} (limit {rmin:g})"),
              _polygon_check("profile_polygon", profile.work, profile.phi)]
    bore = design.bore_radius if design.bore_radius is not None else default_bore_radius(profile)
    if design.bore_radius is not None:
        rad = np.linalg.norm(profile.work, axis=1)
        k = int(np.argmin(rad))
        checks.append(Check("bore", bool(rad[k] > bore), float(rad[k]), _deg(profile.phi[k]), float(bore), "mm",
                            f"profile's smallest radius {rad[k]:.6g} mm vs bore radius {bore:.6g} mm"))
    return FlatCheckReport(design.name, tuple(checks), profile, float(bore), float(rmin))
