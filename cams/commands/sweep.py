"""``cams sweep``: a table of sized cams over ranges of design-file keys."""

from __future__ import annotations

import csv
import sys

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_INTERRUPTED, EXIT_OK
from laws.errors import InputError

__all__ = ["register", "run"]




def run(args) -> int:
    try:
        return _run(args)
    except KeyboardInterrupt:
        # the pool is stopped by cams.sweep.sweep; no CSV is written (atomic_write leaves no temporary)
        print("cams sweep: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


def _run(args) -> int:
    from cams.io.document import read_toml
    from cams.io.files import atomic_write, check_output_paths
    from cams.sweep import csv_header, csv_row, parse_vary, sweep

    if args.jobs is not None and args.jobs < 1:
        raise InputError("--jobs", f"must be an integer >= 1 (processes), got {args.jobs}")
    (out,) = check_output_paths([("--out", args.out)], inputs=[("FILE", args.file)])
    engine = _before_sweep(args, out)
    base = read_toml(args.file)
    vary = [parse_vary(v) for v in args.vary]
    from cams.commands.progress import progress, wanted

    with progress(wanted(args), "solving the designs", unit="design") as bar:  # none in a log file or a pipe
        res = sweep(base, vary, method=args.method, workers=args.jobs, progress=bar.to, **engine)

    def write(tmp):
        with open(tmp, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(csv_header(res.keys))
            for r in res.rows:
                w.writerow(csv_row(r))

    atomic_write(out, "--out", write)
    # one rule for every command (cams.assess): a row without a solution, or not usable (certified, verified, buildable)
    none = sum(1 for r in res.rows if r["error"])
    print(f"{out}: {len(res.rows)} designs ({res.failed} infeasible: {none} without a solution, "
          f"{res.failed - none} not certified, not verified or not buildable) in {res.seconds:.2f} s, "
          f"{res.per_second:.1f} designs/s on {res.workers} process(es)", file=sys.stderr)
    code = EXIT_OK if res.failed == 0 else EXIT_CHECK_FAILED
    return max(code, _after_sweep(args, out))


def _add_front_arguments(q) -> None:
    """The options of the front, the chart and the cluster: ``--pareto``, ``--plot``, ``--axes``
    (:mod:`cams.commands.front`, shared with ``cams front``) and ``--dask``."""
    from cams.commands.front import add_front_arguments

    add_front_arguments(q)
    q.add_argument("--dask", metavar="ADDRESS", help="solve on a Dask cluster: tcp://host:8786, or local (--jobs "
                   "workers); pip install \"cams[dask]\"")


def _before_sweep(args, out) -> dict:
    """Check the front's, the chart's and the cluster's options before solving; the engine's extra arguments.

    Returns
    -------
    dict
        Keyword arguments for :func:`cams.sweep.sweep`: ``executor_factory`` (a callable of no argument
        returning :func:`cams.sweep.cluster.executor`'s context manager) when ``--dask`` is given.
    """
    import functools
    import inspect

    from cams.commands.front import check_front_arguments
    from cams.sweep import sweep
    from cams.sweep.cluster import check_spec, executor

    check_front_arguments(args, out, inputs=[("FILE", args.file)])
    if args.dask is None:
        return {}
    check_spec(args.dask, args.jobs)
    if "executor_factory" not in inspect.signature(sweep).parameters:
        raise InputError("--dask", "this version's sweep engine runs on local processes only; leave out --dask")
    return {"executor_factory": functools.partial(executor, args.dask, args.jobs)}


def _after_sweep(args, out) -> int:
    """The front (``--pareto``) and the chart (``--plot``) of the written table, read back from ``out``.

    Returns 0, or 1 when a front is asked for and no row is usable.
    """
    if args.pareto is None and args.plot is None:
        return EXIT_OK
    from cams.commands.front import front_and_chart

    return front_and_chart(args, out)


def register(sub) -> None:
    """Add the ``sweep`` subcommand."""
    q = sub.add_parser(
        "sweep",
        help="solve a grid of designs varying design-file keys; write a CSV table",
        description="Solve every combination of the varied keys of a design file and write a CSV table: each "
                    "row's sizes, verified and buildable (the profile's checks and [dynamics] included) and why "
                    "not. Exit code 0: every row usable, 1: a row has no solution or fails, 2: bad input.",
        epilog="example: cams sweep examples/rocker_force.toml --vary limits.pressure_angle=30:50:5 "
        "--vary follower.arm=100:200:3 --out sweep.csv",
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--vary", action="append", required=True, metavar="KEY=a:b:n",
                   help="dotted key (list items as motion.0.angle or motion[0].angle) and range (n values "
                   "from a to b) or list v1,v2; repeatable, each key once")
    q.add_argument("--out", required=True, help="CSV file to write")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"), help="override [solve] method")
    q.add_argument("--jobs", type=int, help="processes, an integer >= 1 (default: all cores; never more than the "
                   "designs)")
    q.add_argument("--quiet", action="store_true", help="no progress bar (drawn only when stderr is a terminal)")
    _add_front_arguments(q)
    q.set_defaults(func=run)
