"""``cams report``: inputs, results, checks and pictures as HTML and PDF."""

from __future__ import annotations

import argparse
from pathlib import Path

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK, add_drawing_jobs, check_jobs
from laws.errors import InputError

__all__ = ["register", "run"]


def run(args) -> int:
    from cams.cam import Cam
    from cams.io.files import all_or_nothing, check_output_paths
    from cams.present.report import write_report

    check_jobs(args.jobs)
    cam = Cam.from_file(args.file)
    if not args.out.strip():
        raise InputError("--out", "must name a folder, got an empty path")
    if Path(args.out).is_dir():  # a folder to be made is checked when made
        check_output_paths([("--out", Path(args.out) / name) for name in ("report.html", "report.pdf")],
                           inputs=[("FILE", args.file)])
    from cams.commands.progress import progress, wanted

    with progress(wanted(args), "solving the cam") as bar:  # seconds of work: its progress on a terminal
        a = cam.assessment  # one rule for every command (cams.assess): verified and buildable
        bar.stage("drawing and writing the report")
        with all_or_nothing():  # together or not at all
            written = write_report(cam, args.out, source=args.file, jobs=args.jobs,
                                   note=lambda words: bar.note(f"cams report: note: {words}"))
    for p in written:
        print(p)
    if not a.usable:
        from cams.present.text import print_assessment, verified_words

        print(verified_words(a.to_dict()))
        print_assessment(a.to_dict(), indent="")
    return EXIT_OK if a.usable else EXIT_CHECK_FAILED


def register(sub) -> None:
    """Add the ``report`` subcommand."""
    q = sub.add_parser(
        "report",
        help="one report (HTML and PDF) with inputs, results, checks and pictures",
        description="Write report.html and report.pdf for a design file.",
        epilog="example: cams report examples/rocker_form.toml --out report",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--out", default="report", help="output folder (default: report)")
    add_drawing_jobs(q)
    q.add_argument("--quiet", action="store_true", help="no progress (drawn on a terminal's stderr when the work "
                   "runs past about two seconds)")
    q.set_defaults(func=run)
