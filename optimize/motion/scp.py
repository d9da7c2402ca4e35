"""The trust-region loop of sequential convex programming, one home for the rocker's designs.

Each step solves a convex model of the problem around the current iterate
within a trust radius (the caller's ``model``), evaluates the step exactly
(the caller's ``exact``: the cam sized or checked by the exact method) and
keeps it only when its exact value is smaller. The radius doubles after a
step that achieved more than 3/4 of the decrease the model predicted and is
quartered after a refused one. The local-optimality measure is the decrease
the model still predicts within the last radius, relative to the value (0 at
a first-order stationary point).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["Iterate", "Outcome", "minimize", "MAX_ITERATIONS", "TRUST0", "TRUST_MIN"]

#: Iterations at most.
MAX_ITERATIONS = 40
#: Initial trust radius on the normalized law S at the samples (S' gets four times as much).
TRUST0 = 0.05
#: The trust radius below which the iteration stops.
TRUST_MIN = 1e-5
#: The relative decrease the model must still predict to go on.
STATIONARY = 1e-9


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
    accepted: int
    trust: float
    local_measure: float
    history: tuple[float, ...]


def minimize(start: Iterate, model: Callable[[Iterate, float], tuple[float, np.ndarray] | None],
             exact: Callable[[np.ndarray], Iterate | None], *, trust: float = TRUST0) -> Outcome:
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
    """
    it = start
    history = [float(start.value)]
    iterations = accepted = 0
    measure = np.inf
    while iterations < MAX_ITERATIONS and trust >= TRUST_MIN:
        iterations += 1
        step = model(it, trust)
        if step is None:
            trust /= 4
            continue
        predicted = it.value - step[0]
        measure = max(predicted, 0.0) / max(abs(it.value), 1e-300)
        if measure < STATIONARY:
            break
        new = exact(step[1])
        if new is None or not new.value < it.value:
            trust /= 4
            continue
        ratio = (it.value - new.value) / predicted
        it = new
        history.append(float(new.value))
        accepted += 1
        if ratio > 0.75:
            trust *= 2
    return Outcome(best=it, iterations=iterations, accepted=accepted, trust=trust, local_measure=float(measure),
                   history=tuple(history))
