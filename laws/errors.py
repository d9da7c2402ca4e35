"""The error family shared by every package of the project.

All errors a user can cause are subclasses of :class:`CamsError`, itself a
``ValueError``. Each names the offending field so that the command line can
print it as one line and exit with code 2.

A solver that cannot settle on a valid input is the product's failure, not the
user's: :class:`SolverError`, not a :class:`CamsError`, which the command line
prints as one line with exit code 1.
"""

from __future__ import annotations

import math
from typing import Literal, overload

import numpy as np

__all__ = ["CamsError", "InputError", "InfeasibleError", "SolverError", "check_option", "check_number",
           "check_positive", "check_numbers", "show_value"]


class CamsError(ValueError):
    """Base class of the errors a user's input can cause."""


class InputError(CamsError):
    """An input field has a value outside what is allowed.

    Parameters
    ----------
    field : str
        Dotted name of the field, e.g. ``"limits.pressure_angle"``.
    message : str
        What is wrong and what is allowed.
    """

    def __init__(self, field: str, message: str):
        self.field = field
        super().__init__(f"{field}: {message}" if field else message)


class InfeasibleError(CamsError):
    """No design satisfies the constraints (empty zone, unreachable L, ...)."""

    def __init__(self, field: str, message: str):
        self.field = field
        super().__init__(f"{field}: {message}" if field else message)


class SolverError(RuntimeError):
    """A solver could not settle on an input that is valid: a fault of the product, not of the input.

    Not a :class:`CamsError` (a caller that takes those for bad input or an
    empty zone must not take this for either); the command line reports it as
    one line and exit code 1.

    Parameters
    ----------
    message : str
        Which solver and what it could not do, one line.
    """


def check_option(field: str, value: object, allowed: tuple[str, ...]) -> str:
    """Return ``value`` if it is one of ``allowed``, else raise :class:`InputError`."""
    if not isinstance(value, str) or value not in allowed:
        listed = ", ".join(repr(a) for a in allowed)
        raise InputError(field, f"{value!r} is not a valid option, must be one of {listed}")
    return value


@overload
def check_number(field: str, value: object, *, lo: float | None = ..., strict: bool = ...,
                 allow_none: Literal[False] = ...) -> float: ...
@overload
def check_number(field: str, value: object, *, lo: float | None = ..., strict: bool = ...,
                 allow_none: bool) -> float | None: ...
def check_number(field: str, value: object, *, lo: float | None = None, strict: bool = False,
                 allow_none: bool = False) -> float | None:
    """Return ``value`` as a float if it is a finite number within bounds, else raise :class:`InputError`.

    Parameters
    ----------
    field : str
        Dotted name of the field for the message.
    value : object
        A Python or NumPy int or float; booleans are refused.
    lo : float, optional
        Lower bound, in the value's own unit.
    strict : bool, optional
        ``value > lo`` instead of ``value >= lo``.
    allow_none : bool, optional
        Pass None through (an optional field left out).

    Returns
    -------
    float or None
        ``float(value)``; None only for a None with ``allow_none``.

    Examples
    --------
    >>> check_number("dynamics.mass", 2, lo=0.0, strict=True)
    2.0
    >>> try:
    ...     check_number("dynamics.mass", 0, lo=0.0, strict=True)
    ... except InputError as e:
    ...     print(e)
    dynamics.mass: must be > 0, got 0.0
    >>> try:
    ...     check_number("dynamics.load", 10 ** 400)
    ... except InputError as e:
    ...     print(e)
    dynamics.load: must be a finite number, got 1.00000e+400, too large
    """
    if value is None and allow_none:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(field, f"must be a finite number, got {show_value(value)}")
    try:
        value = float(value)  # a Python int of any size: too large for a float raises here
    except OverflowError:
        raise InputError(field, f"must be a finite number, got {show_value(value)}, too large") from None
    if not math.isfinite(value):
        raise InputError(field, f"must be a finite number, got {show_value(value)}")
    if lo is not None and (value <= lo if strict else value < lo):
        raise InputError(field, f"must be {'>' if strict else '>='} {lo:g}, got {show_value(value)}")
    return value


def check_positive(field: str, value: object) -> float:
    """``value`` as a float if it is a finite number > 0, else :class:`InputError` "must be a number > 0, got ...".

    :func:`check_number` with ``lo=0, strict=True`` and one message for every way to miss.

    Examples
    --------
    >>> check_positive("linkage.crank", 40)
    40.0
    >>> try:
    ...     check_positive("linkage.crank", "4")
    ... except InputError as e:
    ...     print(e)
    linkage.crank: must be a number > 0, got '4'
    """
    try:
        return float(check_number(field, value, lo=0.0, strict=True))
    except InputError:
        raise InputError(field, f"must be a number > 0, got {show_value(value)}") from None


def check_numbers(field: str, values: object, what: str = "") -> np.ndarray:
    """``values`` as a one-dimensional float array of finite numbers, else :class:`InputError` on ``field``.

    Parameters
    ----------
    field : str
        Dotted name of the field for the message.
    values : object
        A sequence (or array) of numbers; a string is refused.
    what : str
        What the values are, starting the message (``"span 2"``); empty: the message starts with "must".

    Examples
    --------
    >>> check_numbers("table.u", [0, 0.5, 1]).tolist()
    [0.0, 0.5, 1.0]
    >>> try:
    ...     check_numbers("table.u", [[0, 1]])
    ... except InputError as e:
    ...     print(e)
    table.u: must be a flat (one-dimensional) sequence of numbers, got shape (1, 2)
    """
    lead = f"{what} must" if what else "must"
    if isinstance(values, (str, bytes)):
        raise InputError(field, f"{lead} be a sequence of numbers, got {values!r}")
    try:
        a = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise InputError(field, f"{lead} be a sequence of numbers, got {values!r}") from None
    if a.ndim != 1:
        raise InputError(field, f"{lead} be a flat (one-dimensional) sequence of numbers, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise InputError(field, f"{lead} hold finite numbers only, got {values!r}")
    return a


def show_value(v) -> str:
    """``v`` for a message: a number as Python writes it (``-5.0``, ``3``, ``nan``; a NumPy scalar as its
    Python value; an integer of more than 30 digits in scientific notation, its leading digits kept), a list,
    tuple or array element-wise, anything else as its repr.

    >>> import numpy as np
    >>> show_value(np.float64(-5.0)), show_value([1, np.float64(2.5)]), show_value("abc")
    ('-5.0', '[1, 2.5]', "'abc'")
    """
    if isinstance(v, (np.integer, int)) and not isinstance(v, bool):
        digits = str(abs(int(v)))
        if len(digits) <= 30:
            return str(int(v))
        return f"{'-' if v < 0 else ''}{digits[0]}.{digits[1:6]}e+{len(digits) - 1}"
    if isinstance(v, (np.floating, float)):
        return repr(float(v))
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(show_value(x) for x in v) + "]"
    if isinstance(v, np.ndarray):
        return show_value(v.tolist())
    return repr(v)
