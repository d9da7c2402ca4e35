"""The ``cams`` command line: a thin layer over the API.

Every subcommand turns a :class:`~laws.errors.CamsError` (bad input, no
feasible design) into one line on stderr and exit code 2.
"""

from __future__ import annotations

import argparse
import json
import sys

from laws.errors import CamsError

__all__ = ["main"]

EXIT_OK, EXIT_CHECK_FAILED, EXIT_BAD_INPUT = 0, 1, 2


class _Parser(argparse.ArgumentParser):
    """argparse with usage errors as one line and exit code 2."""

    def error(self, message):  # noqa: D102
        self.exit(EXIT_BAD_INPUT, f"{self.prog}: error: {message}\n")


def _cmd_laws(args) -> int:
    from laws.characteristics import law_table

    rows = law_table()
    if args.json:
        print(json.dumps(rows, indent=2))
        return EXIT_OK
    print(f"{'law':<20} {'Cv':>8} {'Ca':>8} {'Cj':>8}")
    for r in rows:
        cells = ["inf" if r[k] is None else f"{r[k]:.4f}" for k in ("Cv", "Ca", "Cj")]
        print(f"{r['name']:<20} {cells[0]:>8} {cells[1]:>8} {cells[2]:>8}")
    return EXIT_OK


def _fmt_deg(x) -> str:
    return "-" if x is None else f"{x:.4f} deg"


def print_summary(rep: dict) -> None:
    """Short readable summary of a solve report (as from ``SolveResult.to_dict``)."""
    unit = "mm"
    print(f"{rep['name']}: {rep['follower']} follower, method {rep['method']}, {rep['mode']}")
    print(f"  R0      = {rep['R0']:.6f} {unit}")
    if rep["L"] is not None:
        print(f"  L       = {rep['L']:.6f} {unit}")
    if rep["offset"] is not None:
        print(f"  offset  = {rep['offset']:.6f} {unit}")
    c = rep["centre"]
    print(f"  centre  = ({c['x']:.6f}, {c['y']:.6f}) {unit}")
    mp, lim = rep["max_pressure_angle"], rep["limits"]
    print(f"  max pressure angle: rise {_fmt_deg(mp['rise'])} (limit {_fmt_deg(lim['rise'])}), "
          f"return {_fmt_deg(mp['return'])} (limit {_fmt_deg(lim['return'])})")
    if rep["binding"]:
        print("  binding: " + ", ".join(f"{b['line']} at {b['phi']:.4f} deg" for b in rep["binding"]))
    eb = rep["error_bound"]
    print(f"  error bound: {'not stated by this method' if eb is None else f'{eb:.3g} {unit}'}; "
          f"verified: {'yes' if rep['verified'] else 'NO'}; {rep['seconds'] * 1e3:.1f} ms")
    for n in rep["notes"]:
        print(f"  note: {n}")


def _cmd_solve(args) -> int:
    from cams.designfile import load_design
    from optimize.solve import solve

    design = load_design(args.file)
    result = solve(design, method=args.method, objective=design.extra.get("objective", "R0"))
    rep = result.to_dict()
    if args.json:
        print(json.dumps(rep, indent=2))
    else:
        print_summary(rep)
    return EXIT_OK if result.verified else EXIT_CHECK_FAILED


def _build_parser() -> argparse.ArgumentParser:
    p = _Parser(
        prog="cams",
        description="Disk-cam design: minimum size, profiles and checks.",
        epilog="example: cams solve examples/rocker_force.toml",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    q = sub.add_parser("laws", help="table of motion laws with Cv, Ca, Cj", epilog="example: cams laws --json")
    q.add_argument("--json", action="store_true", help="print JSON instead of a table")
    q.set_defaults(func=_cmd_laws)
    q = sub.add_parser(
        "solve",
        help="smallest cam: R0, L or offset, verified pressure angle",
        description="Find the allowable-centre zone and the smallest cam of a design file.",
        epilog="example: cams solve examples/rocker_force.toml --json",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"), help="override [solve] method")
    q.add_argument("--json", action="store_true", help="print the report as JSON")
    q.set_defaults(func=_cmd_solve)
    return p


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit code."""
    parser = _build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return EXIT_BAD_INPUT
    try:
        return args.func(args)
    except CamsError as e:
        print(f"cams {args.command}: error: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except OSError as e:
        print(f"cams {args.command}: error: {e.filename or ''}: {e.strerror or e}", file=sys.stderr)
        return EXIT_BAD_INPUT


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
