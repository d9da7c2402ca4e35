"""Forces at a force-closed flat-faced follower: contact force, sliding friction, camshaft torque, jump speed.

The roller's model (:mod:`cams.dynamics.forces`) with the flat face's contact: the follower is one rigid body with
one coordinate ``q`` (the swing ``psi`` of a rocker, rad, or the lift ``s`` of a translating follower, m, from the
near dwell); the cam turns at a constant speed ``omega`` (rad/s); the spring ``F0 + k q``, the load ``P`` and the
inertia ``m q''`` are the roller's (:mod:`cams.dynamics.forces`), and so is the closing spring's choice
(:func:`cams.dynamics.forces.chosen_spring`: kinematic, the same for every face) and the jump speed
(:func:`cams.dynamics.jump.jump_speed`: contact is lost where ``m q'' + F0 + k q + P`` turns negative, whatever
the face).

Contact geometry
----------------
The cam touches the face at the point ``X`` of the envelope (:mod:`cams.kinematics.flat`, frames there): on a
translating face at ``x = -e + eps s'`` from the follower's axis, on a rocker's face at ``c`` from the pivot's foot
(positive towards the cam). The cam pushes the face along the face's unit normal ``m`` (away from the cam): the
normal force ``N >= 0``. A flat face has no pressure-angle jamming: the normal's lever about a rocker's pivot is the
contact position ``c`` itself, a translating face's normal lies along its motion.

Friction (the sign conventions)
-------------------------------
* At the face: sliding (Coulomb) friction, dimensionless coefficient ``mu_f`` (``[dynamics] face_friction``). The
  cam's material point at ``X`` slides along the face, relative to it, at ``v_sl = (v_cam - v_face) . u`` (m/s;
  ``u`` the unit vector along the face in which contact positions grow, ``v_cam = eps omega J (X - O)``, ``O`` the
  cam centre, ``v_face`` the follower's material point at ``X``). The friction force on the follower is
  ``F_f = mu_f N sign(v_sl)`` along ``u`` (the cam drags the face the way it slides); ``-F_f`` acts on the cam.
  The power it dissipates, the sliding loss, is ``mu_f N |v_sl| >= 0``.
* In the guide (translating) or the pivot (rocker), coefficient ``mu`` (``[dynamics] friction``), opposing the
  motion ``sign(q')`` as for the roller: the guide takes the contact force's component across the axis, the face
  friction ``|F_f|``, and rubs ``mu |F_f|`` (the moment of the contact's offset along the face is taken by the
  guide without friction, as the roller's model takes no guide length); the pivot journal of radius ``r_j``
  carries the contact force ``N sqrt(1 + mu_f^2)`` (with ``F_f``; without sliding ``N``) and rubs
  ``mu r_j N sqrt(1 + mu_f^2)``.

Hence, along ``q`` (``G_N``: the normal force's generalized force per newton, 1 for a translating face, the lever
``c`` in m for a rocker; ``G_F``: the face friction's per newton, 0 for a translating face, ``-f`` in m for a rocker,
``f`` the face offset)::

    N = (m q'' + F0 + k q + P) / (G_N + sign(v_sl) mu_f G_F - sign(q') c_g)

with ``c_g = mu mu_f |sign(v_sl)|`` (translating) or ``mu r_j sqrt(1 + mu_f^2 sign(v_sl)^2)`` (rocker). The
denominator stays positive for every sensible friction; where it does not the follower locks, and the design is
refused (:class:`laws.errors.InputError` naming the friction).

Camshaft torque
---------------
``T`` (N m, positive: the shaft drives the cam in its sense of rotation ``eps``) is the moment about the cam
centre of the follower's push on the cam: ``T = eps (X - O) x (N m + F_f u)``; by the power balance
``T omega = N-and-F_f's power on the follower + mu_f N |v_sl|`` (the follower's power ``G q'`` plus the sliding
loss), which the tests check on the sampled profile.

Units: the design's lengths in mm (``length_unit`` m each), forces in N (N m for a rocker's generalized forces),
speeds in m/s, powers in W, angles in radians.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from cams.dynamics.forces import CamForces, DesignForces, chosen_spring
from cams.dynamics.impacts import rigid_impacts
from cams.dynamics.jump import jump_speed
from cams.dynamics.motion import cam_speed, dynamics_grid, follower_kinematics, si_per_unit
from cams.kinematics.flat import (
    oscillating_contact,
    oscillating_pressure,
    oscillating_setup,
    oscillating_terms,
    rocker_frame_turn,
)
from cams.kinematics.vectors import cross
from cams.model.design import FlatFaceDesign
from cams.model.dynamics import FollowerDynamics
from cams.model.follower import FlatTranslating
from laws.errors import InputError
from laws.units import turn_degrees

__all__ = ["FlatContact", "flat_contact", "FlatCamForces", "flat_cam_forces", "flat_design_forces"]


def _perp(v: np.ndarray) -> np.ndarray:
    """``J v``: the vectors ``v`` (shape ``(..., 2)``) turned counter-clockwise by 90 degrees."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


@dataclass(frozen=True, eq=False)
class FlatContact:
    """Where and how the cam touches a flat face, at cam angles, in one fixed frame (design length unit).

    The frame is the translating follower's (:mod:`cams.model.follower`) or a rocker's line-of-centres frame (pivot
    at the origin, the cam centre at ``(L, 0)``: :func:`cams.kinematics.flat.rocker_frame_turn`).

    Attributes
    ----------
    point : ndarray, shape (n, 2)
        The contact point ``X``.
    normal : ndarray, shape (n, 2)
        The face's unit normal ``m``, away from the cam: the direction of the cam's push on the follower.
    along : ndarray, shape (n, 2)
        The unit vector ``u`` along the face in which contact positions grow.
    lever : ndarray, shape (n, 2)
        ``dX/ds`` of the follower's material point at ``X`` per unit of the program's coordinate ``s`` (length per
        length for a translating face, length per radian for a rocker).
    position : ndarray, shape (n,)
        The contact's position on the face (length): from the follower's axis, or from the pivot's foot, positive
        towards the cam (:mod:`cams.kinematics.flat`).
    gamma : ndarray, shape (n,)
        The face's pressure angle (radians): 0 for a translating face, ``atan(|f| / |c|)`` for a rocker's.
    centre : ndarray, shape (2,)
        The cam centre ``O``.
    ds : ndarray, shape (n,)
        ``s'``, the program's rate per radian of cam angle (length or radians per radian).
    frame_turn : float
        Angle (radians) that turns a vector of this frame into the follower's fixed frame (0 for a translating
        face; ``-beta`` for a rocker, :func:`cams.kinematics.flat.rocker_frame_turn`).
    """

    point: np.ndarray
    normal: np.ndarray
    along: np.ndarray
    lever: np.ndarray
    position: np.ndarray
    gamma: np.ndarray
    centre: np.ndarray
    ds: np.ndarray
    frame_turn: float

    def sliding_per_radian(self, cam_sense: int) -> np.ndarray:
        """The cam's velocity relative to the face at the contact, along ``u``, per radian of cam angle
        (length/rad): ``(eps J (X - O) - (dX/ds) s') . u``."""
        v_cam = cam_sense * _perp(self.point - self.centre)
        v_face = self.lever * self.ds[:, None]
        return np.sum((v_cam - v_face) * self.along, axis=-1)


def flat_contact(design: FlatFaceDesign, R0: float, phi: np.ndarray) -> FlatContact:
    """The contact of the cam of base radius ``R0`` (length) on the flat face at cam angles ``phi`` (radians).

    From the envelope's kinematics (:mod:`cams.kinematics.flat`): a translating face (the cam centre at
    ``(-e, -R0)``, the face the line ``y = s``) touches at ``(-e + eps s', s)``; a rocker's face, whose normal
    has the angle ``a`` in the line-of-centres frame, at ``f m + c u`` with ``u = -sigma J m`` and ``c`` the contact
    position (:func:`cams.kinematics.flat.oscillating_contact`).
    """
    fo, prog, eps = design.follower, design.program, design.cam_sense
    phi = np.asarray(phi, dtype=float)
    if isinstance(fo, FlatTranslating):
        mo = prog.evaluate(phi)
        e = float(fo.offset)
        x = -e + eps * mo.ds
        point = np.stack([x, mo.s], axis=-1)
        ones, zeros = np.ones_like(phi), np.zeros_like(phi)
        normal = np.stack([zeros, ones], axis=-1)
        return FlatContact(
            point=point,
            normal=normal,
            along=np.stack([ones, zeros], axis=-1),
            lever=normal.copy(),
            position=x,
            gamma=zeros,
            centre=np.array([-e, -float(R0)]),
            ds=mo.ds,
            frame_turn=0.0,
        )
    L, f, sigma = float(fo.centre_distance), float(fo.face_offset), fo.sense
    a0 = oscillating_setup(prog, L, float(R0), f, sigma)
    _, a, _, dth, _, _, dp, _ = oscillating_terms(prog, L, f, sigma, eps, a0, phi=phi)
    c = oscillating_contact(L, sigma, a, dp / dth)
    m = np.stack([np.cos(a), np.sin(a)], axis=-1)
    u = -sigma * _perp(m)
    point = f * m + c[:, None] * u
    return FlatContact(
        point=point,
        normal=m,
        along=u,
        lever=sigma * _perp(point),
        position=c,
        gamma=oscillating_pressure(f, c),
        centre=np.array([L, 0.0]),
        ds=prog.evaluate(phi).ds,
        frame_turn=-rocker_frame_turn(a0, sigma),
    )


@dataclass(frozen=True, eq=False)
class FlatCamForces(CamForces):
    """The forces of a flat-faced follower over one cam turn (:class:`cams.dynamics.forces.CamForces`'s fields).

    As the roller's, with: ``gamma`` the face's pressure angle; ``along`` and ``lateral`` the components of the
    cam's whole push (normal force and face friction) along and across the follower's contact point's direction of
    motion during the rise (N; a translating face's ``lateral`` is the face friction, what its guide takes);
    ``force`` that push in the follower's fixed frame; ``friction`` the guide's or pivot's; ``jammed`` all False and
    ``gamma_limit`` NaN: a flat face has no pressure-angle jamming (the JSON says null).

    Attributes
    ----------
    sliding : ndarray
        The cam's velocity relative to the face at the contact, along the face (m/s; positive in the direction
        contact positions grow).
    face_force : ndarray
        The face's sliding friction on the follower along the face, ``mu_f N sign(sliding)`` (N).
    position : ndarray
        The contact's position on the face (mm), as :class:`FlatContact`.
    """

    sliding: np.ndarray = field(default_factory=lambda: np.zeros(0))
    face_force: np.ndarray = field(default_factory=lambda: np.zeros(0))
    position: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @property
    def sliding_loss(self) -> np.ndarray:
        """The power lost to sliding at the face, ``|F_f v_sl| = mu_f N |v_sl|`` (W, >= 0)."""
        return np.abs(self.face_force * self.sliding)

    def to_dict(self) -> dict:
        """:meth:`CamForces.to_dict`'s keys, ``jammed`` and ``jamming_limit_deg`` None (no pressure-angle jamming),
        and ``max_sliding_speed`` (m/s, the largest ``|v_sl|``) and ``mean_sliding_loss`` (W, the sliding loss's
        mean over the turn; None with rigid impacts, whose work is not in the samples)."""
        out: dict[str, Any] = super().to_dict()
        finite = np.isfinite(self.contact)
        out["jammed"] = None
        out["jamming_limit_deg"] = None
        out["max_sliding_speed"] = float(np.max(np.abs(self.sliding)))
        out["mean_sliding_loss"] = float(np.mean(self.sliding_loss[finite])) if not self.impacts else None
        return out


def _lock_error(dyn: FollowerDynamics, phi: float) -> InputError:
    """The error of a follower the friction locks (the push's generalized force, less the guide's or pivot's
    friction, <= 0) at cam angle ``phi`` (radians)."""
    field = "dynamics.face_friction" if dyn.face_friction > 0 else "dynamics.friction"
    return InputError(
        field,
        f"the follower locks at cam angle {turn_degrees(phi):.4g} deg: with friction "
        f"{dyn.friction:g} and face_friction {dyn.face_friction:g} the friction outweighs the cam's push along "
        "the follower's motion; lower the friction",
    )


def flat_cam_forces(
    design: FlatFaceDesign, R0: float, dyn: FollowerDynamics, *, rpm: float | None = None, samples: int = 720, phi=None
) -> FlatCamForces:
    """Contact force, face friction and camshaft torque of a flat-faced follower over one cam turn.

    Parameters
    ----------
    design : FlatFaceDesign
    R0 : float
        The cam's base radius (the sized one, :attr:`cams.faces.result.SolveResult.R0`), length.
    dyn : FollowerDynamics
        With its ``spring`` set; ``face_friction`` the face's sliding friction.
    rpm : float, optional
        Cam speed, rev/min; default ``design.rpm``.
    samples : int
        Cam angles per turn (ignored with ``phi``).
    phi : array_like, optional
        Cam angles (radians) at which to evaluate instead.

    Returns
    -------
    FlatCamForces
        ``ok`` is False where contact would be lost or at a rigid impact.

    Raises
    ------
    InputError
        No spring; friction that locks the follower (see the module).
    """
    if dyn.spring is None:
        raise InputError("dynamics.spring_rate", "the forces need a spring; design one with spring_for_contact")
    w = cam_speed(design, rpm)
    phi = dynamics_grid(samples) if phi is None else np.asarray(phi, dtype=float)
    eps = design.cam_sense
    lu = dyn.length_unit
    rocker = design.follower.kind == "rocker"
    q, dq, d2q, _ = follower_kinematics(design, phi, dyn)
    k = flat_contact(design, R0, phi)
    per_q = lu / si_per_unit(design, dyn)  # metres of the material point per design unit, per unit of q
    g_n = np.sum(k.normal * k.lever, axis=-1) * per_q
    g_f = np.sum(k.along * k.lever, axis=-1) * per_q
    w_sl = k.sliding_per_radian(eps)
    scale = max(float(np.max(np.abs(k.point - k.centre))), 1e-300)
    s_sl = np.sign(np.where(np.abs(w_sl) > 1e-12 * scale, w_sl, 0.0))
    mu, mu_f = dyn.friction, dyn.face_friction
    if rocker:
        c_g = mu * dyn.journal_radius * lu * np.sqrt(1.0 + (mu_f * s_sl) ** 2)
    else:
        c_g = mu * mu_f * np.abs(s_sl)
    mo_ds = design.program.evaluate(phi).ds
    sgn = np.sign(np.where(np.abs(mo_ds) > 1e-12 * max(design.program.lift, 1.0), mo_ds, 0.0))
    denom = g_n + s_sl * mu_f * g_f - sgn * c_g
    need = dyn.mass * w**2 * d2q + dyn.spring.force(q) + dyn.load
    tiny = 1e-12 * (np.max(np.abs(g_n)) or 1.0)
    locked = (denom <= tiny) & (need > 0)
    if np.any(locked):
        raise _lock_error(dyn, float(phi[int(np.argmax(locked))]))
    N = need / np.maximum(denom, tiny)
    F_f = mu_f * N * s_sl
    push = N[:, None] * k.normal + F_f[:, None] * k.along
    torque = eps * cross(k.point - k.centre, push) * lu
    direction = k.lever / np.linalg.norm(k.lever, axis=-1, keepdims=True)
    along = np.sum(push * direction, axis=-1)
    lateral = np.abs(cross(direction, push))
    turn = np.exp(1j * k.frame_turn)
    return FlatCamForces(
        phi=phi,
        omega=w,
        q=q,
        dq=w * dq,
        d2q=w**2 * d2q,
        gamma=k.gamma,
        contact=N,
        along=along,
        lateral=lateral,
        force=(push[:, 0] + 1j * push[:, 1]) * turn,
        torque=torque,
        spring=dyn.spring.force(q),
        inertia=dyn.mass * w**2 * d2q,
        friction=-sgn * c_g * N,
        amplification=1.0 / np.maximum(denom, tiny),
        jammed=np.zeros(phi.shape, dtype=bool),
        gamma_limit=float("nan"),
        impacts=rigid_impacts(design),
        length_unit=lu,
        sliding=w * w_sl * lu,
        face_force=F_f,
        position=k.position,
    )


def flat_design_forces(design: FlatFaceDesign, R0: float) -> tuple[DesignForces | None, str | None]:
    """Spring, forces and jump speed of a flat-faced follower's design with ``[dynamics]``, or why there are none.

    The spring is :func:`cams.dynamics.forces.chosen_spring`'s (the given one, or the one that keeps contact with
    the margin at the design's speed), the jump speed :func:`cams.dynamics.jump.jump_speed`'s; ``R0`` is the sized
    cam's base radius (length). A flat face is always force-closed.

    Returns
    -------
    (DesignForces or None, note or None)
        ``None`` without ``[dynamics]``; ``None`` with a note without a cam speed.
    """
    spec = design.dynamics
    if spec is None:
        return None, None
    if not design.rpm:
        return None, "[dynamics] needs cam.rpm for the forces"
    spring = chosen_spring(spec, design)
    dyn = spec.dynamics.with_spring(spring)
    return DesignForces(spring, flat_cam_forces(design, R0, dyn), jump_speed(design, dyn)), None
