"""Law names on the interface and the objects behind them."""

from __future__ import annotations

from laws.base import Law
from laws.errors import InputError
from laws.modified import ModifiedCycloid, ModifiedSine, ModifiedTrapezoid
from laws.standard import Cycloidal, Harmonic, Linear, Parabolic, Poly345, Poly4567

__all__ = ["LAWS", "get_law"]

#: The library's named laws, in the order tables list them.
LAWS: dict[str, Law] = {
    law.name: law
    for law in (
        Linear(),
        Parabolic(),
        Harmonic(),
        Cycloidal(),
        Poly345(),
        Poly4567(),
        ModifiedTrapezoid(),
        ModifiedSine(),
        ModifiedCycloid(),
    )
}


def get_law(name: str, field: str = "law") -> Law:
    """Return the named law.

    Parameters
    ----------
    name : str
        One of the keys of :data:`LAWS`.
    field : str
        Field name used in the error message (e.g. ``"motion[0].law"``).

    Returns
    -------
    Law
        The shared, immutable law object.

    Raises
    ------
    InputError
        ``name`` is not a known law; the message lists the known names.
    """
    try:
        return LAWS[name]
    except (KeyError, TypeError):
        listed = ", ".join(LAWS)
        raise InputError(field, f"unknown law {name!r}, must be one of {listed}") from None
