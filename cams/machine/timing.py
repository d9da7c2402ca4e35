"""The cam in its machine: windows of the cycle, the cam's timing and the cycle diagram.

The pipeline (:func:`design_machine`): the linkage's stroke analysis
(:func:`cams.machine.linkage.analyse`) -> the cutting and out-of-work windows on the
crank's cycle (:func:`windows`) -> the cam's rises placed inside the
out-of-work window with a margin, which fixes the cam's mounting angle
(:func:`place_cam`) -> the cam sized as by ``cams solve``
(:func:`optimize.solve.solve`) -> the cycle diagram with an independent check
that feeding never overlaps cutting (:func:`cycle_diagram`).

Cycle angle
-----------
``c`` is the crank's rotation, in its own sense of rotation, from the dead
position that *ends* the working stroke (seed 003's position 1: the tool at
its lower limit, the slider's "下极限"). So the return stroke is
``[0, return_span]`` and the working stroke ``[return_span, 2 pi]``. Frame crank
angle ``phi = origin + sense * c``. Intervals are ``(start, end)`` with start
in [0, 2 pi) and ``end > start``; an end beyond 2 pi means the interval runs
past position 1 into the next cycle. Radians inside, degrees in
``to_dict``.

Cam angle
---------
The cam turns ``ratio`` times per crank turn (1 on the crank's shaft,
Z_crank / Z_cam through a gear pair). Its program angle (``laws.program``:
radians from the start of the first phase, in the cam's sense) is
``ratio * (c - mount)``: ``mount`` is the cycle angle at which the cam starts
its program.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING
from fractions import Fraction
from math import gcd

import numpy as np
from scipy.optimize import brentq

from cams.cam import Cam
from cams.model.design import CamDesign
from cams.model.follower import Rocker
from cams.machine.linkage.analysis import WORKING, Machine, StrokeReport, analyse
from laws.errors import show_value
from laws.errors import InfeasibleError, InputError, check_option
from laws.program import Program

if TYPE_CHECKING:  # types only: the module is imported where it is used
    from cams.assess import Assessment

__all__ = [
    "CuttingZone",
    "Drive",
    "Timing",
    "Windows",
    "CamTiming",
    "CycleDiagram",
    "MachineSpec",
    "MachineResult",
    "windows",
    "place_cam",
    "check_follower_direction",
    "cycle_diagram",
    "design_machine",
    "PLACEMENTS",
]

TWO_PI = 2 * np.pi
PLACEMENTS = ("centre", "early", "late")


def _deg(x: float) -> float:
    return float(np.degrees(x))


def _frac(field_: str, v) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not np.isfinite(v) or not 0 <= v < 1:
        raise InputError(field_, f"must be a fraction of the stroke in [0, 1), got {show_value(v)}")
    return float(v)


@dataclass(frozen=True)
class CuttingZone:
    """Where the tool is in the work: a part of the working stroke.

    Parameters
    ----------
    approach : float
        Fraction of the stroke H the tool travels in the air before it cuts
        (overrun at the start), in [0, 1).
    overrun : float
        Fraction of H after the cut ends (overrun at the end), in [0, 1).
    working : {"slow", "fast", "forward", "backward"}
        Which stroke is the working one (see :func:`cams.machine.linkage.analyse`).
    """

    approach: float = 0.0
    overrun: float = 0.0
    working: str = "slow"

    def __post_init__(self):
        _frac("cutting.approach", self.approach)
        _frac("cutting.overrun", self.overrun)
        if self.approach + self.overrun >= 1:
            raise InputError("cutting", f"approach + overrun must be < 1 (a part of the stroke is cut), got {self.approach + self.overrun:g}")
        check_option("cutting.working", self.working, WORKING)


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
    def shaft(cls) -> "Drive":
        """The cam on the crank's shaft (seed 003: the feed cam is fixed on O2)."""
        return cls()

    @classmethod
    def gears(cls, z_crank: int, z_cam: int, *, mesh: str = "external") -> "Drive":
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
class Windows:
    """The crank cycle's windows (cycle angles, radians).

    Attributes
    ----------
    stroke : StrokeReport
        The output's dead positions, stroke and time ratio.
    origin : float
        Frame crank angle of cycle angle 0: the dead position ending the
        working stroke (seed 003's position 1).
    sense : int
        The crank's sense of rotation.
    working_start : float
        Cycle angle where the working stroke begins (= the return span).
    cut_start, cut_end : float
        Cycle angles where the tool enters and leaves the work (seed 003's
        positions 5' and 12').
    """

    stroke: StrokeReport
    origin: float
    sense: int
    working_start: float
    cut_start: float
    cut_end: float

    @property
    def cutting(self) -> tuple[float, float]:
        """(start, end) of the cut, cycle angles."""
        return self.cut_start, self.cut_end

    @property
    def out_of_work(self) -> tuple[float, float]:
        """(start, end) of the tool's out-of-work window, start in [0, 2 pi); it runs through position 1 (end > 2 pi)."""
        start = self.cut_end - TWO_PI if self.cut_end >= TWO_PI else self.cut_end
        return start, self.cut_start + TWO_PI - (self.cut_end - start)

    def frame_angle(self, c):
        """Frame crank angle of cycle angles ``c``."""
        return self.origin + self.sense * np.asarray(c, dtype=float)

    def cycle_angle(self, phi):
        """Cycle angle in [0, 2 pi) of frame crank angles ``phi``."""
        return np.mod(self.sense * (np.asarray(phi, dtype=float) - self.origin), TWO_PI)

    def to_dict(self) -> dict:
        """JSON-ready: cycle angles in degrees."""
        o = self.out_of_work
        return {
            "origin_frame_deg": _deg(np.mod(self.origin, TWO_PI)),
            "crank_rotation": "ccw" if self.sense == 1 else "cw",
            "return": [0.0, _deg(self.working_start)],
            "working": [_deg(self.working_start), 360.0],
            "cutting": [_deg(self.cut_start), _deg(self.cut_end)],
            "out_of_work": [_deg(o[0]), _deg(o[1])],
            "out_of_work_span": _deg(o[1] - o[0]),
        }


def windows(machine: Machine, cutting: CuttingZone, *, samples: int = 720) -> Windows:
    """The cycle's windows from the linkage's motion.

    Parameters
    ----------
    machine : Machine
        A linkage of :mod:`cams.machine.linkage.machines`.
    cutting : CuttingZone
        The cut as a part of the working stroke.
    samples : int, optional
        Grid of the stroke analysis.

    Returns
    -------
    Windows
    """
    rep = analyse(machine, working=cutting.working, samples=samples)
    sense = machine.crank_sense
    origin = rep.end
    ws = rep.return_span
    H = rep.stroke

    def travel(c):  # distance from the working stroke's start, along the working stroke
        return abs(float(machine.output(np.array([origin + sense * c])).s[0]) - rep.s_start)

    def at(frac):
        if frac <= 0:
            return ws
        if frac >= 1:
            return TWO_PI
        return brentq(lambda c: travel(c) - frac * H, ws, TWO_PI, xtol=1e-13, rtol=1e-15)

    return Windows(rep, origin, sense, ws, at(cutting.approach), at(1 - cutting.overrun))


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
            "mount_deg": _deg(self.mount),
            "mount_frame_deg": _deg(np.mod(self.mount_frame, TWO_PI)),
            "rises_deg": [[_deg(a), _deg(b)] for a, b in self.rises],
            "margins_deg": [_deg(m) for m in self.margins],
            "largest_rise_deg": _deg(self.largest_rise),
            "period": {"cam_turns": self.period[0], "crank_turns": self.period[1]},
            "ratio": float(self.ratio),
            "key_angle_deg": None if self.key_angle is None else _deg(np.mod(self.key_angle, TWO_PI)),
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
        why = f"{gears}the cam turns {drive.ratio:g} times per crank turn, so the angle between them changes from turn to turn"
    else:
        why = f"{gears}with an external mesh the cam turns against the crank, so the angle between them changes as they turn"
    raise InputError("timing.follower_direction",
                     f"gives the key angle between the crank and the cam's start radius, fixed only when the cam turns "
                     f"with the crank ([drive] kind = 'shaft', or equal gears with mesh = 'internal'); {why}: remove it")


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
            f"({np.degrees(w0) % 360:.4g} to {np.degrees(w1) % 360:.4g} deg after position 1); {what} take{'s' if len(rises) == 1 else ''} "
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


@dataclass(frozen=True, eq=False)
class CycleDiagram:
    """Data of the cycle diagram (цикловая диаграмма / 运动循环图) on one crank-angle axis.

    Attributes
    ----------
    crank : ndarray
        Cycle angle, radians, over the repeating period (q crank turns).
    tool : ndarray
        The tool's distance from its position at cycle angle 0 (length): 0 at
        position 1, H at the start of the working stroke.
    follower : ndarray
        The cam follower's displacement: swing in radians (rocker) or lift
        (translating).
    cutting : ndarray of bool
        The tool is in the work: moving in the working direction with its
        travel between approach and 1 - overrun of the stroke (from the motion
        itself, not from :class:`Windows`).
    feeding : ndarray of bool
        The follower is in a rise.
    overlap : bool
        Feeding and cutting at the same sample anywhere.
    follower_unit : str
        ``"rad"`` or the length unit.
    return_overlap : bool
        The follower's return (not a feed) happens partly during the cut;
        harmless for a ratchet feed, reported as a note.
    """

    crank: np.ndarray
    tool: np.ndarray
    follower: np.ndarray
    cutting: np.ndarray
    feeding: np.ndarray
    overlap: bool
    follower_unit: str
    return_overlap: bool = False

    def to_dict(self, *, step_deg: float = 5.0) -> dict:
        """JSON-ready samples every ``step_deg`` degrees (follower in degrees for a rocker)."""
        deg = np.degrees(self.crank)
        pick = np.isclose(np.mod(deg + 1e-9, step_deg), 0.0, atol=1e-6)
        f = np.degrees(self.follower) if self.follower_unit == "rad" else self.follower
        return {
            "step_deg": step_deg,
            "crank_deg": [round(float(x), 6) for x in deg[pick]],
            "tool": [float(x) for x in self.tool[pick]],
            "follower": [float(x) for x in f[pick]],
            "follower_unit": "deg" if self.follower_unit == "rad" else self.follower_unit,
        }

    def plot(self, path, *, title: str = "cycle diagram"):
        """Draw the diagram to ``path`` (PNG, SVG, PDF by suffix); returns the path."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        deg = np.degrees(self.crank)
        fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(9, 5.5))
        ax1.plot(deg, self.tool, color="C0")
        ax1.set_ylabel("tool from position 1, mm")
        f = np.degrees(self.follower) if self.follower_unit == "rad" else self.follower
        ax2.plot(deg, f, color="C1")
        ax2.set_ylabel("follower, " + ("deg" if self.follower_unit == "rad" else self.follower_unit))
        ax2.set_xlabel("cycle angle from position 1 (crank rotation), deg")
        for ax in (ax1, ax2):
            ax.fill_between(deg, 0, 1, where=self.cutting, transform=ax.get_xaxis_transform(), color="C3", alpha=0.15, label="cutting")
            ax.fill_between(deg, 0, 1, where=self.feeding, transform=ax.get_xaxis_transform(), color="C2", alpha=0.25, label="feeding")
            ax.grid(True, alpha=0.3)
        ax1.legend(loc="upper right")
        ax1.set_title(title + ("  -- OVERLAP" if self.overlap else ""))
        fig.tight_layout()
        fig.savefig(path)
        plt.close(fig)
        return path


def cycle_diagram(
    machine: Machine,
    win: Windows,
    cutting: CuttingZone,
    program: Program,
    timing: CamTiming,
    *,
    per_turn: int = 3600,
    follower_unit: str = "rad",
) -> CycleDiagram:
    """Tool and follower on one crank-angle axis, with the feeding-vs-cutting check.

    Parameters
    ----------
    machine : Machine
    win : Windows
    cutting : CuttingZone
    program : Program
    timing : CamTiming
    per_turn : int, optional
        Samples per crank turn (multiple of 72 keeps the 5-degree JSON grid exact).
    follower_unit : str
        ``"rad"`` for a rocker, else the length unit.

    Returns
    -------
    CycleDiagram
    """
    q = timing.period[1]
    c = np.linspace(0.0, TWO_PI * q, per_turn * q + 1)
    out = machine.output(win.frame_angle(c))
    rep = win.stroke
    tool = np.abs(out.s - rep.s_end)
    travel = np.abs(out.s - rep.s_start)
    H = rep.stroke
    moving_work = np.sign(out.ds * win.sense) == rep.direction  # d/dt = ds/dphi * omega, omega ~ sense
    tol = 1e-9 * H
    cut = moving_work & (travel >= cutting.approach * H - tol) & (travel <= (1 - cutting.overrun) * H + tol)
    cam = timing.ratio * (c - timing.mount)
    mo = program.evaluate(cam)
    idx = program.phase_of(cam)
    kinds = np.array([p.kind for p in program.phases])[idx]
    feeding = kinds == "rise"
    # a sample exactly on a window's edge may be both (the cut's first instant and the rise's last): ignore zero-length contact
    inner_cut = cut & np.roll(cut, 1) & np.roll(cut, -1)
    overlap = bool(np.any(inner_cut & feeding))
    ret = bool(np.any(inner_cut & (kinds == "return")))
    return CycleDiagram(c, tool, mo.s, cut, feeding, overlap, follower_unit, ret)


@dataclass(frozen=True)
class MachineSpec:
    """A machine with its feed cam, as read from a machine file.

    Parameters
    ----------
    name : str
    linkage : Machine
        One of :mod:`cams.machine.linkage.machines`.
    cutting : CuttingZone
    drive : Drive
    timing : Timing
    cam : CamDesign
        The cam's design; its ``cam_sense`` and ``rpm`` follow the crank and the drive.
    units : str
        Length unit of the file.
    """

    name: str
    linkage: Machine
    cutting: CuttingZone
    drive: Drive
    timing: Timing
    cam: CamDesign
    units: str = "mm"
    extra: dict = field(default_factory=dict, compare=False, hash=False)


@dataclass(frozen=True)
class MachineResult:
    """Everything :func:`design_machine` finds.

    ``bore``: with ``[cam] bore_radius``, the profile check of the bore:
    ``{"bore_radius", "min_work_radius", "clear"}`` (lengths in the file's
    unit; ``clear``: the working profile's smallest radius exceeds the bore's;
    None when no profile could be built).

    ``assessment``: the feed cam judged by the rule every command shares
    (:func:`cams.assess.assess_cam`): verified, buildable (a working profile,
    no undercut, a valid closed profile, the bore, ``[dynamics]``) and certified.
    """

    spec: MachineSpec
    stroke: StrokeReport
    windows: Windows
    timing: CamTiming
    solve: object  # optimize.solve.SolveResult
    diagram: CycleDiagram
    bore: dict | None = None
    assessment: Assessment | None = None

    @property
    def overlap(self) -> bool:
        """True when feeding overlaps cutting somewhere (a failed check)."""
        return self.diagram.overlap

    @property
    def notes(self) -> list[str]:
        """Remarks: the bore check's outcome (a bore the profile cuts into fails :attr:`ok`) and those that do not fail."""
        out = []
        b = self.bore
        if b is not None:
            u = self.spec.units
            if b["clear"]:
                out.append(f"bore radius {b['bore_radius']:g} {u}: the working profile's smallest radius "
                           f"{b['min_work_radius']:.4f} {u} clears it")
            else:
                out.append(f"bore radius {b['bore_radius']:g} {u} is NOT clear of the working profile, whose smallest "
                           f"radius is {b['min_work_radius']:.4f} {u}: choose a smaller bore (cam.bore_radius)")
        if self.diagram.return_overlap:
            out.append("the follower's return overlaps the cut (no feed then with a ratchet drive); "
                       "placement = 'early' or a shorter return keeps it out")
        return out

    @property
    def ok(self) -> bool:
        """No overlap and a usable feed cam (:attr:`cams.assess.Assessment.usable`: certified, verified and
        buildable, the bore included), as every other command judges a cam."""
        return not self.overlap and bool(self.assessment.usable)

    def to_dict(self) -> dict:
        """JSON-ready report: lengths in the file's unit, angles in degrees."""
        lk = self.spec.linkage
        syn = getattr(lk, "synthesis", None)
        return {
            "name": self.spec.name,
            "units": self.spec.units,
            "linkage": lk.lengths(),
            "synthesis": None if syn is None else syn.to_dict(),
            "analysis": self.stroke.to_dict(),
            "windows": self.windows.to_dict(),
            "drive": self.spec.drive.to_dict(),
            "timing": {**self.timing.to_dict(), "margin_deg": _deg(self.spec.timing.margin), "placement": self.spec.timing.placement},
            "cam": self.solve.to_dict(),
            **self.assessment.to_dict(),
            "overlap": self.overlap,
            "bore": self.bore,
            "notes": self.notes,
            "diagram": self.diagram.to_dict(),
        }


def design_machine(spec: MachineSpec, *, method: str | None = None) -> MachineResult:
    """Windows, cam timing, the cam's design and the cycle diagram of a machine.

    Parameters
    ----------
    spec : MachineSpec
    method : str, optional
        Override of the cam solver's method.

    Returns
    -------
    MachineResult
        With ``[cam] bore_radius`` its ``bore`` compares the bore with the
        sized cam's working profile (as ``cams check`` does).
    """
    from optimize.solve import solve

    win = windows(spec.linkage, spec.cutting)
    tm = place_cam(win, spec.cam.program, spec.drive, spec.timing)
    design = spec.cam if method is None else spec.cam.with_(method=method)
    res = solve(design, objective=design.objective)
    unit = "rad" if isinstance(spec.cam.follower, Rocker) else spec.units
    dia = cycle_diagram(spec.linkage, win, spec.cutting, spec.cam.program, tm, follower_unit=unit)
    cam = Cam(design, solution=res)  # the cam just sized: assessed, not solved again
    assessment = cam.assessment  # one rule for every command (cams.assess): verified, buildable, certified
    return MachineResult(spec, win.stroke, win, tm, res, dia, _bore(cam), assessment)


def _bore(cam: Cam) -> dict | None:
    """The profile check of ``[cam] bore_radius`` (None without one, or without a profile): the working profile's
    smallest radius vs the bore."""
    bore = cam.options.bore_radius
    checks = cam.computed("checks")  # None: a knife edge in a groove, or no profile at the tolerance
    if bore is None or checks is None:
        return None
    rmin = cam.profile.min_work_radius
    return {"bore_radius": float(bore), "min_work_radius": float(rmin), "clear": bool(rmin > bore)}
