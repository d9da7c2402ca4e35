"""Cycle numbers of a one-input linkage: dead positions, stroke, time ratio, transmission angle.

Works on any machine that exposes the protocol :class:`Machine`:
``output(phi, omega=1.0) -> Slide`` (the working member's coordinate along
its path and its derivatives), ``transmission(phi)`` (the smallest
transmission angle of its dyads, radians) and ``crank_sense`` (+1 the crank
turns counter-clockwise, -1 clockwise).

Crank angles ``phi`` are radians in the machine's frame (counter-clockwise
from +x). Spans are crank *rotations* in the crank's own sense, so they are
positive whatever the sense.

Dead positions are the roots of the output's analogue velocity ds/dphi,
bracketed on a grid and refined by Brent's method to ~1e-13 rad.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

import numpy as np

from cams.machine.linkage.primitives import Slide
from laws.errors import InfeasibleError, check_option
from laws.units import TWO_PI

__all__ = ["Machine", "StrokeReport", "dead_positions", "analyse", "WORKING"]

WORKING = ("slow", "fast", "forward", "backward")


class Machine(Protocol):
    """What :func:`analyse` and the coupling need from a linkage."""

    @property
    def crank_sense(self) -> int:  # pragma: no cover - protocol
        """+1: the crank turns counter-clockwise, -1: clockwise."""
        ...

    def output(self, phi: np.ndarray, omega: float = 1.0) -> Slide:  # pragma: no cover - protocol
        ...

    def transmission(self, phi: np.ndarray) -> np.ndarray:  # pragma: no cover - protocol
        ...

    def lengths(self) -> dict:  # pragma: no cover - protocol
        """JSON-ready: the type, the lengths (the machine's unit), the crank's rotation and speed."""
        ...


def dead_positions(machine: Machine, *, samples: int = 720) -> np.ndarray:
    """Crank angles (radians in [0, 2 pi)) where the output stops: ds/dphi = 0.

    Parameters
    ----------
    machine : Machine
    samples : int, optional
        Grid used to bracket the roots (the roots are then refined).

    Returns
    -------
    ndarray
        Sorted angles of the output's extreme positions.

    Notes
    -----
    A machine may offer ``dead_position_hints()``: frame angles (radians)
    where its output is known to stop (e.g. a swinging lever's extreme
    positions). Each is bracketed by grid points a hair either side of it, so
    that two dead positions closer together than the grid's step (a quick
    return with a large time ratio) are not lost.
    """
    from laws.search import bracketed_root

    grid = np.linspace(0.0, TWO_PI, samples + 1)
    hints = getattr(machine, "dead_position_hints", None)
    if hints is not None:
        h = np.mod(np.asarray(hints(), dtype=float), TWO_PI)
        d = 1e-9
        extra = np.concatenate([h - d, h + d])
        grid = np.unique(np.concatenate([grid, extra[(extra > 0) & (extra < TWO_PI)]]))
    samples = grid.size - 1
    v = machine.output(grid).ds
    out = []
    for k in range(samples):
        a, b = grid[k], grid[k + 1]
        va, vb = v[k], v[k + 1]
        if va == 0.0:
            out.append(a)
        elif va * vb < 0:
            speed = lambda p: float(machine.output(np.array([p])).ds[0])  # noqa: E731
            out.append(bracketed_root(speed, a, b, xtol=1e-14, rtol=1e-15))
    return np.sort(np.mod(np.asarray(out, dtype=float), TWO_PI))


def _rotation(sense: int, a: float, b: float) -> float:
    """Crank rotation in its own sense from frame angle a to frame angle b, in [0, 2 pi)."""
    return float(np.mod(sense * (b - a), TWO_PI))


@dataclass(frozen=True)
class StrokeReport:
    """The output's cycle: its dead positions, stroke and time ratio.

    Attributes
    ----------
    start, end : float
        Frame crank angles (radians) of the dead positions that begin and end
        the working stroke.
    s_start, s_end : float
        Output coordinate at those positions (length).
    stroke : float
        ``|s_end - s_start|``.
    working_span, return_span : float
        Crank rotation (radians, in the crank's sense) of the working and the
        return stroke; they sum to 2 pi.
    time_ratio : float
        K = working_span / return_span for a slow working stroke (>= 1).
    min_transmission : float
        Smallest transmission angle over the cycle, radians.
    min_transmission_at : float
        Frame crank angle where it occurs, radians.
    working : str
        The rule that chose the working stroke (see :func:`analyse`).
    """

    start: float
    end: float
    s_start: float
    s_end: float
    stroke: float
    working_span: float
    return_span: float
    time_ratio: float
    min_transmission: float
    min_transmission_at: float
    working: str

    @property
    def direction(self) -> int:
        """+1 when the output's coordinate grows during the working stroke."""
        return 1 if self.s_end > self.s_start else -1

    def to_dict(self) -> dict:
        """JSON-ready: angles in degrees, lengths in the machine's unit."""
        d = np.degrees
        return {
            "dead_positions_deg": [float(d(self.start)), float(d(self.end))],
            "output_at_dead": [float(self.s_start), float(self.s_end)],
            "stroke": float(self.stroke),
            "working_span_deg": float(d(self.working_span)),
            "return_span_deg": float(d(self.return_span)),
            "time_ratio": float(self.time_ratio),
            "min_transmission_deg": float(d(self.min_transmission)),
            "min_transmission_at_deg": float(d(self.min_transmission_at)),
            "working": self.working,
        }


def analyse(machine: Machine, *, working: str = "slow", samples: int = 720) -> StrokeReport:
    """Dead positions, stroke, time ratio and transmission angle of a machine.

    Parameters
    ----------
    machine : Machine
    working : {"slow", "fast", "forward", "backward"}
        Which stroke is the working one: the slower (quick-return machines;
        a tie goes to "forward"), the faster, the one where the output's
        coordinate grows, or the one where it falls.
    samples : int, optional
        Grid for bracketing dead positions and for the transmission minimum
        (refined by a bounded scalar search).

    Returns
    -------
    StrokeReport

    Raises
    ------
    InfeasibleError
        The output does not have exactly two dead positions per turn.
    """
    check_option("working", working, WORKING)
    dead = dead_positions(machine, samples=samples)
    if len(dead) != 2:
        raise InfeasibleError("linkage", f"the output has {len(dead)} dead positions per turn; this analysis needs 2")
    sense = machine.crank_sense
    s = machine.output(dead).s
    a, b = float(dead[0]), float(dead[1])
    span_ab = _rotation(sense, a, b)  # stroke from a to b
    span_ba = TWO_PI - span_ab
    forward_is_ab = s[1] > s[0]
    if working == "forward" or (working == "slow" and abs(span_ab - span_ba) < 1e-9):
        ab = forward_is_ab
        working_used = "forward"
    elif working == "backward":
        ab = not forward_is_ab
        working_used = working
    elif working == "slow":
        ab = span_ab > span_ba
        working_used = working
    else:
        ab = span_ab < span_ba
        working_used = working
    if ab:
        start, end, s0, s1, w_span = a, b, s[0], s[1], span_ab
    else:
        start, end, s0, s1, w_span = b, a, s[1], s[0], span_ba
    r_span = TWO_PI - w_span

    from laws.search import grid_minimum

    grid = np.linspace(0.0, TWO_PI, samples, endpoint=False)
    mu_at, mu_min = grid_minimum(
        lambda p: float(machine.transmission(np.array([p]))[0]),
        grid,
        machine.transmission(grid),
        xatol=1e-12,
        period=TWO_PI,
    )
    return StrokeReport(
        start=start,
        end=end,
        s_start=float(s0),
        s_end=float(s1),
        stroke=float(abs(s1 - s0)),
        working_span=w_span,
        return_span=r_span,
        time_ratio=w_span / r_span,
        min_transmission=mu_min,
        min_transmission_at=float(np.mod(mu_at, TWO_PI)),
        working=working_used,
    )
