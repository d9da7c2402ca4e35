"""A flat-faced follower's cam, sampled: the working profile (the envelope of the face lines).

The envelope, its radius of curvature and the contact on the face are
:mod:`cams.kinematics.flat`'s (frames and signs there); this module samples
them: :func:`translating_flat_face` and :func:`oscillating_flat_face` at a
given base radius, :func:`flat_face_cam` for a design, and
:func:`flat_face_profile` within a chord tolerance (what the files export).

Design files
------------
``[follower] face = "flat"`` makes :func:`cams.io.designfile.design_from_dict`
return a :class:`cams.model.design.FlatFaceDesign` (followers
:class:`cams.model.follower.FlatTranslating`, :class:`cams.model.follower.FlatRocker`);
:func:`optimize.flat.size_flat_face` sizes it (base radius, face travel,
pressure angle: :class:`optimize.flat.FlatFaceSolution`),
:func:`flat_face_profile` samples the cam within a chord tolerance and
:func:`cams.checks.flat.check_flat_face` checks it. Contact positions on a
rocker's face are measured from the pivot's foot, positive towards the cam,
everywhere.

The names this module held before the split by stage (the followers, the
sizing, the checks) are still importable from here for one release, with a
:class:`DeprecationWarning` naming their new home.

Angles in radians, lengths in the design's unit (mm).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from cams.kinematics.flat import (
    check_cam_sense,
    envelope,
    oscillating_contact,
    oscillating_cusps,
    oscillating_parts,
    oscillating_pressure,
    oscillating_setup,
    oscillating_terms,
    phase_minimum,
    translating_cusps,
    translating_parts,
)
from cams.model.design import FlatFaceDesign
from cams.model.follower import FlatRocker, FlatTranslating, check_length
from laws.errors import InputError
from laws.program import Program

if TYPE_CHECKING:  # the design's module imports this one's followers
    from cams.model.design import FlatFaceDesign

__all__ = [
    "FlatFaceProfile",
    "translating_flat_face",
    "oscillating_flat_face",
    "flat_face_cam",
    "flat_face_profile",
    "MIN_SAMPLES",
    "MAX_SAMPLES",
]

@dataclass(frozen=True, eq=False)
class FlatFaceProfile:
    """A flat-faced follower's cam, sampled.

    Attributes
    ----------
    phi : ndarray, shape (n,)
        Cam angles, radians (the phase starts among them).
    point : ndarray, shape (n, 2)
        Cam profile (envelope of the face lines), cam frame, length unit: origin
        at the cam centre, axes parallel at ``phi = 0`` to the translating
        follower's fixed frame, or to a rocker's line-of-centres frame
        (:mod:`cams.model.follower`).
    rho : ndarray, shape (n,)
        Radius of curvature of the profile, positive convex.
    contact : ndarray, shape (n,)
        Contact point's position along the face, length: from the follower's
        axis (translating, +X positive) or from the foot of the perpendicular
        from the pivot (oscillating, positive towards the cam: the same sign
        as :attr:`optimize.flat.FlatFaceSolution.face_range`).
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

    # the attributes the exports (cams.manufacture) read (a flat face has no pitch curve and no groove)
    pitch = None
    outer = None
    roller_radius = 0.0
    groove = False

    def __len__(self) -> int:
        return len(self.phi)

    @property
    def work(self) -> np.ndarray:
        """The cam profile (``point``), under the name :mod:`cams.manufacture` uses."""
        return self.point

    @property
    def R0(self) -> float:
        """The base radius (``base_radius``), under the name :mod:`cams.manufacture` uses."""
        return self.base_radius

    @property
    def min_work_radius(self) -> float:
        """The profile's smallest distance from the cam centre (length), exactly: R0.

        The face's distance from the centre, the support function ``p``, grows with the lift (``R0 + s`` for a
        translating face; ``f - L cos a`` with ``a`` turning away from the line of centres for a rocker), so it is
        smallest at the near dwell, ``p = R0``; and the profile's nearest point to the centre is where ``p`` is
        smallest, at distance ``p`` (:func:`cams.kinematics.flat.flat_radii`). Not the sampled polyline's.
        """
        return float(self.base_radius)

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



def translating_flat_face(program: Program, *, base_radius: float, cam_sense: int = 1, offset: float = 0.0,
                          samples: int = 1440, phi: np.ndarray | None = None) -> FlatFaceProfile:
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
    phi : ndarray, optional
        The cam angles (radians) to evaluate at instead of ``samples``' (at a phase joint the later phase's).

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
    R0 = check_length("base_radius", base_radius)
    eps = check_cam_sense(cam_sense)
    e = check_length("follower.offset", offset, positive=False)
    phi = _grid(program, samples) if phi is None else np.asarray(phi, dtype=float)
    m = program.evaluate(phi)
    theta = np.pi / 2 - eps * phi
    X, rho, p_t = envelope(theta, np.full_like(phi, -eps), np.zeros_like(phi), R0 + m.s, m.ds, m.d2s)
    contact = -e - p_t  # fixed-frame x of the contact: O_x + p_theta * (J m)_x, J m = (-1, 0)
    lo, at = phase_minimum(translating_parts(program, R0)[0], program)
    cusps = translating_cusps(program, eps)
    if cusps:
        lo, at = -np.inf, cusps[0][0]
    return FlatFaceProfile(phi, X, rho, contact, np.zeros_like(phi), R0, lo, at)



def oscillating_flat_face(program: Program, *, centre_distance: float, base_radius: float, face_offset: float = 0.0,
                          rise_sense: int = -1, cam_sense: int = 1, samples: int = 1440,
                          phi: np.ndarray | None = None) -> FlatFaceProfile:
    """Cam of an oscillating (rocker) flat-faced follower.

    Parameters
    ----------
    program : Program
        Lift is the swing (radians).
    centre_distance : float
        L, pivot to cam centre (length); the cam centre is at ``(L, 0)`` in the
        line-of-centres frame (:func:`cams.kinematics.flat.rocker_frame_turn`).
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
    phi : ndarray, optional
        The cam angles (radians) to evaluate at instead of ``samples``' (at a phase joint the later phase's).

    Returns
    -------
    FlatFaceProfile
        ``contact`` measured from the pivot's foot on the face, positive
        towards the cam (along ``-rise_sense J m``).
        A velocity jump that gives a cusp makes ``min_rho = -inf``.

    Raises
    ------
    InputError
        Non-positive lengths; a base circle the face cannot touch; a face that
        would turn past the line of centres; a face turning with the cam.
    """
    L = check_length("centre_distance", centre_distance)
    R0 = check_length("base_radius", base_radius)
    f = check_length("face_offset", face_offset, positive=False)
    eps = check_cam_sense(cam_sense)
    a0 = oscillating_setup(program, L, R0, f, rise_sense)
    phi = _grid(program, samples) if phi is None else np.asarray(phi, dtype=float)
    phi, a, theta, dth, d2th, p, dp, d2p = oscillating_terms(program, L, f, rise_sense, eps, a0, phi=phi)
    X, rho, p_t = envelope(theta, dth, d2th, p, dp, d2p)
    contact = oscillating_contact(L, rise_sense, a, p_t)
    gamma = oscillating_pressure(f, contact)
    lo, at = phase_minimum(oscillating_parts(program, L, f, rise_sense, eps, a0)[0], program)
    cusps = oscillating_cusps(program, L, rise_sense, eps, a0)
    if cusps:
        lo, at = -np.inf, cusps[0][0]
    return FlatFaceProfile(phi, X, rho, contact, gamma, R0, lo, at)



def flat_face_cam(design: FlatFaceDesign, base_radius: float, *, samples: int = 1440,
                  phi: np.ndarray | None = None) -> FlatFaceProfile:
    """The sampled cam of a flat-face design (:class:`cams.model.design.FlatFaceDesign`) at a base radius (at the
    cam angles ``phi``, radians, when given)."""
    fo = design.follower
    if isinstance(fo, FlatTranslating):
        cam = translating_flat_face(design.program, base_radius=base_radius, cam_sense=design.cam_sense,
                                    offset=fo.offset, samples=samples, phi=phi)
    else:
        cam = oscillating_flat_face(design.program, centre_distance=fo.centre_distance, base_radius=base_radius,
                                    face_offset=fo.face_offset, rise_sense=fo.sense, cam_sense=design.cam_sense,
                                    samples=samples, phi=phi)
    return replace(cam, name=design.name)


#: Fewest samples per turn of an exported flat-face profile, and the most.
MIN_SAMPLES, MAX_SAMPLES = 360, 2_000_000


def flat_face_profile(design: FlatFaceDesign, base_radius: float, *, tolerance: float | None = None,
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
    if isinstance(design.follower, FlatRocker):
        dtheta = np.abs(design.follower.sense * design.program.evaluate(coarse.phi).ds - design.cam_sense)
    worst = float(np.max(np.abs(coarse.rho) * dtheta**2))
    n = int(np.ceil(2 * np.pi * np.sqrt(worst / (8 * tolerance))))
    if n > MAX_SAMPLES:
        raise InputError(field, f"a chord tolerance of {tolerance:g} needs {n:.3g} points a turn, more than "
                         f"{MAX_SAMPLES}; use a larger tolerance")
    return replace(flat_face_cam(design, base_radius, samples=max(n, MIN_SAMPLES)), tolerance=float(tolerance))

