"""TOML text from a parsed document: what the project writes back as a design file.

Values: strings (basic, escaped), booleans, integers, finite floats (``repr``:
read back, the same bits), arrays of them; tables and arrays of tables, each
table's plain keys first, then its sub-tables (``[motion.law]`` after a
``[[motion]]`` row's keys). Comments of the file read are not kept.
"""

from __future__ import annotations

import re

import numpy as np

__all__ = ["dumps", "value"]

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def value(v: object) -> str:
    """A TOML value: a string, a boolean, an integer, a finite float (its ``repr``) or an array of them.

    Examples
    --------
    >>> value([0.1, 2, "a\\"b", True])
    '[0.1, 2, "a\\\\"b", true]'
    """
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        x = float(v)
        if not np.isfinite(x):
            raise ValueError(f"a design file holds finite numbers only, got {x!r}")
        return repr(x)
    if isinstance(v, str):
        # a basic string: quote, backslash and control characters escaped
        return '"' + "".join(
            "\\" + ch if ch in '"\\' else f"\\u{ord(ch):04X}" if ord(ch) < 0x20 or ord(ch) == 0x7F else ch
            for ch in v) + '"'
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(value(x) for x in v) + "]"
    raise TypeError(f"cannot write {type(v).__name__} in a design file")


def _key(k: str) -> str:
    return k if _BARE.match(k) else value(k)


def _tables(v: object) -> bool:
    return isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v)


def _write(lines: list[str], table: dict, prefix: str) -> None:
    for k, v in table.items():
        if not isinstance(v, dict) and not _tables(v):
            lines.append(f"{_key(k)} = {value(v)}")
    for k, v in table.items():
        if isinstance(v, dict):
            lines += ["", f"[{prefix}{_key(k)}]"]
            _write(lines, v, f"{prefix}{_key(k)}.")
    for k, v in table.items():
        if _tables(v):
            for item in v:
                lines += ["", f"[[{prefix}{_key(k)}]]"]
                _write(lines, item, f"{prefix}{_key(k)}.")


def dumps(doc: dict) -> str:
    """The document as TOML text (ends with a newline).

    Examples
    --------
    >>> print(dumps({"name": "x", "motion": [{"phase": "rise", "law": {"kind": "spline"}}]}), end="")
    name = "x"
    <BLANKLINE>
    [[motion]]
    phase = "rise"
    <BLANKLINE>
    [motion.law]
    kind = "spline"
    """
    lines: list[str] = []
    _write(lines, doc, "")
    return "\n".join(lines).lstrip("\n") + "\n"
