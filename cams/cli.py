"""The ``cams`` command line: a thin layer over the API.

Every subcommand turns a :class:`~laws.errors.CamsError` (bad input, no
feasible design) into one line on stderr and exit code 2, and a
:class:`~laws.errors.SolverError` (a solver that could not settle on a valid
input: the product's failure) into one line and exit code 1. The subcommands
live in :mod:`cams.commands`, one module each.

Importing this module loads only the standard library (``cams`` itself is
empty): :func:`main` first takes Ctrl-C, then imports the project, so an
interrupt while NumPy loads ends with one line and exit code 130 too.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys

__all__ = ["main"]

#: The BLAS libraries' thread counts for a command's process, unless the user set them: one thread. The matrices
#: of a design are small (hundreds of rows): several threads do not speed them up but wait on each other, and
#: on a loaded machine a least-squares step of 163 x 523 took 1 s threaded against 10 ms on one thread.
BLAS_THREADS = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS")

#: Exit code after Ctrl-C (128 + SIGINT), as shells report it (also :data:`cams.commands.common.EXIT_INTERRUPTED`).
_EXIT_INTERRUPTED = 130


def _interrupted_while_loading(signum, frame) -> None:  # pragma: no cover - runs in a subprocess (tested)
    """SIGINT before the commands run: nothing is written yet, so say so in one line and leave at once."""
    os.write(2, b"cams: interrupted\n")
    os._exit(_EXIT_INTERRUPTED)


class _Parser(argparse.ArgumentParser):
    """argparse with usage errors as one line and exit code 2."""

    def error(self, message):
        from cams.commands.common import EXIT_BAD_INPUT

        self.exit(EXIT_BAD_INPUT, f"{self.prog}: error: {message}\n")


def _version() -> str:
    """The installed distribution's version (the package's own ``cams.__version__`` is above this layer)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("cams")
    except PackageNotFoundError:  # run from a checkout that was never installed
        return "(not installed: see pyproject.toml)"


class _Version(argparse.Action):
    """``--version``: looked up only when asked (the distribution's metadata costs every other command nothing)."""

    def __call__(self, parser, namespace, values, option_string=None):
        print(f"cams {_version()}")  # on standard output, as argparse's own version action
        parser.exit()


def build_parser() -> argparse.ArgumentParser:
    """The full parser with every subcommand registered."""
    import importlib

    from cams.commands import COMMANDS

    p = _Parser(
        prog="cams",
        description="Disk-cam design: allowable-centre zone, minimum size, profiles and checks.",
        epilog="example: cams solve examples/rocker_force.toml",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--version", action=_Version, nargs=0, help="print the version of cams and exit")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name in COMMANDS:
        importlib.import_module(f"cams.commands.{name}").register(sub)
    for sp in sub.choices.values():
        # one formatter for all: descriptions wrapped to the terminal
        sp.formatter_class = argparse.HelpFormatter
    return p


def main(argv: list[str] | None = None) -> int:
    """Run the command line; return the exit code.

    Until the project's modules are loaded, Ctrl-C ends the process with one
    line on stderr and exit code 130; from then on it is a
    :class:`KeyboardInterrupt` that the command turns into the same (its
    outputs whole or absent, see :mod:`cams.io.files`).

    The BLAS libraries run on one thread (:data:`BLAS_THREADS`) when NumPy was not yet loaded and the user set no
    count of their own.
    """
    if "numpy" not in sys.modules:
        for name in BLAS_THREADS:
            os.environ.setdefault(name, "1")
    try:
        previous = signal.signal(signal.SIGINT, _interrupted_while_loading)
        ours = True
    except ValueError:  # not the main thread: signals are not ours to take
        previous, ours = None, False
    try:
        import warnings

        from cams.commands.common import EXIT_BAD_INPUT, EXIT_CHECK_FAILED, EXIT_INTERRUPTED, EXIT_OK
        from laws.errors import CamsError, SolverError

        parser = build_parser()
    finally:
        if ours:
            signal.signal(signal.SIGINT, signal.default_int_handler if previous is None else previous)
    try:
        args = parser.parse_args(argv)
    except KeyboardInterrupt:
        print("cams: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    if not getattr(args, "func", None):
        parser.print_help()
        return EXIT_BAD_INPUT
    try:
        with warnings.catch_warnings():
            # matplotlib's font and layout notices are not the user's errors: a name in a script the font
            # lacks is drawn as boxes, a crowded figure keeps its default layout
            warnings.filterwarnings("ignore", message=r"Glyph \d+ .*missing from", category=UserWarning)
            warnings.filterwarnings("ignore", message=r".*constrained_layout not applied", category=UserWarning)
            warnings.filterwarnings("ignore", message=r".*layout not applied", category=UserWarning)
            return args.func(args)
    except CamsError as e:
        print(f"cams {args.command}: error: {e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except SolverError as e:
        # not the input's fault: no exit 2 as if it were
        print(f"cams {args.command}: solver failure (a fault of cams, not of the input): {e}", file=sys.stderr)
        return EXIT_CHECK_FAILED
    except KeyboardInterrupt:
        # Ctrl-C: one line, the shell's exit code for SIGINT; outputs are whole or absent (cams.io.files)
        print(f"cams {args.command}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:
        # the reader went away (e.g. `cams solve ... | head`): not an error of ours
        sys.stderr.close()
        return EXIT_OK
    except OSError as e:
        # the commands' files name their option (cams.io.files); an error without a file name is a standard stream's
        print(f"cams {args.command}: error: {e.filename or 'standard output'}: {e.strerror or e}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except MemoryError:
        print(f"cams {args.command}: error: out of memory; use fewer samples or a lighter method", file=sys.stderr)
        return EXIT_BAD_INPUT


def entry() -> int:
    """The ``cams`` program (the console script, ``python -m cams.cli``): :func:`main` on the process's arguments,
    then the objects it made frozen out of the garbage collector (:func:`gc.freeze`) before the process ends.

    The interpreter's last collection at exit would otherwise walk every object of every module loaded (matplotlib
    and its figures' remains: 0.1-0.2 s after a drawing command) only to free memory the process is about to give
    back whole. Not for a caller that goes on running after :func:`main` (tests, a notebook): they call
    :func:`main`.
    """
    import gc

    code = main()
    gc.freeze()
    return code


if __name__ == "__main__":  # pragma: no cover
    sys.exit(entry())
