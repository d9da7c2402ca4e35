"""``cams solve``: the smallest cam of a design file, verified."""

from __future__ import annotations

import argparse
import json

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK

__all__ = ["register", "print_summary"]


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


def run(args) -> int:
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



def register(sub) -> None:
    """Add the ``solve`` subcommand."""
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
    q.set_defaults(func=run)
