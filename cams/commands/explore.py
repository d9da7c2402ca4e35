"""``cams explore``: one self-contained HTML page in which the cam centre (or a flat face's size) is moved by hand."""

from __future__ import annotations

import argparse
import sys

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK

__all__ = ["register", "run"]


def run(args) -> int:
    from pathlib import Path

    from cams.cam import Cam
    from cams.io.designfile import load_design
    from cams.io.files import atomic_write, check_output_paths, writes_stdout
    from cams.present.explore import explore_data, page
    from laws.errors import InputError

    # before any work: an unwritable page, or one that would replace the design file, is said at once
    check_output_paths([("--out", args.out)], inputs=[("FILE", args.file)])
    if not writes_stdout(args.out) and Path(args.out).suffix.lower() not in (".html", ".htm"):
        raise InputError("--out", f"{args.out!r}: the page is HTML, give a .html name (or - for standard output)")
    design = load_design(args.file)
    cam = Cam(design)
    from cams.commands.progress import progress, wanted

    with progress(wanted(args) and design.optimize is not None, "designing the motion"):
        data = explore_data(cam)
    html = page(data)

    def write(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(html)

    atomic_write(args.out, "--out", write)
    say = sys.stderr if writes_stdout(args.out) else sys.stdout  # the page itself may be the standard output
    if data["diagnosis"] is not None:
        print(f"wrote {args.out}: no cam can be sized ({data['diagnosis']}); the page says why", file=say)
        return EXIT_CHECK_FAILED
    a = cam.assessment  # one rule for every command (cams.assess): verified and buildable
    print(
        f"wrote {args.out}: the sized cam's {'centre' if data['face']['mode'] == 'centre' else 'size'} to start "
        f"from; open it in a browser",
        file=say,
    )
    if not a.usable:
        for line in a.failures:
            print(f"  FAIL: {line}", file=say)
    return EXIT_OK if a.usable else EXIT_CHECK_FAILED


def register(sub) -> None:
    """Add the ``explore`` subcommand."""
    q = sub.add_parser(
        "explore",
        help="write an interactive page: drag the cam centre over the allowable zone",
        description="Write one self-contained HTML page (no server, nothing fetched) showing the allowable-centre "
        "zone with its binding lines t-t and t1-t1, the sized cam's centre and a point you drag: R0, L "
        "or the offset, the largest pressure angle of each phase against its limit, the pressure angle "
        "over the cycle, the profile to scale with any undercut, computed in the page with a stated "
        "error bound. A flat-faced follower: its base radius (and a rocker's centre distance) are "
        "moved instead. Exit code 0: the sized cam is usable, 1: it fails a check or none can be "
        "sized (the page says why), 2: bad input.",
        epilog="example: cams explore examples/rocker_force.toml --out rocker.html",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--out", required=True, help="the page to write (HTML)")
    q.add_argument(
        "--quiet",
        action="store_true",
        help="no progress (drawn on a terminal's stderr while the motion design of [optimize] runs)",
    )
    q.set_defaults(func=run)
