"""Reading TOML input files, and checking a parsed document's numbers, nesting, tables and keys.

Design and machine files are read by :func:`read_toml`; the whole document is
checked by :func:`check_document` (finite numbers of a bounded size, a bounded
nesting) and its tables by :func:`toml_table`, :func:`toml_number`,
:func:`toml_integer` and :func:`check_keys`, so that both loaders name the
offending field the same way. Writing files is :mod:`cams.io.files`.
"""

from __future__ import annotations

import math
import os
from collections.abc import Collection
from pathlib import Path
from typing import Literal, overload

from laws.errors import InputError, show_value

__all__ = ["read_toml", "check_document", "toml_table", "toml_number", "toml_integer", "check_keys", "MAX_NUMBER",
           "MAX_DEPTH"]

#: The largest size of a number in a design or machine file (integers included): far beyond any quantity a
#: cam or a machine has (lengths are further limited to 1e9 mm), and small enough that sums and products of a
#: few such numbers stay finite and integers stay exact in floating point.
MAX_NUMBER = 1e15
#: The deepest nesting of tables and arrays a file may have (the files use 3 at most: a machine file's
#: ``forces.friction.A``).
MAX_DEPTH = 16


def read_toml(path: str | os.PathLike) -> dict:
    """Parse a TOML file.

    Its numbers and nesting are checked by the loaders that build on it
    (:func:`check_document`), so that the API's dicts get the same checks.

    Parameters
    ----------
    path : path-like
        The file, UTF-8 text; a leading byte-order mark is accepted.

    Returns
    -------
    dict
        The parsed document (tables as dicts, arrays of tables as lists).

    Raises
    ------
    InputError
        Field ``FILE``: the file cannot be read, is not UTF-8, is not valid
        TOML or nests too deeply for the parser.
    """
    import tomllib

    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8-sig")  # -sig: a byte-order mark some editors write is not content
    except OSError as e:
        raise InputError("FILE", f"cannot read {str(p)!r}: {e.strerror or e}") from None
    except UnicodeDecodeError:
        raise InputError("FILE", f"{str(p)!r} is not UTF-8 text") from None
    try:
        d = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise InputError("FILE", f"{p}: not valid TOML: {e}") from None
    except RecursionError:
        raise InputError("FILE", f"{p}: arrays or tables nested too deeply (at most {MAX_DEPTH} levels)") from None
    return d


def check_document(d: dict) -> None:
    """Refuse an empty document, and what no key of a design or machine file allows, wherever it is.

    A non-finite float (TOML's ``nan``, ``inf``), a number larger than
    :data:`MAX_NUMBER` in size (a 100-bit integer, ``1e300``) and nesting
    deeper than :data:`MAX_DEPTH` levels. The walk is iterative, so a deep
    document cannot exhaust Python's stack. Types and ranges of each key are
    checked by the loaders (:func:`toml_number`).

    Parameters
    ----------
    d : dict
        A parsed document (or a dict built like one, for the API).

    Raises
    ------
    InputError
        Naming the value's dotted path, e.g. ``motion[2].angle``; ``FILE`` for
        an empty document or too deep a nesting.
    """
    if not d:
        raise InputError("FILE", "the file is empty (no table, no key); see examples/ for complete files")
    stack: list[tuple[str, object, int]] = [("", d, 0)]
    while stack:
        path, v, depth = stack.pop()
        if isinstance(v, dict):
            items = [(f"{path}.{k}" if path else str(k), x) for k, x in v.items()]
        elif isinstance(v, (list, tuple)):
            items = [(f"{path}[{i}]", x) for i, x in enumerate(v)]
        else:
            _finite(path, v)
            continue
        if depth >= MAX_DEPTH:
            raise InputError(path or "FILE", f"arrays or tables nested too deeply (at most {MAX_DEPTH} levels)")
        stack += [(q, x, depth + 1) for q, x in reversed(items)]


def _finite(field: str, v: object) -> None:
    """Refuse ``v`` if it is a number that is not finite or larger than :data:`MAX_NUMBER` in size."""
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        return
    if isinstance(v, float) and not math.isfinite(v):
        raise InputError(field, f"must be a finite number, got {v!r}")
    if abs(v) > MAX_NUMBER:
        raise InputError(field, f"{show_value(v)} is too large: numbers in a file are at most {MAX_NUMBER:g} in size")


def toml_table(d: dict, key: str) -> dict:
    """The table ``d[key]`` of a parsed TOML document, ``{}`` when absent.

    Parameters
    ----------
    d : dict
        A parsed document or table.
    key : str
        The table's name, also the field named in errors.

    Returns
    -------
    dict
        The table (not a copy).

    Raises
    ------
    InputError
        ``d[key]`` is not a table.
    """
    t = d.get(key, {})
    if not isinstance(t, dict):
        raise InputError(key, f"must be a table ([{key}]), got {_kind(t)}")
    return t


def _kind(v: object) -> str:
    """What a TOML value is, for messages: ``an array``, ``the string 'x'``, ``the number 3``."""
    if isinstance(v, dict):
        return "a table"
    if isinstance(v, list):
        return "an array"
    if isinstance(v, bool):
        return f"the boolean {str(v).lower()}"
    if isinstance(v, str):
        return f"the string {v!r}"
    if isinstance(v, (int, float)):
        return f"the number {v!r}"
    return f"a {type(v).__name__} value"


@overload
def toml_number(table: dict, key: str, field: str, *, default: float, required: bool = ...) -> float: ...
@overload
def toml_number(table: dict, key: str, field: str, *, default: None = ..., required: Literal[True] = ...) -> float: ...
@overload
def toml_number(table: dict, key: str, field: str, *, default: None = ..., required: bool) -> float | None: ...


def toml_number(table: dict, key: str, field: str, *, default: float | None = None,
                required: bool = True) -> float | None:
    """The number ``table[key]`` as a float, in the file's own unit (no conversion).

    Parameters
    ----------
    table : dict
        A parsed TOML table.
    key : str
        The entry.
    field : str
        Name of the entry in error messages, e.g. ``"follower.arm"``.
    default : float or None, optional
        Returned when ``key`` is absent; a default other than None makes the
        entry optional.
    required : bool, optional
        With ``default`` None, whether an absent entry is an error (else None
        is returned).

    Returns
    -------
    float or None
        The value, ``default`` when absent.

    Raises
    ------
    InputError
        A required entry is missing, or the value is not a finite number of
        size at most :data:`MAX_NUMBER` (booleans, strings, arrays and tables
        are refused).
    """
    if key not in table:
        if required and default is None:
            raise InputError(field, "is required")
        return default
    v = table[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise InputError(field, f"must be a number, got {_kind(v)}")
    _finite(field, v)
    return float(v)


def toml_integer(table: dict, key: str, field: str, *, default: int, lo: int, hi: int) -> int:
    """The whole number ``table[key]`` within ``[lo, hi]``, ``default`` when absent.

    Parameters
    ----------
    table : dict
        A parsed TOML table.
    key : str
        The entry.
    field : str
        Name of the entry in error messages, e.g. ``"solve.samples"``.
    default : int
        Returned when ``key`` is absent.
    lo, hi : int
        The allowed range, both included.

    Returns
    -------
    int

    Raises
    ------
    InputError
        The value is not an integer (``2.0`` and ``true`` are refused) or
        lies outside ``[lo, hi]``; the message gives the range.
    """
    v = table.get(key, default)
    if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
        shown = show_value(v) if isinstance(v, int) and not isinstance(v, bool) else _kind(v)
        raise InputError(field, f"must be an integer from {lo} to {hi}, got {shown}")
    return v


def check_keys(table: dict, allowed: Collection[str], field: str) -> None:
    """Refuse entries of ``table`` outside ``allowed``: the one unknown-key check of the files.

    Parameters
    ----------
    table : dict
        A parsed TOML table.
    allowed : set or sequence of str
        Its allowed keys: a set is listed sorted in the message, a sequence
        (a table's documented order, e.g. the ``[dynamics]`` keys) as given.
    field : str
        Name of the table in the error message.

    Raises
    ------
    InputError
        Unknown keys; the message lists them sorted, then the allowed ones.
    """
    unknown = set(table) - set(allowed)
    if unknown:
        shown = sorted(allowed) if isinstance(allowed, (set, frozenset)) else list(allowed)
        raise InputError(field, f"unknown key(s) {', '.join(sorted(unknown))}; allowed: {', '.join(shown)}")
