"""``cams check``: solve a design, then check its profile (jamming, undercut, validity, bore)."""

from __future__ import annotations

import argparse
import json

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK, face_cam
from cams.present.text import print_checks

__all__ = ["register"]


def run(args) -> int:
    from cams.io.designfile import load_design
    from cams.present.text import print_assessment, verified_words

    design = load_design(args.file)
    cam = face_cam(design, args)
    _ = cam.options  # bad options fail before solving
    from cams.commands.progress import progress, wanted

    # the motion design of [optimize] runs for seconds: its progress on a terminal
    with progress(wanted(args) and design.optimize is not None, "designing the motion"):
        a = cam.assessment  # one rule for every command (cams.assess): verified and buildable
        report = cam.computed("checks")  # None: a knife edge in a groove, or no profile at the tolerance
        _ = cam.forces  # the [dynamics] line's, computed before the bar is erased
    rep = {"name": design.name, "passed": False, "checks": []} if report is None else report.to_dict()
    rep.update(a.to_dict())
    passed = a.usable and report is not None and report.passed
    rep["passed"] = passed
    notes: list[str] = []
    if design.chosen:  # how the chosen cam's centre was found
        notes = [n for n in cam.solution.notes if not any(n in f for f in a.failures)]  # said once, on its FAIL line
    if notes:
        rep["notes"] = notes
    if args.json:
        print(json.dumps(rep, indent=2))
    else:
        if report is not None:
            print_checks(rep)
        else:
            print(f"{design.name}: no profile to check")
        _print_dynamics(cam)
        print(f"  {verified_words(rep)}")
        print_assessment(rep)
        for n in notes:
            print(f"  note: {n}")
    return EXIT_OK if passed else EXIT_CHECK_FAILED


def _print_dynamics(cam) -> None:
    """The ``[dynamics]`` table's results, as ``cams solve`` prints them: spring, contact force, torque, jump speed
    (nothing without the table; why not, when the table is given but no force is computed)."""
    from cams.present.text import print_cam_forces

    d = cam.design
    if d.dynamics is None:
        return
    speed = "" if d.rpm is None else f" at {d.rpm:g} rpm"
    df, note = cam.forces, cam.forces_note
    if df is None:
        print(f"  dynamics{speed}: {note or 'no forces computed'}")
        return
    print(f"  dynamics{speed}:")
    print_cam_forces(df.to_dict(), indent="    ", follower=d.follower.kind)


def register(sub) -> None:
    """Add the ``check`` subcommand."""
    q = sub.add_parser(
        "check",
        help="solve, then check the profile: jamming, undercut, polygon, bore",
        description="Solve a design file and check the finished profile: pressure angle recomputed from the "
                    "pitch curve, undercut and sharp points, a valid closed working profile, the bore, the [dynamics] "
                    "table when given. "
                    "A flat-faced follower: convexity (radius of curvature >= limits.min_radius), a valid "
                    "closed profile, the bore. Exit code 0: all pass, 1: a check fails, 2: bad input.",
        epilog="example: cams check examples/rocker_force.toml --json",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--tolerance", type=float, help="chord tolerance in mm (default [profile] tolerance or 0.001)")
    q.add_argument("--method", choices=("exact", "convex", "exhaustive"),
                   help="override [solve] method (roller followers)")
    q.add_argument("--json", action="store_true", help="print the checks as JSON")
    q.add_argument("--quiet", action="store_true",
                   help="no progress (drawn on a terminal's stderr while the motion design of [optimize] runs)")
    q.set_defaults(func=run)
