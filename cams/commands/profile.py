"""``cams profile``: solve a design and export its profile (CSV, DXF, SVG)."""

from __future__ import annotations

import argparse
import json

import numpy as np

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK, face_cam
from cams.words import length_format

__all__ = ["register"]


#: The outputs of ``cams profile``, by option name.
OUTPUTS = ("csv", "dxf", "svg", "table")
#: Said when no output option is given: what the command can write.
NOTHING_ASKED = ("no file written: give --dxf OUT (a drawing), --svg OUT (a drawing to scale), --csv OUT (the "
                 "profile's points) or --table OUT (the lift table, --step DEG) to write one")


def _check_outputs(args) -> None:
    """Refuse bad output paths and a bad ``--step`` before anything is computed: a path empty, unwritable, the
    design file, or one twice; a step without ``--table``, not > 0 or not dividing 360."""
    from cams.io.files import check_output_paths
    from cams.manufacture.curves import check_curve
    from cams.manufacture.table import table_angles
    from laws.errors import InputError

    check_curve(args.curve)
    if args.step is not None and args.table is None:
        raise InputError("--step", "is the lift table's step: give --table OUT too")
    if args.table is not None:
        table_angles(1.0 if args.step is None else args.step)
    check_output_paths([(f"--{opt}", getattr(args, opt)) for opt in OUTPUTS], inputs=[("FILE", args.file)])


def _write(args, cam, prof, bore, failing: str = "", drawing: dict | None = None) -> list[str]:
    """Write the outputs asked for, all of them or none (each rendered to a temporary first).

    ``failing`` (the reasons a failing cam fails) marks the DXF and SVG as failing; a CSV (the profile's, the
    lift table) is never marked. ``drawing``: the DXF's and SVG's fitted ``curves``, ``datum`` and ``keyway``.
    """
    from cams.io.files import STDOUT, all_or_nothing
    from cams.manufacture.dxf import write_dxf
    from cams.manufacture.points import write_csv
    from cams.manufacture.svg import write_svg
    from cams.manufacture.table import table_angles, write_table

    written = []
    with all_or_nothing():
        if args.table is not None:
            deg = table_angles(1.0 if args.step is None else args.step)
            cols = cam.face.table(cam.design, cam.solution, np.radians(deg))
            cols[0] = ("phi_deg", deg)      # the datum's angles as given, not through radians
            written.append(str(write_table(cols, args.table)))
        if args.csv is not None:
            written.append(str(write_csv(prof, args.csv)))
        if args.dxf is not None:
            written.append(str(write_dxf(prof, args.dxf, bore_radius=bore, failing=failing, **(drawing or {}))))
        if args.svg is not None:
            written.append(str(write_svg(prof, args.svg, bore_radius=bore, failing=failing, **(drawing or {}))))
    return [f"{w} (standard output)" if w == STDOUT else w for w in written]


def _summary_stream(args):
    """Where the summary goes: stderr when a file is written to standard output, so the two do not mix."""
    import sys

    from cams.io.files import writes_stdout

    return sys.stderr if any(writes_stdout(getattr(args, o)) for o in OUTPUTS) else sys.stdout


def _report(cam, prof, bore, given) -> dict:
    """The summary of the exported profile (lengths mm), without the assessment and the files written."""
    design, sol = cam.design, cam.solution
    if prof is None:  # a knife edge in a groove: no profile
        return {"name": design.name, "R0": float(sol.R0),
                "centre": {"x": float(sol.centre[0]), "y": float(sol.centre[1])}}
    from cams.present.faces import presenter

    return {"name": design.name, **presenter(cam).profile_report(cam, prof, bore, given)}


def _marks(args, cam, prof, rep: dict) -> dict:
    """The exact curves (``exact``, when a drawing is asked for or a keyway given), the ``datum`` and the
    ``keyway`` (its wall checked: :class:`~laws.errors.InputError` on ``cam.keyway_depth``) of the drawings;
    adds ``datum`` and ``keyway`` to the report ``rep``."""
    design = cam.design
    if prof is None or (args.dxf is None and args.svg is None and design.keyway_width is None):
        return {}
    from cams.manufacture.keyway import check_keyway_wall, keyway_of

    exact = cam.face.exact(design, cam.solution)
    datum = exact.datum
    rep["datum"] = {"x": float(datum[0]), "y": float(datum[1]),
                    "angle_deg": float(np.degrees(np.arctan2(datum[1], datum[0])) % 360.0)}
    keyway = keyway_of(design, datum)
    if keyway is not None:
        wall = check_keyway_wall(exact, float(design.bore_radius), keyway, design.hub_wall)
        rep["keyway"] = {"width": keyway.width, "depth": keyway.depth,
                         "angle_deg": float(np.degrees(design.keyway_angle or 0.0)),
                         "direction_deg": float(np.degrees(keyway.alpha) % 360.0), "wall": wall}
    return {"exact": exact, "datum": datum, "keyway": keyway, "curves": None}


def _curves_report(kind: str, prof, fitted) -> dict:
    """The written curves: ``curve``, ``tolerance`` (mm) and per layer ``elements`` and ``distance`` (mm, the
    certified distance to the exact curve; a polyline's is its chord tolerance, sampled, not certified: null)."""
    if fitted is not None:
        return fitted.to_dict()
    layers = {"PROFILE": prof.work, "OUTER": prof.outer, "PITCH": prof.pitch}
    return {"curve": kind, "tolerance": float(prof.tolerance),
            "layers": {k: {"elements": len(v), "distance": None} for k, v in layers.items() if v is not None}}


def _curves_line(rc: dict) -> str:
    """One line on the written curves: the count of elements and the certified distance per layer."""
    words = {"arcs": "arcs", "spline": "spline spans", "polyline": "chords"}[rc["curve"]]
    parts = [f"{k} {v['elements']} {words}" + ("" if v["distance"] is None else
                                              f" within {v['distance']:.3g} mm")
             for k, v in rc["layers"].items()]
    tail = ("certified against the exact curve" if rc["curve"] != "polyline" else
            "sampled, not certified")
    return f"curves ({rc['curve']}): " + ", ".join(parts) + f" (tolerance {rc['tolerance']:g} mm; {tail})"


def run(args) -> int:
    import sys

    from cams.io.designfile import load_design
    from cams.present.text import print_assessment, verified_words
    from cams.profile.roller import default_bore_radius

    design = load_design(args.file)
    cam = face_cam(design, args)
    opts = cam.options  # bad options fail before solving
    _check_outputs(args)  # fail before solving, and before writing any file
    out = _summary_stream(args)
    from cams.commands.progress import progress, wanted

    # the motion design of [optimize] runs for seconds: its progress on a terminal
    with progress(wanted(args) and design.optimize is not None, "designing the motion"):
        a = cam.assessment  # one rule for every command (cams.assess): verified and buildable
        prof = None if cam.face.no_profile(design) is not None else cam.profile
    bore = None
    if prof is not None:
        bore = opts.bore_radius if opts.bore_radius is not None else default_bore_radius(prof)
    rep = _report(cam, prof, bore, opts.bore_radius)
    rep.update(a.to_dict())
    drawing = _marks(args, cam, prof, rep)
    exact = drawing.pop("exact", None)
    asked = any(getattr(args, o) is not None for o in OUTPUTS)
    refused = ""
    written: list[str] = []
    if asked and prof is None:
        refused = "no profile to write"
    elif asked and not a.usable and not args.allow_failed:
        refused = "the cam fails (" + ", ".join(a.short) + "); --allow-failed writes them, marked as failing"
    elif asked:
        if prof is not None and (args.dxf is not None or args.svg is not None):
            from cams.manufacture.curves import fit_curves

            drawing["curves"] = fit_curves(exact, prof.tolerance, args.curve)
        # a suggested bore is not drawn: only a given one
        written = _write(args, cam, prof, opts.bore_radius, failing="" if a.usable else "; ".join(a.failures),
                         drawing=drawing)
    rep["written"] = written
    drawn = written and (args.dxf is not None or args.svg is not None)
    rep["curves"] = _curves_report(args.curve, prof, drawing["curves"]) if drawn else None
    if args.json:
        print(json.dumps(rep, indent=2), file=out)
    else:
        f = length_format(rep["R0"])  # enough digits for the cam's size
        if prof is None or bore is None:  # a bore whenever there is a profile
            print(f"{rep['name']}: no profile: R0 = {rep['R0']:{f}} mm", file=out)
        else:
            from cams.present.faces import presenter

            print(presenter(cam).profile_line(rep, bore, f), file=out)
        print(f"  {verified_words(rep)}", file=out)
        print_assessment(rep, file=out)
        if rep.get("keyway"):
            kw = rep["keyway"]
            print(f"  keyway  = {kw['width']:{f}} mm wide, {kw['depth']:{f}} mm deep at {kw['angle_deg']:.4f} deg "
                  f"from the datum; it leaves a hub wall of {kw['wall']:{f}} mm", file=out)
        if rep["curves"] is not None:
            print(f"  {_curves_line(rep['curves'])}", file=out)
        for w in written:
            print(f"  wrote {w}{'' if a.usable else ' (marked as failing where the format allows)'}", file=out)
        if not asked:
            print(f"  {NOTHING_ASKED}", file=out)
    if refused:
        print(f"cams profile: no file written: {refused}", file=sys.stderr)
    return EXIT_OK if a.usable else EXIT_CHECK_FAILED


def register(sub) -> None:
    """Add the ``profile`` subcommand."""
    q = sub.add_parser(
        "profile",
        help="solve, then export the cam profile as CSV, DXF or SVG",
        description="Solve a design file and write its profile in the cam frame (mm) within a chord tolerance, "
                    "or its lift table; a cam that fails a check is written only with --allow-failed. Exit code "
                    "0: usable, 1: a check fails, 2: bad input.",
        epilog="example: cams profile examples/rocker_force.toml --dxf cam.dxf --table lift.csv --step 1",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--csv", metavar="OUT", help="write the points as CSV (columns: docs/files.md)")
    q.add_argument("--dxf", metavar="OUT", help="write a DXF drawing (layers: docs/files.md, Drawings)")
    q.add_argument("--svg", metavar="OUT", help="write an SVG drawing to scale")
    q.add_argument("--table", metavar="OUT", help="write the lift table (CSV, units in the header) every --step "
                   "from cam angle 0")
    q.add_argument("--step", type=float, metavar="DEG", help="lift table step, degrees dividing 360 (default 1)")
    q.add_argument("--tolerance", type=float, help="chord tolerance in mm (default [profile] tolerance or 0.001), "
                   "the curves' certified distance to the exact one")
    q.add_argument("--curve", default="arcs", metavar="KIND",
                   help="the DXF's and SVG's curves: arcs (default; a biarc fit), spline "
                   "(cubic B-spline) or polyline")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"),
                   help="override [solve] method (roller followers)")
    q.add_argument("--allow-failed", action="store_true", help="write the files of a cam that fails a check, "
                   "marked as failing (exit code 1)")
    q.add_argument("--json", action="store_true", help="print the summary as JSON")
    q.add_argument("--quiet", action="store_true",
                   help="no progress bar (drawn on a terminal while [optimize] runs)")
    q.set_defaults(func=run)
