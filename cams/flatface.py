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

* Translating face (frame of :class:`cams.follower.Translating`: Y along the
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

Angles in radians, lengths in the design's unit (mm).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from laws.errors import InputError
from laws.program import Program

__all__ = [
    "FlatFaceProfile",
    "translating_flat_face",
    "oscillating_flat_face",
    "min_base_radius_translating",
    "min_base_radius_oscillating",
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
    """Smallest ``fun(i, u)`` over the cycle (per phase, grid + bounded search) and its cam angle."""
    best, at = np.inf, 0.0
    for i, p in enumerate(program.phases):
        u = np.linspace(0, 1, grid + 1)
        v = fun(i, u)
        k = int(np.argmin(v))
        bu, bv = float(u[k]), float(v[k])
        if p.kind != "dwell":
            res = minimize_scalar(lambda x: float(fun(i, np.array([x]))[0]), method="bounded",
                                  bounds=(u[max(k - 1, 0)], u[min(k + 1, grid)]), options={"xatol": 1e-13})
            if res.fun < bv:
                bu, bv = float(res.x), float(res.fun)
        if bv < best:
            best, at = bv, float(program.starts[i] + bu * p.angle)
    return best, at


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


# -- translating -------------------------------------------------------------------------------


def _translating_rho(program: Program, R0: float):
    def rho(i, u):
        m = program.evaluate_phase(i, u)
        return R0 + m.s + m.d2s
    return rho


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
        point's x in the follower frame (the axis at x = 0).

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
    lo, at = _phase_min(_translating_rho(program, R0), program)
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
    """
    rmin = _check_length("min_radius", min_radius, positive=False)
    v, at = _phase_min(_translating_rho(program, 0.0), program)
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

    def rho_of(i, u):
        _, _, _, t1, t2, q, q1, q2 = _oscillating_terms(program, L, f, rise_sense, eps, a0, phase=i, u=u)
        return _rho(t1, t2, q, q1, q2)

    lo, at = _phase_min(rho_of, program)
    return FlatFaceProfile(phi, X, rho, contact, gamma, R0, lo, at)


def min_base_radius_oscillating(program: Program, *, centre_distance: float, face_offset: float = 0.0,
                                rise_sense: int = -1, cam_sense: int = 1, min_radius: float = 0.0,
                                scan: int = 200) -> tuple[float, float]:
    """Smallest R0 of an oscillating flat-faced follower's cam with ``rho >= min_radius``.

    R0 ranges over ``(0, f + L cos(swing))`` (beyond, the face would turn past
    the line of centres); the smallest radius of curvature is scanned over
    ``scan`` values of R0 and the first admissible one refined by root finding.

    Returns
    -------
    R0 : float
        Length.
    at : float
        Cam angle (radians) of the binding position.

    Raises
    ------
    InputError
        No R0 in the range gives a convex enough profile.
    """
    L = _check_length("centre_distance", centre_distance)
    f = _check_length("face_offset", face_offset, positive=False)
    rmin = _check_length("min_radius", min_radius, positive=False)
    hi = f + L * np.cos(program.lift)
    lo = max(f - L, 0.0)
    if hi <= lo:
        raise InputError("centre_distance", f"L = {L:g} is too short for a swing of {np.degrees(program.lift):g} degrees")

    def margin(R0):
        cam = oscillating_flat_face(program, centre_distance=L, base_radius=R0, face_offset=f,
                                    rise_sense=rise_sense, cam_sense=cam_sense, samples=64)
        return cam.min_rho - rmin, cam.min_rho_at

    grid = lo + (hi - lo) * (np.arange(1, scan + 1) / (scan + 1))
    prev = None
    for R0 in grid:
        g, at = margin(R0)
        if g >= 0:
            if prev is None:
                return float(R0), at
            R = brentq(lambda x: margin(x)[0], prev, R0, xtol=1e-12 * L)
            return float(R), margin(R)[1]
        prev = R0
    raise InputError("min_radius", f"no base radius below {hi:.6g} gives a radius of curvature >= {rmin:g}")
