"""The jump speed: the cam speed above which the spring no longer holds the follower on the cam.

Units: cam speeds in rad/s and rev/min, cam angles in radians (degrees only
in :func:`jump_dict` and :func:`jump_text`, for JSON and reports).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import partial

import numpy as np

from cams.dynamics.impacts import rigid_impacts
from cams.dynamics.motion import dynamics_grid, follower_kinematics, si_per_unit
from cams.kinematics.extremum import maximize, phase_positions
from cams.model.design import Design
from cams.model.dynamics import FollowerDynamics
from laws.errors import InputError
from laws.units import TWO_PI, omega_to_rpm

__all__ = ["JumpSpeed", "jump_speed", "jump_dict", "jump_text"]


@dataclass(frozen=True)
class JumpSpeed:
    """The speed at which the follower leaves the cam (jump, отрыв).

    Attributes
    ----------
    omega : float
        Cam speed, rad/s, above which contact is lost; 0 with a velocity jump
        down (contact is lost there at any speed).
    rpm : float
        The same in rev/min.
    phi : float
        Cam angle (radians) where contact is lost first.
    at_impact : bool
        The jump is at a velocity jump down (a rigid impact), at any speed.
    between_impacts_rpm : float or None
        With rigid impacts: the jump speed of the motion between them (the
        samples' value, excluding the impacts); None without impacts.
    """

    omega: float
    rpm: float
    phi: float
    at_impact: bool = False
    between_impacts_rpm: float | None = None


def jump_speed(design: Design, dyn: FollowerDynamics, *, samples: int = 7200) -> JumpSpeed:
    """The cam speed above which the follower jumps, for the given spring.

    Contact is lost where ``m omega^2 d2q/dphi^2 + F0 + k q + P`` turns
    negative; only decelerations (``d2q < 0``) can pull the follower off, so
    ``1 / omega_jump^2 = max of g = -m d2q/dphi^2 / (F0 + k q + P)``, the
    pull-off per holding force, found per rise and return phase on a grid of
    ``samples`` cam angles a turn and refined where its slope changes sign (the
    kernel's search, :func:`cams.kinematics.extremum.maximize`; one-sided at
    the phase ends, so a maximum on an acceleration jump is exact). A velocity
    jump down (:func:`rigid_impacts`) is an infinite deceleration: the jump
    speed is then 0 (``at_impact``) and the value between the impacts is kept
    in ``between_impacts_rpm``.

    Parameters
    ----------
    design : cams.model.design.Design
        A roller's or a flat face's (the jump speed needs only the motion, the spring and the load).
    dyn : FollowerDynamics
        With its ``spring``.
    samples : int
        Cam angles per turn scanned before refining.

    Returns
    -------
    JumpSpeed

    Raises
    ------
    InputError
        No spring, or a spring (and load) that cannot hold the follower on
        the cam even at rest.
    """
    if dyn.spring is None:
        raise InputError("dynamics.spring_rate", "the jump speed needs a spring")
    phi = dynamics_grid(samples)
    q = follower_kinematics(design, phi, dyn)[0]
    spring = dyn.spring
    hold = spring.force(q) + dyn.load
    if np.any(hold < 0):
        k = int(np.argmin(hold))
        raise InputError(
            "dynamics.preload",
            f"the spring and the load cannot hold the follower on the cam even at rest: "
            f"{hold[k]:.6g} at cam angle {np.degrees(phi[k]):.6g} deg; raise the preload",
        )
    prog = design.program
    si = si_per_unit(design, dyn)

    def pull(i: int, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``g = -m q'' / (F0 + k q + P)`` in phase ``i`` and its derivative by the cam angle."""
        mo = prog.evaluate_phase(i, u)
        q, dq, d2q, d3q = mo.s * si, mo.ds * si, mo.d2s * si, mo.d3s * si
        h = spring.force(q) + dyn.load
        with np.errstate(divide="ignore", invalid="ignore"):
            g = -dyn.mass * d2q / h
            dg = -dyn.mass * (d3q * h - d2q * spring.rate * dq) / h**2
        return g[None], dg[None]

    best, at = 0.0, 0.0  # no deceleration: never pulled off (an infinite speed)
    for i, p in enumerate(prog.phases):
        if p.kind == "dwell":
            continue
        n = max(8, int(np.ceil(samples * p.angle / TWO_PI)))
        top, u = maximize(partial(pull, i), phase_positions(prog, i, n))
        if top[0] > best:
            best, at = float(top[0]), float(prog.starts[i] + u[0] * p.angle)
    w = float(np.sqrt(1.0 / best)) if best > 0 else np.inf
    impacts = rigid_impacts(design)
    down = [i for i in impacts if i.separation]
    if down:
        return JumpSpeed(omega=0.0, rpm=0.0, phi=down[0].phi, at_impact=True, between_impacts_rpm=omega_to_rpm(w))
    return JumpSpeed(omega=w, rpm=omega_to_rpm(w), phi=float(np.mod(at, TWO_PI)),
                     between_impacts_rpm=omega_to_rpm(w) if impacts else None)


def jump_dict(jump: JumpSpeed | None) -> dict:
    """``jump_rpm``, ``jump_at_deg`` (cam angle) and ``jump_at_impact`` of a jump speed (all None without one)."""
    if jump is None:
        return {"jump_rpm": None, "jump_at_deg": None, "jump_at_impact": None}
    return {"jump_rpm": jump.rpm, "jump_at_deg": float(np.degrees(jump.phi)), "jump_at_impact": jump.at_impact}


def jump_text(rpm, digits: int = 6) -> str:
    """A jump speed for reports: ``"168.6 rpm"``, or ``"none ..."`` when nothing pulls the follower off the cam
    (no deceleration: the speed is infinite, or None from JSON)."""
    if rpm is None or not np.isfinite(rpm):
        return "none (no deceleration pulls the follower off the cam)"
    return f"{rpm:.{digits}g} rpm"
