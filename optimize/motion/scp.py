"""The trust-region loop of sequential convex programming, one home for the rocker's designs.

Each step solves a convex model of the problem around the current iterate
within a trust radius (the caller's ``model``), evaluates the step exactly
(the caller's ``exact``: the cam sized or checked by the exact method) and
keeps it only when its exact value is smaller. The radius doubles after a
step that achieved more than 3/4 of the decrease the model predicted and is
quartered after a refused one; the loop stops when the radius falls below
:data:`TRUST_MIN` (or after :data:`MAX_ITERATIONS`).

The models sample their constraints, so a model's value at the current
iterate differs from the exact value by the sampling; the local-optimality
measure therefore compares the model with itself: the decrease it predicts
within the radius :data:`MEASURE_TRUST` against its value with the radius 0
(nothing moved), relative to the exact value. It is 0 at a first-order
stationary point of the model (no feasible direction of descent) and grows
with the slope of descent left.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["Iterate", "Outcome", "minimize", "stationarity", "solved", "MAX_ITERATIONS", "TRUST0", "TRUST_MIN",
           "MEASURE_TRUST"]

#: Iterations at most.
MAX_ITERATIONS = 40
#: Initial trust radius, in the models' units (the normalized law S at the samples; each model says what else
#: it bounds with it: S' and S'' four and sixteen times as much, a ratio or R0 over the scale as much).
TRUST0 = 0.05
#: The radius within which the local-optimality measure asks the model for a decrease.
MEASURE_TRUST = 1e-3
#: The trust radius below which the iteration stops.
TRUST_MIN = 1e-5


@dataclass(frozen=True)
class Iterate:
    """An exactly evaluated iterate: the laws' variables ``v``, its exact ``value`` and what the caller keeps
    with it (``state``: its programme, its centre...)."""

    v: np.ndarray
    value: float
    state: Any


@dataclass(frozen=True)
class Outcome:
    """The loop's result: the last accepted iterate and how it got there."""

    best: Iterate
    iterations: int
    trust: float
    local_measure: float
    history: tuple[float, ...]

    @property
    def accepted(self) -> int:
        """The steps accepted."""
        return len(self.history) - 1


def minimize(start: Iterate, model: Callable[[Iterate, float], tuple[float, np.ndarray] | None],
             exact: Callable[[np.ndarray], Iterate | None], *, trust: float = TRUST0,
             measure: bool = True) -> Outcome:
    """Sequential convex programming from ``start`` (module notes).

    Parameters
    ----------
    start : Iterate
    model : callable
        ``model(iterate, trust) -> (model value, step variables)``, or None when the model is infeasible
        within ``trust``; the model value in the unit of ``Iterate.value``.
    exact : callable
        ``exact(step variables) -> Iterate``, or None when the step is refused (a cap exceeded, no cam).
    trust : float
        The initial trust radius.
    measure : bool
        Whether to compute the local-optimality measure at the result (two more model solves); ``nan`` if not
        (a first loop whose result only starts another).
    """
    it = start
    history = [float(start.value)]
    iterations = 0
    while iterations < MAX_ITERATIONS and trust >= TRUST_MIN:
        iterations += 1
        step = model(it, trust)
        if step is None:
            trust /= 4
            continue
        predicted = it.value - step[0]
        if predicted <= 0:          # the model sees no decrease within the radius
            trust /= 4
            continue
        new = exact(step[1])
        if new is None or not new.value < it.value:
            trust /= 4
            continue
        ratio = (it.value - new.value) / predicted
        it = new
        history.append(float(new.value))
        if ratio > 0.75:
            trust *= 2
    return Outcome(best=it, iterations=iterations, trust=trust,
                   local_measure=stationarity(model, it) if measure else float("nan"), history=tuple(history))


def stationarity(model: Callable[[Iterate, float], tuple[float, np.ndarray] | None], it: Iterate,
                 radius: float = MEASURE_TRUST) -> float:
    """The local-optimality measure at ``it`` (module notes): ``(m(0) - m(radius)) / |value|``, at least 0;
    ``inf`` when the model is infeasible at radius 0 (the iterate breaks the model's own constraints)."""
    at = model(it, 0.0)
    near = model(it, radius)
    if at is None or near is None:
        return float("inf")
    return max(at[0] - near[0], 0.0) / max(abs(it.value), 1e-300)


def solved(program, n: int) -> tuple[float, np.ndarray] | None:
    """A model's value and its first ``n`` variables (:func:`optimize.motion.conic.solve`), or None when the
    solver finds it infeasible."""
    from optimize.motion.conic import solve

    sol = solve(program)
    return (float(sol.value), sol.v[:n]) if sol.feasible else None
