"""``cams sweep``: a table of sized cams over ranges of design-file keys."""

from __future__ import annotations

import argparse
import csv
import sys

from cams.commands.common import EXIT_OK

__all__ = ["register", "run"]


def run(args) -> int:
    from cams.files import atomic_write, check_output_path, read_toml
    from cams.sweep import COLUMNS, parse_vary, sweep

    out = check_output_path(args.out, "--out")
    base = read_toml(args.file)
    vary = [parse_vary(v) for v in args.vary]
    res = sweep(base, vary, method=args.method, workers=args.jobs, progress=not args.quiet)

    def write(tmp):
        with open(tmp, "w", newline="", encoding="utf-8") as fh:
            w = csv.DictWriter(fh, fieldnames=list(res.keys) + list(COLUMNS))
            w.writeheader()
            for r in res.rows:
                w.writerow({k: ("" if v is None else v) for k, v in r.items()})

    atomic_write(out, "--out", write)
    bad = sum(1 for r in res.rows if r["error"])
    print(f"{out}: {len(res.rows)} designs ({bad} infeasible) in {res.seconds:.2f} s, "
          f"{res.per_second:.1f} designs/s on {res.workers} process(es)", file=sys.stderr)
    return EXIT_OK


def register(sub) -> None:
    """Add the ``sweep`` subcommand."""
    q = sub.add_parser(
        "sweep",
        help="solve a grid of designs varying design-file keys; write a CSV table",
        description="Solve every combination of the varied keys of a design file and write a CSV table.",
        epilog="example: cams sweep examples/rocker_force.toml --vary limits.pressure_angle=30:50:5 "
        "--vary follower.arm=100:200:3 --out sweep.csv",
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--vary", action="append", required=True, metavar="KEY=a:b:n",
                   help="dotted key and range (n values from a to b) or list v1,v2; repeatable")
    q.add_argument("--out", required=True, help="CSV file to write")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"), help="override [solve] method")
    q.add_argument("--jobs", type=int, help="processes (default: all cores)")
    q.add_argument("--quiet", action="store_true", help="no progress bar")
    q.set_defaults(func=run)
