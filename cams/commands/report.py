"""``cams report``: inputs, results, checks and pictures as HTML and PDF."""

from __future__ import annotations

import argparse

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK

__all__ = ["register", "run"]


def run(args) -> int:
    from cams.cam import Cam
    from cams.report import write_report

    cam = Cam.from_file(args.file)
    for p in write_report(cam, args.out):
        print(p)
    return EXIT_OK if cam.checks.passed and cam.solution.verified else EXIT_CHECK_FAILED


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
    q.set_defaults(func=run)
