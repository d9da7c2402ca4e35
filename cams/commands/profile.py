"""``cams profile``: solve a design and export its profile (CSV, DXF, SVG)."""

from __future__ import annotations

import argparse
import json
from typing import Any

import numpy as np

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK, face_cam
from cams.words import length_format
from laws.units import turn_degrees

__all__ = ["register"]


#: The drawings whose curve's motion is measured (``export_motion``), in the order they are written.
MOTION_FORMATS = ("dxf", "svg")
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
    from cams.io.files import check_suffix

    for opt, suffix, what in (("csv", ".csv", "CSV"), ("table", ".csv", "a CSV table"), ("dxf", ".dxf", "DXF"),
                              ("svg", ".svg", "SVG")):
        check_suffix(getattr(args, opt), f"--{opt}", (suffix,), what)
    if args.max_accel_error is not None:
        from cams.manufacture.motion import check_share

        check_share(args.max_accel_error)
        if not any(getattr(args, f) is not None for f in MOTION_FORMATS):
            raise InputError("--max-accel-error", "measures a drawing's curve: give --dxf OUT or --svg OUT too")
        if args.tolerance is not None:
            raise InputError("--max-accel-error", "chooses the tolerance: give it or --tolerance, not both")


def _render(fmt: str, prof, path, bore, failing: str = "", drawing: dict | None = None):
    """Write the drawing ``fmt`` (``"dxf"``, ``"svg"``) of ``prof`` to ``path``: the one call of each writer, for
    the files asked for and for the copies the export's motion is measured on."""
    from cams.manufacture.dxf import write_dxf
    from cams.manufacture.svg import write_svg

    writer = {"dxf": write_dxf, "svg": write_svg}[fmt]
    return writer(prof, path, bore_radius=bore, failing=failing, field=f"--{fmt}", **(drawing or {}))


def _write(args, cam, prof, bore, failing: str = "", drawing: dict | None = None) -> list[str]:
    """Write the outputs asked for, all of them or none (each rendered to a temporary first).

    ``failing`` (the reasons a failing cam fails) marks the DXF and SVG as failing; a CSV (the profile's, the
    lift table) is never marked. ``drawing``: the DXF's and SVG's fitted ``curves``, ``datum`` and ``keyway``.
    """
    from cams.io.files import STDOUT, all_or_nothing
    from cams.manufacture.points import write_csv
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
        for fmt in MOTION_FORMATS:
            if getattr(args, fmt) is not None:
                written.append(str(_render(fmt, prof, getattr(args, fmt), bore, failing, drawing)))
    return [f"{w} (standard output)" if w == STDOUT else w for w in written]


def _measured(args, cam, prof, bore, failing: str, drawing: dict | None = None) -> list[tuple[dict, Any]]:
    """The motion each drawing asked for gives: its ``export_motion`` entry and its
    :class:`cams.kinematics.exported.ExportMotion`, read back from a copy the same writer draws first (so that a
    drawing whose curve cannot be followed stops the command before any file is written)."""
    import tempfile

    from cams.manufacture.motion import export_entry, measure

    out = []
    for fmt in MOTION_FORMATS:
        if getattr(args, fmt) is None:
            continue
        with tempfile.TemporaryDirectory() as tmp:
            path = _render(fmt, prof, f"{tmp}/copy.{fmt}", bore, failing, drawing)
            els, motion = measure(cam.design, cam.solution, path, f"--{fmt}")
        out.append((export_entry(fmt, prof.tolerance, els, motion), motion))
    return out


def _search(args, cam):
    """``--max-accel-error``: the coarsest tolerance whose drawing keeps the acceleration error within the share
    (:func:`cams.manufacture.motion.coarsest_tolerance`), measured on the first drawing asked for (a DXF)."""
    import tempfile

    from cams.manufacture.curves import fit_curves
    from cams.manufacture.motion import Trial, coarsest_tolerance, curve_kind, measure
    from cams.model.options import profile_options
    from cams.profile.roller import DEFAULT_TOLERANCE_FRACTION, MAX_TOLERANCE_FRACTION

    fmt = next(f for f in MOTION_FORMATS if getattr(args, f) is not None)  # one is given (_check_outputs)
    design, sol = cam.design, cam.solution
    exact = cam.face.exact(design, sol)
    base = cam.profile  # the default tolerance's: its exact smallest radius sets the range searched
    smallest = float(base.min_work_radius)
    coarsest = 0.999 * MAX_TOLERANCE_FRACTION * smallest  # just inside the cap (cap_tolerance)
    finest = min(base.tolerance, DEFAULT_TOLERANCE_FRACTION * smallest) / 10.0
    kinds: list[str] = []
    done: dict[float, Trial] = {}

    def evaluate(tol: float) -> Trial:
        if tol in done:
            return done[tol]
        prof = cam.face.profile(design, sol, profile_options(design, tolerance=tol))
        drawing = {"curves": fit_curves(exact, prof.tolerance, args.curve)}  # the curve --curve asks for
        with tempfile.TemporaryDirectory() as tmp:
            els, motion = measure(design, sol, _render(fmt, prof, f"{tmp}/trial.{fmt}", None, "", drawing),
                                  f"--{fmt}")
        kinds.append(curve_kind(els))
        done[tol] = Trial(tol, motion.da_ratio, len(els))
        return done[tol]

    evaluate(coarsest)  # the curve kind the writer draws, for the message
    return coarsest_tolerance(evaluate, coarsest, finest, args.max_accel_error, curve=kinds[0]).tolerance


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
                    "angle_deg": float(turn_degrees(np.arctan2(datum[1], datum[0])))}
    keyway = keyway_of(design, datum)
    if keyway is not None:
        wall = check_keyway_wall(exact, float(design.bore_radius), keyway, design.hub_wall)
        rep["keyway"] = {"width": keyway.width, "depth": keyway.depth,
                         "angle_deg": float(np.degrees(design.keyway_angle or 0.0)),
                         "direction_deg": float(turn_degrees(keyway.alpha)), "wall": wall}
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
        if args.max_accel_error is not None and cam.face.no_profile(design) is None:
            from cams.cam import Cam

            chosen = _search(args, cam)
            cam = Cam(design, method=args.method, tolerance=chosen, solution=cam.solution)
            opts = cam.options
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
    measured: list[tuple[dict, Any]] = []
    if asked and prof is None:
        refused = "no profile to write"
    elif asked and not a.usable and not args.allow_failed:
        refused = "the cam fails (" + ", ".join(a.short) + "); --allow-failed writes them, marked as failing"
    elif asked:
        if prof is not None and (args.dxf is not None or args.svg is not None):
            from cams.manufacture.curves import fit_curves

            drawing["curves"] = fit_curves(exact, prof.tolerance, args.curve)
        # a suggested bore is not drawn: only a given one
        failing = "" if a.usable else "; ".join(a.failures)
        # a failing cam's drawings (--allow-failed: an undercut, a crossing profile) are written, not followed:
        # the motion of a curve that is not a cam's profile is no measure of the export
        measured = _measured(args, cam, prof, opts.bore_radius, failing, drawing) if a.usable else []
        written = _write(args, cam, prof, opts.bore_radius, failing=failing, drawing=drawing)
        rep["export_motion"] = [entry for entry, _ in measured]
    rep["written"] = written
    rep.setdefault("export_motion", [])
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
        for entry, motion in measured:
            print(f"  {_motion_words(entry, motion)}", file=out)
        if not asked:
            print(f"  {NOTHING_ASKED}", file=out)
    if refused:
        print(f"cams profile: no file written: {refused}", file=sys.stderr)
    return EXIT_OK if a.usable else EXIT_CHECK_FAILED


def _motion_words(entry: dict, motion) -> str:
    """One line of an ``export_motion`` entry, units beside every number, with its shares of the law's lift and
    peaks (``motion``: its :class:`cams.kinematics.exported.ExportMotion`)."""
    u = "deg" if motion.rocker else "mm"

    def num(v: float | None, unit: str, ratio: float, of: str) -> str:
        if v is None or not np.isfinite(ratio):
            return "unbounded (a knife edge on a corner)" if v is None else f"{v:.3g} {unit}"
        pct = 100 * ratio
        return f"{v:.3g} {unit} ({pct:{'.0f' if pct >= 100 else '.3g'}} % of the law's {of})"

    return (f"the motion the {entry['format'].upper()}'s {entry['curve']} gives (tolerance {entry['tolerance']:.3g} "
            f"mm, {entry['elements']} elements), largest errors against the law: displacement "
            f"{num(entry['max_ds'], u, motion.ds_ratio, 'lift')}, velocity "
            f"{num(entry['max_dv'], u + '/rad', motion.dv_ratio, 'peak')}, acceleration "
            f"{num(entry['max_da'], u + '/rad²', motion.da_ratio, 'peak')}")


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
    q.add_argument("--tolerance", type=float, help="chord tolerance and certified curve distance, mm (default "
                   "[profile] tolerance)")
    q.add_argument("--curve", default="arcs", metavar="KIND",
                   help="the DXF's and SVG's curves: arcs (default; a biarc fit), spline "
                   "(cubic B-spline) or polyline")
    q.add_argument("--max-accel-error", type=float, metavar="SHARE",
                   help="the coarsest tolerance whose drawing keeps the follower's acceleration error within SHARE "
                        "of the law's peak (0.05: 5 %%)")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"),
                   help="override [solve] method (roller followers)")
    q.add_argument("--allow-failed", action="store_true", help="write the files of a cam that fails a check, "
                   "marked as failing (exit code 1)")
    q.add_argument("--json", action="store_true", help="print the summary as JSON")
    q.add_argument("--quiet", action="store_true",
                   help="no progress bar")
    q.set_defaults(func=run)
