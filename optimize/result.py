"""What the solvers return."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["Binding", "CentreSolution", "LINE_NAMES"]

#: The seed's names of the two sides of a wedge (index: side).
LINE_NAMES = ("t-t", "t1-t1")


@dataclass(frozen=True)
class Binding:
    """A constraint active at the solution.

    ``phase`` index in the program, ``phi`` cam angle (radians), ``side`` 0 for
    the seed's t-t line, 1 for t1-t1: t-t where the pressure angle, signed
    positive where the cam drives the follower along its rise, reaches
    ``+[gamma]`` (the rise's lines), t1-t1 where it reaches ``-[gamma]`` (the
    return's lines under form closure, the start position's under force
    closure); see :mod:`optimize.zone`. Mirror-image designs name their lines
    alike.
    """

    phase: int
    phi: float
    side: int

    @classmethod
    def of_line(cls, wedges, k: int) -> Binding:
        """The constraint of line ``k`` of ``wedges.lines()`` (two lines a sampled position, t-t first).

        Parameters
        ----------
        wedges : optimize.zone.Wedges
            The sampled zone.
        k : int
            Index into the flattened lines: position ``k // 2``, side ``k % 2``.
        """
        return cls(int(wedges.phase[k // 2]), float(wedges.phi[k // 2]), int(k % 2))

    @property
    def line(self) -> str:
        """The seed's name of the line: ``"t-t"`` (side 0) or ``"t1-t1"`` (side 1)."""
        return LINE_NAMES[self.side]


@dataclass(frozen=True)
class CentreSolution:
    """A cam centre found by one solver for one objective.

    Attributes
    ----------
    centre : ndarray, shape (2,)
        Cam centre in the follower's fixed frame (length unit).
    objective : float
        Value of the objective at ``centre`` (length).
    method : str
    samples : int or None
        Steps per phase of the sampled methods; None for ``exact``.
    binding : tuple of Binding
    error_bound : float or None
        Bound on |objective - true continuous optimum| (length), None where the
        method cannot state one.
    violation : float
        Largest signed distance of ``centre`` outside the continuous zone
        (length; <= 0 means inside).
    iterations : int
    lower_bound : float or None
        A proven lower bound of the true continuous optimum (length), None
        where the method states none.
    certified : bool or None
        True when ``error_bound`` is within the method's stated accuracy
        (:data:`optimize.exact.CERT_RTOL`); False when the bounds disagree
        beyond it (the answer is not to be used); None for methods that
        certify nothing.
    """

    centre: np.ndarray
    objective: float
    method: str
    samples: int | None
    binding: tuple[Binding, ...] = ()
    error_bound: float | None = None
    violation: float = 0.0
    iterations: int = 0
    lower_bound: float | None = None
    certified: bool | None = None
    notes: tuple[str, ...] = field(default_factory=tuple)
