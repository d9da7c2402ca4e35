"""Law names on the interface and the objects behind them."""

from __future__ import annotations

from laws.base import Law
from laws.errors import InputError
from laws.standard import Cycloidal, Harmonic, Linear, Parabolic, Poly345, Poly4567

__all__ = ["LAWS", "get_law"]

#: The library's named laws, in the order tables list them.
LAWS: dict[str, Law] = {
    law.name: law
    for law in (Linear(), Parabolic(), Harmonic(), Cycloidal(), Poly345(), Poly4567())
}


def get_law(name: str, field: str = "law") -> Law:
    """Return the law called ``name``; raise :class:`InputError` naming ``field`` otherwise."""
    try:
        return LAWS[name]
    except (KeyError, TypeError):
        listed = ", ".join(LAWS)
        raise InputError(field, f"unknown law {name!r}, must be one of {listed}") from None
