"""``cams front``: the Pareto front and the chart of a sweep's written table, without solving again.

``cams sweep ... --pareto COL,COL --plot F.png`` does the same at the end of a sweep, from the file it
has just written (:func:`front_and_chart`, shared by both commands).
"""

from __future__ import annotations

import sys
from pathlib import Path

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK
from laws.errors import InputError

__all__ = [
    "register",
    "run",
    "add_front_arguments",
    "parse_axes",
    "check_front_arguments",
    "check_columns",
    "pareto_path",
    "front_and_chart",
]

#: Rows of the front printed on the terminal (all of them are in the saved CSV).
PRINTED_ROWS = 20


def pareto_path(out: str | Path) -> Path:
    """Where the front of the table ``out`` is saved: beside it, ``sweep.csv`` -> ``sweep.pareto.csv``."""
    p = Path(out)
    return p.with_name(f"{p.stem}.pareto.csv")


def add_front_arguments(q) -> None:
    """The options of a front and a chart: ``--pareto``, ``--plot``, ``--axes`` (short helps: ``cams sweep``'s
    help stays on one screen; the README and docs/files.md say the rest)."""
    q.add_argument(
        "--pareto",
        metavar="COLS",
        help="the Pareto front over COLS (R0,L; max:COL maximises), usable rows: printed, saved as NAME.pareto.csv",
    )
    q.add_argument("--plot", metavar="CHART", help="a chart (.png/.svg/.pdf) of --axes with the front")
    q.add_argument("--axes", metavar="X,Y[,C]", help="the chart's x,y[,colour] (default: --pareto's)")


def parse_axes(args) -> tuple[str | None, str | None, str | None]:
    """``--axes X,Y[,C]`` -> (x, y, colour); (None, None, None) when not given.

    Raises
    ------
    InputError
        Naming ``--axes``: not two or three columns, or given without ``--plot``.
    """
    if args.axes is None:
        return None, None, None
    if args.plot is None:
        raise InputError("--axes", "are the chart's: give --plot CHART.png too")
    parts = [a.strip() for a in args.axes.split(",")]
    if len(parts) not in (2, 3) or not all(parts):
        raise InputError("--axes", f"{args.axes!r}: give X,Y or X,Y,COLOUR (column names)")
    return parts[0], parts[1], parts[2] if len(parts) == 3 else None


def check_front_arguments(args, table: str | None, inputs: list, table_field: str = "--out") -> list[Path]:
    """Check ``--pareto``'s form, ``--plot``'s extension and paths, before anything is solved or read.

    ``table`` is the sweep's output (None: written to standard output, which cannot be read back), given by the
    option ``table_field``.
    Returns the paths written: the front's CSV and the chart, those asked for.
    """
    from cams.io.files import check_output_paths, output_kind
    from cams.present.sweepplot import FORMATS
    from cams.sweep.pareto import parse_objectives

    if args.pareto is not None:
        parse_objectives(args.pareto)
    asked = args.pareto is not None or args.plot is not None
    x, _, _ = parse_axes(args)
    if not asked:
        return []
    # a table is a regular file (or a name not yet taken) or a folder of Parquet parts; anything else is a stream
    # (standard output, /dev/fd/N, a device, a FIFO), which cannot be read back nor have the front saved beside it
    if table is None or output_kind(table)[0] not in ("file", "folder"):
        raise InputError(
            "--pareto" if args.pareto is not None else "--plot",
            f"the front and the chart are read back from the table: give {table_field} a file, not a stream",
        )
    if args.plot is not None:
        ext = Path(args.plot).suffix.lower().lstrip(".")
        if ext not in FORMATS:
            raise InputError("--plot", f"{args.plot!r}: the chart is written as .png, .svg or .pdf")
        if x is None and (args.pareto is None or len(parse_objectives(args.pareto)) < 2):
            raise InputError("--plot", "give --axes X,Y, or --pareto with two columns (the chart's axes)")
    if args.pareto is not None:
        from cams.sweep.output import SIDECAR_SUFFIX, sidecar_path

        front = pareto_path(table)
        if sidecar_path(front).exists() or front.name.lower().endswith(SIDECAR_SUFFIX):
            raise InputError("--pareto", f"the front is saved as {front}, another sweep's table (its sidecar is "
                             "beside it): give the table another name")
    outs = [("--pareto", pareto_path(table) if args.pareto is not None else None), ("--plot", args.plot)]
    return check_output_paths(outs, inputs=[*inputs, ("--out", table)])


def _print_front(table, front, saved: Path | None) -> None:
    """The front as a small table on standard output: row index, the varied keys, the objectives with units."""
    lead = [n for n in ("index", "file") if n in table.columns]
    keys = [n for n in table.names if "." in n or "[" in n]  # the varied design-file keys
    objs = [o.column for o in front.objectives]
    cols = lead + [k for k in keys if k not in objs] + objs
    pos = {n: table.names.index(n) for n in cols}
    head = [table.label(n) for n in cols]
    if "index" not in table.columns:
        head, cols = ["row", *head], ["row", *cols]
    body = []
    for i in front.rows[:PRINTED_ROWS]:
        cells = table.cells[int(i)]
        body.append([str(int(i)) if n == "row" else cells[pos[n]] for n in cols])
    widths = [max(len(h), *(len(r[j]) for r in body)) if body else len(h) for j, h in enumerate(head)]
    print("  ".join(h.rjust(w) for h, w in zip(head, widths, strict=True)))
    for r in body:
        print("  ".join(c.rjust(w) for c, w in zip(r, widths, strict=True)))
    if len(front.rows) > PRINTED_ROWS:
        print(f"... {len(front.rows) - PRINTED_ROWS} more rows of the front in {saved}")


#: The columns of a sweep's table that hold words or flags, never numbers to compare or draw.
WORDS = ("file", "verified", "buildable", "failures", "error")


def _numbers(table, name: str, usable, field: str, table_field: str) -> str:
    """The column named ``name`` (with or without its unit), its cells checked to be numbers for a front or a
    chart: :func:`check_columns` has passed it (a column of the table, not of words or flags).

    Raises
    ------
    InputError
        Naming ``table_field``: a cell that is not a number in a column of numbers (an edit), or a cell that holds
        a number that is not finite (``nan``, ``inf``: a sweep leaves a cell without a value empty, so such a cell
        is an edit, neither empty nor comparable). Naming ``field``: a column empty in every usable row (a
        rocker's offset: nothing to compare).
    """
    import numpy as np

    col = table.column(name, field)
    cells = table.columns[col]
    j = table.names.index(col)
    if not _numeric(cells):  # a column of numbers with a word in it (check_columns passed it): an edit
        w = next(k for k, r in enumerate(table.cells) if r[j].strip() and not _is_number(r[j].strip()))
        raise InputError(table_field, f"{table.path}: data row {w + 1}, column {table.headers[j]!r} holds "
                         f"{table.cells[w][j]!r}, not a number as the column's other cells")
    for i in np.flatnonzero(~np.isfinite(cells)):
        if table.cells[i][j].strip():
            raise InputError(table_field, f"{table.path}: data row {i + 1}, column {table.headers[j]!r} holds "
                             f"{table.cells[i][j]!r}: a sweep writes a finite number or leaves the cell empty")
    if usable.any() and np.all(np.isnan(cells[usable])):
        raise InputError(field, f"{col!r} is empty in every usable row: nothing to compare")
    return col


def _numeric(cells) -> bool:
    """Whether a column read back (:class:`cams.sweep.outfile.SweepTable`) holds numbers only."""
    import numpy as np

    return isinstance(cells, np.ndarray) and cells.dtype.kind in "fi"


def _words(table) -> frozenset[str]:
    """The columns of ``table`` that hold words or flags: not numbers, and no cell a number (a column of numbers
    with a word in it is an edit, which :func:`_numbers` names by its row)."""
    return frozenset(
        n for j, n in enumerate(table.names)
        if not _numeric(table.columns[n]) and not any(_is_number(r[j].strip()) for r in table.cells)
    )


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _usable(table, field: str):
    """Which rows of ``table`` a front may offer: :func:`cams.sweep.pareto.usable_mask` (the rows
    :func:`cams.sweep.output.failed` passes).

    Raises
    ------
    InputError
        Naming ``field``: the table has no ``error`` or no ``failures`` column (it cannot say which rows are
        usable).
    """
    from cams.sweep.pareto import usable_mask

    return usable_mask(table.columns, field=field, name=str(table.path))


def check_columns(args, table, words: set[str] | frozenset[str] = frozenset()) -> None:
    """Check that ``--pareto``'s and ``--axes``' columns are ``table``'s columns of numbers, each objective once:
    ``cams sweep`` checks them against the header of the table it is about to write, before solving.

    ``words`` are the varied keys whose values are words or flags (a law's name).

    Raises
    ------
    InputError
        Naming ``--pareto`` or ``--axes``: a column the table will not have (the message lists them), one that will
        hold words or flags, or an objective given twice (with and without its unit suffix).
    """
    from cams.sweep.pareto import parse_objectives

    def number(name: str, field: str) -> str:
        col = table.column(name, field)
        if col in WORDS or col in words:
            raise InputError(field, f"{col!r} is not a column of numbers (words or True/False)")
        return col

    if args.pareto is not None:
        seen: list[str] = []
        for o in parse_objectives(args.pareto):
            col = number(o.column, "--pareto")
            if col in seen:
                raise InputError("--pareto", f"{args.pareto!r}: column {col!r} is given twice")
            seen.append(col)
    if args.plot is not None:
        for a in parse_axes(args):
            if a is not None:
                number(a, "--axes")


def front_and_chart(args, path: str | Path, *, field: str = "--out") -> int:
    """Read the table at ``path``; print and save its Pareto front (``--pareto``); draw its chart (``--plot``).

    Returns
    -------
    int
        0, or 1 when a front is asked for and no row is usable (the front is empty: no design to offer).

    Raises
    ------
    InputError
        Naming ``--pareto`` or ``--axes``: a column the table does not have (the message lists them) or that
        holds no numbers; naming ``field``: the table cannot be read. Nothing is written then.
    """
    from cams.sweep.outfile import read_table, write_rows
    from cams.sweep.pareto import Objective, pareto_front, parse_objectives

    table = read_table(path, field)
    n = len(table)
    usable = _usable(table, field)
    # every column named is resolved, the front computed and the chart built before anything is written
    check_columns(args, table, words=_words(table))  # columns of the table, of numbers, each objective once
    objs: tuple[Objective, ...] = ()
    if args.pareto is not None:
        objs = tuple(Objective(_numbers(table, o.column, usable, "--pareto", field), o.maximise)
                     for o in parse_objectives(args.pareto))
    front = pareto_front(table.columns, objs, usable=usable) if objs else None
    fig = None
    if args.plot is not None:
        from cams.present.sweepplot import sweep_chart

        ax, ay, ac = parse_axes(args)
        if ax is not None and ay is not None:
            x, y = _numbers(table, ax, usable, "--axes", field), _numbers(table, ay, usable, "--axes", field)
            colour = _numbers(table, ac, usable, "--axes", field) if ac else None
        elif len(objs) >= 2:
            x, y = objs[0].column, objs[1].column
            colour = objs[2].column if len(objs) > 2 else None
        else:
            raise InputError("--plot", "give --axes X,Y, or --pareto with two columns (the chart's axes)")
        by = {o.column: o.maximise for o in objs}
        step = len(objs) == 2 and {x, y} == set(by)  # the staircase is the front's edge in these two columns only
        fig = sweep_chart(
            table.columns,
            table.units,
            x,
            y,
            colour=colour,
            usable=usable,
            front=None if front is None else front.rows,
            step=step,
            maximise=(by.get(x, False), by.get(y, False)),
            title=f"{Path(path).name}: {n} designs, {int(usable.sum())} usable",
        )
    if table.dropped:
        print(f"{path}: {table.dropped} line(s) left out: another count of cells than the header's (cut short by an "
              "interrupted writer, or edited)", file=sys.stderr)
    from cams.io.files import all_or_nothing

    saved, chart = None, None
    with all_or_nothing():  # the front's CSV and the chart together or neither (a chart that cannot be written)
        if front is not None:
            saved = write_rows(pareto_path(path), table, front.rows, "--pareto")
        if fig is not None:
            from cams.present.sweepplot import save_chart

            chart = save_chart(fig, args.plot)
    code = EXIT_OK
    if front is not None:
        names = ", ".join(f"{o} ({table.units[o.column]})" if table.units.get(o.column) else str(o) for o in objs)
        print(
            f"Pareto front over {names} (minimised unless max:): {len(front.rows)} of {n} rows "
            f"({front.unusable} unusable and {front.empty} with an empty objective left out)"
        )
        if len(front.rows):
            _print_front(table, front, saved)
        for g in front.ties:
            print(f"rows {', '.join(map(str, g))} have equal objectives: all on the front")
        print(f"wrote {saved}: the front's {len(front.rows)} row(s), the table's columns", file=sys.stderr)
        if not len(front.rows):
            print(f"{path}: no usable row, the front is empty", file=sys.stderr)
            code = EXIT_CHECK_FAILED
    if chart is not None:
        print(f"wrote {chart}", file=sys.stderr)
    return code


def run(args) -> int:
    check_front_arguments(args, args.table, inputs=[("TABLE", args.table)], table_field="TABLE")
    if args.pareto is None and args.plot is None:
        raise InputError("--pareto", "give --pareto COL,COL or --plot CHART.png (or both)")
    return front_and_chart(args, args.table, field="TABLE")


def register(sub) -> None:
    """Add the ``front`` subcommand."""
    q = sub.add_parser(
        "front",
        help="the Pareto front and a chart of a sweep's table (CSV or Parquet), without solving again",
        description="Read a table written by cams sweep; print and save its Pareto front over the chosen columns "
        "(usable rows only: no error, no failures) and draw a chart of two columns coloured by a third. "
        "Exit code 0, 1: no usable row (the front is empty), 2: bad input.",
        epilog="example: cams front sweep.csv --pareto R0,max_pressure_angle_rise --plot front.png",
    )
    q.add_argument("table", metavar="TABLE", help="the sweep's table (CSV, or .parquet through pyarrow)")
    add_front_arguments(q)
    q.set_defaults(func=run)
