"""The motion design's request, typed: a design file's ``[optimize]`` table.

The free phases' laws are designed together with the cam: each free rise or
return becomes a spline of the given ``degree`` on ``spans`` equal knot spans,
its derivatives continuous up to ``continuity`` at the knots and at the joints
with the neighbouring phases, its normalized peaks (``Cv = max |S'|``,
``Ca = max |S''|``, ``Cj = max |S'''|``, derivatives of the normalized rise
``S(u)`` with respect to ``u`` in [0, 1]) under the caps. What is minimized:

- ``"R0"`` the pitch curve's base radius (mm), ``"L"`` the centre distance
  (mm, rocker);
- ``"pressure_angle"`` the largest ratio of the pressure angle to its limit
  (the cam's size held);
- ``"Ca"``, ``"Cj"`` the largest normalized acceleration or jerk over the free
  phases; ``"jerk_squared"``, ``"snap_squared"`` the sum over the free phases
  of the integral of ``S'''(u)**2`` or ``S''''(u)**2`` over ``u`` in [0, 1]
  (dimensionless; the cam's size held).

Translating followers: a second stage then returns, among the laws whose
objective is within ``(1 + smoothing_slack)`` times the value found, the
smoothest (the least integral of the squared derivative after the last
continuous one: ``S''''`` for C3; :mod:`optimize.motion.smooth`).

Each field is checked once, here, with the message the file's key gets.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from laws.errors import InputError, check_option, show_value

__all__ = ["MOTION_OBJECTIVES", "CAP_KEYS", "MotionDesignSpec", "MotionCertificate", "DEFAULT_DEGREE", "DEFAULT_SPANS",
           "DEFAULT_CONTINUITY", "MAX_DEGREE", "MAX_SPANS",
           "MAX_ROCKER_SPANS", "MAX_VARIABLES", "MAX_SMOOTHING_SLACK"]

#: What ``[optimize] objective`` may ask for.
MOTION_OBJECTIVES = ("R0", "L", "pressure_angle", "Ca", "Cj", "jerk_squared", "snap_squared")
#: The caps on the free phases' normalized peaks, by the derivative they bound.
CAP_KEYS = {"max_Cv": 1, "max_Ca": 2, "max_Cj": 3}
#: The default spline space: degree 7, 20 spans, C3 (the 4-5-6-7 polynomial's smoothness).
DEFAULT_DEGREE = 7
DEFAULT_SPANS = 20
DEFAULT_CONTINUITY = 3
MAX_DEGREE = 11
#: The most knot spans a phase: the programs' matrices grow with their square (80 spans took about 1.5 s, 100
#: about 3 s after the imports on this project's machine before the smoothing stage about doubled them; 400 took
#: minutes).
MAX_SPANS = 100
#: The free phases' variables at most, free phases x spans x (degree + 1): the programs' matrices are dense, their
#: memory grows with its square (two free phases of degree 7 on 100 spans, 1,600 variables: 1.2 GB and about
#: 20 s; of degree 11 on 100 spans, 2,400: 2.6 GB).
MAX_VARIABLES = 1600
#: Knot spans per free phase at most for a rocker (sequential convex programming: dozens of programs whose
#: size grows with the spans; 40 spans take about 15 s a free phase).
MAX_ROCKER_SPANS = 40
#: ``smoothing_slack`` is below this: the share of the objective given up for smoothness (1 would double it).
MAX_SMOOTHING_SLACK = 1.0
#: The largest cap: a normalized peak beyond it is no cap a cam could meet with a roller (the library's laws
#: have peaks below 100), and would only spoil the programs' scaling.
MAX_CAP = 1e6

#: A cap: a number (normalized, > 0) or a library law's name (that law's peak), or None (no cap).
Cap = float | str | None


@dataclass(frozen=True)
class MotionDesignSpec:
    """A request to design the free phases' laws together with the cam.

    Parameters
    ----------
    free : tuple of (str or int)
        ``"rise"`` (every rise), ``"return"`` (every return) or phase indices
        (0-based ``[[motion]]`` rows, each a rise or a return); empty: no
        free phase (the laws as given, the cam sized with the same certificate).
    objective : str
        One of :data:`MOTION_OBJECTIVES`.
    max_Cv, max_Ca, max_Cj : tuple of cap
        One cap per free phase (in the order of the phases), or one for all
        (a tuple of one): a number (dimensionless, > 0), a law's name of the
        library (its peak), or None (no cap).
    continuity : int
        Derivatives continuous at the knots and the joints: 1, 2 or 3.
    degree : int
        Polynomial degree of each span, ``continuity < degree <= MAX_DEGREE``.
    spans : int
        Knot spans per free phase, 1 to :data:`MAX_SPANS`.
    smoothing_slack : float
        The share of the objective given up for smoothness, in [0, 1): the
        second stage returns the smoothest law whose objective is at most
        ``(1 + smoothing_slack)`` times the first stage's value (translating
        followers; :mod:`optimize.motion.smooth`).
    """

    free: tuple[str | int, ...] = ("rise",)
    objective: str = "R0"
    max_Cv: tuple[Cap, ...] = (None,)
    max_Ca: tuple[Cap, ...] = (None,)
    max_Cj: tuple[Cap, ...] = (None,)
    continuity: int = DEFAULT_CONTINUITY
    degree: int = DEFAULT_DEGREE
    spans: int = DEFAULT_SPANS
    smoothing_slack: float = 0.0

    def __post_init__(self) -> None:
        if not isinstance(self.free, tuple):
            raise InputError("optimize.free", f'must name the free phases: "rise", "return" or phase indices, got '
                             f"{show_value(self.free)}")
        for v in self.free:
            if isinstance(v, bool) or not (isinstance(v, int) or v in ("rise", "return")):
                raise InputError("optimize.free", f'each entry must be "rise", "return" or a phase index, got '
                                 f"{show_value(v)}")
        check_option("optimize.objective", self.objective, MOTION_OBJECTIVES)
        for key in ("continuity", "degree", "spans"):
            v = getattr(self, key)
            if isinstance(v, bool) or not isinstance(v, int):
                raise InputError(f"optimize.{key}", f"must be a whole number, got {show_value(v)}")
        if self.continuity not in (1, 2, 3):
            raise InputError("optimize.continuity", f"must be 1, 2 or 3 (derivatives continuous at the joints), got "
                             f"{self.continuity}")
        if self.degree <= self.continuity:
            raise InputError("optimize.degree", f"must be above the continuity ({self.continuity}): a degree-"
                             f"{self.degree} spline cannot carry {self.continuity} continuous derivatives across "
                             "its knots")
        if self.degree > MAX_DEGREE:
            raise InputError("optimize.degree", f"must be at most {MAX_DEGREE}, got {self.degree}")
        if not 1 <= self.spans <= MAX_SPANS:
            raise InputError("optimize.spans", f"must be from 1 to {MAX_SPANS}, got {self.spans}")
        slack = self.smoothing_slack
        if isinstance(slack, bool) or not isinstance(slack, (int, float)) or not 0 <= slack < MAX_SMOOTHING_SLACK:
            raise InputError("optimize.smoothing_slack", f"must be a number in [0, {MAX_SMOOTHING_SLACK:g}) (the "
                             f"share of the objective given up for smoothness), got {show_value(slack)}")
        from laws.registry import LAWS

        for key in CAP_KEYS:
            caps = getattr(self, key)
            if not isinstance(caps, tuple) or not caps:
                raise InputError(f"optimize.{key}", f"must be a number, a law's name or a list of them, got "
                                 f"{show_value(caps)}")
            for c in caps:
                if c is None:
                    continue
                if isinstance(c, str):
                    if c not in LAWS:
                        raise InputError(f"optimize.{key}", f"unknown law {c!r}: a cap is a number > 0 or one of "
                                         f"{', '.join(LAWS)}")
                elif isinstance(c, bool) or not isinstance(c, (int, float)) or not (0 < c <= MAX_CAP):
                    raise InputError(f"optimize.{key}", f"a cap must be a number in (0, {MAX_CAP:g}] (normalized) or "
                                     f"a law's name, got {show_value(c)}")

    def cap(self, key: str, k: int) -> Cap:
        """The cap ``key`` (``"max_Ca"``...) of the ``k``-th free phase (one cap given: it holds for each)."""
        caps = getattr(self, key)
        return caps[0] if len(caps) == 1 else caps[k]


@dataclass(frozen=True)
class MotionCertificate:
    """The motion design's certificate: what was designed, the value found and what proves it.

    Attributes
    ----------
    objective : str
        What was minimized (:data:`MOTION_OBJECTIVES`).
    value : float
        The checked design's value (mm for ``"R0"`` and ``"L"``; the ratio of pressure angle to limit; the
        normalized peak; the dimensionless integral), computed on the designed laws themselves.
    lower_bound : float or None
        A proven lower bound on the space's optimum (a convex program's); None for a local optimum.
    gap : float or None
        ``(value - lower_bound) / |value|``.
    certified : bool
        The design's checks: the cam verified, the caps met by the laws themselves, the size held and, for a
        convex program's bound, a gap; what the commands' exit code takes (:mod:`cams.assess`). The JSON's
        ``certified`` says more: this and :attr:`bound_proven` (its ``checked`` is this).
    degree, spans, continuity, pieces : int
        The spline space (``pieces``: subdivisions of a span for the conservative constraints).
    free : tuple of int
        The free phases, their ``[[motion]]`` indices from 0.
    caps : tuple of dict
        ``{phase, derivative, max}`` per cap.
    phases : tuple of dict
        Per free phase: ``phase``, ``kind``, ``Cv``, ``Ca``, ``Cj`` of the designed law and of the ``original``.
    reference : dict or None
        The original laws' cam: ``R0``, ``L`` (mm) and ``centre`` ``{x, y}`` (mm); None when they admit none.
    held_R0 : float or None
        The base radius held (mm) by objectives other than R0 and L.
    floor : float or None
        The R0 (mm) the cam was grown to so that its profile passes its checks; None when the optimum passes.
    method : str
        ``"conic"`` or ``"sequential convex programming"``.
    local_measure : float or None
        A local optimum's measure (the decrease its model predicts within a small radius); None for a conic one.
    iterations : int or None
    history : tuple of float
        The objective at each accepted iterate.
    smoothing : dict or None
        What the second stage's smoothing bought (docs/files.md, *Smoothing*); None when no second stage ran.
    seconds : float
        Time of the laws' design (s).
    notes : tuple of str
    """

    objective: str
    value: float
    lower_bound: float | None
    gap: float | None
    certified: bool
    degree: int
    spans: int
    continuity: int
    pieces: int
    free: tuple[int, ...]
    caps: tuple[dict[str, Any], ...]
    phases: tuple[dict[str, Any], ...]
    reference: dict[str, Any] | None
    held_R0: float | None
    floor: float | None
    method: str
    local_measure: float | None
    iterations: int | None
    history: tuple[float, ...] = field(default_factory=tuple)
    smoothing: dict[str, Any] | None = None
    seconds: float = 0.0
    notes: tuple[str, ...] = field(default_factory=tuple)

    @property
    def bound_proven(self) -> bool:
        """False when a convex program's lower bound proves nothing beyond the trivial (0 or below, the value
        above 0); True otherwise (a local optimum claims no bound)."""
        return self.lower_bound is None or not (self.lower_bound <= 0 < self.value)

    def to_dict(self) -> dict:
        """The JSON report's ``optimize`` object (units as in :class:`MotionCertificate`): ``checked`` is
        :attr:`certified`, ``certified`` that and :attr:`bound_proven` (no more than the text says), and
        ``bound_proven`` the rule the text and the picture word the bound by."""
        return {
            "objective": self.objective,
            "value": self.value,
            "lower_bound": self.lower_bound,
            "gap": self.gap,
            "certified": self.certified and self.bound_proven,
            "checked": self.certified,
            "bound_proven": self.bound_proven,
            "degree": self.degree,
            "spans": self.spans,
            "continuity": self.continuity,
            "pieces": self.pieces,
            "free": list(self.free),
            "caps": [dict(c) for c in self.caps],
            "phases": [dict(p) for p in self.phases],
            "reference": self.reference,
            "held_R0": self.held_R0,
            "floor": self.floor,
            "method": self.method,
            "local_measure": self.local_measure,
            "iterations": self.iterations,
            "history": list(self.history),
            "smoothing": self.smoothing,
            "seconds": self.seconds,
            "notes": list(self.notes),
        }
