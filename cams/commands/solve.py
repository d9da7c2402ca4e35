"""``cams solve``: the smallest cam of a design file, verified."""

from __future__ import annotations

import argparse
import json
import sys

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK
from cams.present.text import print_assessment

__all__ = ["register"]


def _check_save(args, design) -> None:
    """Refuse ``--save-design`` before any work: no ``[optimize]`` table, or a path that cannot be written."""
    from cams.io.files import check_output_paths, writes_stdout
    from laws.errors import InputError

    if getattr(design, "optimize", None) is None:
        raise InputError("--save-design", "the design has no [optimize] table: no law was designed, nothing to save")
    check_output_paths([("--save-design", args.save_design)], inputs=[("FILE", args.file)])
    from cams.io.files import check_suffix

    check_suffix(args.save_design, "--save-design", (".toml",), "a design file (TOML)")
    if writes_stdout(args.save_design):
        raise InputError("--save-design", "standard output carries the report: name a file")


def _save(args, cam, rep: dict, usable: bool) -> None:
    """Write the designed design file (``--save-design``) of a usable cam; say so in ``rep``'s notes either way."""
    if args.save_design is None:
        return
    if not usable:
        rep["notes"].append(f"--save-design: {args.save_design} not written: the designed cam fails a check")
        return
    from pathlib import Path

    from cams.io.designfile import designed_document
    from cams.io.document import read_toml
    from cams.io.files import atomic_write
    from cams.io.tomlwrite import dumps

    o = cam.solution.optimization
    held = getattr(cam.design, "centre", None) if o.objective == "pressure_angle" else None
    doc = designed_document(read_toml(args.file), cam.design.program, tuple(o.free), floor=o.floor, centre=held)
    source = Path(args.file).name.replace("\n", " ").replace("\r", " ")
    text = f"# The laws designed by cams solve from {source}\n" + dumps(doc)
    path = atomic_write(args.save_design, "--save-design", lambda tmp: Path(tmp).write_text(text, encoding="utf-8"))
    rep["saved_design"] = str(path)


def _said_saved(rep: dict) -> None:
    if rep.get("saved_design"):
        print(f"wrote {rep['saved_design']}")


def _work(cam, design, bar):
    """The report's dict, the forces' dict and the assessment (None: an exact answer not certified)."""
    rep = cam.solution.to_dict()
    if rep.get("certified") is False:
        return rep, None, None
    bar.stage("checking the cam")
    forces = None
    if design.dynamics is not None:
        from cams.dynamics.forces import impact_note

        df, note = cam.forces, cam.forces_note  # computed once: the assessment reads them too
        if note:
            rep["notes"].append(note)
        if df is not None:
            forces = df.to_dict()
            note = impact_note(df.forces)
            if note:
                rep["notes"].append(note)
    if cam.face.forces_computed:
        rep["forces"] = forces
    if design.contact is not None:
        c, note = cam.contact, cam.contact_note
        rep["contact"] = None if c is None else c.to_dict()
        for n in ([note] if note else []) + ([] if c is None else c.notes()):
            rep["notes"].append(n)
    if design.dynamics is not None and design.dynamics.dynamics.train_stiffness is not None:
        bar.stage("the follower train's vibration")
        v = cam.vibration
        rep["vibration"] = None if v is None else v.to_dict()
    # one rule for every command (cams.assess): verified, and buildable (a working profile, its checks, dynamics)
    a = cam.assessment
    rep.update(a.to_dict())
    return rep, forces, a


def run(args) -> int:
    from cams.commands.common import face_cam
    from cams.io.designfile import load_design
    from cams.present.faces import presenter

    design = load_design(args.file)
    if args.save_design is not None:
        _check_save(args, design)
    cam = face_cam(design, args)
    from cams.commands.progress import progress, wanted

    # the motion design runs for seconds: its progress on a terminal (none for a design of fixed laws)
    with progress(wanted(args) and design.optimize is not None, "designing the motion") as bar:
        rep, forces, a = _work(cam, design, bar)
    if a is None:
        return _not_certified(args, rep)
    _save(args, cam, rep, a.usable)
    if args.json:
        if forces is not None:
            from cams.dynamics.forces import json_safe

            rep["forces"] = json_safe(forces)  # an unbounded force (rigid impact) as null: strict JSON
        print(json.dumps(rep, indent=2))
    else:
        presenter(cam).print_summary(rep)
        print_assessment(rep)
        _said_saved(rep)
    return EXIT_OK if a.usable else EXIT_CHECK_FAILED


def _not_certified(args, rep: dict) -> int:
    """An exact answer whose bounds disagree: said so, never printed as an answer (exit 1)."""
    eb = rep["error_bound"]
    gap = "no feasible centre was found near it" if eb is None else f"its bounds differ by {eb:.3g} mm"
    msg = (f"not certified: the exact method's result for R0 ({rep['R0']:.9g} mm) is not proven: {gap}; "
           "try --method convex")
    if args.json:
        print(json.dumps(rep, indent=2))
        print(f"cams solve: {msg}", file=sys.stderr)
    else:
        print(f"{rep['name']}: {msg}")
    return EXIT_CHECK_FAILED


def register(sub) -> None:
    """Add the ``solve`` subcommand."""
    q = sub.add_parser(
        "solve",
        help="smallest cam: R0, L or offset, verified pressure angle",
        description="Find the allowable-centre zone and the smallest cam of a design file. For a flat-faced "
                    "follower (face = \"flat\"): the smallest base radius from convexity (radius of curvature "
                    ">= limits.min_radius), the face width the contact travels over and the pressure angle, "
                    "which the geometry fixes.",
        epilog="example: cams solve examples/rocker_force.toml --json",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"),
                   help="override [solve] method (roller followers)")
    q.add_argument("--json", action="store_true", help="print the report as JSON")
    q.add_argument("--save-design", metavar="FILE",
                   help="with [optimize]: write the design with the designed laws as spline law tables (no "
                        "[optimize]; it solves to the same cam); only for a cam that passes every check")
    q.add_argument("--quiet", action="store_true",
                   help="no progress (drawn on a terminal's stderr while the motion design of [optimize] runs)")
    q.set_defaults(func=run)
