"""``cams ARGS`` run in the test's own process, for the tests that check what a command prints and returns
rather than the process itself (its start-up, signals, the light import keep their subprocess).

:func:`cams_cli` is a drop-in for ``subprocess.run([python, "-m", "cams.cli", *args], capture_output=True,
text=True, cwd=cwd)``: the same :func:`cams.cli.main` the module's ``__main__`` calls, its return value the exit
code (``SystemExit``, argparse's usage errors, included), its standard output and error captured whole (a
standard stream's ``buffer`` too, for the commands that write bytes to ``-``). Python shows a fresh process's
warnings on stderr under its default filters; they are shown here the same way, so a test that asks for an empty
or one-line stderr still sees them. An exception that would have been a traceback propagates and fails the test.
"""

from __future__ import annotations

import contextlib
import io
import subprocess
import sys
import warnings
from pathlib import Path

from cams.cli import main

ROOT = Path(__file__).resolve().parents[1]


def _stream() -> io.TextIOWrapper:
    return io.TextIOWrapper(io.BytesIO(), encoding="utf-8", newline="", write_through=True)


def _text(s: io.TextIOWrapper) -> str:
    s.flush()
    return s.buffer.getvalue().decode("utf-8")  # type: ignore[attr-defined]


def cams_cli(*args, cwd: Path | str | None = None) -> subprocess.CompletedProcess:
    """``cams ARGS`` in this process (in ``cwd``, the repository's root by default): its exit code, stdout,
    stderr."""
    argv = [str(a) for a in args]
    out, err = _stream(), _stream()
    with contextlib.ExitStack() as stack:
        stack.enter_context(contextlib.chdir(cwd or ROOT))
        stack.enter_context(contextlib.redirect_stdout(out))
        stack.enter_context(contextlib.redirect_stderr(err))
        stack.enter_context(warnings.catch_warnings())
        # Python's default filters (a fresh `python -m cams.cli`): shown once per place, deprecations hidden
        warnings.resetwarnings()
        warnings.simplefilter("default")
        for category in (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning):
            warnings.filterwarnings("ignore", category=category)
        warnings.showwarning = _show
        try:
            code = main(argv)
        except SystemExit as e:
            code = e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
            if e.code is not None and not isinstance(e.code, int):
                print(e.code, file=sys.stderr)
    return subprocess.CompletedProcess([sys.executable, "-m", "cams.cli", *argv], code, _text(out), _text(err))


def _show(message, category, filename, lineno, file=None, line=None) -> None:
    """Write a warning to the (redirected) stderr as Python's own handler does."""
    sys.stderr.write(warnings.formatwarning(message, category, filename, lineno, line))


__all__ = ["cams_cli"]
