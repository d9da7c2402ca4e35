"""``cams profile``: solve a design and export its profile (CSV, DXF, SVG)."""

from __future__ import annotations

import argparse
import json

from cams.commands.common import EXIT_OK, is_flat, refuse_method
from cams.words import bore_text, length_format

__all__ = ["register"]


def _check_outputs(args) -> None:
    """Refuse bad output paths before anything is computed: empty, unwritable, the design file, or one twice."""
    from cams.files import check_output_paths

    check_output_paths([(f"--{opt}", getattr(args, opt)) for opt in ("csv", "dxf", "svg")],
                       inputs=[("FILE", args.file)])


def _write(args, prof, bore) -> list[str]:
    """Write the outputs asked for, all of them or none (each rendered to a temporary first)."""
    from cams.export import write_csv, write_dxf, write_svg
    from cams.files import all_or_nothing

    written = []
    with all_or_nothing():
        if args.csv is not None:
            written.append(str(write_csv(prof, args.csv)))
        if args.dxf is not None:
            written.append(str(write_dxf(prof, args.dxf, bore_radius=bore)))
        if args.svg is not None:
            written.append(str(write_svg(prof, args.svg, bore_radius=bore)))
    return written


def _run_flat(args, design) -> int:
    from cams.flatface import flat_face_profile, size_flat_face
    from cams.profile import default_bore_radius, resolve_tolerance

    refuse_method(args.method)
    tol, field = resolve_tolerance(design.tolerance, args.tolerance)
    _check_outputs(args)  # fail before sizing, and before writing any file
    sol = size_flat_face(design)
    prof = flat_face_profile(design, sol.R0, tolerance=tol, field=field)
    bore = design.bore_radius if design.bore_radius is not None else default_bore_radius(prof)
    written = _write(args, prof, design.bore_radius)  # a suggested bore is not drawn
    rep = {
        "name": design.name,
        "face": "flat",
        "points": len(prof),
        "tolerance": prof.tolerance,
        "R0": prof.R0,
        "centre": {"x": float(sol.centre[0]), "y": float(sol.centre[1])},
        "min_work_radius": prof.min_work_radius,
        "min_rho": sol.min_rho,
        "min_radius": design.min_radius,
        "bore_radius": bore,
        "bore_suggested": design.bore_radius is None,
        "columns": "phi_deg,work_x,work_y",
        "written": written,
    }
    if args.json:
        print(json.dumps(rep, indent=2))
    else:
        f = length_format(rep["R0"])
        print(f"{rep['name']}: {rep['points']} points at tolerance {rep['tolerance']:g} mm, "
              f"R0 = {rep['R0']:{f}} mm, profile radius >= {rep['min_work_radius']:{f}} mm, "
              f"radius of curvature >= {sol.min_rho:{f}} mm, {bore_text(bore, rep['bore_suggested'])}")
        if not sol.verified:
            print(f"  warning: radius of curvature {sol.min_rho:.6g} mm < limits.min_radius {design.min_radius:g} mm "
                  "(run cams check)")
        for w in written:
            print(f"  wrote {w}")
    return EXIT_OK


def run(args) -> int:
    from cams.checks import curvature_extremes
    from cams.designfile import load_design
    from cams.profile import build_profile, default_bore_radius, profile_options, smallest_cam_radius
    from optimize.solve import solve

    design = load_design(args.file)
    if is_flat(design):
        return _run_flat(args, design)
    opts = profile_options(design, tolerance=args.tolerance)
    _check_outputs(args)  # fail before solving, and before writing any file
    result = solve(design, method=args.method, objective=design.extra.get("objective", "R0"))
    prof = build_profile(result.design, result.centre, tolerance=opts.tolerance)
    bore = opts.bore_radius if opts.bore_radius is not None else default_bore_radius(prof)
    ext = curvature_extremes(result.design, result.centre)  # all that can fail, before writing
    written = _write(args, prof, opts.bore_radius)  # a suggested bore is not drawn
    cam_r = smallest_cam_radius(result.design, result.centre)[0]
    rep = {
        "name": design.name,
        "points": len(prof),
        "tolerance": prof.tolerance,
        "R0": prof.R0,
        "centre": {"x": float(result.centre[0]), "y": float(result.centre[1])},
        "roller_radius": prof.roller_radius,
        "min_work_radius": prof.min_work_radius,
        "bore_radius": bore,
        "bore_suggested": opts.bore_radius is None,
        "smallest_cam_radius": cam_r,
        "largest_roller_radius": ext.convex if prof.outer is None else min(ext.convex, ext.concave),
        "groove": prof.groove,
        "written": written,
    }
    if args.json:
        print(json.dumps(rep, indent=2))
    else:
        f = length_format(rep["R0"])
        print(f"{rep['name']}: {rep['points']} points at tolerance {rep['tolerance']:g} mm, "
              f"R0 = {rep['R0']:{f}} mm (pitch curve), cam's smallest radius {cam_r:{f}} mm, "
              f"{bore_text(bore, rep['bore_suggested'])}")
        if rep["largest_roller_radius"] <= prof.roller_radius:
            print(f"  warning: undercut: roller radius {prof.roller_radius:g} mm >= largest allowed "
                  f"{rep['largest_roller_radius']:.4f} mm (run cams check)")
        for w in written:
            print(f"  wrote {w}")
    return EXIT_OK


def register(sub) -> None:
    """Add the ``profile`` subcommand."""
    q = sub.add_parser(
        "profile",
        help="solve, then export the cam profile as CSV, DXF or SVG",
        description="Solve a design file and write its profile in the cam frame (mm): pitch curve, working "
                    "profile (and outer groove wall), sampled within a chord tolerance. A flat-faced follower's cam "
                    "has no pitch curve: CSV columns phi_deg,work_x,work_y.",
        epilog="example: cams profile examples/rocker_force.toml --csv cam.csv --dxf cam.dxf --svg cam.svg",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--csv", metavar="OUT", help="write phi_deg,pitch_x,pitch_y,work_x,work_y[,outer_x,outer_y] "
                   "(flat face: phi_deg,work_x,work_y)")
    q.add_argument("--dxf", metavar="OUT", help="write a DXF drawing: layers PROFILE (working profile), OUTER (a "
                   "groove's outer wall), PITCH (roller-centre path), BASE (circle of radius R0, the pitch curve's base "
                   "circle), BORE")
    q.add_argument("--svg", metavar="OUT", help="write an SVG drawing to scale")
    q.add_argument("--tolerance", type=float, help="chord tolerance in mm (default [profile] tolerance or 0.001)")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"),
                   help="override [solve] method (roller followers)")
    q.add_argument("--json", action="store_true", help="print the summary as JSON")
    q.set_defaults(func=run)
