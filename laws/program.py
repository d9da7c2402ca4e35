"""Cycle programs: the sequence of phases over one cam turn.

Conventions
-----------
Cam angle ``phi`` in radians, measured in the cam's sense of rotation from the
start of the first phase, periodic with period ``2 pi``. The displacement ``s``
is the follower's swing angle (radians, rocker) or stroke (length, translating)
measured from the near-dwell position; derivatives are taken with respect to
``phi`` (analogues), time derivatives follow from the cam speed.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from laws.base import Law
from laws.errors import InputError
from laws.units import TWO_PI, rpm_to_omega

__all__ = ["Phase", "Program", "Motion", "TWO_PI", "wrap_angle"]

_KINDS = ("rise", "dwell", "return")
#: Tolerance on the sum of phase angles (radians).
ANGLE_TOL = 1e-9


def _is_positive(x) -> bool:
    """True for a finite real number > 0 (False for anything else, strings included)."""
    try:
        return bool(np.isfinite(x) and x > 0)
    except TypeError:
        return False


def wrap_angle(phi: np.ndarray | float) -> np.ndarray:
    """Cam angles reduced to [0, 2 pi) (radians).

    ``np.mod`` can return exactly ``2 pi`` for a tiny negative angle; such a
    value is mapped to 0, the start of the cycle.
    """
    x = np.mod(np.asarray(phi, dtype=float), TWO_PI)
    return np.where(x >= TWO_PI, 0.0, x)


@dataclass(frozen=True)
class Phase:
    """One phase of a cycle.

    Parameters
    ----------
    kind : {"rise", "dwell", "return"}
    angle : float
        Cam angle the phase lasts, radians, > 0.
    law : Law, str or None
        Normalized law; required for rise and return, ignored for dwell. A
        name of :data:`laws.registry.LAWS` is replaced by the law when the
        :class:`Program` is built.
    height : float or None
        Displacement change of a rise or return (same unit as the lift);
        ``None`` means the whole lift.
    """

    kind: str
    angle: float
    law: Law | str | None = None
    height: float | None = None


@dataclass(frozen=True)
class Motion:
    """Displacement and its derivatives with respect to the cam angle.

    ``s`` in the lift's unit, ``ds`` per radian, ``d2s`` per radian squared,
    ``d3s`` per radian cubed.
    """

    s: np.ndarray
    ds: np.ndarray
    d2s: np.ndarray
    d3s: np.ndarray

    def time_derivatives(self, rpm: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Velocity, acceleration and jerk in time for a cam at ``rpm`` (per s, s^2, s^3)."""
        if not np.isfinite(rpm) or rpm <= 0:
            raise InputError("cam.rpm", f"must be a positive number, got {rpm!r}")
        w = rpm_to_omega(rpm)
        return self.ds * w, self.d2s * w**2, self.d3s * w**3


@dataclass(frozen=True)
class Program:
    """A cycle program over one cam turn.

    Parameters
    ----------
    phases : tuple of Phase
        In order; their angles sum to ``2 pi``.
    lift : float
        Total swing (radians) or stroke (length), > 0.

    Raises
    ------
    InputError
        A phase angle <= 0, angles not summing to 2 pi, a missing or
        unknown law, or heights that leave the follower outside [0, lift] or
        not back at 0. The field is named ``"motion[i].angle"`` and so on.
    """

    phases: tuple[Phase, ...]
    lift: float

    def __post_init__(self):
        from laws.registry import get_law

        try:
            phases = tuple(self.phases)
        except TypeError:
            raise InputError("motion", f"must be a sequence of phases, got {self.phases!r}") from None
        if not _is_positive(self.lift):
            raise InputError("lift", f"must be a positive number, got {self.lift!r}")
        if not phases:
            raise InputError("motion", "needs at least one phase")
        checked = []
        for i, p in enumerate(phases):
            f = f"motion[{i}]"
            if not isinstance(p, Phase):
                raise InputError(f, f"must be a Phase, got {type(p).__name__}")
            if p.kind not in _KINDS:
                raise InputError(f"{f}.phase", f"{p.kind!r} is not valid, must be one of rise, dwell, return")
            if not _is_positive(p.angle):
                shown = f"{np.degrees(p.angle)!r} degrees" if isinstance(p.angle, (int, float)) else repr(p.angle)
                raise InputError(f"{f}.angle", f"must be > 0 degrees, got {shown}")
            if p.kind != "dwell":
                if p.law is None:
                    raise InputError(f"{f}.law", f"a {p.kind} needs a law")
                if isinstance(p.law, str):
                    p = replace(p, law=get_law(p.law, f"{f}.law"))
                elif not isinstance(p.law, Law):
                    raise InputError(f"{f}.law", f"must be a law or a law name, got {type(p.law).__name__}")
            if p.height is not None and not (_is_positive(p.height) and p.height <= self.lift * (1 + 1e-12)):
                raise InputError(f"{f}.height", f"must be in (0, lift={self.lift:.10g}], got {float(p.height):.10g}")
            checked.append(p)
        object.__setattr__(self, "phases", tuple(checked))
        total = sum(p.angle for p in self.phases)
        if abs(total - TWO_PI) > ANGLE_TOL:
            raise InputError("motion", f"phase angles sum to {np.degrees(total):.10g} degrees, must sum to 360")
        level = 0.0
        top = 0.0
        tol = 1e-9 * self.lift
        for i, p in enumerate(self.phases):
            if p.kind == "rise":
                level += self.height_of(i)
            elif p.kind == "return":
                level -= self.height_of(i)
            if level > self.lift + tol or level < -tol:
                raise InputError(f"motion[{i}]",
                                 f"takes the follower to {level:.6g}, outside [0, lift={self.lift:.6g}]")
            top = max(top, level)
        if abs(level) > tol:
            raise InputError("motion", f"the follower ends the cycle at {level:.6g}, must return to 0")
        if abs(top - self.lift) > tol:
            raise InputError("motion", f"the follower reaches only {top:.6g}, the lift is {self.lift:.6g}")

    # -- structure ---------------------------------------------------------
    def height_of(self, i: int) -> float:
        """Displacement change of phase ``i`` (0 for a dwell)."""
        p = self.phases[i]
        if p.kind == "dwell":
            return 0.0
        return self.lift if p.height is None else float(p.height)

    def signed_height(self, i: int) -> float:
        """Displacement change of phase ``i`` with its sign: ``+h`` on a rise, ``-h`` on a return, 0 on a dwell.

        A rise or return's displacement is ``levels[i] + signed_height(i) * S(u)`` with ``S`` its normalized law.
        """
        sign = {"rise": 1.0, "return": -1.0, "dwell": 0.0}[self.phases[i].kind]
        return sign * self.height_of(i)

    def law_of(self, i: int) -> Law:
        """Normalized law of rise or return phase ``i`` (a law's name was replaced by the law at construction).

        Raises
        ------
        InputError
            Phase ``i`` is a dwell, which has no law.
        """
        law = self.phases[i].law
        if not isinstance(law, Law):
            raise InputError(f"motion[{i}].law", "a dwell has no law")
        return law

    @cached_property
    def starts(self) -> np.ndarray:
        """Cam angle at the start of each phase (radians), plus ``2 pi`` at the end (read-only)."""
        st = np.concatenate([[0.0], np.cumsum([p.angle for p in self.phases])])
        st.setflags(write=False)
        return st

    @cached_property
    def levels(self) -> np.ndarray:
        """Displacement at the start of each phase (read-only)."""
        lv = [0.0]
        for i in range(len(self.phases) - 1):
            lv.append(lv[-1] + self.signed_height(i))
        out = np.asarray(lv)
        out.setflags(write=False)
        return out

    def phase_of(self, phi: np.ndarray | float) -> np.ndarray:
        """Index of the phase containing each cam angle (half-open ``[start, end)``)."""
        x = wrap_angle(phi)
        idx = np.searchsorted(self.starts, x, side="right") - 1
        return np.clip(idx, 0, len(self.phases) - 1)

    def locate(self, phi: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
        """The phase containing each cam angle and the angle reached within it.

        Parameters
        ----------
        phi : array_like or float
            Cam angles, radians, any real values (periodic, period ``2 pi``).

        Returns
        -------
        index : ndarray of int
            Phase index of each angle (its ``[[motion]]`` index from 0); at a joint between phases, the later
            phase (half-open ``[start, end)``, as :meth:`phase_of`).
        within : ndarray of float
            Cam angle from that phase's start, radians, in ``[0, angle]`` of the phase up to rounding
            (``within / angle`` is the phase's normalized position ``u``).
        """
        x = wrap_angle(phi)
        idx = self.phase_of(x)
        return idx, np.asarray(x - self.starts[idx])

    # -- evaluation ----------------------------------------------------------
    def evaluate_phase(self, i: int, u: np.ndarray | float) -> Motion:
        """Motion inside phase ``i`` at normalized positions ``u`` in [0, 1].

        One-sided at the phase ends: the values are the limits from inside the
        phase, which is what the constraint of a phase needs at its ends.
        """
        p = self.phases[i]
        u = np.asarray(u, dtype=float)
        base = self.levels[i]
        if p.kind == "dwell":
            z = np.zeros_like(u)
            return Motion(base + z, z, z.copy(), z.copy())
        sh = self.signed_height(i)
        S = self.law_of(i).evaluate(u)
        b = p.angle
        return Motion(base + sh * S[0], sh * S[1] / b, sh * S[2] / b**2, sh * S[3] / b**3)

    def evaluate(self, phi: np.ndarray | float) -> Motion:
        """Motion at cam angles ``phi`` (radians, any real values, periodic).

        At a joint between phases the later phase's values are returned.
        """
        idx, within = self.locate(phi)
        out = [np.zeros_like(within) for _ in range(4)]
        for i, p in enumerate(self.phases):
            m = idx == i
            if not np.any(m):
                continue
            mo = self.evaluate_phase(i, within[m] / p.angle)
            for k, arr in enumerate((mo.s, mo.ds, mo.d2s, mo.d3s)):
                out[k][m] = arr
        return Motion(*out)
