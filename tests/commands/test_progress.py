"""Progress of long work: a bar on standard error when it is a terminal, nothing in a pipe or with --quiet.

The terminal is a pseudo-terminal (:func:`pty.openpty`) sized 80 x 24 like a real one; what the command writes to
it is read back byte for byte.
"""

from __future__ import annotations

import fcntl
import os
import pty
import struct
import subprocess
import sys
import termios
from types import SimpleNamespace

import pytest

from tests.conftest import EXAMPLES, ROOT

DESIGNED = EXAMPLES / "translating_designed_rise.toml"  # its motion design runs 2 to 6 s, as the machine is loaded
#: ``cams ARGS`` with the bar drawn at once (no two seconds' delay: the test does not hang on the machine's speed)
_CAMS_AT_ONCE = (
    "-c",
    "import sys; import cams.commands.progress as p; p.DELAY_S = 0.0; from cams.cli import main; "
    "sys.exit(main(sys.argv[1:]))",
)


def _env() -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": str(ROOT)}


def _on_a_terminal(*argv: str, sized: bool = True) -> tuple[int, str]:
    """Run ``python argv`` with stderr on a pseudo-terminal; return its exit code and what reached the terminal."""
    master, slave = pty.openpty()
    if sized:
        fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 80, 0, 0))
    p = subprocess.Popen(
        [sys.executable, *argv], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=slave, cwd=ROOT, env=_env()
    )
    os.close(slave)
    seen = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # the child closed the terminal (EIO on Linux)
            break
        if not chunk:
            break
        seen += chunk
    os.close(master)
    return p.wait(timeout=120), seen.decode("utf-8", "replace")


def _in_a_pipe(*argv: str) -> tuple[int, str]:
    r = subprocess.run([sys.executable, *argv], capture_output=True, text=True, cwd=ROOT, env=_env(), timeout=120)
    return r.returncode, r.stderr


_WORK = """
import sys, time
from cams.commands.progress import progress, wanted
from types import SimpleNamespace
quiet = sys.argv[1] == "quiet"
with progress(wanted(SimpleNamespace(quiet=quiet)), "working", total=3, unit="step") as bar:
    for _ in range(3):
        t = time.monotonic()
        while time.monotonic() - t < 0.9:
            pass
        bar.advance()
print("after", file=sys.stderr)
"""


@pytest.mark.parametrize("sized", [True, False])
def test_the_bar_appears_on_a_terminal_after_two_seconds(sized):
    """2.7 s of work in 3 steps: the bar shows its words and count on the terminal (one that tells no size too),
    and is erased before the command's own words."""
    rc, seen = _on_a_terminal("-c", _WORK, "loud", sized=sized)
    assert rc == 0
    assert "working:" in seen and "3/3" in seen and "\r" in seen
    before, _, after = seen.rpartition("after")
    assert after.strip() == "" and before.endswith("\r")  # the line was cleared: the words start at column 0


def test_no_bar_in_a_pipe_nor_with_quiet():
    rc, err = _in_a_pipe("-c", _WORK, "loud")
    assert rc == 0 and err == "after\n"
    rc, seen = _on_a_terminal("-c", _WORK, "quiet")
    assert rc == 0 and seen.strip() == "after"


def test_short_work_shows_no_bar():
    """Under two seconds: nothing but the command's words, even on a terminal."""
    quick = _WORK.replace("0.9", "0.1")
    rc, seen = _on_a_terminal("-c", quick, "loud")
    assert rc == 0 and seen.strip() == "after"


def test_wanted_reads_quiet_and_the_terminal(monkeypatch):
    from cams.commands.progress import wanted

    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    assert wanted(SimpleNamespace(quiet=False)) and wanted(SimpleNamespace())
    assert not wanted(SimpleNamespace(quiet=True))
    monkeypatch.setattr(sys.stderr, "isatty", lambda: False, raising=False)
    assert not wanted(SimpleNamespace(quiet=False))


def test_the_motion_design_shows_its_progress_on_a_terminal_only():
    """cams solve with [optimize]: 'designing the motion' and its elapsed time on the terminal; in a pipe and with
    --quiet nothing on stderr; the report on stdout is the same either way."""
    rc, seen = _on_a_terminal(*_CAMS_AT_ONCE, "solve", str(DESIGNED))
    assert rc == 0 and "designing the motion: 00:0" in seen
    rc, err = _in_a_pipe(*_CAMS_AT_ONCE, "solve", str(DESIGNED))
    assert rc == 0 and err == ""
    rc, seen = _on_a_terminal(*_CAMS_AT_ONCE, "solve", str(DESIGNED), "--quiet")
    assert rc == 0 and seen == ""


@pytest.mark.parametrize("command", ["check", "profile"])
def test_check_and_profile_show_the_motion_designs_progress_too(command):
    rc, seen = _on_a_terminal(*_CAMS_AT_ONCE, command, str(DESIGNED))
    assert rc == 0 and "designing the motion: 00:0" in seen
    rc, seen = _on_a_terminal(*_CAMS_AT_ONCE, command, str(DESIGNED), "--quiet")
    assert rc == 0 and seen == ""


def test_the_animation_counts_its_frames(tmp_path):
    """animate_profile calls its progress once a frame written, up to the GIF's own frame count (read by Pillow)."""
    from PIL import Image

    from cams.cam import Cam
    from cams.present.plots import animate_profile

    calls: list[tuple[int, int]] = []
    p = animate_profile(
        Cam.from_file(EXAMPLES / "translating_force.toml"),
        tmp_path / "a.gif",
        frames=5,
        progress=lambda k, n: calls.append((k, n)),
    )
    with Image.open(p) as im:
        frames = im.n_frames
    assert frames == 5 and calls == [(k, frames) for k in range(1, frames + 1)]


def test_plot_counts_its_pictures(capsys, monkeypatch, tmp_path):
    """cams plot on a terminal (stderr's isatty, the bar at once): one step a picture, the total is the pictures."""
    from cams.cli import main

    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    monkeypatch.setattr("cams.commands.progress.DELAY_S", 0.0)
    rc = main(["plot", str(EXAMPLES / "rocker_force.toml"), "--out", str(tmp_path), "--only", "motion,pressure"])
    out, err = capsys.readouterr()
    assert rc == 0 and len(out.split()) == 4  # two pictures, PNG and SVG each
    assert "/2 [" in err and "drawing 2 pictures" in err
    rc = main(["plot", str(EXAMPLES / "rocker_force.toml"), "--out", str(tmp_path), "--only", "motion", "--quiet"])
    assert rc == 0 and capsys.readouterr().err == ""


@pytest.mark.skipif(not hasattr(os, "register_at_fork"), reason="no os.register_at_fork (not POSIX): processes are not forked there, no fork to guard")
def test_the_bar_does_not_draw_while_the_process_forks(capsys):
    """A process forked while a bar is drawn (cams plot's pictures, a sweep's workers) is forked while the bar's
    thread holds none of its locks: the bar's drawing lock is taken around the fork (held in the child's copy,
    free again here), and tqdm runs no monitor thread of its own that could be drawing at that moment."""
    import threading

    from tqdm import TMonitor

    import cams.commands.progress as progress_module

    with progress_module.progress(True, "working") as bar:
        (drawing,) = progress_module._DRAWING
        assert not drawing.locked()
        pid = os.fork()
        if pid == 0:  # the child: only os._exit, nothing of the test's own; a fork of its own would not wait
            os._exit(0 if drawing.locked() and progress_module._DRAWING == [] else 1)
        _, status = os.waitpid(pid, 0)
        assert os.waitstatus_to_exitcode(status) == 0  # taken while forking
        assert not drawing.locked()  # and given back here
        assert not any(isinstance(t, TMonitor) for t in threading.enumerate())
        bar.note("a note above the bar")
    assert progress_module._DRAWING == []
    assert "a note above the bar\n" in capsys.readouterr().err


def test_a_note_without_a_bar_is_one_line_on_stderr(capsys):
    from cams.commands.progress import Progress

    Progress().note("cams plot: note: something")
    assert capsys.readouterr() == ("", "cams plot: note: something\n")
