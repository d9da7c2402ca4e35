"""``cams machine``: a linkage's synthesis, its cycle windows, the feed cam's timing and design."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK

__all__ = ["register", "print_machine"]


def _iv(iv) -> str:
    if iv[1] > 360 + 1e-9:
        return f"{iv[0]:.3f} .. {iv[1] - 360:.3f} deg (through position 1)"
    return f"{iv[0]:.3f} .. {iv[1]:.3f} deg"


def print_machine(rep: dict) -> None:
    """Readable summary of a machine report (as from ``MachineResult.to_dict``)."""
    from cams.commands.solve import print_summary

    u = rep["units"]
    lk = rep["linkage"]
    print(f"{rep['name']}: {lk['type']} linkage")
    syn = rep["synthesis"]
    if syn is not None:
        course = f"K = {syn['time_ratio']:g}, H = {syn['stroke']:g} {u}, L = {syn['centre_distance']:g} {u}"
        if syn.get("rod_ratio") is not None:
            course += f", rod ratio = {syn['rod_ratio']:g}"
        print(f"  synthesis from {course}: swing theta = {syn['swing_deg']:.4f} deg")
    lengths = ", ".join(f"{k} = {v:.4f}" for k, v in lk.items() if isinstance(v, float) and not k.endswith("_deg") and k != "rpm")
    print(f"  lengths ({u}): {lengths}")
    a = rep["analysis"]
    print(
        f"  stroke {a['stroke']:.4f} {u}, time ratio K = {a['time_ratio']:.6f}, dead positions at "
        f"{a['dead_positions_deg'][0]:.3f} and {a['dead_positions_deg'][1]:.3f} deg (frame), "
        f"min transmission angle {a['min_transmission_deg']:.3f} deg at {a['min_transmission_at_deg']:.3f} deg"
    )
    w = rep["windows"]
    print(f"  cycle angle from position 1 (end of the working stroke, frame {w['origin_frame_deg']:.3f} deg), crank {w['crank_rotation']}:")
    print(f"    return {_iv(w['return'])}, working {_iv(w['working'])}")
    print(f"    cutting {_iv(w['cutting'])}, out of work {_iv(w['out_of_work'])}, {w['out_of_work_span']:.3f} deg")
    t = rep["timing"]
    dr = rep["drive"]
    drive = "same shaft" if dr["teeth"] is None else f"gears {dr['teeth'][0]}/{dr['teeth'][1]} ({dr['sense']} sense)"
    print(f"  cam: {drive}, ratio {t['ratio']:g}; program starts at cycle angle {t['mount_deg']:.3f} deg "
          f"(crank at {t['mount_frame_deg']:.3f} deg frame)")
    for r in t["rises_deg"]:
        print(f"    rise over crank {_iv(r)}")
    print(f"    free margins {t['margins_deg'][0]:.3f} / {t['margins_deg'][1]:.3f} deg (asked {t['margin_deg']:.3f}); "
          f"largest feasible rise {t['largest_rise_deg']:.3f} deg of cam")
    if t["key_angle_deg"] is not None:
        print(f"    key angle crank -> cam start radius {t['key_angle_deg']:.3f} deg")
    print(f"  feeding overlaps cutting: {'YES' if rep['overlap'] else 'no'}")
    for n in rep.get("notes", []):
        print(f"  note: {n}")
    print_summary(rep["cam"])


def run(args) -> int:
    from cams.machine import design_machine
    from cams.machinefile import load_machine

    spec = load_machine(args.file)
    res = design_machine(spec, method=args.method)
    rep = res.to_dict()
    if args.plot:
        out = Path(args.plot)
        out.mkdir(parents=True, exist_ok=True)
        path = out / f"{Path(args.file).stem}_cycle.png"
        res.diagram.plot(path, title=spec.name)
        rep["plots"] = [str(path)]
    if args.json:
        print(json.dumps(rep, indent=2, ensure_ascii=False))
    else:
        print_machine(rep)
        for p in rep.get("plots", []):
            print(f"  plot: {p}")
    return EXIT_OK if res.ok else EXIT_CHECK_FAILED


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
    q.add_argument("--plot", metavar="DIR", help="write the cycle diagram as a PNG into DIR")
    q.set_defaults(func=run)
