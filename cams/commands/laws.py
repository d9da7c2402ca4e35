"""``cams laws``: the table of motion laws with Cv, Ca, Cj."""

from __future__ import annotations

import argparse
import json

from cams.commands.common import EXIT_OK

__all__ = ["register"]


def run(args) -> int:
    from laws.characteristics import law_table

    rows = law_table()
    if args.json:
        print(json.dumps(rows, indent=2))
        return EXIT_OK
    print(f"{'law':<20} {'Cv':>8} {'Ca':>8} {'Cj':>8}")
    for r in rows:
        cells = ["inf" if r[k] is None else f"{r[k]:.4f}" for k in ("Cv", "Ca", "Cj")]
        mark = " *" if r["name"] == "modified_cycloid" else ""
        print(f"{r['name']:<20} {cells[0]:>8} {cells[1]:>8} {cells[2]:>8}{mark}")
    print("inf: the law jumps in velocity (Ca) or acceleration (Cj) where it meets a dwell or inside.")
    print("* modified_cycloid: cycloid with a constant-velocity middle half; values derived here, not"
          " checked against a published Wildt/Norton table.")
    return EXIT_OK



def register(sub) -> None:
    """Add the ``laws`` subcommand to ``sub`` (an argparse subparsers object)."""
    q = sub.add_parser("laws", help="table of motion laws with Cv, Ca, Cj",
                       description="Table of the motion laws with their characteristic values.",
                       epilog="example: cams laws --json", formatter_class=argparse.RawDescriptionHelpFormatter)
    q.add_argument("--json", action="store_true", help="print JSON instead of a table")
    q.set_defaults(func=run)
