"""The follower's motion at its peaks: the largest velocity, acceleration and jerk over the cycle, and where.

The follower's displacement ``s(phi)`` (a rocker's swing in radians, a translating follower's stroke in the
length unit) has the derivatives ``s^(k)`` by the cam angle of its program (:meth:`laws.program.Program.
evaluate_phase`: each phase's law scaled by its height and angle). At a cam speed ``omega`` (rad/s, from rpm)
the follower's k-th time derivative is ``s^(k) omega^k``; without a speed the peaks are the analogues, per
radian^k of cam angle. A jump of ``s'`` (a hard impact) makes the acceleration and the jerk unbounded there, a
jump of ``s''`` (a soft impact) the jerk: their value is then None (infinite), at the first such jump.

Each peak is the largest absolute value over every phase, one-sided at the phase ends, searched on a grid of
each phase refined round its best point (:func:`cams.kinematics.flat.zoom_minimum`'s repeated grids, no
derivative of the next order needed).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laws.program import Program
from laws.units import rpm_to_omega, turn_degrees

__all__ = ["Peak", "Peaks", "motion_peaks", "KINDS"]

#: The peaks' names, by the order of the derivative (1, 2, 3).
KINDS = ("velocity", "acceleration", "jerk")
_POWERS = ("", "²", "³")


@dataclass(frozen=True)
class Peak:
    """One peak of the follower's motion.

    Attributes
    ----------
    value : float or None
        The largest absolute value (in ``unit``); None where it is unbounded (a jump of the derivative below).
    at : float
        Cam angle where it is reached (radians, in [0, 2 pi)); of the first jump where unbounded.
    unit : str
        ``mm/s``, ``mm/s²``, ``mm/s³`` (translating) or ``rad/s``... (rocker) at a speed; per radian of cam
        angle without one (``mm/rad``, ``rad/rad²``...).
    """

    value: float | None
    at: float
    unit: str

    def to_dict(self) -> dict:
        """JSON-ready ``{value, at_deg, unit}`` (value None: unbounded)."""
        return {"value": self.value, "at_deg": float(turn_degrees(self.at)), "unit": self.unit}


@dataclass(frozen=True)
class Peaks:
    """The follower's velocity, acceleration and jerk peaks (:func:`motion_peaks`); ``rpm`` the speed or None."""

    velocity: Peak
    acceleration: Peak
    jerk: Peak
    rpm: float | None

    def to_dict(self) -> dict:
        """JSON-ready ``{velocity, acceleration, jerk}``, each :meth:`Peak.to_dict`."""
        return {k: getattr(self, k).to_dict() for k in KINDS}


def _largest(program: Program, k: int, grid: int) -> tuple[float, float]:
    """The largest ``|s^(k)|`` over the cycle (per radian^k) and its cam angle (radians), refined per phase; a
    later phase's must be larger by more than 1e-12 of the value to replace an earlier one's."""
    from cams.kinematics.flat import zoom_minimum

    best, at = -1.0, 0.0  # the values are >= 0
    for i, p in enumerate(program.phases):
        if p.kind == "dwell":
            continue
        def f(u: np.ndarray, i: int = i) -> np.ndarray:
            m = program.evaluate_phase(i, u)
            return -np.abs((m.ds, m.d2s, m.d3s)[k - 1])
        u = np.linspace(0.0, 1.0, grid + 1)
        v = f(u)
        j = int(np.argmin(v))
        bu, bv = zoom_minimum(f, u[max(j - 1, 0)], u[min(j + 1, grid)], float(u[j]), float(v[j]))
        if -bv > best * (1 + 1e-12):
            best, at = -bv, float(program.starts[i] + bu * p.angle)
    return float(best), at


def motion_peaks(program: Program, *, rocker: bool, rpm: float | None = None, grid: int = 2000) -> Peaks:
    """The follower's peak velocity, acceleration and jerk, and the cam angles where they are reached.

    Parameters
    ----------
    program : laws.program.Program
        The motion program: a rocker's lift in radians, a translating follower's in the length unit (mm).
    rocker : bool
        A rocker (units rad) or a translating follower (units mm).
    rpm : float or None
        Cam speed, rev/min; None: the peaks per radian of cam angle.
    grid : int
        Steps per phase of the search before the refinement.

    Returns
    -------
    Peaks

    Examples
    --------
    A cycloidal rise of 20 mm over 90 degrees at 60 rpm (omega = 2 pi rad/s): the peak velocity is
    ``Cv h omega / beta = 2 * 20 * 2 pi / (pi / 2) = 160 mm/s``, halfway through the rise.

    >>> from laws.program import Phase, Program
    >>> prog = Program((Phase("rise", np.pi / 2, "cycloidal"), Phase("return", np.pi / 2, "cycloidal"),
    ...                 Phase("dwell", np.pi)), 20.0)
    >>> pk = motion_peaks(prog, rocker=False, rpm=60.0)
    >>> round(pk.velocity.value, 9), round(float(np.degrees(pk.velocity.at)), 6), pk.velocity.unit
    (160.0, 45.0, 'mm/s')
    """
    from laws.diagnostics import find_impacts

    unit = "rad" if rocker else "mm"
    omega = None if rpm is None else rpm_to_omega(rpm)
    impacts = find_impacts(program)
    hard = [m.phi for m in impacts if m.kind == "hard"]
    jumps = sorted(m.phi for m in impacts)
    out = []
    for k in (1, 2, 3):
        unbounded = (k == 2 and hard) or (k == 3 and jumps)
        denominator = f"s{_POWERS[k - 1]}" if omega is not None else f"rad{_POWERS[k - 1]}"
        u = f"{unit}/{denominator}"
        if unbounded:
            out.append(Peak(None, float(hard[0] if k == 2 else jumps[0]), u))
            continue
        v, at = _largest(program, k, grid)
        out.append(Peak(float(v * (1.0 if omega is None else omega**k)), at, u))
    return Peaks(out[0], out[1], out[2], rpm=rpm)
