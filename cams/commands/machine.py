"""``cams machine``: a linkage's synthesis, its cycle windows, the feed cam's timing and design."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK

__all__ = ["register", "print_machine", "print_forces"]


def _iv(iv) -> str:
    if iv[1] > 360 + 1e-9:
        return f"{iv[0]:.3f} .. {iv[1] - 360:.3f} deg (through position 1)"
    return f"{iv[0]:.3f} .. {iv[1]:.3f} deg"


def print_machine(rep: dict) -> None:
    """Readable summary of a machine report (as from ``MachineResult.to_dict``)."""
    from cams.present.text import print_assessment, print_summary

    u = rep["units"]
    lk = rep["linkage"]
    print(f"{rep['name']}: {lk['type']} linkage")
    syn = rep["synthesis"]
    if syn is not None:
        course = f"K = {syn['time_ratio']:g}, H = {syn['stroke']:g} {u}, L = {syn['centre_distance']:g} {u}"
        if syn.get("rod_ratio") is not None:
            course += f", rod ratio = {syn['rod_ratio']:g}"
        print(f"  synthesis from {course}: swing theta = {syn['swing_deg']:.4f} deg")
    lengths = ", ".join(f"{k} = {v:.4f} {u}" for k, v in lk.items()
                        if isinstance(v, float) and not k.endswith("_deg") and k != "rpm")
    print(f"  lengths: {lengths}")
    a = rep["analysis"]
    print(
        f"  stroke {a['stroke']:.4f} {u}, time ratio K = {a['time_ratio']:.6f}, dead positions at "
        f"{a['dead_positions_deg'][0]:.3f} and {a['dead_positions_deg'][1]:.3f} deg (frame), "
        f"min transmission angle {a['min_transmission_deg']:.3f} deg at {a['min_transmission_at_deg']:.3f} deg"
    )
    w = rep["windows"]
    print(f"  cycle angle from position 1 (end of the working stroke, frame {w['origin_frame_deg']:.3f} deg), "
          f"crank {w['crank_rotation']}:")
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
    print_assessment(rep)  # the feed cam by the rule every command shares (cams.assess)


def print_forces(rep: dict, *, follower: str = "rocker") -> None:
    """Readable summary of a forces report (as from ``MachineForces.to_dict``).

    ``follower`` (the cam's follower kind) gives the spring's units
    (:func:`cams.words.spring_text`).
    """
    import math

    from cams.dynamics.jump import jump_text
    from cams.words import deg, force, spring_text, torque

    lk = rep.get("linkage")
    if lk is not None:
        mb = lk["balancing_moment"]
        passes = {1: "no friction from the reactions", 2: "two-stage friction"}.get(
            lk["passes"], f"{lk['passes']} friction passes")
        print(f"  forces at {lk['rpm']:.4g} rpm ({passes}); angles: {lk['angle_reference']}:")
        print(f"    balancing moment: max |M_b| = {mb['max_abs']:.4g} N m at {mb['at_deg']:.1f} deg, "
              f"mean {mb['mean']:.4g} N m; "
              f"Zhukovsky's lever agrees within {mb['virtual_work_max_difference']:.2g} N m")
        for name, p in lk["pairs"].items():
            print(f"    pair {name:8s} ({p['kind']:9s}): max {p['max']:.5g} N at {p['at_deg']:.1f} deg, "
                  f"mean {p['mean']:.5g} N")
        if lk["friction_power_mean_W"]:
            parts = ", ".join(f"{k} {v:.3g} W" for k, v in lk["friction_power_mean_W"].items())
            print(f"    friction losses: mean {lk['friction_power_total_mean_W']:.4g} W ({parts}); "
                  f"drive power mean {lk['drive_power_mean_W']:.4g} W")
        else:
            print(f"    drive power mean {lk['drive_power_mean_W']:.4g} W")
    fw = rep.get("flywheel")
    # the flywheel's curves are over the same angle as the linkage's (fw["angle_reference"])
    if fw is not None:
        print(f"  flywheel for delta = {fw['delta']:g}: driving moment {fw['driving_moment']:.4g} N m, excess work "
              f"{fw['excess_work']:.4g} J, J_F = {fw['flywheel_inertia']:.4g} kg m^2; omega {fw['omega_min']:.4g} .. "
              f"{fw['omega_max']:.4g} rad/s")
    cam = rep.get("cam")
    if cam is not None:
        sp = cam["spring"]

        def at(key):
            where = f"cam angle {deg(cam[key + '_deg'])}"
            cyc = cam.get(key + "_cycle_deg")
            if cyc:
                where += f" = cycle angle {', '.join(deg(c) for c in cyc)}"
            return where

        print(f"  cam forces at {cam['rpm']:.6g} rpm: spring {spring_text(sp['rate'], sp['preload'], follower)}; "
              f"max contact force {force(cam['max_contact_force'])} at {at('max_contact_at')}; "
              f"max camshaft torque {torque(cam['max_torque'])} at {at('max_torque_at')}")
        bi = cam.get("between_impacts")
        if bi:
            print(f"    between the rigid impacts: max contact force {force(bi['max_contact_force'])}, max camshaft "
                  f"torque {torque(bi['max_torque'])}, jump speed {jump_text(bi['jump_rpm'])}")
        if cam["jump_rpm"] is None or not math.isfinite(cam["jump_rpm"]):
            jump = jump_text(None)
        elif cam.get("jump_at_impact"):
            jump = f"0 rpm: the follower leaves the cam at any speed at its velocity drop (at {at('jump_at')})"
        else:
            jump = f"{jump_text(cam['jump_rpm'])} (at {at('jump_at')})"
        print(f"    jump speed {jump}; jamming limit {deg(cam['jamming_limit_deg'])}; contact lost: "
              f"{'YES' if cam['contact_lost'] else 'no'}; jammed: {'YES' if cam['jammed'] else 'no'}")
    for n in rep.get("notes", []):
        print(f"  note: {n}")


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
    from cams.machine.machinefile import load_machine
    from cams.machine.timing import design_machine

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
            paths = write_machine_plots(out, Path(args.file).stem, res.diagram, forces, title=spec.name)
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
