"""A rise law from a user's table of ``(u, S)`` values.

The table is interpolated by a quintic B-spline (``scipy.interpolate.
make_interp_spline``, degree 5), so ``S`` is continuous up to its fourth
derivative and ``S', S'', S'''`` are the spline's own derivatives. Two end
treatments:

- ``clamped=False`` (default): not-a-knot ends; needs at least 6 points. The
  end velocity and acceleration are whatever the data imply.
- ``clamped=True``: zero velocity and acceleration at both ends, the usual
  choice between dwells; needs at least 2 points (with exactly the two end
  points it is the 3-4-5 polynomial).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from laws.base import Law
from laws.errors import InputError, check_numbers

if TYPE_CHECKING:
    from scipy.interpolate import BSpline

__all__ = ["TableLaw"]

#: Spline degree.
DEGREE = 5
#: Tolerance on the end points ``(0, 0)`` and ``(1, 1)``.
END_TOL = 1e-12


@dataclass(frozen=True)
class TableLaw(Law):
    """A rise law interpolating a table of ``(u, S)`` points.

    Parameters
    ----------
    u : tuple of float
        Normalized positions (dimensionless), strictly increasing from 0 to 1.
    s : tuple of float
        Normalized rise at those positions, ``s[0] = 0``, ``s[-1] = 1``.
    clamped : bool, keyword-only
        Zero velocity and acceleration at both ends (see the module notes).
    name : str, keyword-only
        Name shown in tables.

    Raises
    ------
    InputError
        Field ``"table.u"``: not finite numbers, not strictly increasing, not
        starting at 0 or ending at 1, fewer points than the spline needs.
        Field ``"table.s"``: not finite numbers, length different from ``u``,
        not starting at 0 or ending at 1.

    Examples
    --------
    >>> law = TableLaw([0, 0.5, 1], [0, 0.5, 1], clamped=True)
    >>> round(float(law.evaluate(0.5)[1]), 6)
    1.875
    """

    u: tuple[float, ...]
    s: tuple[float, ...]
    clamped: bool = field(default=False, kw_only=True)
    name: str = field(default="table", kw_only=True)
    _spline: BSpline = field(init=False, repr=False, compare=False, hash=False)

    def __post_init__(self):
        u = check_numbers("table.u", self.u)
        s = check_numbers("table.s", self.s)
        if s.size != u.size:
            raise InputError("table.s", f"has {s.size} values, table.u has {u.size}; they must match")
        need = 2 if self.clamped else DEGREE + 1
        if u.size < need:
            how = "a clamped" if self.clamped else "an unclamped"
            raise InputError("table.u", f"{how} degree-{DEGREE} spline needs at least {need} points, got {u.size}")
        if np.any(np.diff(u) <= 0):
            i = int(np.argmax(np.diff(u) <= 0))
            raise InputError("table.u",
                             f"must be strictly increasing, but u[{i + 1}] = {u[i + 1]:g} <= u[{i}] = {u[i]:g}")
        if abs(u[0]) > END_TOL or abs(u[-1] - 1.0) > END_TOL:
            raise InputError("table.u", f"must start at 0 and end at 1, got {u[0]:g} .. {u[-1]:g}")
        if abs(s[0]) > END_TOL or abs(s[-1] - 1.0) > END_TOL:
            raise InputError("table.s", f"must start at 0 and end at 1 (a normalized rise), got {s[0]:g} .. {s[-1]:g}")
        u[0], u[-1], s[0], s[-1] = 0.0, 1.0, 0.0, 1.0
        bc = ([(1, 0.0), (2, 0.0)], [(1, 0.0), (2, 0.0)]) if self.clamped else None
        from scipy.interpolate import make_interp_spline  # here: importing it costs 0.3 s

        # scipy documents bc_type as a pair of lists of (derivative order, value); its stubs allow numbers only
        spline = make_interp_spline(u, s, k=DEGREE, bc_type=bc)  # type: ignore[arg-type]
        object.__setattr__(self, "u", tuple(u.tolist()))
        object.__setattr__(self, "s", tuple(s.tolist()))
        object.__setattr__(self, "_spline", spline)

    def _evaluate(self, u):
        sp = self._spline
        return tuple(sp(u, nu=k) for k in range(4))
