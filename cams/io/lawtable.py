"""Motion laws written as tables in a design file (``[motion.law]``), read and written.

A ``[[motion]]`` phase's ``law`` is a law's name (``law = "poly345"``) or a
table of the normalized law itself (dimensionless ``S(u)``, ``u`` in [0, 1];
the phase's angle and height scale it), written after the phase's other keys::

    [[motion]]
    phase = "rise"
    angle = 120
    [motion.law]
    kind = "spline"          # "spline" | "polynomial"
    degree = 5               # optional, checked against the coefficients
    breaks = [0.0, 1.0]      # optional: equal spans by default
    coefficients = [[0, 0, 0, 1, 1, 1]]

or inline, ``law = { kind = "polynomial", start = [0, 0], end = [0, 0] }``.

- ``kind = "spline"``: a :class:`laws.spline.SplineLaw`, keys ``degree``,
  ``breaks``, ``coefficients`` (one array of Bernstein coefficients per knot
  span) and ``name``;
- ``kind = "polynomial"``: :meth:`laws.polynomial.PolynomialLaw.from_boundary`,
  keys ``start`` and ``end`` (up to 3 numbers each: the normalized velocity,
  acceleration and jerk at ``u = 0`` and ``u = 1``) and ``name``.

The table's shape (keys, types) is checked here, naming the file's field
(``motion[0].law.coefficients``); the values by the law itself, its message
kept and its field renamed to the file's.
"""

from __future__ import annotations

import numpy as np

from cams.io.document import check_keys, toml_integer
from cams.io.tomlwrite import value
from laws.base import Law
from laws.bernstein import from_power
from laws.errors import InputError, check_number, check_option, show_value
from laws.polynomial import PolynomialLaw
from laws.registry import LAWS
from laws.spline import MAX_DEGREE, SplineLaw

__all__ = ["LAW_KINDS", "LAW_KEYS", "law_from_table", "law_to_table", "toml_law_lines"]

#: The kinds of a law table.
LAW_KINDS = ("spline", "polynomial")
#: The keys of a law table of each kind, in their documented order.
LAW_KEYS = {
    "spline": ("kind", "name", "degree", "breaks", "coefficients"),
    "polynomial": ("kind", "name", "start", "end"),
}
_BOUNDARY = "at most 3 numbers: the normalized velocity, acceleration and jerk"


def law_from_table(table: dict, field: str) -> Law:
    """The law of a design file's law table.

    Parameters
    ----------
    table : dict
        The parsed ``[motion.law]`` table (see the module notes).
    field : str
        Its name in error messages, e.g. ``"motion[0].law"``.

    Returns
    -------
    SplineLaw or PolynomialLaw
        The normalized law (dimensionless), named by the table's ``name``,
        else by its kind.

    Raises
    ------
    InputError
        Naming the entry (``motion[0].law.kind``, ``motion[0].law.breaks``,
        ``motion[0].law.coefficients[1][2]``...): a missing or unknown kind,
        unknown keys (the allowed ones listed), wrong types, a degree the
        coefficients do not have, and every value the law refuses.
    """
    if not isinstance(table, dict):
        raise InputError(field, f"must be a law name or a law table, got {show_value(table)}")
    if "kind" not in table:
        raise InputError(f"{field}.kind", "is required in a law table: "
                         + ", ".join(f'"{k}"' for k in LAW_KINDS) + " (or give the law's name: law = \"poly345\")")
    kind = check_option(f"{field}.kind", table["kind"], LAW_KINDS)
    check_keys(table, LAW_KEYS[kind], field)
    name = table.get("name", kind)
    if not isinstance(name, str) or not name:
        raise InputError(f"{field}.name", f"must be a non-empty string, got {show_value(name)}")
    try:
        if kind == "spline":
            law: Law = _spline(table, field, name)
        else:
            start = _numbers(table.get("start", []), f"{field}.start", _BOUNDARY, most=3)
            end = _numbers(table.get("end", []), f"{field}.end", _BOUNDARY, most=3)
            law = PolynomialLaw.from_boundary(start=start, end=end, name=name)
    except InputError as e:
        if e.field.startswith(field):
            raise
        raise _renamed(e, field) from None
    _check_range(law, field)
    return law


#: Points at which a law table's S is checked to stay within [0, 1], and what it may leave by (normalized: 30 nm
#: on a 30 mm stroke; the motion design keeps its laws within half of it).
RANGE_POINTS = 4001
RANGE_TOL = 1e-6


def _check_range(law: Law, field: str) -> None:
    """Refuse a law whose S leaves [0, 1] (the follower would leave its stroke or swing): at RANGE_POINTS."""
    u = np.linspace(0.0, 1.0, RANGE_POINTS)
    S = law.evaluate(u)[0]
    j = int(np.argmax(np.maximum(S - 1.0, -S)))
    if S[j] > 1 + RANGE_TOL or S[j] < -RANGE_TOL:
        raise InputError(field, f"S leaves [0, 1]: S = {S[j]:.6g} at u = {u[j]:.4g}; a normalized rise keeps the "
                         "follower within its stroke (or swing)")


def _spline(table: dict, field: str, name: str) -> SplineLaw:
    f = f"{field}.coefficients"
    if "coefficients" not in table:
        raise InputError(f, "is required: one array of Bernstein coefficients per knot span, e.g. "
                         "[[0, 0, 0, 1, 1, 1]] (the 3-4-5 polynomial)")
    c = table["coefficients"]
    if not isinstance(c, list) or not c:
        raise InputError(f, "must be a non-empty array of arrays of numbers (one per knot span), "
                         f"got {show_value(c)}")
    rows = [_numbers(r, f"{f}[{j}]", "the Bernstein coefficients of one knot span") for j, r in enumerate(c)]
    if "degree" in table:
        degree = toml_integer(table, "degree", f"{field}.degree", default=1, lo=1, hi=MAX_DEGREE)
        for j, r in enumerate(rows):
            if len(r) != degree + 1:
                raise InputError(f, f"degree {degree} takes {degree + 1} coefficients a span, span {j} has {len(r)}")
    if "breaks" not in table:
        return SplineLaw.uniform(rows, name=name)
    breaks = _numbers(table["breaks"], f"{field}.breaks", "the knot spans' ends from 0 to 1")
    return SplineLaw(tuple(breaks), tuple(tuple(r) for r in rows), name=name)


def _numbers(value: object, field: str, what: str, *, most: int | None = None) -> list[float]:
    """``value`` as a list of floats: an array of finite numbers (``most`` at most)."""
    if not isinstance(value, list):
        raise InputError(field, f"must be an array of numbers ({what}), got {show_value(value)}")
    if most is not None and len(value) > most:
        raise InputError(field, f"takes {what}, got {len(value)} values")
    return [check_number(f"{field}[{i}]", v) for i, v in enumerate(value)]


def _renamed(e: InputError, field: str) -> InputError:
    """The law's own error on the file's field: ``spline.breaks`` -> ``motion[0].law.breaks``."""
    message = str(e)[len(e.field) + 2:] if e.field else str(e)
    key = e.field.split(".", 1)[1] if e.field.startswith(("spline.", "polynomial.")) else e.field
    return InputError(f"{field}.{key}" if key else field, message)


def law_to_table(law: Law) -> dict | str:
    """A law as a design file writes it: a law table, or a named law's name.

    Parameters
    ----------
    law : Law
        A :class:`SplineLaw`, a :class:`PolynomialLaw` (written as a spline of
        one span of its degree: its Bernstein coefficients), or one of the
        named laws of :data:`laws.registry.LAWS`.

    Returns
    -------
    dict or str
        ``{"kind": "spline", "name", "degree", "breaks", "coefficients"}``
        with Python floats (``repr`` writes each exactly, so the file reads
        back the same bits), or the named law's name.

    Raises
    ------
    InputError
        Field ``"law"``: any other law (a :class:`laws.table.TableLaw`, a law
        of one's own), or a polynomial above the spline's largest degree.

    Examples
    --------
    >>> from laws.polynomial import PolynomialLaw
    >>> t = law_to_table(PolynomialLaw((0, 0, 0, 10, -15, 6), name="345"))
    >>> t["degree"], t["coefficients"]
    (5, [[0.0, 0.0, 0.0, 1.0, 1.0, 1.0]])
    >>> law_to_table(LAWS["cycloidal"])
    'cycloidal'
    """
    if isinstance(law, PolynomialLaw):
        if law.degree > MAX_DEGREE:
            raise InputError("law", f"a polynomial of degree {law.degree} cannot be written as a law table: "
                             f"a spline's degree is at most {MAX_DEGREE}")
        b = from_power(law.degree) @ np.asarray(law.coefficients, float)
        law = SplineLaw((0.0, 1.0), (tuple(b.tolist()),), name=law.name)
    if isinstance(law, SplineLaw):
        return {
            "kind": "spline",
            "name": law.name,
            "degree": law.degree,
            "breaks": [float(x) for x in law.breaks],
            "coefficients": [[float(x) for x in r] for r in law.coefficients],
        }
    if isinstance(law, Law) and LAWS.get(law.name) == law:
        return law.name
    raise InputError("law", f"a {type(law).__name__} cannot be written in a design file: only spline and "
                     f"polynomial laws (as a law table) and the named laws ({', '.join(LAWS)})")


def toml_law_lines(table: dict | str, key: str = "motion.law") -> list[str]:
    """TOML lines of a law as :func:`law_to_table` gives it.

    Parameters
    ----------
    table : dict or str
        A law table, or a named law's name.
    key : str
        The table's dotted name.

    Returns
    -------
    list of str
        For a name, the one line ``law = "NAME"`` (a key of the ``[[motion]]``
        table); for a table, its header ``[motion.law]`` and one line a key,
        to follow the last ``[[motion]]`` table's own keys. Floats are written
        with ``repr``: read back, they are the same numbers.

    Examples
    --------
    >>> toml_law_lines({"kind": "spline", "coefficients": [[0.0, 0.1, 1.0]]})
    ['[motion.law]', 'kind = "spline"', 'coefficients = [[0.0, 0.1, 1.0]]']
    >>> toml_law_lines("poly345")
    ['law = "poly345"']
    """
    if isinstance(table, str):
        return [f"law = {value(table)}"]
    return [f"[{key}]", *(f"{k} = {value(v)}" for k, v in table.items())]
