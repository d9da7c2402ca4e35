"""A time simulation of a force-closed follower on its cam (tests only).

The follower is a mass (or a rocker's inertia) ``m`` on its closing spring, with
the load ``P``; the cam is a stiff, damped, one-sided contact along the
follower's coordinate:

    m q'' = Q - (F0 + k q) - P,    Q = max(0, k_c p + c_c p')  while p = q_cam(t) - q > 0, else 0

(``q_cam(t)``: the program's lift at the cam angle ``omega t``). Nothing here uses
the closed-form contact force of :mod:`cams.dynamics.forces`: the follower may leave the
cam, and leaving it shows as a positive gap ``q - q_cam``, found by a solve_ivp
event. Friction is left out: it changes the size of the contact force, not its sign.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from cams.dynamics.motion import follower_kinematics
from cams.model.design import CamDesign
from cams.model.dynamics import FollowerDynamics

__all__ = ["Flight", "simulate"]


@dataclass(frozen=True)
class Flight:
    """What the simulation saw over the cycles after the first."""

    max_gap: float  # largest q - q_cam, m or rad (negative: always pressed on)
    first_lift_off: float | None  # cam angle (radians, mod 2 pi) where the contact first opens
    penetration: float  # largest penetration, m or rad
    lifted: bool  # the gap exceeded the threshold (a real flight, not a touch)


def simulate(design: CamDesign, dyn: FollowerDynamics, rpm: float, *, cycles: int = 2, stiffness_ratio: float = 150.0,
             threshold: float = 1e-3) -> Flight:
    """Integrate the follower over ``cycles`` cam turns at ``rpm``.

    ``stiffness_ratio`` sets the contact's natural frequency as a multiple of the
    cam's speed; ``threshold`` is the gap, as a fraction of the lift, that counts
    as a lift-off.
    """
    w = rpm * 2 * np.pi / 60
    m, sp, P = dyn.mass, dyn.spring, dyn.load
    kc = m * (stiffness_ratio * w) ** 2
    cc = 2 * 0.7 * np.sqrt(kc * m)

    # the cam's lift as a cubic Hermite table (values and slopes from the program): fast and C1
    nt = 20000
    grid = np.linspace(0.0, 2 * np.pi, nt + 1)
    qg, dqg, _, _ = follower_kinematics(design, grid, dyn)
    qg, dqg = qg.tolist(), dqg.tolist()
    h = 2 * np.pi / nt

    def cam(t):
        x = (w * t) % (2 * np.pi)
        k = min(int(x / h), nt - 1)
        u = x / h - k
        q0, q1, d0, d1 = qg[k], qg[k + 1], dqg[k] * h, dqg[k + 1] * h
        u2, u3 = u * u, u * u * u
        q = (2 * u3 - 3 * u2 + 1) * q0 + (u3 - 2 * u2 + u) * d0 + (-2 * u3 + 3 * u2) * q1 + (u3 - u2) * d1
        dq = ((6 * u2 - 6 * u) * q0 + (3 * u2 - 4 * u + 1) * d0 + (-6 * u2 + 6 * u) * q1 + (3 * u2 - 2 * u) * d1) / h
        return q, dq * w

    def rhs(t, y):
        q, v = y
        qc, vc = cam(t)
        p, pd = qc - q, vc - v
        Q = max(0.0, kc * p + cc * pd) if p > 0 else 0.0
        return [v, (Q - sp.force(q) - P) / m]

    scale = float(np.ptp(qg))
    thr = threshold * scale

    def gap(t, y):  # the contact opens: the penetration reaches 0
        return y[0] - cam(t)[0]

    gap.direction = 1
    q0 = cam(0.0)[0] - (sp.force(cam(0.0)[0]) + P) / kc
    T = cycles * 2 * np.pi / w
    sol = solve_ivp(rhs, (0, T), [q0, 0.0], method="LSODA", rtol=1e-8, atol=1e-10 * scale, events=gap,
                    max_step=2 * np.pi / w / 2000, dense_output=True)
    assert sol.success, sol.message
    t = np.linspace(2 * np.pi / w, T, 20001)  # after the first cycle
    q = sol.sol(t)[0]
    qc = np.array([cam(x)[0] for x in t])
    g = q - qc
    after = sol.t_events[0][sol.t_events[0] >= 2 * np.pi / w]
    first = None if after.size == 0 else float(np.mod(w * after[0], 2 * np.pi))
    return Flight(max_gap=float(np.max(g)), first_lift_off=first, penetration=float(np.max(-g)), lifted=bool(np.max(g) > thr))
