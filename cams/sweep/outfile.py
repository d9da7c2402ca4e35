"""A sweep's written table read back: its columns, their units, and the rows a front keeps.

A sweep writes a CSV whose result columns carry their unit as a suffix (``R0_mm``,
``max_pressure_angle_rise_deg``), or Parquet (through pyarrow) with the same column names. The front
and the chart are computed from that file, so they work on a sweep written long ago, or streamed
row by row, as on one just solved. A column is named with or without its unit suffix (``R0`` or
``R0_mm``); the varied keys (dotted, ``follower.arm``) keep their design file's units and carry no
suffix.
"""

from __future__ import annotations

import csv
import io
import math
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from laws.errors import InputError

__all__ = [
    "UNITS",
    "PARQUET_SUFFIXES",
    "PARQUET_MAGIC",
    "SweepTable",
    "split_unit",
    "read_table",
    "table_of",
    "write_rows",
]

#: The names of a Parquet table (``cams sweep`` writes any other as CSV unless ``--format`` says Parquet).
PARQUET_SUFFIXES = (".parquet", ".pq")

#: The four bytes a Parquet file begins and ends with: a table is read as what it holds, not by its name.
PARQUET_MAGIC = b"PAR1"

#: The unit suffixes a result column's name may end with (``_mm``, ``_deg``...), longest tried first.
UNITS = (
    "mm",
    "deg",
    "MPa",
    "GPa",
    "um",
    "µm",
    "m",
    "s",
    "ms",
    "N",
    "Nm",
    "N_mm",
    "rpm",
    "Hz",
    "J",
    "kg",
    "W",
    "percent",
)


def split_unit(header: str) -> tuple[str, str]:
    """A column header -> (name, unit): ``"R0_mm"`` -> ``("R0", "mm")``; ``"verified"`` -> ``("verified", "")``.

    A dotted header (a varied design-file key) keeps its whole name and no unit.

    >>> split_unit("max_pressure_angle_rise_deg")
    ('max_pressure_angle_rise', 'deg')
    >>> split_unit("follower.arm")
    ('follower.arm', '')
    """
    if "." not in header and "[" not in header:
        for u in sorted(UNITS, key=len, reverse=True):
            if header.endswith("_" + u) and len(header) > len(u) + 1:
                return header[: -len(u) - 1], u
    return header, ""


@dataclass(frozen=True)
class SweepTable:
    """The rows of a sweep's output.

    Attributes
    ----------
    path : Path
        The file read.
    headers : tuple of str
        The columns as written (with their unit suffixes), in the file's order.
    names : tuple of str
        The same columns without their unit suffixes.
    units : dict
        Name -> unit (``""`` for flags, text and the varied keys).
    columns : dict
        Name -> values: a float array (NaN for an empty cell) for a column of numbers, a bool array for
        ``True``/``False`` flags, else a list of str or None (empty).
    cells : list of list of str
        The rows' cells as written (so rows copied to another CSV keep every digit).
    dropped : int
        Lines left out for having another count of cells than the header (a line cut short by an
        interrupted writer).
    """

    path: Path
    headers: tuple[str, ...]
    names: tuple[str, ...]
    units: dict
    columns: dict
    cells: list
    dropped: int

    def __len__(self) -> int:
        return len(self.cells)

    def column(self, name: str, field: str = "--pareto") -> str:
        """The column's name (no unit) for ``name`` given with or without its unit suffix.

        Raises
        ------
        InputError
            Naming ``field`` and listing the columns: ``name`` is neither a column nor a header.
        """
        if name in self.columns:
            return name
        if name in self.headers:
            return self.names[self.headers.index(name)]
        raise InputError(
            field,
            f"{name!r} is not a column of {self.path}; the columns are: "
            f"{', '.join(self.names)} (with or without the unit suffix)",
        )

    def label(self, name: str) -> str:
        """``"R0 (mm)"``: the column with its unit, for a table's header or a chart's axis."""
        u = self.units.get(name, "")
        return f"{name} ({u})" if u else name


def _cells_to_column(values: list[str]) -> np.ndarray | list:
    filled = [v for v in values if v != ""]
    if filled and all(v in ("True", "False") for v in filled):
        if len(filled) == len(values):
            return np.array([v == "True" for v in values], dtype=bool)
        return [None if v == "" else v == "True" for v in values]
    try:
        return np.array([math.nan if v == "" else float(v) for v in values], dtype=float)
    except ValueError:
        return [None if v == "" else v for v in values]


def _read_csv(path: Path, data: bytes, field: str) -> tuple[list[str], list[list[str]], int]:
    if b"\0" in data:  # text never holds a NUL byte: binary data read as text would give garbled cells
        raise InputError(field, f"cannot read {path}: it holds binary data, neither a CSV nor Parquet")
    try:
        rows = list(csv.reader(io.StringIO(data.decode("utf-8"), newline="")))
    except (UnicodeDecodeError, csv.Error) as e:
        raise InputError(field, f"cannot read {path} as a CSV: {e}") from None
    if not rows or not rows[0]:
        raise InputError(field, f"{path} is empty: no header line")
    header, body = rows[0], rows[1:]
    kept = [r for r in body if len(r) == len(header)]
    return header, kept, len(body) - len(kept)


def _read_parquet(path: Path, data: bytes | None, field: str) -> tuple[list[str], list[list[str]], int]:
    import importlib

    try:
        pa = importlib.import_module("pyarrow")  # optional: a module of no type stubs
        pq = importlib.import_module("pyarrow.parquet")
    except ImportError:
        raise InputError(field, f"{path} is Parquet: install pyarrow (pip install pyarrow) to read it") from None
    try:
        t = pq.read_table(path if data is None else pa.BufferReader(data))  # a folder of parts, or the bytes
    except (OSError, ValueError) as e:
        raise InputError(field, f"cannot read {path}: {e}") from None
    header = list(t.column_names)
    data_ = t.to_pydict()

    def cell(v) -> str:
        # null is an empty cell (what a sweep writes there); a float NaN is kept as "nan", an edit a front refuses
        if v is None:
            return ""
        if isinstance(v, float):
            r = repr(v)  # the shortest text that reads back the same number, as the CSV writer's
            return r[:-2] if r.endswith(".0") else r
        return str(v)

    cells = [[cell(data_[h][i]) for h in header] for i in range(t.num_rows)]
    return header, cells, 0


def _format_held(path: Path, data: bytes, field: str) -> str:
    """``"parquet"`` or ``"csv"``: what the bytes of the table at ``path`` are (its name does not decide).

    A Parquet file begins and ends with :data:`PARQUET_MAGIC`; anything else is read as a CSV. The sidecar
    ``path.sweep.json``, when there, must name the same format.

    Raises
    ------
    InputError
        Naming ``field``: Parquet's first mark without its last (a file cut short), a ``.parquet`` name on other
        bytes, or a sidecar that names the other format.
    """
    from cams.sweep.output import sidecar_format

    if data[:4] == PARQUET_MAGIC:
        if len(data) < 8 or data[-4:] != PARQUET_MAGIC:
            raise InputError(field, f"cannot read {path}: it begins as Parquet but does not end as one (cut short)")
        held = "parquet"
    elif path.suffix.lower() in PARQUET_SUFFIXES:
        raise InputError(field, f"cannot read {path}: named as Parquet, but it is not (no {PARQUET_MAGIC!r} marks)")
    else:
        held = "csv"
    said = sidecar_format(path)
    if said is not None and said != held:
        raise InputError(
            field,
            f"cannot read {path}: it holds {held}, but its sidecar says the sweep wrote {said} "
            "(an edited or replaced table)",
        )
    return held


def read_table(path: str | os.PathLike, field: str = "--from") -> SweepTable:
    """Read a sweep's output: CSV, or Parquet (through pyarrow), told apart by the bytes the file holds (Parquet
    begins and ends with ``PAR1``) whatever its name; a folder is read as Parquet parts.

    Raises
    ------
    InputError
        Naming ``field``: the file cannot be read, has no header, is binary but not Parquet, is Parquet cut
        short, is named ``.parquet`` and is not, holds another format than its sidecar says, or is Parquet
        without pyarrow.
    """
    p = Path(path)
    if p.is_dir():  # a folder of Parquet parts
        header, cells, dropped = _read_parquet(p, None, field)
    else:
        try:
            with open(p, "rb") as fh:  # a file, or a stream read once
                data = fh.read()
        except OSError as e:
            raise InputError(field, f"cannot read {path}: {e}") from None
        if _format_held(p, data, field) == "parquet":
            header, cells, dropped = _read_parquet(p, data, field)
        else:
            header, cells, dropped = _read_csv(p, data, field)
    return table_of(p, header, cells, dropped, field)


def table_of(
    path: str | os.PathLike, header: Sequence[str], cells: list | None = None, dropped: int = 0, field: str = "--from"
) -> SweepTable:
    """The :class:`SweepTable` of a ``header`` and its rows' ``cells`` (none: the table a sweep is about to write,
    whose columns a front's options are checked against before solving).

    Raises
    ------
    InputError
        Naming ``field``: a header that names one column twice (an edited table: which one would a front read?).
    """
    cells = [] if cells is None else cells
    twice = sorted({h for h in header if list(header).count(h) > 1})
    if twice:
        raise InputError(
            field, f"{path}: the header names the column {twice[0]!r} twice; a sweep's table names each column once"
        )
    names = [split_unit(h)[0] for h in header]
    if len(set(names)) != len(names):  # e.g. "R0" and "R0_mm" both: keep the headers whole
        names = list(header)
    units = {n: (split_unit(h)[1] if n != h else "") for n, h in zip(names, header, strict=True)}
    columns = {n: _cells_to_column([r[j] for r in cells]) for j, n in enumerate(names)}
    return SweepTable(
        path=Path(path),
        headers=tuple(header),
        names=tuple(names),
        units=units,
        columns=columns,
        cells=cells,
        dropped=dropped,
    )


def write_rows(path: str | os.PathLike, table: SweepTable, rows: Sequence[int] | np.ndarray, field: str) -> Path:
    """Write ``table``'s header and the ``rows`` (positions, in that order) as a CSV, whole or not at all."""
    from cams.io.files import atomic_write

    def write(tmp):
        with open(tmp, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(table.headers)
            for i in rows:
                w.writerow(table.cells[int(i)])

    return atomic_write(path, field, write)
