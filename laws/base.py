"""The interface every normalized motion law implements.

A law is a normalized rise ``S(u)`` on ``u`` in [0, 1] with ``S(0) = 0`` and
``S(1) = 1``. Its derivatives are taken with respect to ``u`` and are analytic.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from typing import ClassVar

import numpy as np

__all__ = ["Law"]


class Law(ABC):
    """A normalized rise law ``S(u)``, ``u`` in [0, 1].

    Subclasses are frozen dataclasses with a ``name`` and implement
    :meth:`_evaluate` for ``u`` already clipped to [0, 1]. A piecewise law
    lists the positions where its pieces meet in :attr:`breakpoints`, so that
    diagnostics can look for jumps there (one-sided limits).
    """

    name: str
    #: Positions ``u`` in (0, 1) where the pieces of a piecewise law meet.
    breakpoints: ClassVar[tuple[float, ...]] = ()

    def evaluate(self, u: np.ndarray | float) -> np.ndarray:
        """Evaluate the law and its first three derivatives.

        Parameters
        ----------
        u : array_like
            Normalized phase position; values outside [0, 1] are clipped.

        Returns
        -------
        numpy.ndarray
            Array of shape ``(4,) + np.shape(u)``: ``S, S', S'', S'''``
            (derivatives with respect to ``u``).
        """
        uu = np.clip(np.asarray(u, dtype=float), 0.0, 1.0)
        out = np.empty((4, *uu.shape))
        s, s1, s2, s3 = self._evaluate(uu)
        out[0], out[1], out[2], out[3] = s, s1, s2, s3
        return out

    @abstractmethod
    def _evaluate(self, u: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Return ``S, S', S'', S'''`` at ``u`` in [0, 1]."""
