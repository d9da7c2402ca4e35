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
