"""The trade-off between base radius R0 and centre distance L (rocker followers).

Along the zone's edge from the admissible centre with the least L to the one
with the least R0, each L has its least R0: the Pareto front of the two sizes.
Each point is the fixed-L problem (seed 3.23-3.25) solved on the sampled zone.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.model.design import CamDesign
from cams.model.follower import Rocker
from laws.errors import InputError
from optimize.circle import best_on_circle

__all__ = ["TradeOff", "tradeoff"]


@dataclass(frozen=True)
class TradeOff:
    """Pareto front of (L, R0): arrays of equal length, L increasing, R0 decreasing.

    ``centres`` has shape (n, 2), fixed frame of :mod:`cams.model.follower`.
    """

    L: np.ndarray
    R0: np.ndarray
    centres: np.ndarray


def tradeoff(design: CamDesign, n: int = 25, *, samples: int | None = None) -> TradeOff:
    """The least R0 for ``n`` centre distances from the least L to the L of the least R0.

    Parameters
    ----------
    design : CamDesign
        A rocker design.
    n : int
        Number of points (>= 2).
    samples : int, optional
        Steps per phase of the sampled zone used (default: the design's).
    """
    if not isinstance(design.follower, Rocker):
        raise InputError("follower.kind", "the R0-L trade-off applies to rocker followers")
    if n < 2:
        raise InputError("n", f"must be >= 2, got {n}")
    from optimize.sizing import nearest

    f = design.follower
    A0 = f.position(0.0)
    a = nearest(design, f.pivot, method="exact")
    b = nearest(design, A0, method="exact")
    Ls = np.linspace(np.linalg.norm(a.centre), np.linalg.norm(b.centre), n)
    cs = [a.centre]
    for L in Ls[1:-1]:
        c = best_on_circle(design, f.pivot, L, lambda O: float(np.linalg.norm(O - A0)),
                           samples=samples or design.samples)
        cs.append(c if c is not None else np.full(2, np.nan))
    cs.append(b.centre)
    C = np.asarray(cs)
    ok = np.all(np.isfinite(C), axis=1)
    C, Ls = C[ok], Ls[ok]
    return TradeOff(L=np.linalg.norm(C, axis=1), R0=np.linalg.norm(C - A0, axis=1), centres=C)
