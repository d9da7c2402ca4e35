"""The error family shared by every package of the project.

All errors a user can cause are subclasses of :class:`CamsError`, itself a
``ValueError``. Each names the offending field so that the command line can
print it as one line and exit with code 2.
"""

from __future__ import annotations

__all__ = ["CamsError", "InputError", "InfeasibleError", "check_option"]


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


def check_option(field: str, value: object, allowed: tuple[str, ...]) -> str:
    """Return ``value`` if it is one of ``allowed``, else raise :class:`InputError`."""
    if not isinstance(value, str) or value not in allowed:
        listed = ", ".join(repr(a) for a in allowed)
        raise InputError(field, f"{value!r} is not a valid option, must be one of {listed}")
    return value
