"""Values in error messages: numbers plainly, in the user's units, never as NumPy reprs.

``show_value(np.float64(-5.0))`` is ``-5.0`` (not ``np.float64(-5.0)``),
``show_value([1, np.float64(2.5)])`` ``[1, 2.5]``, ``show_value("abc")`` ``'abc'``
(tests/linkage/test_show_value.py).
"""

from __future__ import annotations

import numpy as np

__all__ = ["show_value"]


def show_value(v) -> str:
    """``v`` for a message: a number as Python writes it (``-5.0``, ``3``, ``nan``; a NumPy scalar as its
    Python value), a list, tuple or array element-wise, anything else as its repr."""
    if isinstance(v, (np.integer, int)) and not isinstance(v, bool):
        return str(int(v))
    if isinstance(v, (np.floating, float)):
        return repr(float(v))
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(show_value(x) for x in v) + "]"
    if isinstance(v, np.ndarray):
        return show_value(v.tolist())
    return repr(v)
