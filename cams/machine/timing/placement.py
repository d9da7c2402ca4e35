"""The cam's timing: the drive from the crank to the cam and the rises placed in the out-of-work window.

The cam turns ``ratio`` times per crank turn (1 on the crank's shaft,
Z_crank / Z_cam through a gear pair). Its program angle (``laws.program``:
radians from the start of the first phase, in the cam's sense) is
``ratio * (c - mount)``: ``mount`` is the cycle angle at which the cam starts
its program (:func:`place_cam`).
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction
from math import gcd

import numpy as np

from cams.machine.timing.cycle import Windows, deg
from laws.errors import InfeasibleError, InputError, check_option, show_value
from laws.program import Program
from laws.units import TWO_PI, turn_degrees

__all__ = ["Drive", "Timing", "CamTiming", "check_follower_direction", "place_cam", "PLACEMENTS"]

PLACEMENTS = ("centre", "early", "late")


@dataclass(frozen=True)
class Drive:
    """How the cam's shaft is driven from the crank.

    Parameters
    ----------
    ratio : float
        Cam turns per crank turn, > 0 (Z_crank / Z_cam for a gear pair).
    sense : {+1, -1}
        +1: the cam turns in the crank's sense (same shaft, internal mesh);
        -1: opposite (external mesh).
    teeth : tuple of int or None
        (Z_crank, Z_cam), e.g. seed 004's (Z5, Z6).
    """

    ratio: float = 1.0
    sense: int = 1
    teeth: tuple[int, int] | None = None

    def __post_init__(self):
        if not (isinstance(self.ratio, (int, float)) and np.isfinite(self.ratio) and self.ratio > 0):
            raise InputError("drive.ratio", f"must be > 0, got {show_value(self.ratio)}")
        if self.sense not in (1, -1):
            raise InputError("drive.mesh", "sense must be +1 or -1")

    @classmethod
    def shaft(cls) -> Drive:
        """The cam on the crank's shaft (seed 003: the feed cam is fixed on O2)."""
        return cls()

    @classmethod
    def gears(cls, z_crank: int, z_cam: int, *, mesh: str = "external") -> Drive:
        """A gear pair: Z_crank on the crank's shaft drives Z_cam on the cam's (seed 004: Z5-Z6)."""
        for f, z in (("drive.z_crank", z_crank), ("drive.z_cam", z_cam)):
            if isinstance(z, bool) or not isinstance(z, int) or z < 1:
                raise InputError(f, f"must be a positive whole number of teeth, got {show_value(z)}")
        check_option("drive.mesh", mesh, ("external", "internal"))
        return cls(ratio=z_crank / z_cam, sense=-1 if mesh == "external" else 1, teeth=(z_crank, z_cam))

    @property
    def period(self) -> tuple[int, int]:
        """(p, q): the cam makes p turns while the crank makes q; the pattern then repeats."""
        if self.teeth is not None:
            a, b = self.teeth
            g = gcd(a, b)
            return a // g, b // g
        f = Fraction(self.ratio).limit_denominator(1000)
        return f.numerator, f.denominator

    def to_dict(self) -> dict:
        """JSON-ready description."""
        return {
            "ratio": float(self.ratio),
            "sense": "same" if self.sense == 1 else "opposite",
            "teeth": None if self.teeth is None else list(self.teeth),
        }


@dataclass(frozen=True)
class Timing:
    """How the cam's rises are placed in the out-of-work window.

    Parameters
    ----------
    margin : float
        Crank angle kept free at both ends of the window, radians, >= 0.
    placement : {"centre", "early", "late"}
        The rises' span centred in the window, or pushed to its start (right
        after the cut) or to its end (right before the next cut), less the margin.
    follower_direction : float or None
        Direction (frame angle, radians) from the cam centre to the roller
        centre at the start of the cam's program; the report then gives the
        key angle between the crank and the cam's start radius. Only for a
        cam that turns with the crank (:func:`check_follower_direction`).
    """

    margin: float = 0.0
    placement: str = "centre"
    follower_direction: float | None = None

    def __post_init__(self):
        if not (isinstance(self.margin, (int, float)) and np.isfinite(self.margin) and 0 <= self.margin < np.pi):
            shown = np.degrees(self.margin) if isinstance(self.margin, (int, float)) else self.margin
            raise InputError("timing.margin", f"must be in [0, 180) degrees, got {show_value(shown)}")
        check_option("timing.placement", self.placement, PLACEMENTS)


@dataclass(frozen=True)
class CamTiming:
    """The cam's rises placed in the cycle.

    Attributes
    ----------
    mount : float
        Cycle angle at which the cam starts its program (radians).
    mount_frame : float
        Frame crank angle at that moment (radians).
    rises : tuple of (float, float)
        Every rise's crank interval over the repeating period (cycle angles,
        radians, start in [0, 2 pi)).
    margins : tuple of float
        Smallest free crank angle between a rise and the window's start, and
        between a rise and the window's end (radians).
    largest_rise : float
        The largest single rise angle of the cam (radians of cam rotation)
        that fits the window with the margins.
    period : tuple of int
        (p, q): the cam's p turns in q crank turns.
    key_angle : float or None
        Angle from the crank O2A to the cam's start radius, counter-clockwise,
        radians (same-shaft cams with a given follower direction).
    """

    mount: float
    mount_frame: float
    rises: tuple[tuple[float, float], ...]
    margins: tuple[float, float]
    largest_rise: float
    period: tuple[int, int]
    ratio: float
    key_angle: float | None = None

    def to_dict(self) -> dict:
        """JSON-ready: degrees."""
        return {
            "mount_deg": deg(self.mount),
            "mount_frame_deg": deg(np.mod(self.mount_frame, TWO_PI)),
            "rises_deg": [[deg(a), deg(b)] for a, b in self.rises],
            "margins_deg": [deg(m) for m in self.margins],
            "largest_rise_deg": deg(self.largest_rise),
            "period": {"cam_turns": self.period[0], "crank_turns": self.period[1]},
            "ratio": float(self.ratio),
            "key_angle_deg": None if self.key_angle is None else deg(np.mod(self.key_angle, TWO_PI)),
        }


def check_follower_direction(timing: Timing, drive: Drive) -> None:
    """Refuse ``timing.follower_direction`` unless the cam turns with the crank (same speed, same sense).

    The key angle it gives (the crank to the cam's start radius) stays the
    same only then: on the crank's shaft, or through equal gears meshing
    internally. A cam at another speed, or turning against the crank, has no
    such fixed angle.

    Raises
    ------
    InputError
        On ``timing.follower_direction``, saying why.
    """
    if timing.follower_direction is None or (drive.ratio == 1 and drive.sense == 1):
        return
    gears = "" if drive.teeth is None else f"gears {drive.teeth[0]}/{drive.teeth[1]}: "
    if drive.ratio != 1:
        why = (f"{gears}the cam turns {drive.ratio:g} times per crank turn, so the angle between them changes "
               "from turn to turn")
    else:
        why = (f"{gears}with an external mesh the cam turns against the crank, so the angle between them changes "
               "as they turn")
    raise InputError("timing.follower_direction",
                     "gives the key angle between the crank and the cam's start radius, fixed only when the cam "
                     "turns with the crank ([drive] kind = 'shaft', or equal gears with mesh = 'internal'); "
                     f"{why}: remove it")


def _rise_intervals(program: Program) -> list[tuple[float, float]]:
    st = program.starts
    return [(float(st[i]), float(st[i + 1])) for i, p in enumerate(program.phases) if p.kind == "rise"]


def place_cam(win: Windows, program: Program, drive: Drive, timing: Timing) -> CamTiming:
    """Place the cam's rises inside the out-of-work window; the cam's mounting angle.

    The span from the start of the first rise to the end of the last one (in
    the cam's program) is placed in the window by ``timing.placement``; then
    every rise over the repeating period (p cam turns in q crank turns) is
    checked to lie inside the window with the margin.

    Parameters
    ----------
    win : Windows
    program : Program
        The cam's motion program (radians of cam rotation).
    drive : Drive
    timing : Timing

    Returns
    -------
    CamTiming

    Raises
    ------
    InfeasibleError
        The rises do not fit: the message gives the window, what the rises
        need and the largest rise angle that would fit.
    InputError
        ``timing.follower_direction`` with a cam that does not turn with the
        crank (:func:`check_follower_direction`).
    """
    check_follower_direction(timing, drive)
    i = drive.ratio
    m = timing.margin
    w0, w1 = win.out_of_work
    Lw = w1 - w0
    rises = _rise_intervals(program)
    if not rises:
        raise InputError("motion", "the cam program has no rise to place")
    a0, b1 = rises[0][0], rises[-1][1]
    span = (b1 - a0) / i  # crank angle of the feed span
    largest = i * max(Lw - 2 * m, 0.0)
    room = Lw - 2 * m
    if span > room + 1e-12:
        what = "the rise" if len(rises) == 1 else "the rises from the first's start to the last's end"
        fits = m > 0 and span <= Lw + 1e-12  # the rises would fit with a smaller margin
        margin_fix = f"the largest timing.margin that fits is {np.degrees((Lw - span) / 2):.4g} deg" if fits else \
            f"{what} alone take{'s' if len(rises) == 1 else ''} more than the window"
        if m > 0 and room <= 1e-12:
            # the margin alone fills the window: it, not the motion, is what leaves no room
            raise InfeasibleError(
                "timing.margin",
                f"{np.degrees(m):.4g} deg at both ends of the {np.degrees(Lw):.4g} deg out-of-work window (crank "
                f"angle) leave no room for {what}, which take{'s' if len(rises) == 1 else ''} "
                f"{np.degrees(span):.4g} deg of crank; {margin_fix}",
            )
        raise InfeasibleError(
            "motion",
            f"feed window too short: the tool is out of the work for {np.degrees(Lw):.4g} deg of crank angle "
            f"({turn_degrees(w0):.4g} to {turn_degrees(w1):.4g} deg after position 1); "
            f"{what} take{'s' if len(rises) == 1 else ''} "
            f"{np.degrees(b1 - a0):.4g} deg of cam = {np.degrees(span):.4g} deg of crank at ratio {i:g}, plus 2 x "
            f"{np.degrees(m):.4g} deg margin; the largest feasible rise angle is {np.degrees(largest):.4g} deg"
            + (" (less the other phases between the rises)" if len(rises) > 1 else "")
            + (f"; or {margin_fix}" if fits else ""),
        )
    if timing.placement == "centre":
        start = w0 + m + (room - span) / 2
    elif timing.placement == "early":
        start = w0 + m
    else:
        start = w1 - m - span
    mount = np.mod(start - a0 / i, TWO_PI)

    p, q = drive.period
    placed, before, after = [], np.inf, np.inf
    for j in range(p):
        for a, b in rises:
            c0 = mount + (a + TWO_PI * j) / i
            c1 = mount + (b + TWO_PI * j) / i
            rel = np.mod(c0 - w0, TWO_PI)  # from the window's start
            if rel + (c1 - c0) > Lw - m + 1e-9 or rel < m - 1e-9 or (c1 - c0) >= TWO_PI:
                raise InfeasibleError(
                    "drive",
                    f"with the cam turning {p} time(s) in {q} crank turn(s) (ratio {i:g}) a rise recurs at crank "
                    f"angles {np.degrees(np.mod(c0, TWO_PI)):.4g}-{np.degrees(np.mod(c0, TWO_PI) + c1 - c0):.4g} deg, "
                    f"outside the out-of-work window {np.degrees(w0):.4g}-{np.degrees(w1):.4g} deg (margin "
                    f"{np.degrees(m):.4g} deg); choose a ratio 1/n (one cam turn in n crank turns) or fewer rises",
                )
            before, after = min(before, rel), min(after, Lw - rel - (c1 - c0))
            s = np.mod(c0, TWO_PI)
            placed.append((float(s), float(s + c1 - c0)))
    mount_frame = float(win.frame_angle(mount))
    key = None
    if timing.follower_direction is not None:
        key = float(timing.follower_direction - mount_frame)
    return CamTiming(
        mount=float(mount),
        mount_frame=mount_frame,
        rises=tuple(sorted(placed)),
        margins=(float(before), float(after)),
        largest_rise=float(largest),
        period=(p, q),
        ratio=float(i),
        key_angle=key,
    )
