"""``cams new``: a commented design file to start from."""

from __future__ import annotations

import argparse

from cams.commands.common import EXIT_OK

__all__ = ["register", "run"]


def run(args) -> int:
    from cams.io.templates import TEMPLATES

    text = TEMPLATES[f"{args.kind}_flat" if args.flat else args.kind]
    if args.out is None:
        print(text, end="")
        return EXIT_OK
    from cams.io.files import (
        atomic_write,
        check_output_path,
        output_kind,
        writes_stdout,
    )

    path = check_output_path(args.out, "--out")
    from cams.io.files import check_suffix

    check_suffix(args.out, "--out", (".toml",), "a design file (TOML)")
    out = output_kind(path)
    if out[0] == "file" and out[1].exists() and not args.force:  # a device, a FIFO or - is written to, not replaced
        from laws.errors import InputError

        raise InputError("--out", f"{str(path)!r} exists; use --force to overwrite")

    def write(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(text)

    to_stdout = writes_stdout(path)
    atomic_write(path, "--out", write)
    if not to_stdout:
        print(path)
    return EXIT_OK


def register(sub) -> None:
    """Add the ``new`` subcommand."""
    q = sub.add_parser(
        "new",
        help="write a commented design file to start from",
        description="Print (or write) a commented design file for a follower kind.",
        epilog="example: cams new rocker --out my_cam.toml; cams new translating --flat",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("kind", choices=("rocker", "translating"), help="follower kind")
    q.add_argument("--flat", action="store_true", help="a flat-faced follower (sized by convexity)")
    q.add_argument("--out", help="file to write (default: print)")
    q.add_argument("--force", action="store_true", help="overwrite an existing file")
    q.set_defaults(func=run)
