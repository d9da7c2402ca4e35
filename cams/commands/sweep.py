"""``cams sweep``: a table of sized cams over design-file keys, streamed as it is solved, resumable."""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_INTERRUPTED, EXIT_OK, check_jobs
from laws.errors import InputError

__all__ = ["register", "run"]


def run(args) -> int:
    state: dict = {}
    try:
        return _run(args, state)
    except KeyboardInterrupt:
        # the pool is stopped by the engine; the rows done stay in the file, whole lines only
        out = state.get("out")
        if out is not None and state.get("rows", 0):
            print(f"cams sweep: interrupted; {out} holds {state['rows']} row(s): run again with --resume to go on",
                  file=sys.stderr)
        else:
            if state.get("created") is not None:  # a header and a sidecar, no row: nothing to resume, nothing left
                _remove(state["created"])
            print("cams sweep: interrupted before a row was solved; nothing written", file=sys.stderr)
        return EXIT_INTERRUPTED


def _remove(out: Path) -> None:
    """Remove the files a sweep that wrote no row began at ``out``: the table, its sidecar, its Parquet parts."""
    from cams.sweep.output import parts_dir, sidecar_path

    for p in (out, sidecar_path(out)):
        p.unlink(missing_ok=True)
    shutil.rmtree(parts_dir(out), ignore_errors=True)


def _n(k: int, what: str) -> str:
    return f"{k} {what}{'' if k == 1 else 'es' if what.endswith('s') else 's'}"


def _format(args, out: Path) -> str:
    from cams.sweep.outfile import PARQUET_SUFFIXES

    by_name = "parquet" if out.suffix.lower() in PARQUET_SUFFIXES else "csv"
    if args.format is not None:
        named = by_name if out.suffix.lower() in (".csv", *PARQUET_SUFFIXES) else args.format
        if named != args.format:  # a Parquet file named .csv (or back) would mislead whoever opens it by its name
            raise InputError("--format", f"{args.format} does not fit --out {str(out)!r} (a .{named} name): "
                             f"give --out a .{'parquet' if args.format == 'parquet' else 'csv'} name")
        return args.format
    return by_name


def _grid(args):
    from cams.io.document import read_toml
    from cams.sweep.grid import BaseFile, file_hash, make_grid, parse_vary, read_sweep_file

    if args.sweep_file is not None:
        if args.files or args.vary or args.zip:
            raise InputError("--sweep-file", "names the files, keys and mode itself: give no FILE, --vary or --zip "
                             "with it")
        files, vary, mode, method = read_sweep_file(args.sweep_file)
        method = args.method or method
    else:
        if not args.files:
            raise InputError("FILE", "give a design file (or several), or --sweep-file")
        if not args.vary:
            raise InputError("--vary", "give at least one KEY=a:b:n or KEY=v1,v2 (or a --sweep-file)")
        files, mode, method = list(args.files), ("zip" if args.zip else "grid"), args.method
        vary = [parse_vary(v) for v in args.vary]
    seen: dict[Path, int] = {}
    for k, f in enumerate(files):  # one file twice: the same designs solved twice
        first = files[seen.setdefault(Path(f).resolve(), k)]
        if seen[Path(f).resolve()] != k:
            same = "" if first == f else f" (as {first!r})"
            raise InputError("FILE" if args.sweep_file is None else "--sweep-file",
                             f"{f!r} is given twice{same}; give each file once")
    bases = []
    for f in files:
        try:
            bases.append(BaseFile(f, read_toml(f), file_hash(f)))
        except InputError as e:  # a design file the sweep file names: the sweep file's `files` is at fault
            if args.sweep_file is None:
                raise
            why = str(e).removeprefix(f"{e.field}: ")
            raise InputError("--sweep-file", f"{args.sweep_file}: files: {why}") from None
    for b in bases:
        if args.sweep_file is None and "files" in b.design:
            raise InputError("FILE", f"{b.label!r} is a sweep file: give it as --sweep-file {b.label}")
    origin = "--vary" if args.sweep_file is None else f"--sweep-file {args.sweep_file}"
    return files, make_grid(bases, vary, mode=mode, method=method, origin=origin)


def _indexes(out: Path, rows: list[dict], size: int) -> set[int]:
    """The indexes of the rows already in ``out`` (``--resume``): each an integer 0 to ``size - 1``, once.

    Raises
    ------
    InputError
        Naming ``--resume``: a row's index is not one of the sweep's, or is held twice (an edited table).
    """
    done: set[int] = set()
    for k, r in enumerate(rows):
        v = r.get("index")
        try:
            i = int(str(v)) if not isinstance(v, bool) else -1
        except ValueError:
            i = -1
        if not 0 <= i < size or i in done:
            why = "held twice" if 0 <= i < size else f"not one of the sweep's 0 to {size - 1}"
            raise InputError("--resume", f"{out}: data row {k + 1} has index {v!r}, {why}; run without --resume "
                             "to start again")
        done.add(i)
    return done


def _run(args, state: dict) -> int:
    from cams.io.files import check_output_paths
    from cams.sweep import run_grid
    from cams.sweep.output import (
        check_identity,
        check_out,
        csv_header,
        failed,
        parts_dir,
        read_rows,
        sink_for,
        write_identity,
    )

    check_jobs(args.jobs)
    ins = [("FILE", f) for f in (args.files or [])] + ([("--sweep-file", args.sweep_file)] if args.sweep_file else [])
    (out,) = check_output_paths([("--out", args.out)], inputs=ins)
    if str(args.out) == "-" or not (out.parent.is_dir() and (not out.exists() or out.is_file())):
        raise InputError("--out", f"{args.out!r}: a sweep streams its rows into a regular file (to resume from it)")
    fmt = _format(args, out)
    resumed = args.resume and (out.exists() or (fmt == "parquet" and parts_dir(out).exists()))
    check_out(out, resumed=resumed)  # a sidecar's name (.sweep.json) said as such, before its .json below
    from cams.io.files import check_suffix
    from cams.sweep.outfile import PARQUET_SUFFIXES

    check_suffix(args.out, "--out", (".csv", *PARQUET_SUFFIXES), "the sweep's table (CSV or Parquet)")
    if fmt == "parquet":
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            raise InputError("--format", "parquet needs pyarrow: pip install 'cams[parquet]'") from None
    files, grid = _grid(args)
    cluster = _before_sweep(args, out, files, grid)
    check_output_paths([("--out", args.out)], inputs=[("FILE", f) for f in files])
    identity = {**grid.identity(), "format": fmt, "columns": csv_header(grid.keys)}
    done: set[int] = set()
    before_failed = 0
    if resumed:
        check_identity(out, identity)
        rows = read_rows(fmt, out, grid.keys)
        done = _indexes(out, rows, grid.size)
        before_failed = sum(map(failed, rows))
    append = bool(done) or (fmt == "parquet" and args.resume)
    if not resumed:  # this run begins the table and its sidecar: with no row solved, it leaves neither behind
        state["created"] = out
        write_identity(out, identity)
    sink = sink_for(fmt, out, grid.keys, append=append)
    state["out"], state["rows"] = out, len(done)

    def write(rows: list[dict]) -> None:
        sink.write(rows)
        state["rows"] += len(rows)

    def said(seconds: float, timed: int, workers: int) -> None:
        todo = grid.size - len(done)
        t = "a second" if seconds < 1 else f"{seconds:.0f} s" if seconds < 120 else f"{seconds / 60:.0f} min"
        print(f"cams sweep: {_n(todo, 'design')}{' to go' if done else ''}, about {t} on {_n(workers, 'process')} "
              f"(estimated from {_n(timed, 'timed design')})", file=sys.stderr)

    from cams.commands.progress import progress, wanted

    try:
        with progress(wanted(args), "solving the designs", unit="design") as bar:  # none in a log file or pipe
            res = run_grid(grid, workers=args.jobs, done=done, sink=write, keep=False, progress=bar.to,
                           estimate=None if args.quiet else said, per_design=args.per_design,
                           cluster=cluster)
    except BaseException as e:
        sink.close(finished=False)
        if isinstance(e, InputError) and state.get("created") is not None and not state["rows"]:
            _remove(out)  # refused before a row was written (--dask's cluster unreachable): no file is left behind
        raise
    sink.close(finished=True)
    infeasible = res.failed + before_failed
    none = "" if not done else f", {len(done)} resumed"
    # one rule for every command (cams.assess): a row without a solution, or not usable (certified, verified,
    # buildable)
    print(f"{out}: {_n(grid.size, 'design')} ({infeasible} infeasible: without a solution, or not certified, verified "
          f"or buildable{none}); {res.solved} solved in {res.seconds:.2f} s, {res.per_second:.1f} designs/s on "
          f"{res.workers} process(es)", file=sys.stderr)
    code = EXIT_OK if infeasible == 0 else EXIT_CHECK_FAILED
    return max(code, _after_sweep(args, out))


def _add_front_arguments(q) -> None:
    """The options of the front, the chart and the cluster: ``--pareto``, ``--plot``, ``--axes``
    (:mod:`cams.commands.front`, shared with ``cams front``) and ``--dask``."""
    from cams.commands.front import add_front_arguments

    add_front_arguments(q)
    q.add_argument("--dask", metavar="ADDRESS", help="solve on a Dask cluster: tcp://host:8786, or local (--jobs "
                   "workers); pip install \"cams[dask]\"")


def _before_sweep(args, out, files, grid) -> str | None:
    """Check the front's, the chart's and the cluster's options before solving (``--pareto``'s and ``--axes``'
    columns against the header of the table about to be written); the cluster's address, if any.

    Returns
    -------
    str or None
        ``--dask``'s value (``local`` or a scheduler's address) for the engine's ``cluster``; None: this
        machine's processes.
    """
    from cams.commands.front import check_front_arguments
    from cams.sweep.cluster import check_spec

    check_front_arguments(args, out, inputs=[("FILE", f) for f in files])
    if args.pareto is not None or args.plot is not None:
        from cams.commands.front import check_columns
        from cams.sweep.outfile import table_of
        from cams.sweep.output import csv_header

        # a varied key of words (a law's name) or flags is a column the front cannot compare nor the chart draw
        words = {k for k, vs in zip(grid.keys, grid.values, strict=True)
                 if any(isinstance(v, (str, bool)) for v in vs)}
        check_columns(args, table_of(out, csv_header(grid.keys), field="--out"), words)
    if args.dask is None:
        return None
    check_spec(args.dask, args.jobs)
    return str(args.dask)


def _after_sweep(args, out) -> int:
    """The front (``--pareto``) and the chart (``--plot``) of the written table, read back from ``out``.

    Returns 0, or 1 when a front is asked for and no row is usable.
    """
    if args.pareto is None and args.plot is None:
        return EXIT_OK
    from cams.commands.front import front_and_chart

    return front_and_chart(args, out)


def register(sub) -> None:
    """Add the ``sweep`` subcommand (docs/files.md, Sweeps, says the rest)."""
    q = sub.add_parser(
        "sweep",
        help="solve a grid of designs varying design-file keys; stream a CSV (or Parquet) table",
        description="Solve every combination of the varied keys; rows written as solved, resumable. Exit 0: "
                    "all usable, 1: a row fails, 2: bad input. docs/files.md, Sweeps",
        epilog="example: cams sweep examples/rocker_force.toml --vary 'motion[0].law=cycloidal,poly345' --out s.csv",
    )
    q.add_argument("files", nargs="*", metavar="FILE", help="design file(s); several: one more axis (column file)")
    q.add_argument("--vary", action="append", metavar="KEY=a:b:n|v1,v2",
                   help="a dotted key (motion[0].law) and a range or a list of numbers or words; repeatable")
    q.add_argument("--zip", action="store_true", help="pair the keys' values instead of every combination")
    q.add_argument("--sweep-file", metavar="S.toml", help="files, keys, values and mode from a TOML file")
    q.add_argument("--out", required=True, help="the table, written as rows are solved (.csv, .parquet)")
    q.add_argument("--format", choices=("csv", "parquet"), help="default: by --out's extension")
    q.add_argument("--resume", action="store_true", help="go on with --out's sweep (the same: OUT.sweep.json)")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"), help="override [solve] method")
    q.add_argument("--jobs", type=int, help="processes, >= 1 (default: all cores)")
    q.add_argument("--per-design", action="store_true", help="size each design by itself, not by the batch solver")
    q.add_argument("--quiet", action="store_true", help="no estimate, no progress bar")
    _add_front_arguments(q)
    q.set_defaults(func=run)
