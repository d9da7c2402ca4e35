"""Forces at a force-closed cam: contact force, camshaft torque, the closing spring and the jump speed.

Model
-----
The follower is one rigid body with one coordinate ``q``: the swing ``psi``
(rad) of a rocker or the lift ``s`` (m) of a translating follower, from the
near dwell (:mod:`cams.model.follower`). The cam turns at a constant speed
``omega`` (rad/s), so ``q' = omega dq/dphi`` and ``q'' = omega^2 d2q/dphi^2``
(``phi``: cam angle of :mod:`laws.program`). Acting on the follower, in the
sense of ``q`` (the rise):

* the contact force ``N >= 0`` of the cam on the roller, along the pitch
  curve's outward normal ``n`` (the roller turns freely: no tangential force),
  whose generalized force is ``N |dA/dq| cos(gamma)``; ``gamma`` is the pressure
  angle (angle between ``n`` and the roller centre's direction of motion
  during the rise; ``n`` and ``gamma`` are the kernel's,
  :mod:`cams.kinematics.inversion`), ``|dA/dq|`` the arm (m) of a rocker or 1
  for a translating follower;
* the closing spring ``-(F0 + k q)``: preload ``F0`` at the near dwell and rate
  ``k`` (N and N/m, or N m and N m/rad for a rocker's torsional spring);
* a constant external load ``-P`` (N or N m) opposing the rise (a weight, a
  working resistance); a negative ``P`` pulls the follower away from the cam;
* friction proportional to the contact force, opposing the motion:
  ``-sign(q') c N`` with ``c = mu sin(gamma)`` for a translating follower (the
  guide takes the lateral force ``N sin(gamma)``; coefficient ``mu``) and
  ``c = mu r_j`` for a rocker (pivot journal of radius ``r_j`` carrying about
  ``N``); none in dwells;
* the inertia force ``-m q''`` (``m``: reduced mass, kg, or the rocker's moment
  of inertia about its pivot, kg m^2; include a third of the spring's mass).

Hence the contact force::

    N = (m q'' + F0 + k q + P) / (|dA/dq| cos(gamma) - sign(q') c)

Contact holds while the numerator is positive (the denominator stays positive
outside jamming). During the rise the denominator falls to 0 at the
friction-dependent limit ``gamma_lim`` (``tan gamma_lim = 1 / mu`` for a
translating follower, ``cos gamma_lim = mu r_j / l`` for a rocker): ``N``
grows without bound as ``gamma`` approaches it and beyond it the cam cannot
drive at all -- jamming (заклинивание) in force terms
(:func:`jamming_limit`, :attr:`CamForces.amplification`).

The camshaft torque (N m, positive: the shaft drives the cam in its sense of
rotation) is the moment of the roller's force on the cam about the cam's
centre, ``T = eps N (r x n)`` (``r`` from the cam centre to the roller
centre); by the power balance it equals ``N |dA/dq| cos(gamma) dq/dphi``.

Rigid impacts (velocity jumps of the program) are described in :mod:`cams.dynamics.impacts`;
the jump speed is :mod:`cams.dynamics.jump`'s.

Units: the design's lengths are in mm, the files' only length unit
(``length_unit``: metres per design unit, 1e-3); forces in N, masses in kg,
time in s.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from cams.dynamics.impacts import rigid_impacts
from cams.dynamics.jump import JumpSpeed, jump_dict, jump_speed
from cams.dynamics.motion import cam_speed, dynamics_grid, follower_kinematics, si_per_unit
from cams.kinematics.inversion import contact_normal, invert, pressure_angle
from cams.kinematics.vectors import cross
from cams.model.design import CamDesign, Design
from cams.model.dynamics import DynamicsSpec, FollowerDynamics, Spring
from cams.model.follower import Rocker
from laws.errors import InputError
from laws.errors import check_number as _num
from laws.units import omega_to_rpm

__all__ = [
    "impact_note",
    "json_safe",
    "CamForces",
    "cam_forces",
    "spring_for_contact",
    "jamming_limit",
    "chosen_spring",
    "DesignForces",
    "design_forces",
]

"""Keys of a design file's optional ``[dynamics]`` table."""


def impact_note(forces: CamForces) -> str | None:
    """One line on the rigid impacts of a :class:`CamForces` for a report's notes; None without any."""
    if not forces.impacts:
        return None
    parts = []
    for i in forces.impacts:
        what = "contact force unbounded" if not i.separation else "the follower leaves the cam at any speed"
        jump = i.shown_jump(forces.omega, forces.length_unit)
        parts.append(f"{np.degrees(i.phi):.2f} deg ({jump:+.4g} {i.unit}: {what})")
    return ("rigid impacts (velocity jumps, infinite acceleration) at cam angle " + ", ".join(parts)
            + "; the forces and the jump speed are unbounded or lost there, the other figures are between the "
            "impacts; use a law without velocity jumps (e.g. cycloidal, modified trapezoid)")


def json_safe(obj):
    """``obj`` with every non-finite float (an unbounded force, ``inf``) as None, for strict JSON."""
    if isinstance(obj, dict):
        return {k: json_safe(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [json_safe(v) for v in obj]
    if isinstance(obj, float) and not np.isfinite(obj):
        return None
    return obj


def jamming_limit(design: CamDesign, dyn: FollowerDynamics) -> float:
    """Pressure angle (radians) at which the rise jams: the contact force needed grows without bound.

    ``arctan(1 / mu)`` for a translating follower, ``arccos(mu r_j / l)`` for
    a rocker; pi/2 without friction.

    Examples
    --------
    >>> from cams.model.design import CamDesign, Limits
    >>> from cams.model.follower import Translating
    >>> from laws.program import Phase, Program
    >>> prog = Program((Phase("rise", np.pi, "cycloidal"), Phase("return", np.pi, "cycloidal")), 20.0)
    >>> d = CamDesign(Translating(5.0, offset=0.0), prog, Limits(np.radians(30)))
    >>> round(float(np.degrees(jamming_limit(d, FollowerDynamics(0.5, friction=0.2)))), 4)
    78.6901
    """
    mu = dyn.friction
    if isinstance(design.follower, Rocker):
        ratio = mu * dyn.journal_radius / design.follower.arm
        if ratio >= 1:
            return 0.0
        return float(np.arccos(ratio))
    return float(np.arctan2(1.0, mu))


@dataclass(frozen=True, eq=False)
class CamForces:
    """Forces over one cam turn.

    Attributes
    ----------
    phi : ndarray
        Cam angle, radians from the program's start, in the cam's sense.
    omega : float
        Cam speed, rad/s.
    q, dq, d2q : ndarray
        Follower coordinate (m or rad) and its derivatives in time (per s, s^2).
    gamma : ndarray
        Pressure angle, radians in [0, pi).
    contact : ndarray
        Contact force N, N (negative where contact would be lost; inf where jammed).
    along, lateral : ndarray
        Its components along the roller centre's direction of motion during the
        rise (``N cos gamma``) and across it (``N sin gamma``), N.
    force : ndarray of complex
        The cam's force on the roller in the follower's fixed frame
        (:mod:`cams.model.follower`), ``Fx + i Fy``, N.
    torque : ndarray
        Camshaft torque, N m (positive: the shaft drives).
    spring, inertia : ndarray
        Spring force F0 + k q and the inertia term m q'' (N or N m).
    friction : ndarray
        Friction force or moment on the follower, opposing its motion (N or N m).
    amplification : ndarray
        ``1 / (|dA/dq| cos(gamma) - sign(q') c)``: contact force per unit of
        the force the follower needs (1/m for a rocker); inf where jammed.
    jammed : ndarray of bool
        The cam cannot drive: the denominator is <= 0 during a rise.
    gamma_limit : float
        :func:`jamming_limit`, radians.
    impacts : tuple of RigidImpact
        The program's velocity jumps: the arrays above hold the forces between
        them; at them the force is unbounded (see the module).
    length_unit : float
        Metres per design length unit (for the impacts' velocity jumps).
    """

    phi: np.ndarray
    omega: float
    q: np.ndarray
    dq: np.ndarray
    d2q: np.ndarray
    gamma: np.ndarray
    contact: np.ndarray
    along: np.ndarray
    lateral: np.ndarray
    force: np.ndarray
    torque: np.ndarray
    spring: np.ndarray
    inertia: np.ndarray
    friction: np.ndarray
    amplification: np.ndarray
    jammed: np.ndarray
    gamma_limit: float
    impacts: tuple = ()
    length_unit: float = 1e-3

    @property
    def lost(self) -> np.ndarray:
        """True where the contact force would be negative (the follower leaves the cam), at the samples."""
        return self.contact < 0

    @property
    def unbounded(self) -> bool:
        """A velocity jump up somewhere: the contact force (an impulse) is unbounded there."""
        return any(not i.separation for i in self.impacts)

    @property
    def separation(self) -> bool:
        """A velocity jump down somewhere: the follower leaves the cam there at any speed."""
        return any(i.separation for i in self.impacts)

    @property
    def contact_lost(self) -> bool:
        """Contact lost at a sample or at a velocity jump down."""
        return bool(np.any(self.lost)) or self.separation

    @property
    def ok(self) -> bool:
        """Contact everywhere, no jamming and no rigid impact (bounded forces)."""
        return not (self.contact_lost or np.any(self.jammed) or self.impacts)

    @property
    def rpm(self) -> float:
        """Cam speed, rev/min."""
        return omega_to_rpm(self.omega)

    def _driving_braking(self) -> tuple[tuple[float, float | None], tuple[float, float | None]]:
        """((largest driving torque, its cam angle in degrees), (largest braking torque, its angle)), sampled.

        Driving: ``torque > 0`` (the camshaft delivers work); braking: ``torque < 0``, given as the most
        negative value. 0 and None when the torque never has that sign.
        """
        t = np.where(np.isfinite(self.torque), self.torque, 0.0)
        kd, kb = int(np.argmax(t)), int(np.argmin(t))
        drive = (float(t[kd]), float(np.degrees(self.phi[kd]))) if t[kd] > 0 else (0.0, None)
        brake = (float(t[kb]), float(np.degrees(self.phi[kb]))) if t[kb] < 0 else (0.0, None)
        return drive, brake

    def _speeds_up(self, at: float) -> bool:
        """At a velocity jump up at cam angle ``at`` (rad): True when the follower's speed grows across it.

        The cam's impulse does the work ``m (v+^2 - v-^2) / 2``, positive (driving) when ``|v+| > |v-|``;
        ``v-`` and ``v+`` are the velocities at the nearest samples before and at or after ``at``.
        """
        d = np.angle(np.exp(1j * (self.phi - at)))
        before = np.where(d < 0, d, -np.inf)
        after = np.where(d >= -1e-12, d, np.inf)
        v0, v1 = self.dq[int(np.argmax(before))], self.dq[int(np.argmin(after))]
        return bool(abs(v1) >= abs(v0))

    def to_dict(self) -> dict:
        """JSON-ready extremes (N, N m, degrees).

        The camshaft torque is positive where it drives (the camshaft
        delivers work, a torque in the cam's sense of rotation) and negative
        where it brakes (the follower gives work back): ``max_torque`` is the
        largest absolute value with its sign, ``max_driving_torque`` the
        largest positive one (0 with ``max_driving_torque_at_deg`` None when
        there is none), ``max_braking_torque`` the most negative one (<= 0).

        With rigid impacts (:attr:`impacts`) the extremes are the true ones:
        ``max_contact_force`` (and ``max_torque``, and ``max_lateral_force``)
        ``inf`` at the first velocity jump up, ``min_contact_force`` ``-inf``
        at a jump down, ``contact_lost`` True at a jump down; ``impacts`` lists
        them and ``between_impacts`` gives the sampled, finite extremes
        between them. Use :func:`json_safe` before strict JSON (``inf`` -> null).
        """
        finite = np.isfinite(self.contact)
        k = int(np.argmax(np.where(finite, self.contact, -np.inf)))
        kt = int(np.argmax(np.abs(self.torque)))
        drive, brake = self._driving_braking()
        out: dict[str, Any] = {
            "rpm": self.rpm,
            "max_contact_force": float(self.contact[k]),
            "max_contact_at_deg": float(np.degrees(self.phi[k])),
            "min_contact_force": float(np.min(self.contact[finite])) if np.any(finite) else None,
            "max_lateral_force": float(np.max(np.abs(self.lateral[finite]))) if np.any(finite) else None,
            "max_torque": float(self.torque[kt]),
            "max_torque_at_deg": float(np.degrees(self.phi[kt])),
            "max_driving_torque": drive[0],
            "max_driving_torque_at_deg": drive[1],
            "max_braking_torque": brake[0],
            "max_braking_torque_at_deg": brake[1],
            "mean_torque": float(np.mean(self.torque[finite])) if np.any(finite) else None,
            "contact_lost": self.contact_lost,
            "jammed": bool(np.any(self.jammed)),
            "jamming_limit_deg": float(np.degrees(self.gamma_limit)),
            "contact_force_unbounded": self.unbounded,
            "impacts": [i.to_dict(self.omega, self.length_unit) for i in self.impacts],
        }
        if self.impacts:
            keys = ("max_contact_force", "max_contact_at_deg", "min_contact_force", "max_lateral_force", "max_torque",
                    "max_torque_at_deg", "max_driving_torque", "max_driving_torque_at_deg", "max_braking_torque",
                    "max_braking_torque_at_deg", "mean_torque")
            out["between_impacts"] = {key: out[key] for key in keys}
            up = [i for i in self.impacts if not i.separation]
            down = [i for i in self.impacts if i.separation]
            if up:
                at = float(np.degrees(up[0].phi))
                out.update(max_contact_force=np.inf, max_contact_at_deg=at, max_lateral_force=np.inf,
                           max_torque=np.inf, max_torque_at_deg=at)
                for i in up:  # the impulse's work: driving where the follower gains kinetic energy, else braking
                    sign = "driving" if self._speeds_up(i.phi) else "braking"
                    if not np.isinf(out[f"max_{sign}_torque"]):
                        out[f"max_{sign}_torque"] = np.inf if sign == "driving" else -np.inf
                        out[f"max_{sign}_torque_at_deg"] = float(np.degrees(i.phi))
            if down:
                out["min_contact_force"] = -np.inf
            out["mean_torque"] = None  # the impacts' work is not in the samples
        return out


def cam_forces(
    design: CamDesign,
    centre,
    dyn: FollowerDynamics,
    *,
    rpm: float | None = None,
    samples: int = 720,
    phi=None,
) -> CamForces:
    """Contact force, its components and the camshaft torque over one cam turn.

    Parameters
    ----------
    design : CamDesign
    centre : array_like, shape (2,)
        Cam centre in the follower's fixed frame (``SolveResult.centre``),
        design length unit.
    dyn : FollowerDynamics
        With its ``spring`` set.
    rpm : float, optional
        Cam speed, rev/min; default ``design.rpm``.
    samples : int
        Cam angles per turn (ignored with ``phi``).
    phi : array_like, optional
        Cam angles (radians) at which to evaluate instead.

    Returns
    -------
    CamForces
        ``ok`` is False where the contact would be lost or the cam would jam;
        the caller decides (see :func:`spring_for_contact`).
    """
    if dyn.spring is None:
        raise InputError("dynamics.spring_rate", "the forces need a spring; design one with spring_for_contact")
    w = cam_speed(design, rpm)
    phi = dynamics_grid(samples) if phi is None else np.asarray(phi, dtype=float)
    f = design.follower
    mo = design.program.evaluate(phi)
    q, dq, d2q, arm = follower_kinematics(design, phi, dyn)
    inv = invert(design, centre, phi, mo)
    n = contact_normal(inv)
    gamma = pressure_angle(inv)
    cosg, sing = np.cos(gamma), np.sin(gamma)
    eps = design.cam_sense

    mu = dyn.friction
    c = mu * dyn.journal_radius * dyn.length_unit if isinstance(f, Rocker) else mu * sing
    sgn = np.sign(np.where(np.abs(mo.ds) > 1e-12 * max(design.program.lift, 1.0), mo.ds, 0.0))
    denom = arm * cosg - sgn * c
    need = dyn.mass * w**2 * d2q + dyn.spring.force(q) + dyn.load
    rising = sgn > 0
    jammed = rising & (denom <= 1e-12 * arm) & (need > 0)
    tiny = 1e-12 * arm
    with np.errstate(divide="ignore"):
        amp = np.where(denom > tiny, 1.0 / np.maximum(denom, tiny), np.inf)
    N = np.where(jammed, np.inf, need / np.maximum(denom, tiny))
    fric = -sgn * c * np.where(np.isfinite(N), N, 0.0)
    torque = eps * N * cross(inv.r, n) * dyn.length_unit
    force = N * (n[..., 0] + 1j * n[..., 1])
    return CamForces(
        phi=phi,
        omega=w,
        q=q,
        dq=w * dq,
        d2q=w**2 * d2q,
        gamma=gamma,
        contact=N,
        along=N * cosg,
        lateral=N * sing,
        force=force,
        torque=torque,
        spring=dyn.spring.force(q),
        inertia=dyn.mass * w**2 * d2q,
        friction=fric,
        amplification=amp,
        jammed=jammed,
        gamma_limit=jamming_limit(design, dyn),
        impacts=rigid_impacts(design),
        length_unit=dyn.length_unit,
    )


def spring_for_contact(
    design: Design,
    dyn: FollowerDynamics,
    *,
    rpm: float | None = None,
    margin: float = 1.2,
    rate: float | None = None,
    samples: int = 3600,
    min_installed: float | None = None,
    max_installed: float | None = None,
) -> Spring:
    """The closing spring that keeps the roller on the cam with a margin at a speed.

    Contact needs ``F0 + k q >= need = margin * (-m q'' - P)`` at every cam
    angle: the spring exceeds, by the factor ``margin``, the force that would
    pull the follower off the cam (its inertia in deceleration, less the load
    that presses it on). Friction does not enter: it changes the contact
    force's size, not its sign (see the module).

    The spring is one that can be bought: its installed compression
    ``d0 = F0 / k`` (a torsional spring's installed twist) lies within
    ``[min_installed, max_installed]``, by default between a quarter of the
    follower's travel ``h`` and ``h`` -- a preload of 20 % to 50 % of the
    spring's largest force ``F0 + k h``, as the SEED unit design guide
    *Cam Mechanisms* (section 15, "Force closure") advises for cam follower
    springs (``F0 / (F0 + k h) = d0 / (d0 + h)``). Without such a bound the
    least largest force is approached only by a constant-force spring
    (``k -> 0``, ``d0 -> infinity``), which nobody stocks.

    The chosen spring (no ``rate``)
    -------------------------------
    It minimizes the largest force ``F0 + k h`` over ``k >= 0`` and
    ``d0 in [lo, hi]`` subject to ``k (d0 + q_i) >= need_i`` at every sampled
    angle ``i`` -- a linear programme in ``(k, F0)``, since ``lo k <= F0 <=
    hi k`` is linear -- and among the springs of that least largest force it
    is the stiffest. Closed form:

    1. For a fixed ``d0`` (with ``d0 + q_i > 0``; ``q_i >= 0``) every
       constraint is a lower bound on ``k``, and the largest force
       ``k (d0 + h)`` grows with ``k``: the best rate is the least,
       ``k(d0) = max_i need_i / (d0 + q_i)``, and the largest force is
       ``F(d0) = max_i need_i (d0 + h) / (d0 + q_i)`` (over ``need_i > 0``).
    2. Each term ``need_i (1 + (h - q_i) / (d0 + q_i))`` with ``need_i > 0``
       does not increase with ``d0`` (``h >= q_i``), so neither does ``F``:
       its least value ``F* = F(hi)`` is taken at ``d0 = hi``.
    3. ``k(d0)`` does not increase with ``d0`` either, so the stiffest spring
       of largest force ``F*`` has the least ``d0 >= lo`` with ``F(d0) <=
       F*``: term by term ``need_i (d0 + h) <= F* (d0 + q_i)``, i.e.
       ``d0 >= (need_i h - F* q_i) / (F* - need_i)`` for ``need_i < F*``
       (a term with ``need_i = F*`` has ``q_i = h`` and holds for every
       ``d0``), so ``d0 = max(lo, max_i (need_i h - F* q_i) / (F* - need_i))``,
       which is ``<= hi`` since ``F* >= need_i (hi + h) / (hi + q_i)``. It
       differs from ``hi`` only when the term at ``q = h`` sets ``F*``, and
       then its spring exerts less force at every ``q < h`` than the one at
       ``hi`` for the same largest force.

    When no angle needs a pull (``need <= 0`` everywhere: the load alone
    keeps the follower on the cam) no spring is needed: rate and preload 0,
    said in the spring's ``note``.

    Parameters
    ----------
    design : CamDesign
    dyn : FollowerDynamics
        Its ``spring`` is ignored.
    rpm : float, optional
        Speed at which contact must hold, rev/min; default ``design.rpm``.
    margin : float
        >= 1.
    rate : float, optional
        A given spring rate (N/m or N m/rad): only the preload is chosen, the
        least that holds and gives an installed compression of at least
        ``min_installed``. A rate of 0 (a constant-force spring) takes no
        bounds.
    samples : int
        Cam angles per turn checked.
    min_installed, max_installed : float, optional
        Bounds on the installed compression ``F0 / k``: design length unit
        (mm) for a translating follower, radians (the installed twist) for a
        rocker; >= 0. Defaults: a quarter of the travel and the travel (the
        default of one never crosses the other given).

    Returns
    -------
    Spring
        With its ``travel`` (the follower's stroke, m or rad), ``torsional``
        for a rocker, and a ``note`` when the given rate needs an installed
        compression above the default range, or no spring is needed.

    Raises
    ------
    InputError
        ``margin < 1``, a negative rate or bound, bounds reversed or given
        with a rate of 0; a given ``max_installed`` below the installed
        compression that a given rate needs (field
        ``dynamics.max_installed_compression`` / ``max_installed_twist``), or
        that leaves no force at an angle that needs one; a spring whose
        largest force would exceed ``dyn.max_spring_force`` (field
        ``dynamics.spring_rate`` with a given rate, else
        ``dynamics.max_spring_force``).
    """
    m = _num("dynamics.margin", margin, lo=1.0)
    torsional = design.follower.kind == "rocker"
    what = "twist" if torsional else "compression"
    lo_key, hi_key = f"dynamics.min_installed_{what}", f"dynamics.max_installed_{what}"
    _num(lo_key, min_installed, lo=0.0, allow_none=True)
    _num(hi_key, max_installed, lo=0.0, allow_none=True)
    w = cam_speed(design, rpm)
    phi = dynamics_grid(samples)
    si = si_per_unit(design, dyn)

    def needs(at: np.ndarray) -> tuple[np.ndarray, np.ndarray]:  # q and the spring force contact needs, at angles
        q, _, d2q, _ = follower_kinematics(design, at, dyn)
        return q, m * (-dyn.mass * w**2 * d2q - dyn.load)

    q, need = needs(phi)
    h = max(float(np.max(q)), float(design.program.lift) * si)  # the travel, m or rad

    def shown(d: float) -> str:  # an installed compression (m or rad) in the file's unit
        return f"{np.degrees(d):.6g} deg" if torsional else f"{d / dyn.length_unit:.6g} mm"

    lo = None if min_installed is None else min_installed * si
    hi = None if max_installed is None else max_installed * si
    if lo is not None and hi is not None and lo > hi:
        raise InputError(hi_key, f"must be >= {lo_key.split('.')[1]} ({shown(lo)}), got {shown(hi)}")
    lo_d = min(h / 4, np.inf if hi is None else hi) if lo is None else lo
    hi_d = max(h, lo_d) if hi is None else hi
    speed = f"{omega_to_rpm(w):.6g} rpm with margin {m:g}"
    note = None
    if rate is not None:
        k = _num("dynamics.spring_rate", rate, lo=0.0)
        if k == 0 and (lo is not None or hi is not None):
            raise InputError(lo_key if lo is not None else hi_key, f"a spring_rate of 0 (a constant-force spring) "
                             f"has no installed {what}: remove the bound or give a positive spring_rate")
        # the least preload, its binding angles refined between the samples
        q, need = _refined(needs, phi, q, need, [need - k * q])
        F0 = max(0.0, float(np.max(need - k * q)))
        if k > 0:
            least = F0 / k
            F0 = max(F0, k * lo_d)
            if least > hi_d * (1 + 1e-12):
                said = (f"a spring of rate {k:.6g} {'N m/rad' if torsional else 'N/m'} keeps contact at {speed} only "
                        f"with an installed {what} of at least {shown(least)} (preload {F0:.6g} "
                        f"{'N m' if torsional else 'N'})")
                if hi is not None:
                    raise InputError(hi_key, f"{said}, above the largest allowed, {shown(hi)}: allow more or give a "
                                     "stiffer spring_rate")
                note = (f"{said}, above the usual range (up to the travel, {shown(h)}: a preload of at most half the "
                        "spring's largest force); a stiffer spring would need less")
    elif not np.any(need > 0):
        return Spring(0.0, 0.0, travel=h, torsional=torsional,
                      note=f"the load alone keeps the follower on the cam at {speed}: no spring is needed")
    else:
        if np.any((hi_d + q <= 0) & (need > 0)):
            raise InputError(hi_key, f"an installed {what} of {shown(hi_d)} leaves no spring force at the near dwell, "
                             f"where contact at {speed} needs {float(np.max(need[hi_d + q <= 0])):.6g} "
                             f"{'N m' if torsional else 'N'}: allow more")
        d0 = _least_largest(q, need, h, lo_d, hi_d)
        # refine between the samples where the spring binds (at d0 and at hi, which sets the least largest force)
        with np.errstate(divide="ignore"):
            q, need = _refined(needs, phi, q, need, [np.where(need > 0, need / (d + q), -np.inf) for d in (d0, hi_d)])
        d0 = _least_largest(q, need, h, lo_d, hi_d)
        pos = need > 0
        k = float(np.max(need[pos] / (d0 + q[pos])))
        F0 = max(k * d0, float(np.max(need - k * q)))  # round-off: the constraints hold exactly
    top = F0 + k * h
    if dyn.max_spring_force is not None and top > dyn.max_spring_force * (1 + 1e-12):
        cap = dyn.max_spring_force
        if rate is not None:
            unsprung = FollowerDynamics(dyn.mass, dyn.load, None, dyn.friction, dyn.journal_radius, dyn.length_unit)
            free = spring_for_contact(design, unsprung, rpm=rpm, margin=margin, samples=samples,
                                      min_installed=min_installed, max_installed=max_installed)
            hint = f"; a free rate ({free.rate:.6g}) would need {free.preload + free.rate * h:.6g}"
        elif float(np.max(need)) < cap:
            pos = need > 0
            d_req = float(np.max((need[pos] * h - cap * q[pos]) / (cap - need[pos])))
            hint = f"; a larger max_installed_{what}, {shown(d_req)} or more, would keep it within"
        else:
            hint = f"; no spring can: contact needs {float(np.max(need)):.6g} at some angle"
        raise InputError(
            "dynamics.spring_rate" if rate is not None else "dynamics.max_spring_force",
            f"a spring of rate {k:.6g} cannot keep contact at {speed} at any preload within the installed {what}'s "
            f"range ({shown(lo_d)} to {shown(hi_d)}) and the spring's largest force {cap:.6g}: it needs {top:.6g}"
            f"{hint}",
        )
    return Spring(rate=k, preload=F0, travel=h, torsional=torsional, note=note)


def _least_largest(q: np.ndarray, need: np.ndarray, h: float, lo: float, hi: float) -> float:
    """The installed compression ``d0`` of the stiffest spring of least largest force (:func:`spring_for_contact`,
    steps 1-3): ``q`` the follower's coordinate, ``need`` the force contact needs there (some > 0), ``h`` the
    travel, ``[lo, hi]`` the bounds on ``d0`` (``hi + q > 0`` where ``need > 0``)."""
    pos = need > 0
    qp, npos = q[pos], need[pos]
    top = float(np.max(npos * (hi + h) / (hi + qp)))  # F* = F(hi), steps 1-2
    below = npos < top
    bounds = (npos[below] * h - top * qp[below]) / (top - npos[below])
    d0 = float(min(hi, max(lo, float(np.max(bounds, initial=-np.inf)))))  # step 3
    if not float(np.max(npos * (d0 + h) / (d0 + qp))) <= top * (1 + 1e-9):  # round-off near a tie
        d0 = hi
    return d0


def _refined(needs, phi: np.ndarray, q: np.ndarray, need: np.ndarray, scores, count: int = 8):
    """``q`` and ``need`` with, added, 201 angles across the two sample steps around each of the ``count`` largest
    local maxima of every score in ``scores`` (arrays over ``phi``, a uniform grid over one turn): the spring's
    binding angles lie between the samples, and a peak of a smooth function is then found to about 1e-10 of its
    relative size (the sampled one, to about ``(step / 2)^2`` times its curvature)."""
    step = float(phi[1] - phi[0])
    extra = []
    for sc in scores:
        peak = (sc >= np.roll(sc, 1)) & (sc >= np.roll(sc, -1)) & np.isfinite(sc)
        idx = np.flatnonzero(peak)
        idx = idx[np.argsort(-sc[idx], kind="stable")][:count]
        extra.append((phi[idx][:, None] + step * np.linspace(-1.0, 1.0, 201)[None, :]).ravel())
    at = np.mod(np.concatenate(extra), 2 * np.pi)
    qa, na = needs(at)
    return np.concatenate([q, qa]), np.concatenate([need, na])


def chosen_spring(spec: DynamicsSpec, design: Design, *, rpm: float | None = None) -> Spring:
    """The spring of ``spec``: the given one, or the one :func:`spring_for_contact` chooses at ``rpm``.

    The given spring is returned with its ``travel`` (the follower's stroke)
    and ``torsional`` set from ``design``, so that its installed compression
    and largest force can be reported.

    Parameters
    ----------
    spec : DynamicsSpec
        The design's ``[dynamics]`` (:attr:`cams.model.design.CamDesign.dynamics`), with its bounds on the
        installed compression or twist.
    design : CamDesign
    rpm : float, optional
        Speed at which contact must hold, rev/min; default ``design.rpm``.
    """
    if spec.dynamics.spring is not None:
        travel = float(design.program.lift) * si_per_unit(design, spec.dynamics)
        return replace(spec.dynamics.spring, travel=travel, torsional=design.follower.kind == "rocker")
    lo, hi = spec.installed_bounds
    return spring_for_contact(design, spec.dynamics, rpm=rpm, margin=spec.margin, rate=spec.rate,
                              min_installed=lo, max_installed=hi)


@dataclass(frozen=True)
class DesignForces:
    """The forces of a sized, force-closed cam from its design file's ``[dynamics]``.

    ``spring`` is the given one or the one chosen for the contact margin at
    the design's speed; ``forces`` the contact force and torque over a turn at
    that speed; ``jump`` the speed at which the follower would leave the cam.
    """

    spring: Spring
    forces: CamForces
    jump: JumpSpeed

    def to_dict(self) -> dict:
        """JSON-ready: the spring, force extremes, jump speed.

        ``spring``: :meth:`cams.model.dynamics.Spring.to_dict` -- rate (N/m;
        N m/rad), preload (N; N m), installed compression (mm) or installed
        twist (deg), largest force (N; N m), note.

        With rigid impacts (see :meth:`CamForces.to_dict`) ``jump_rpm`` is 0
        at a velocity jump down (``jump_at_impact``) and ``between_impacts``
        also holds the jump speed of the motion between the impacts.
        """
        out = {"spring": self.spring.to_dict(self.forces.length_unit), **self.forces.to_dict(), **jump_dict(self.jump)}
        if "between_impacts" in out:
            out["between_impacts"]["jump_rpm"] = self.jump.between_impacts_rpm
        return out


def design_forces(design: CamDesign, centre) -> tuple[DesignForces | None, str | None]:
    """Spring, cam forces and jump speed of a design with ``[dynamics]``, or why there are none.

    Returns
    -------
    (DesignForces or None, note or None)
        ``None`` with a note when the design has no ``[dynamics]``, is form
        closed (no closing spring) or has no speed.
    """
    spec = design.dynamics
    if spec is None:
        return None, None
    if design.limits.closure != "force":
        return None, "form-closed cam: no closing spring to size"
    if not design.rpm:
        return None, "[dynamics] needs cam.rpm for the forces"
    spring = chosen_spring(spec, design)
    dyn = spec.dynamics.with_spring(spring)
    return DesignForces(spring, cam_forces(design, centre, dyn), jump_speed(design, dyn)), None
