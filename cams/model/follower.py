"""Followers and their geometry in the fixed frame.

Frames and signs
----------------
* Rocker: origin at the rocker pivot O1, X along the rocker at the near dwell,
  Y to make a right-handed (counter-clockwise positive) frame. The roller centre
  at swing ``psi`` (radians, >= 0 from the near dwell) is
  ``A = arm * (cos(sense*psi), sin(sense*psi))`` with ``sense = +1`` when the
  rocker turns counter-clockwise during the rise, ``-1`` clockwise.
* Translating: origin at the roller centre at the near dwell, Y along the
  follower's rise, X = Y turned clockwise by 90 degrees. ``A = (0, s)``.

Every roller follower exposes the roller-centre position ``A(s)`` and its
derivative ``dA/ds``; everything else (velocities, the instant point D, the
pressure angle) is derived from these two in one place each.

Flat-faced followers (:class:`FlatTranslating`, :class:`FlatRocker`) have a face
line instead of a roller; their envelope is :mod:`cams.kinematics.flat`.

* Flat translating: the translating frame above, the face's point on the axis
  in place of the roller centre (the face is the line ``y = s``).
* Flat rocker: the rocker frame above, the rocker being the face: X along the
  face at the near dwell, from the foot of the perpendicular from the pivot
  towards the cam (the direction in which contact positions on the face are
  positive). Its envelope is computed, and its reports and drawings are given,
  in the *line-of-centres frame* (pivot at the origin, X towards the cam
  centre, which is at ``(L, 0)``): the rocker frame turned by
  ``beta = a0 - sigma 90 deg`` (:func:`cams.kinematics.flat.rocker_frame_turn`),
  the one conversion between the two.

Every follower kind has what :class:`Follower` lists.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from laws.errors import InputError, check_number, check_positive, show_value

__all__ = ["Rocker", "Translating", "FlatTranslating", "FlatRocker", "Follower", "RollerFollower", "FlatFollower",
           "sense_of", "rotation_word", "check_length"]


def sense_of(field: str, word: str) -> int:
    """Map ``"ccw"`` to +1 and ``"cw"`` to -1, else raise :class:`InputError`."""
    if word == "ccw":
        return 1
    if word == "cw":
        return -1
    raise InputError(field, f"{word!r} is not a valid option, must be one of 'cw', 'ccw'")


def rotation_word(sense: int) -> str:
    """The word of a sense of rotation, the inverse of :func:`sense_of`: +1 ``"ccw"``, -1 ``"cw"``."""
    return "ccw" if sense > 0 else "cw"


def _positive(field: str, value: float, *, zero_ok: bool = False) -> float:
    ok = np.isfinite(value) and (value >= 0 if zero_ok else value > 0)
    if not ok:
        raise InputError(field, f"must be {'>= 0' if zero_ok else '> 0'}, got {value!r}")
    return float(value)


@dataclass(frozen=True)
class Rocker:
    """Oscillating (rocker) follower with a roller (or knife edge).

    Parameters
    ----------
    arm : float
        Pivot to roller centre, length unit of the design (mm by default).
    roller_radius : float
        Roller radius, same unit; 0 for a knife edge.
    sense : {+1, -1}
        Rocker's sense of rotation during the rise: +1 counter-clockwise.
    """

    arm: float
    roller_radius: float = 0.0
    sense: int = -1

    kind = "rocker"
    face = "roller"

    def __post_init__(self):
        _positive("follower.arm", self.arm)
        _positive("follower.roller_radius", self.roller_radius, zero_ok=True)
        if self.sense not in (1, -1):
            raise InputError("follower.rise_direction", "must be 'cw' or 'ccw'")

    @property
    def scale(self) -> float:
        """Characteristic length of the design (the arm)."""
        return self.arm

    @property
    def pivot(self) -> np.ndarray:
        """Rocker pivot O1, the reference point of the centre distance L."""
        return np.zeros(2)

    def position(self, s: np.ndarray | float) -> np.ndarray:
        """Roller centre A at swing ``s`` (radians); shape ``s.shape + (2,)``."""
        th = self.sense * np.asarray(s, dtype=float)
        return self.arm * np.stack([np.cos(th), np.sin(th)], axis=-1)

    def tangent(self, s: np.ndarray | float) -> np.ndarray:
        """``dA/ds``: roller-centre displacement per radian of swing."""
        th = self.sense * np.asarray(s, dtype=float)
        return self.sense * self.arm * np.stack([-np.sin(th), np.cos(th)], axis=-1)

    def frame(self, s: np.ndarray | float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``position(s), tangent(s), lever(s)`` at once (one sine and cosine)."""
        th = self.sense * np.asarray(s, dtype=float)
        lev = np.empty((*th.shape, 2))
        lev[..., 0] = np.cos(th)
        lev[..., 1] = np.sin(th)
        A = self.arm * lev
        T = np.empty_like(A)
        T[..., 0] = -self.sense * A[..., 1]
        T[..., 1] = self.sense * A[..., 0]
        return A, T, lev

    def lever(self, s: np.ndarray | float) -> np.ndarray:
        """Unit vector from the pivot to the roller centre (the line D lies on)."""
        th = self.sense * np.asarray(s, dtype=float)
        return np.stack([np.cos(th), np.sin(th)], axis=-1)


@dataclass(frozen=True)
class Translating:
    """Translating follower with a roller (or knife edge).

    Parameters
    ----------
    roller_radius : float
        Roller radius, length unit of the design; 0 for a knife edge.
    offset : float or None
        Fixed offset e of the follower axis from the cam centre, positive when
        the axis lies on the +X side of the cam centre; ``None`` lets the solver
        choose it.
    stroke_scale : float
        Characteristic length (the stroke) for relative tolerances.
    """

    roller_radius: float = 0.0
    offset: float | None = None
    stroke_scale: float = 1.0

    kind = "translating"
    face = "roller"

    def __post_init__(self):
        _positive("follower.roller_radius", self.roller_radius, zero_ok=True)
        if self.offset is not None and not np.isfinite(self.offset):
            raise InputError("follower.offset", f"must be a finite number, got {self.offset!r}")

    @property
    def scale(self) -> float:
        """Characteristic length of the design (the stroke)."""
        return self.stroke_scale

    @property
    def pivot(self) -> np.ndarray:
        """Reference point (the roller centre at the near dwell)."""
        return np.zeros(2)

    def position(self, s: np.ndarray | float) -> np.ndarray:
        """Roller centre A at stroke ``s``; shape ``s.shape + (2,)``."""
        s = np.asarray(s, dtype=float)
        return np.stack([np.zeros_like(s), s], axis=-1)

    def tangent(self, s: np.ndarray | float) -> np.ndarray:
        """``dA/ds``: the unit vector along the follower's rise."""
        s = np.asarray(s, dtype=float)
        return np.stack([np.zeros_like(s), np.ones_like(s)], axis=-1)

    def frame(self, s: np.ndarray | float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``position(s), tangent(s), lever(s)`` at once."""
        return self.position(s), self.tangent(s), self.lever(s)

    def lever(self, s: np.ndarray | float) -> np.ndarray:
        """Unit vector along which the instant point D moves off A (+X)."""
        s = np.asarray(s, dtype=float)
        return np.stack([np.ones_like(s), np.zeros_like(s)], axis=-1)


def check_length(field: str, value: object, *, positive: bool = True) -> float:
    """``value`` as a finite float (``> 0`` when ``positive``), else :class:`InputError` naming ``field``.

    :func:`laws.errors.check_positive`, or :func:`laws.errors.check_number` with the message "must be a number".
    """
    if positive:
        return check_positive(field, value)
    try:
        return float(check_number(field, value))
    except InputError:
        raise InputError(field, f"must be a number, got {show_value(value)}") from None


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

    def __post_init__(self) -> None:
        check_length("follower.offset", self.offset, positive=False)
        check_length("follower.stroke", self.stroke_scale)

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

    def __post_init__(self) -> None:
        check_length("follower.centre_distance", self.centre_distance)
        check_length("follower.face_offset", self.face_offset, positive=False)
        if self.sense not in (1, -1):
            raise InputError("follower.rise_direction", "must be 'cw' or 'ccw'")

    @property
    def scale(self) -> float:
        """Characteristic length (the centre distance L)."""
        return self.centre_distance


class Follower(Protocol):
    """What every follower kind has (roller or flat, rocker or translating).

    Attributes
    ----------
    kind : {"rocker", "translating"}
    face : {"roller", "flat"}
        A roller (a knife edge is a roller of radius 0) or a flat face.
    scale : float
        Characteristic length for relative tolerances (length unit).
    """

    @property
    def kind(self) -> str: ...

    @property
    def face(self) -> str: ...

    @property
    def scale(self) -> float: ...


#: Followers with a roller (or knife edge): the pressure-angle problem of :mod:`optimize`.
RollerFollower = Rocker | Translating
#: Followers with a flat face: sized by convexity (:mod:`optimize.flat`).
FlatFollower = FlatTranslating | FlatRocker
