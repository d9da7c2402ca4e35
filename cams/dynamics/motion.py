"""The follower's motion in SI units at cam angles: the common ground of the forces and the jump speed.

Units: ``q`` in rad (rocker) or m (translating); the design's lengths in its
unit (``length_unit`` metres each); cam speed in rad/s.
"""

from __future__ import annotations

import numpy as np

from cams.model.design import Design
from cams.model.dynamics import FollowerDynamics
from cams.model.follower import Rocker
from laws.errors import InputError, show_value
from laws.errors import check_number as _num
from laws.units import TWO_PI, rpm_to_omega

__all__ = ["cam_speed", "dynamics_grid", "si_per_unit", "follower_kinematics"]


def cam_speed(design: Design, rpm: float | None) -> float:
    """The cam's angular speed (rad/s) at ``rpm`` (rev/min), or at the design's ``cam.rpm`` when ``rpm`` is None."""
    n = design.rpm if rpm is None else rpm
    if n is None:
        raise InputError("cam.rpm", "the cam's speed is needed for its forces; give cam.rpm")
    _num("cam.rpm", n, lo=0.0, strict=True)
    return rpm_to_omega(float(n))


def dynamics_grid(samples: int) -> np.ndarray:
    """``samples`` equally spaced cam angles over one turn (rad), from 0; ``dynamics.samples`` checked (>= 8)."""
    if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or samples < 8:
        raise InputError("dynamics.samples", f"must be an integer >= 8, got {show_value(samples)}")
    return np.linspace(0.0, TWO_PI, int(samples), endpoint=False)


def si_per_unit(design: Design, dyn: FollowerDynamics) -> float:
    """SI units of the follower coordinate ``q`` per unit of the program's ``s``.

    1 for a rocker (rad), roller or flat face, else metres per length unit.
    """
    return 1.0 if design.follower.kind == "rocker" else dyn.length_unit


def follower_kinematics(design: Design, phi: np.ndarray, dyn: FollowerDynamics):
    """q, dq/dphi, d2q/dphi2 in SI and the arm |dA/dq| (m): a roller rocker's; 1 otherwise (a translating
    follower's, and a flat rocker's, whose lever arm moves along the face: :mod:`cams.dynamics.flat_forces`)."""
    mo = design.program.evaluate(phi)
    u = si_per_unit(design, dyn)
    arm = design.follower.arm * dyn.length_unit if isinstance(design.follower, Rocker) else 1.0
    return mo.s * u, mo.ds * u, mo.d2s * u, arm
