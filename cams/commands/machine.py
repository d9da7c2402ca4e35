"""``cams machine``: a linkage's synthesis, its cycle windows, the feed cam's timing and design."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK
from cams.present.machine_text import print_forces, print_machine

__all__ = ["register"]


def _check_plot_folder(path: str) -> None:
    """Refuse a ``--plot`` folder that cannot be one (an existing file, an empty name) before any work."""
    from laws.errors import InputError

    if not str(path).strip():
        raise InputError("--plot", "needs a folder name")
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise InputError("--plot", f"{str(p)!r} is a file; give a folder for the PNGs (it is created when missing)")
    for parent in p.parents:
        if parent.exists() and not parent.is_dir():
            raise InputError("--plot", f"cannot create the folder {str(p)!r}: {str(parent)!r} is a file")


def run(args) -> int:
    from cams.machine.design import design_machine
    from cams.machine.machinefile import load_machine

    if args.plot is not None:
        _check_plot_folder(args.plot)
    spec = load_machine(args.file)
    res = design_machine(spec, method=args.method)
    rep = res.to_dict()
    forces = None
    if args.forces:
        from cams.machine.kinetostatics import machine_forces

        forces = machine_forces(spec, found=res)  # the windows and timing design_machine found
        rep["forces"] = forces.to_dict()
    if args.plot is not None:
        from cams.io.files import all_or_nothing, ensure_folder
        from cams.present.machine_plots import write_machine_plots

        with all_or_nothing():  # every picture written whole, all of them or none
            out = ensure_folder(args.plot, "--plot")
            paths = write_machine_plots(out, Path(args.file).stem, res.diagram, forces, title=spec.name,
                                        follower=rep["cam"]["follower"])
        rep["plots"] = [str(p) for p in paths]
    if args.json:
        from cams.dynamics.forces import json_safe

        print(json.dumps(json_safe(rep), indent=2, ensure_ascii=False, allow_nan=False))
    else:
        print_machine(rep)
        if forces is not None:
            print_forces(rep["forces"], follower=rep["cam"]["follower"])
        for p in rep.get("plots", []):
            print(f"  plot: {p}")
    ok = res.ok and (forces is None or forces.ok)
    return EXIT_OK if ok else EXIT_CHECK_FAILED


def register(sub) -> None:
    """Add the ``machine`` subcommand."""
    q = sub.add_parser(
        "machine",
        help="a machine's linkage, cycle windows, feed-cam timing and cam design",
        description=(
            "Synthesize or check the linkage of a machine file, find the tool's cutting and out-of-work windows, "
            "place the feed cam's rise in the out-of-work window and size the cam."
        ),
        epilog="example: cams machine examples/machines/slotting_machine.toml --json",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="machine file (TOML)")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"), help="override the cam's [solve] method")
    q.add_argument("--json", action="store_true", help="print the report as JSON")
    q.add_argument("--plot", metavar="DIR", help="write the cycle diagram (with --forces also the reactions, balancing "
                   "moment, energy curves and cam forces) as PNGs into DIR")
    q.add_argument("--forces", action="store_true",
                   help="kinetostatics of the linkage ([forces]), its flywheel ([forces] delta) "
                        "and the cam's forces ([dynamics])")
    q.set_defaults(func=run)
