"""What a sweep varies: the keys and their values, the base design files, grid or zip, and the sweep file.

A sweep's combinations are numbered from 0 (the CSV's ``index``): the base files are the outer axis (one file:
one block), then the keys' values, as a full grid (:func:`itertools.product`'s order: the last key fastest) or,
with ``mode = "zip"``, paired (the k-th value of every key together; all keys give as many values). A
combination is computed from its index (:meth:`Grid.combination`), so no list of them is held.

A value is a number (an integral one is written to the design as an integer, e.g. ``solve.samples``), a boolean
(``true``, ``false``) or a string (a law's name, a closure, a sense...). Values are checked against the design
file's schema (:mod:`cams.io.designfile`) before anything is solved: a value of the wrong kind for its key (a
number for a closure, a law that does not exist) is an :class:`~laws.errors.InputError` naming the key. A value of
the right kind that makes one design infeasible (a swing of -5 degrees) is that design's row, not an error.
"""

from __future__ import annotations

import copy
import hashlib
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from laws.errors import CamsError, InputError

__all__ = ["MAX_DESIGNS", "MODES", "parse_vary", "parse_value", "key_parts", "set_key", "as_number", "BaseFile",
           "Grid", "Chunk", "make_grid", "read_sweep_file"]

#: At most this many designs in one sweep (files times the keys' combinations): about an hour on two cores.
MAX_DESIGNS = 100_000

#: How several keys combine: every combination (``grid``) or the k-th values together (``zip``).
MODES = ("grid", "zip")

_NUMBER = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?")
#: nan, inf and infinity, one sign at most, any case (what ``float`` reads of them)
_NOT_FINITE = re.compile(r"[+-]?(nan|inf|infinity)", re.IGNORECASE)


def parse_value(text: str) -> int | float | bool | str:
    """One listed value: a number (``"120"``, ``"0.5"``), ``true``/``false``, else the string itself (quotes
    around it removed: ``"'cw'"`` is ``cw``)."""
    t = text.strip()
    if _NUMBER.fullmatch(t):
        return float(t)
    if t in ("true", "false"):
        return t == "true"
    if len(t) >= 2 and t[0] == t[-1] and t[0] in "'\"":
        t = t[1:-1]
    return t


def _float(text: str) -> float | None:
    """``text`` read as a float: a number as a listed value reads (:func:`parse_value`), or ``nan``, ``inf``,
    ``infinity`` (signed, any case); else None."""
    t = text.strip()
    return float(t) if _NUMBER.fullmatch(t) or _NOT_FINITE.fullmatch(t) else None


def parse_vary(spec: str) -> tuple[str, Any]:
    """``"KEY=a:b:n"`` -> (KEY, n values from a to b); ``"KEY=v1,v2,..."`` -> the listed values.

    Listed values are numbers (an array of floats when all are) or words (``motion[0].law=cycloidal,poly345``:
    a tuple), each checked against the design file's schema by the sweep.

    >>> parse_vary("limits.closure=force,form")
    ('limits.closure', ('force', 'form'))
    """
    if "=" not in spec:
        raise InputError("--vary", f"{spec!r} must look like KEY=a:b:n or KEY=v1,v2")
    key, rng = spec.split("=", 1)
    key = key.strip()
    if not key:
        raise InputError("--vary", f"{spec!r} names no key")
    key_parts(key)
    vals: Any
    parts = rng.split(":")
    ends = [e for e in map(_float, parts) if e is not None]
    if len(parts) > 1 and len(ends) == len(parts):  # a:b:n, every part a number (nan and inf too)
        if len(ends) == 3 and not all(math.isfinite(e) for e in ends):  # nan:120:3, 100:inf:3, 1:2:1e400
            raise InputError("--vary", f"{spec!r}: a range a:b:n takes finite numbers")
        if len(ends) != 3 or not ends[2].is_integer() or ends[2] < 1:
            raise InputError("--vary", f"{spec!r}: a range is a:b:n with a count n >= 1")
        a, b, n = ends[0], ends[1], int(ends[2])
        if n == 1 and a != b:  # linspace would keep a alone: b silently dropped
            raise InputError("--vary", f"{spec!r}: a range of one value has a == b (or give the value alone)")
        if n > MAX_DESIGNS:
            raise InputError("--vary", f"{spec!r}: at most {MAX_DESIGNS:,} values, got {n:,}")
        vals = np.linspace(a, b, n)
    else:
        items = [p for p in rng.split(",")]
        if any(not p.strip() for p in items):
            raise InputError("--vary", f"{spec!r}: an empty value in the list (a range is a:b:n, a list v1,v2)")
        parsed = [parse_value(p) for p in items]
        if all(isinstance(v, float) for v in parsed):
            vals = np.array(parsed, dtype=float)
        else:
            vals = tuple(parsed)
    if isinstance(vals, np.ndarray) and not np.all(np.isfinite(vals)):
        raise InputError("--vary", f"{spec!r}: values must be finite numbers")
    return key, vals


_SEGMENT = re.compile(r"([^.\[\]]+)((?:\[\d+\])*)")


def key_parts(key: str, field: str = "--vary") -> tuple[str, ...]:
    """The parts of a dotted key: ``"motion[0].angle"`` and ``"motion.0.angle"`` -> ``("motion", "0", "angle")``.

    Raises
    ------
    InputError
        Naming ``field``: an empty part or a malformed ``[index]``.
    """
    parts: list[str] = []
    for seg in key.split("."):
        m = _SEGMENT.fullmatch(seg.strip())
        if not m:
            raise InputError(field, f"{key!r} is not a dotted key (table.key, list items as motion.0 or motion[0])")
        parts.append(m.group(1))
        parts += re.findall(r"\[(\d+)\]", m.group(2))
    return tuple(parts)


def _index(node: list, p: str, key: str) -> int:
    if not p.isdigit() or int(p) >= len(node):
        raise InputError("--vary", f"{key!r}: {p!r} is not an index of the list (0 to {len(node) - 1})")
    return int(p)


def set_key(d: dict, key: str, value: Any) -> None:
    """Set the dotted ``key`` of the design-file dict ``d`` to ``value`` (tables made as needed, list items by
    index)."""
    parts = key_parts(key)
    node: Any = d
    for k, p in enumerate(parts[:-1]):
        if isinstance(node, list):
            node = node[_index(node, p, key)]
        else:
            node = node.setdefault(p, {})
        if not isinstance(node, (dict, list)):
            raise InputError("--vary", f"{key!r}: {'.'.join(parts[:k + 1])!r} is a value, not a table or list")
    last = parts[-1]
    if isinstance(node, list):
        node[_index(node, last, key)] = value
    else:
        node[last] = value


def as_number(v: Any) -> Any:
    """A value as written to a design: an integral number as int (for keys like ``solve.samples``), another
    number as float, a string or boolean as it is."""
    if isinstance(v, (bool, np.bool_)):
        return bool(v)
    if isinstance(v, str):
        return v
    f = float(v)
    return int(f) if f.is_integer() and abs(f) < 2**53 else f


@dataclass(frozen=True)
class BaseFile:
    """One base design: its label (the path as given: the CSV's ``file``), its parsed dict and the SHA-256 of its
    bytes (the sweep's identity; empty for a dict given through the API)."""

    label: str
    design: dict
    sha256: str = ""


@dataclass(frozen=True)
class Grid:
    """A sweep's combinations: base files x (the keys' values as a grid, or zipped).

    Attributes
    ----------
    files : tuple of BaseFile
    keys : tuple of str
        Dotted keys as given.
    values : tuple of tuple
        Each key's values (numbers, strings, booleans), as given.
    mode : {"grid", "zip"}
    method : str or None
        Overrides each design's ``[solve] method``.
    """

    files: tuple[BaseFile, ...]
    keys: tuple[str, ...]
    values: tuple[tuple, ...]
    mode: str = "grid"
    method: str | None = None

    @property
    def per_file(self) -> int:
        """Combinations of the keys (one file's block)."""
        if not self.keys:
            return 1
        if self.mode == "zip":
            return len(self.values[0])
        return math.prod(len(v) for v in self.values)

    @property
    def size(self) -> int:
        """Designs in the sweep."""
        return len(self.files) * self.per_file

    def combination(self, index: int) -> tuple[int, tuple]:
        """``(file number, the keys' values)`` of combination ``index`` (0 to :attr:`size` - 1)."""
        f, rest = divmod(index, self.per_file)
        if self.mode == "zip":
            return f, tuple(v[rest] for v in self.values)
        out = []
        for vals in reversed(self.values):  # the last key fastest, as itertools.product
            rest, k = divmod(rest, len(vals))
            out.append(vals[k])
        return f, tuple(reversed(out))

    def design_dict(self, index: int) -> tuple[dict, dict]:
        """The design-file dict of combination ``index`` and its row's first cells (``index``, ``file``, the keys'
        values)."""
        return self.chunk([index]).design_dict(0)

    def identity(self) -> dict:
        """What makes this sweep this sweep (the sidecar file's content): its files with their hashes, keys,
        values, mode and method. Two runs with equal identities write the same rows."""
        return {"files": [{"path": b.label, "sha256": b.sha256} for b in self.files], "keys": list(self.keys),
                "values": [[as_number(v) for v in vals] for vals in self.values], "mode": self.mode,
                "method": self.method}

    def chunk(self, indexes: list[int]) -> Chunk:
        """What a worker needs to build the designs of combinations ``indexes`` (not the whole grid's values)."""
        return Chunk(self.files, self.keys, self.method, tuple((i, *self.combination(i)) for i in indexes))


@dataclass(frozen=True)
class Chunk:
    """Combinations sent to a worker together: the base files, the keys, the method and, per combination,
    ``(index, file number, the keys' values)``."""

    files: tuple[BaseFile, ...]
    keys: tuple[str, ...]
    method: str | None
    items: tuple[tuple[int, int, tuple], ...]

    def design_dict(self, k: int) -> tuple[dict, dict]:
        """The design-file dict of the chunk's ``k``-th combination and its row's first cells (``index``,
        ``file``, the keys' values)."""
        index, f, vals = self.items[k]
        d = copy.deepcopy(self.files[f].design)
        row: dict[str, Any] = {"index": index, "file": self.files[f].label}
        for key, v in zip(self.keys, vals, strict=True):
            set_key(d, key, as_number(v))
            row[key] = as_number(v)
        return d, row


def _message(e: CamsError) -> str:
    """An error's words without its field."""
    s, f = str(e), getattr(e, "field", "") or ""
    return s[len(f) + 2:] if f and s.startswith(f + ": ") else s


def _kind_error(e: CamsError) -> bool:
    """Whether an error says a value is of the wrong kind for its key (not merely out of range)."""
    s = str(e)
    return any(w in s for w in ("must be a number, got", "is not a valid option", "unknown law", "must be a string",
                                "must be a table", "must be an integer", "must be [x, y]", "needs a list of",
                                "must be an array"))


def _involves(field: str, keys: tuple[str, ...]) -> bool:
    """Whether an error about ``field`` can come from the varied ``keys``.

    It does when one is a prefix of the other (``motion`` and ``motion.0.angle``)
    or both are items of the same list (``motion[3].angle`` and ``motion.0.angle``:
    the phases' angles share the turn).
    """
    try:
        f = key_parts(field) if field else ()
    except InputError:
        f = tuple(field.split("."))
    if not f:
        return True  # an error naming no field: cannot tell, keep it a row
    for key in keys:
        k = key_parts(key)
        n = min(len(f), len(k))
        if f[:n] == k[:n]:
            return True
        if len(f) > 1 and len(k) > 1 and f[0] == k[0] and f[1].isdigit() and k[1].isdigit():
            return True
    return False


def _probe(base: dict, assign: dict[str, Any]) -> CamsError | None:
    from cams.io.designfile import design_from_dict

    d = copy.deepcopy(base)
    for k, v in assign.items():
        set_key(d, k, as_number(v))
    try:
        design_from_dict(d)
    except CamsError as e:
        return e
    return None


def _check_base(base: dict, keys: tuple[str, ...], first: tuple, last: tuple,
                origin: str = "--vary") -> InputError | None:
    """A base design that is wrong whatever the varied keys are: its error (exit 2, not a table of the same
    error); an unknown varied key: an error naming ``origin`` (where the keys were given); None when the rows can
    say what is wrong."""
    e = _probe(base, dict(zip(keys, first, strict=True)))
    if e is None:
        return None
    if "unknown key" in str(e):
        b = _probe(base, {})
        if b is not None and str(b) == str(e):
            return e  # type: ignore[return-value]  # the design file's own unknown key
        # a varied key that does not exist in the schema is a mistake in the sweep, not an infeasible design
        return InputError(origin, str(e))
    if _involves(getattr(e, "field", "") or "", keys):
        return None  # the varied values may be at fault: the rows say so
    e2 = _probe(base, dict(zip(keys, last, strict=True)))
    if e2 is not None and str(e2) == str(e):
        return e  # type: ignore[return-value]  # the base design itself is wrong
    return None


def _check_kinds(grid: Grid, origin: str = "--vary") -> None:
    """Each value of each key, of every kind given, tried in a design of each base file (the other keys at their
    first values): a value of the wrong kind for its key is refused, naming the key and where it was given
    (``origin``)."""
    for b in grid.files:
        first = dict(zip(grid.keys, (v[0] for v in grid.values), strict=True))
        for key, vals in zip(grid.keys, grid.values, strict=True):
            tried: set = set()
            for v in vals:
                # numbers: one of each kind is enough; every word is tried (a law name may not exist)
                tag = v if isinstance(v, str) else type(as_number(v))
                if tag in tried:
                    continue
                tried.add(tag)
                e = _probe(b.design, {**first, key: v})
                if e is None or not _kind_error(e):
                    continue
                f = getattr(e, "field", "") or ""
                try:
                    same = key_parts(f) == key_parts(key)
                except InputError:
                    same = False
                if same:
                    what = _message(e)
                    given = (f"--vary {key}={as_number(v)}" if origin == "--vary"
                             else f"{origin} [vary] {key} = {as_number(v)!r}")
                    raise InputError(key, f"{what} ({given})")


def make_grid(files: list[BaseFile], vary: list[tuple[str, Any]], *, mode: str = "grid",
              method: str | None = None, origin: str = "--vary") -> Grid:
    """The sweep's grid, checked before anything is solved. ``origin`` names where the keys and values were given
    in the errors about them (``"--vary"``, or ``"--sweep-file S.toml"``'s ``[vary]``).

    Raises
    ------
    InputError
        A key varied twice; no values; keys of unequal counts with ``mode = "zip"``; more than
        :data:`MAX_DESIGNS` designs; a key that does not exist in the schema; a value of the wrong kind for its
        key; a base design wrong whatever the varied values (its own error).
    """
    if mode not in MODES:
        raise InputError("mode", f"{mode!r} is not a valid option, must be one of 'grid', 'zip'")
    if not files:
        raise InputError("FILE", "the sweep has no base design file")
    keys = tuple(k for k, _ in vary)
    seen: dict[tuple[str, ...], str] = {}  # key parts -> the key as given
    for key in keys:
        parts = key_parts(key)
        if parts in seen:
            same = "" if seen[parts] == key else f" (as {seen[parts]!r})"
            raise InputError(origin, f"{key!r} is varied twice{same}; give each key once with all its values")
        seen[parts] = key
    values = tuple(tuple(v.tolist() if isinstance(v, np.ndarray) else v) for _, v in vary)
    for key, vals in zip(keys, values, strict=True):
        if len(vals) == 0:
            raise InputError(origin, f"{key!r} has no values")
    if mode == "zip" and len({len(v) for v in values}) > 1:
        counts = ", ".join(f"{k}: {len(v)}" for k, v in zip(keys, values, strict=True))
        raise InputError("--zip", f"zipped keys give as many values each, got {counts}")
    count = len(files) * (math.prod(len(v) for v in values) if mode == "grid" else len(values[0]) if values else 1)
    if count > MAX_DESIGNS:  # before anything looks at the values one by one
        raise InputError(origin, f"the sweep has {count:,} designs; at most {MAX_DESIGNS:,} are accepted")
    if mode == "grid":  # the same designs solved twice (zip pairs may repeat one key's value)
        for key, vals in zip(keys, values, strict=True):
            held: set = set()  # equal values hash alike (100 and 1e2): one pass, not a comparison of every pair
            for v in vals:
                if v in held:
                    raise InputError(origin, f"{key!r}: the value {as_number(v)!r} is given twice; give each once")
                held.add(v)
    grid = Grid(files=tuple(files), keys=keys, values=values, mode=mode, method=method)
    first = tuple(v[0] for v in values)
    last = tuple(v[-1] for v in values)
    errors = [_check_base(b.design, keys, first, last, origin) for b in files]
    for b, e in zip(files, errors, strict=True):
        if e is not None and (e.field != origin or all(x is not None for x in errors)):
            if len(files) > 1 and e.field != origin:
                raise InputError(e.field, f"{_message(e)} (in {b.label})")
            raise e
    _check_kinds(grid, origin)
    return grid


def file_hash(path: str | Path) -> str:
    """SHA-256 of a file's bytes (hex)."""
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


#: The keys of a sweep file.
SWEEP_FILE_KEYS = {"files", "mode", "method", "vary"}


def read_sweep_file(path: str | Path) -> tuple[list[str], list[tuple[str, Any]], str, str | None]:
    """A sweep file (TOML): ``(base files, [(key, values)], mode, method)``.

    ::

        files = ["rocker_force.toml", "rocker_form.toml"]   # relative to the sweep file
        mode = "grid"                                       # or "zip"; default "grid"
        method = "exact"                                    # optional, overrides [solve] method
        [vary]
        "motion[0].law" = ["cycloidal", "poly345"]          # a list of values (numbers or words)
        "follower.arm" = "100:200:3"                        # or a range a:b:n as a string

    Raises
    ------
    InputError
        Naming the sweep file's key at fault (``--sweep-file: vary.follower.arm ...``).
    """
    from cams.io.document import read_toml

    p = Path(path)
    try:
        d = read_toml(p)
    except InputError as e:  # the sweep file itself, not a design FILE
        raise InputError("--sweep-file", str(e).removeprefix(f"{e.field}: ")) from None
    for k in d:
        if k not in SWEEP_FILE_KEYS:
            raise InputError("--sweep-file", f"unknown key {k!r}, must be one of files, mode, method, vary")
    files = d.get("files")
    if not isinstance(files, list) or not files or not all(isinstance(f, str) and f for f in files):
        raise InputError("--sweep-file", "files must be a non-empty list of design files (paths relative to the "
                         "sweep file)")
    paths = [str(p.parent / f) if not Path(f).is_absolute() else f for f in files]
    mode = d.get("mode", "grid")
    if mode not in MODES:
        raise InputError("--sweep-file", f"mode {mode!r} is not a valid option, must be one of 'grid', 'zip'")
    method = d.get("method")
    if method is not None and method not in ("exact", "convex", "exhaustive"):
        raise InputError("--sweep-file", f"method {method!r} is not a valid option, must be one of 'exact', "
                         "'convex', 'exhaustive'")
    vary_t = d.get("vary", {})
    if not isinstance(vary_t, dict):
        raise InputError("--sweep-file", "vary must be a table of KEY = [values] or KEY = \"a:b:n\"")
    vary: list[tuple[str, Any]] = []
    for key, v in vary_t.items():
        if isinstance(v, dict):
            raise InputError("--sweep-file", f"vary.{key}: quote dotted keys (\"{key}.{next(iter(v), '')}\" = ...)")
        if isinstance(v, str):
            try:
                vary.append(parse_vary(f"{key}={v}"))
            except InputError as e:  # the sweep file's entry, not a --vary option
                raise InputError("--sweep-file", f"vary.{key} = {v!r}: {str(e).split(': ', 2)[-1]}") from None
        elif isinstance(v, list) and v and all(isinstance(x, (int, float, str, bool)) for x in v):
            nums = [x for x in v if isinstance(x, (int, float)) and not isinstance(x, bool)]
            key_parts(key, "--sweep-file")
            if len(nums) == len(v):
                if not all(math.isfinite(x) for x in nums):
                    raise InputError("--sweep-file", f"vary.{key}: values must be finite numbers")
                vary.append((key, np.array(nums, dtype=float)))
            else:
                vary.append((key, tuple(v)))
        else:
            raise InputError("--sweep-file", f"vary.{key}: must be a non-empty list of values or a range \"a:b:n\"")
    return paths, vary, mode, method
