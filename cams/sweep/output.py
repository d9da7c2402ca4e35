"""A sweep's table on disk: its columns, its cells, the streamed CSV or Parquet, the sidecar identity, resume.

Rows are written as their chunk of designs completes, whole lines only (a CSV line is written in one call and
flushed; a text cell never holds a line break), so an interrupted sweep keeps every row done. A finished sweep's
CSV is rewritten in index order (whole or not at all). Parquet (pyarrow, the optional extra ``parquet``) is
written in parts: each chunk's rows one part file ``OUT.parts/part-NNNNNN.parquet`` (whole or not at all), the
parts joined into ``OUT`` at the end and removed.

Beside the output, ``OUT.sweep.json`` holds the sweep's identity (:meth:`cams.sweep.grid.Grid.identity` and the
header): ``--resume`` continues a sweep only when the identity is the same, drops a partial last line (a sweep
killed while writing) and skips the indexes already written.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import shutil
from pathlib import Path
from typing import Any

import numpy as np

from cams.batch import SIZE_KEYS, VERDICT_KEYS
from laws.errors import InputError

__all__ = ["COLUMNS", "COLUMN_UNITS", "LENGTHS", "csv_header", "csv_row", "cell", "sidecar_path", "write_identity",
           "check_out", "sidecar_format", "SIDECAR_SUFFIX", "check_identity", "CsvSink", "ParquetSink", "sink_for",
           "read_rows", "failed"]

#: Result columns after ``index``, ``file`` and the varied keys: a sized cam's numbers (the batch's, the one home of
#: a row's keys), what only the per-design results carry (the rise's Ca, the contact stress, the residual
#: vibration), then the verdict.
COLUMNS = (*SIZE_KEYS, "Ca_rise", "max_contact_stress", "residual_vibration", *VERDICT_KEYS)

#: Unit of each result column, written into the header as ``name_unit`` (none for flags, text and ratios).
COLUMN_UNITS = {"R0": "mm", "L": "mm", "offset": "mm", "centre_x": "mm", "centre_y": "mm", "blank_diameter": "mm",
                "max_pressure_angle_rise": "deg", "max_pressure_angle_return": "deg", "max_contact_stress": "MPa",
                "error_bound": "mm"}

#: The sized lengths: written to the row's error bound (when it has one).
LENGTHS = ("R0", "L", "offset", "centre_x", "centre_y")

#: Significant digits of a result that carries no bound of its own: float64 arithmetic through trigonometry and
#: root finding carries about 13; 12 drop the last digit's noise (``120``, not ``120.00000000000001``).
DIGITS = 12


def csv_header(keys: tuple[str, ...]) -> list[str]:
    """The header: ``index``, ``file``, the varied keys (units as in the design file), then :data:`COLUMNS` with
    their units.

    >>> csv_header(("follower.arm",))[:4]
    ['index', 'file', 'follower.arm', 'R0_mm']
    """
    return ["index", "file", *keys] + [f"{c}_{COLUMN_UNITS[c]}" if c in COLUMN_UNITS else c for c in COLUMNS]


def _fixed(v: float, decimals: int) -> str:
    s = f"{v:.{decimals}f}"
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def cell(name: str, v: Any, error_bound: float | None = None) -> str:
    """One cell's text: None empty; a float at the precision it carries.

    A varied input to 15 significant digits (a range's values without linspace's last-digit noise: ``0.3``); a
    sized length (:data:`LENGTHS`) to one decimal below its row's ``error_bound`` (the solver's proven bound on
    it), never more digits than the float holds; any other result to :data:`DIGITS` significant digits.
    Booleans as ``True``/``False``; a text's line breaks as spaces (one row, one line).

    >>> cell("R0", 13.240793033539255, 1.37e-12), cell("max_pressure_angle_rise", 45.00000000000015)
    ('13.2407930335393', '45')
    >>> cell("blank_diameter", 120.00000000000001), cell("follower.arm", 0.30000000000000004)
    ('120', '0.3')
    """
    if v is None:
        return ""
    if isinstance(v, bool):
        return str(v)
    if isinstance(v, str):
        return v.replace("\r", " ").replace("\n", " ")
    if isinstance(v, int):
        return str(v)
    f = float(v)
    if not math.isfinite(f):
        return ""
    if name not in COLUMNS:
        return f"{f:.15g}"
    if name in LENGTHS and error_bound is not None and error_bound > 0 and math.isfinite(error_bound) and f != 0:
        decimals = max(0, 1 - math.floor(math.log10(error_bound)))
        lead = math.floor(math.log10(abs(f))) + 1  # digits before the point
        if lead + decimals <= 17:
            return _fixed(f, decimals)
        return repr(f)
    return f"{f:.{DIGITS}g}"


def csv_row(row: dict) -> list[str]:
    """A row's cells in its own key order (:func:`csv_header`'s), each by :func:`cell`.

    >>> csv_row({"R0": 13.240793033539259, "max_pressure_angle_rise": 29.999999999999996, "error_bound": 1.4e-12})
    ['13.2407930335393', '30', '1.4e-12']
    """
    eb = row.get("error_bound")
    return [cell(k, v, eb) for k, v in row.items()]


#: The flags a row may hold; a usable row holds each of them True (:func:`failed`).
FLAGS = ("verified", "buildable")


def failed(row: dict) -> bool:
    """A row that is not usable: no solution (an ``error``) or failures of the one rule (:mod:`cams.assess`).

    Either cell counts when it holds something: None, NaN (an empty Parquet cell) and blank text are empty, as
    in a table read back. A row that holds ``verified`` or ``buildable`` fails unless that flag is True (``True``
    in a table read back): a row edited to say it failed, its ``failures`` left empty, is not usable. A row the
    sweep writes says the same in its ``failures`` (the one rule fails a row that is not verified or not
    buildable with a reason)."""
    return (_given(row.get("error")) or _given(row.get("failures"))
            or any(k in row and not _true(row[k]) for k in FLAGS))


def _true(v) -> bool:
    """A flag that is set: True (numpy's too) or the text ``True`` (a column read back with other words in it)."""
    return v is True or (isinstance(v, np.bool_) and bool(v)) or v == "True"


def _given(v) -> bool:
    return bool(v) and not (isinstance(v, float) and math.isnan(v)) and not (isinstance(v, str) and not v.strip())


#: What a sidecar's name ends with: ``OUT.sweep.json`` beside the table ``OUT``.
SIDECAR_SUFFIX = ".sweep.json"


def sidecar_path(out: Path) -> Path:
    """``OUT.sweep.json`` beside the output ``OUT``."""
    return out.with_name(out.name + SIDECAR_SUFFIX)


def _is_identity(path: Path) -> bool:
    """Whether ``path`` holds a sweep's identity: a JSON object with the keys every sidecar has."""
    try:
        held = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return isinstance(held, dict) and {"files", "keys", "values", "mode", "method", "format", "columns"} <= set(held)


def sidecar_format(out: Path) -> str | None:
    """The format (``"csv"``, ``"parquet"``) the sidecar beside ``out`` says the sweep wrote; None: no
    sidecar, or none that says."""
    side = sidecar_path(out)
    if not side.is_file() or not _is_identity(side):
        return None
    fmt = json.loads(side.read_text(encoding="utf-8"))["format"]
    return fmt if fmt in ("csv", "parquet") else None


def check_out(out: Path, *, resumed: bool = False) -> None:
    """``--out`` may not write over another sweep's files: it may not be a sidecar's name (``*.sweep.json``),
    and where its own sidecar goes there may be nothing, or a sweep's identity (this table's, from an
    earlier run), nothing else (another sweep's table named ``OUT.sweep.json``, or any other file).
    ``resumed``: the sweep goes on with the table there, so its sidecar is read (:func:`check_identity`),
    not written.

    Raises
    ------
    InputError
        Naming ``--out``, with what is allowed.
    """
    if out.name.lower().endswith(SIDECAR_SUFFIX):
        raise InputError("--out", f"{str(out)!r} ends in {SIDECAR_SUFFIX}, the name of a sweep's sidecar (the "
                         "identity beside its table): give the table another name, .csv or .parquet")
    side = sidecar_path(out)
    if not resumed and (side.exists() or side.is_symlink()) and not _is_identity(side):
        raise InputError("--out", f"{str(out)!r}: its sidecar would replace {side}, which is not a sweep's "
                         "identity (another sweep's table, or another file): give --out another name")


def write_identity(out: Path, identity: dict) -> Path:
    """Write the sweep's identity beside ``out`` (whole or not at all)."""
    from cams.io.files import atomic_write

    text = json.dumps(identity, indent=1) + "\n"
    return atomic_write(sidecar_path(out), "--out", lambda tmp: Path(tmp).write_text(text, encoding="utf-8"))


def check_identity(out: Path, identity: dict) -> None:
    """``--resume``: the sidecar beside ``out`` must hold ``identity``.

    Raises
    ------
    InputError
        Naming ``--resume``: no sidecar, or another sweep's.
    """
    side = sidecar_path(out)
    try:
        held = json.loads(side.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise InputError("--resume", f"{out} has no {side.name} beside it: it was not written by cams sweep, or "
                         "not by this version; run without --resume to start again") from None
    except (OSError, ValueError) as e:
        raise InputError("--resume", f"{side} cannot be read ({e})") from None
    if not isinstance(held, dict):
        raise InputError("--resume", f"{side} is not a sweep's identity (a JSON object); run without --resume to "
                         "start again")
    if held != identity:
        what = [k for k in identity if held.get(k) != identity[k]] or ["format"]
        raise InputError("--resume", f"{out} holds another sweep (its {', '.join(what)} differ); run without "
                         "--resume, or give the same files, keys, values, mode and method")


class CsvSink:
    """The streamed CSV: a header, then each chunk's rows appended and flushed, whole lines only."""

    def __init__(self, path: Path, header: list[str], *, append: bool):
        self.path, self.header = path, header
        if append:
            self._fh = open(path, "a", newline="", encoding="utf-8")
        else:
            self._fh = open(path, "w", newline="", encoding="utf-8")
            self._fh.write(self._lines([header]))
            self._fh.flush()

    @staticmethod
    def _lines(rows: list[list[str]]) -> str:
        buf = io.StringIO()
        csv.writer(buf, lineterminator="\n").writerows(rows)
        return buf.getvalue()

    def write(self, rows: list[dict]) -> None:
        """Append ``rows`` (in one write, flushed)."""
        if rows:
            self._fh.write(self._lines([csv_row(r) for r in rows]))
            self._fh.flush()

    def close(self, *, finished: bool) -> None:
        """Close; a finished sweep's file is rewritten in index order (whole or not at all)."""
        self._fh.close()
        if finished:
            from cams.io.files import atomic_write

            header, rows = _read_csv(self.path)
            rows.sort(key=lambda r: int(r[0]))
            atomic_write(self.path, "--out", lambda tmp: Path(tmp).write_text(self._lines([header, *rows]),
                                                                               encoding="utf-8"))


def _read_csv(path: Path) -> tuple[list[str], list[list[str]]]:
    with open(path, newline="", encoding="utf-8") as fh:
        lines = list(csv.reader(fh))
    return (lines[0] if lines else []), lines[1:]


def _typed(header: list[str], text_rows: list[list[str]]):
    """Parquet's columns from the cells' texts: numbers as float64 (the index int64), flags as booleans, text as
    strings, an empty cell as null; a varied key's column numeric when all its values are numbers."""
    import pyarrow as pa

    cols: dict[str, Any] = {}
    for j, name in enumerate(header):
        texts = [r[j] for r in text_rows]
        if name == "index":
            cols[name] = pa.array([int(t) for t in texts], pa.int64())
        elif name in ("verified", "buildable"):  # flags: csv_header gives them no unit
            cols[name] = pa.array([None if t == "" else t == "True" for t in texts], pa.bool_())
        elif name in ("file", "failures", "error"):
            cols[name] = pa.array([t or None for t in texts], pa.string())
        else:
            try:
                cols[name] = pa.array([None if t == "" else float(t) for t in texts], pa.float64())
            except ValueError:
                cols[name] = pa.array([t or None for t in texts], pa.string())
    return pa.table(cols)


class ParquetSink:
    """Parquet in parts: each chunk's rows one part file beside the output; joined into it when finished.

    The cells are those of the CSV (:func:`cell`'s precision), typed: a sweep's Parquet and CSV hold the same
    numbers.
    """

    def __init__(self, path: Path, header: list[str], *, append: bool):
        import pyarrow  # noqa: F401  # the extra is there before anything is solved

        self.path, self.header = path, header
        self.parts = parts_dir(path)
        self._old = append and path.exists()  # a finished sweep's table, resumed: its rows are kept
        if not append:
            shutil.rmtree(self.parts, ignore_errors=True)
        self.parts.mkdir(exist_ok=True)
        self._n = len(list(self.parts.glob("part-*.parquet")))

    def write(self, rows: list[dict]) -> None:
        """One part file with ``rows`` (whole or not at all)."""
        if not rows:
            return
        import pyarrow.parquet as pq

        from cams.io.files import atomic_write

        table = _typed(self.header, [csv_row(r) for r in rows])
        while (self.parts / f"part-{self._n:06d}.parquet").exists():
            self._n += 1
        atomic_write(self.parts / f"part-{self._n:06d}.parquet", "--out",
                     lambda tmp: pq.write_table(table, tmp), suffix=".parquet")
        self._n += 1

    def close(self, *, finished: bool) -> None:
        """A finished sweep: the parts (and a former complete output) joined into the output in index order."""
        if not finished:
            return
        import pyarrow as pa
        import pyarrow.parquet as pq

        from cams.io.files import atomic_write

        tables = [pq.read_table(p) for p in sorted(self.parts.glob("part-*.parquet"))]
        if self._old:
            tables.insert(0, pq.read_table(self.path))
        table = pa.concat_tables(tables) if tables else _typed(self.header, [])
        table = table.sort_by("index")
        atomic_write(self.path, "--out", lambda tmp: pq.write_table(table, tmp), suffix=".parquet")
        shutil.rmtree(self.parts, ignore_errors=True)


def parts_dir(out: Path) -> Path:
    """The Parquet parts' folder beside ``out``."""
    return out.with_name(out.name + ".parts")


def sink_for(fmt: str, out: Path, keys: tuple[str, ...], *, append: bool):
    """The writer of format ``fmt`` (``"csv"`` or ``"parquet"``) for ``out``."""
    header = csv_header(keys)
    if fmt == "parquet":
        return ParquetSink(out, header, append=append)
    return CsvSink(out, header, append=append)


def read_rows(fmt: str, out: Path, keys: tuple[str, ...]) -> list[dict]:
    """``--resume``: the rows already in ``out`` (and its parts), as dicts of the header's names to cell texts
    (Parquet: to values). A CSV's partial last line (a sweep killed while writing) is cut off the file first.

    Raises
    ------
    InputError
        Naming ``--resume``: a header other than this sweep's.
    """
    header = csv_header(keys)
    if fmt == "parquet":
        import pyarrow.parquet as pq

        rows: list[dict] = []
        files = ([out] if out.exists() else []) + sorted(parts_dir(out).glob("part-*.parquet"))
        for p in files:
            t = pq.read_table(p)
            if t.column_names != header:
                raise InputError("--resume", f"{p} has other columns than this sweep's")
            rows += t.to_pylist()
        return rows
    if not out.exists():
        return []
    data = out.read_bytes()
    if data and not data.endswith(b"\n"):
        cut = data.rfind(b"\n") + 1  # a partial last line: the sweep was killed while writing it
        with open(out, "r+b") as fh:
            fh.truncate(cut)
            fh.flush()
            os.fsync(fh.fileno())
    if not out.read_bytes():
        return []
    got, lines = _read_csv(out)
    if got != header:
        raise InputError("--resume", f"{out} has other columns than this sweep's")
    return [dict(zip(header, r, strict=True)) for r in lines if len(r) == len(header)]
