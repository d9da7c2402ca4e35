"""Error messages of the command line: empty files, missing tables, a machine file given to `cams solve` and the
reverse, a byte-order mark, a margin that leaves no room, a read-only output folder, Ctrl-C while loading."""

from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from tests.conftest import EXAMPLES

MACHINE = EXAMPLES / "machines" / "slotting_machine.toml"


def _run(argv, capsys) -> tuple[int, str, str]:
    capsys.readouterr()
    rc = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return rc, out, err


@pytest.mark.parametrize("command", ["solve", "check", "profile", "plot", "report", "machine"])
def test_empty_file_is_named_empty(command, tmp_path, capsys):
    f = tmp_path / "empty.toml"
    f.write_text("", encoding="utf-8")
    rc, _, err = _run([command, f], capsys)
    assert rc == 2 and err.count("\n") == 1 and "the file is empty" in err


def test_missing_follower_table_is_named(tmp_path, capsys):
    f = tmp_path / "nofollower.toml"
    text = EXAMPLES.joinpath("rocker_force.toml").read_text(encoding="utf-8")
    f.write_text(re.sub(r"\[follower\]\n(?:[a-z_]+ = .*\n)+", "", text), encoding="utf-8")
    rc, _, err = _run(["solve", f], capsys)
    assert rc == 2 and err.count("\n") == 1
    assert err.startswith("cams solve: error: follower: the file has no [follower] table")


def test_machine_file_given_to_solve_points_to_cams_machine(capsys):
    for command in ("solve", "check", "report"):
        rc, _, err = _run([command, MACHINE], capsys)
        assert rc == 2 and err.count("\n") == 1 and "`cams machine`" in err and "linkage" in err


def test_design_file_given_to_machine_points_to_cams_solve(capsys):
    rc, _, err = _run(["machine", EXAMPLES / "rocker_force.toml"], capsys)
    assert rc == 2 and err.count("\n") == 1 and "`cams solve`" in err


def test_byte_order_mark_is_accepted(tmp_path, capsys):
    """A file saved with a UTF-8 byte-order mark gives the same answer as without."""
    plain = EXAMPLES / "rocker_force.toml"
    f = tmp_path / "bom.toml"
    f.write_bytes(b"\xef\xbb\xbf" + plain.read_bytes())
    rc, out_bom, err = _run(["solve", "--json", f], capsys)
    assert rc == 0, err
    _, out_plain, _ = _run(["solve", "--json", plain], capsys)
    bom, ref = json.loads(out_bom), json.loads(out_plain)
    for d in (bom, ref):
        d.pop("seconds", None)
    assert bom == ref and ref["R0"] > 0


def _margin_file(tmp_path: Path, margin: float) -> Path:
    f = tmp_path / f"m{margin}.toml"
    f.write_text(re.sub(r"(?m)^margin = .*$", f"margin = {margin!r}", MACHINE.read_text(encoding="utf-8")),
                 encoding="utf-8")
    return f


def test_a_margin_that_leaves_no_room_is_blamed_on_the_margin(tmp_path, capsys):
    """A margin that fills the out-of-work window is the margin's fault, not the motion's; the largest margin the
    message gives is the true one: just below it the machine runs, just above it the run is refused."""
    rc, _, err = _run(["machine", _margin_file(tmp_path, 90.0)], capsys)
    assert rc == 2 and err.count("\n") == 1 and err.startswith("cams machine: error: timing.margin: ")
    largest = float(re.search(r"the largest timing.margin that fits is ([0-9.]+) deg", err).group(1))
    window, rise = (float(x) for x in re.search(r"of the ([0-9.]+) deg out-of-work window .* takes? ([0-9.]+) deg",
                                                 err).groups())
    assert largest == pytest.approx((window - rise) / 2, abs=0.06)  # the message rounds to 4 digits
    assert _run(["machine", _margin_file(tmp_path, largest * 0.999)], capsys)[0] == 0
    rc, _, err = _run(["machine", _margin_file(tmp_path, largest * 1.001)], capsys)
    assert rc == 2 and f"the largest timing.margin that fits is {largest:.4g} deg" in err
    # rises longer than the whole window are the motion's fault, whatever the margin
    f = tmp_path / "long.toml"
    f.write_text(MACHINE.read_text(encoding="utf-8").replace("angle = 60\n", "angle = 200\n", 1), encoding="utf-8")
    rc, _, err = _run(["machine", f], capsys)
    assert rc == 2 and err.startswith("cams machine: error: motion: feed window too short") and "margin that" not in err


@pytest.mark.parametrize("argv", [["machine", MACHINE, "--plot"], ["plot", EXAMPLES / "rocker_force.toml", "--out"],
                                  ["report", EXAMPLES / "rocker_force.toml", "--out"]])
def test_read_only_output_folder_names_the_option(argv, tmp_path, capsys, monkeypatch):
    """A folder the user cannot write into is refused naming the option (as root every folder is writable: the
    permission is simulated for that folder only)."""
    ro = tmp_path / "ro"
    ro.mkdir()
    real = os.access
    monkeypatch.setattr(os, "access", lambda p, mode, **kw: False if Path(p) == ro else real(p, mode, **kw))
    rc, _, err = _run([*argv, ro], capsys)
    assert rc == 2 and err.count("\n") == 1
    assert f" {argv[-1]}: " in err and "not writable" in err
    assert list(ro.iterdir()) == []


def _cams_command() -> list[str]:
    script = Path(sys.executable).parent / "cams"
    if script.exists():
        return [str(script)]
    return [sys.executable, "-c", "import sys; from cams.cli import main; sys.exit(main())"]


def _slow_design(tmp_path: Path) -> Path:
    """A design that takes seconds to solve (the all-pairs method on many samples)."""
    f = tmp_path / "slow.toml"
    text = EXAMPLES.joinpath("rocker_force.toml").read_text(encoding="utf-8")
    f.write_text(text.replace('method = "exact"', 'method = "exhaustive"\nsamples = 1500'), encoding="utf-8")
    return f


def _wait_for_numpy(pid: int, timeout: float = 60.0) -> None:
    """Wait until process ``pid`` has begun to load NumPy (its shared library mapped): the imports are running."""
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        try:
            if "numpy" in Path(f"/proc/{pid}/maps").read_text():
                return
        except OSError:
            return  # the process is gone
        time.sleep(0.001)
    raise AssertionError("the command never loaded NumPy")


@pytest.mark.parametrize("delay", [0.0, 0.01, 0.03, 0.1, 0.2, 0.5, 1.0])
def test_ctrl_c_while_the_imports_run_is_one_line_and_exit_130(delay, tmp_path):
    """SIGINT while the imports run and after (from the moment NumPy begins to load, then at delays up to a second
    into the solve) ends the installed `cams solve` with exit 130 and at most one line on stderr.

    The delays count from NumPy's first mapping, not from the process's start: before it only the interpreter's
    own start-up runs (its ``site`` module, whose Ctrl-C no program can take; a loaded machine can make it last
    longer than any fixed delay), then ``import cams.cli``, which loads only the standard library (next test)."""
    cmd = [*_cams_command(), "solve", str(_slow_design(tmp_path))]
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=tmp_path)
    _wait_for_numpy(p.pid)
    time.sleep(delay)
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=120)
    assert p.returncode == 130, (delay, p.returncode, err)
    assert err.count("\n") <= 1 and "Traceback" not in err, (delay, err)
    assert err in ("", "cams: interrupted\n", "cams solve: interrupted\n")


def test_import_cams_loads_nothing_and_takes_no_signal():
    """`import cams, cams.cli` loads no NumPy and leaves Ctrl-C to Python (no side effect on the importer)."""
    prog = ("import signal, sys\nbefore = signal.getsignal(signal.SIGINT)\nimport cams, cams.cli\n"
            "print('numpy' in sys.modules, signal.getsignal(signal.SIGINT) is before, cams.InputError.__name__)")
    r = subprocess.run([sys.executable, "-c", prog], capture_output=True, text=True, check=True)
    assert r.stdout.split() == ["False", "True", "InputError"]


def _unsettling(monkeypatch) -> None:
    """The nearest-point method made to give up at its first step: a solver that cannot settle."""
    from optimize.planar import NearestPoint

    real = NearestPoint.solve
    monkeypatch.setattr(NearestPoint, "solve", lambda self, max_steps=None: real(self, max_steps=0))


def test_a_solver_that_cannot_settle_is_its_failure_exit_1_not_bad_input(monkeypatch, capsys):
    """Issue 28, defect 1: a solver failure is one line saying so and exit code 1, never exit 2 (bad input)."""
    _unsettling(monkeypatch)
    rc, out, err = _run(["solve", EXAMPLES / "rocker_force.toml"], capsys)
    assert rc == 1 and out == "" and err.count("\n") == 1
    assert err.startswith("cams solve: solver failure (a fault of cams, not of the input): ")
    assert "did not settle in 0 steps" in err


def test_a_solver_failure_in_a_sweep_is_a_row_that_says_so(monkeypatch):
    """One design the solver fails on is a row with its error, not a lost batch (one process: the patch holds; each
    design by itself, the path whose solver is patched)."""
    from cams.sweep import sweep
    from tests.conftest import rocker_dict

    _unsettling(monkeypatch)
    res = sweep(rocker_dict(), [("follower.arm", np.array([100.0]))], workers=1, per_design=True)
    assert res.rows[0]["error"].startswith("solver failure: the nearest-point method did not settle")
    assert res.rows[0]["R0"] is None and res.failed == 1


def test_python_m_cams_is_the_program():
    """``python -m cams ARGS`` runs the program as the console script does: the same output and exit code as
    :func:`cams.cli.main` in process, and a bad option is its one line and exit 2."""
    from tests.inprocess import ROOT, cams_cli

    design = str(ROOT / "examples" / "rocker_force.toml")
    r = subprocess.run([sys.executable, "-m", "cams", "check", design], capture_output=True, text=True, cwd=ROOT)
    here = cams_cli("check", design)
    def strip(text: str) -> str:  # the run's own time
        return re.sub(r"\d+(\.\d+)? ms", "ms", text)

    assert (r.returncode, strip(r.stdout)) == (here.returncode, strip(here.stdout))
    bad = subprocess.run([sys.executable, "-m", "cams", "check", design, "--nosuch"], capture_output=True,
                         text=True, cwd=ROOT)
    assert bad.returncode == 2 and bad.stderr.count("\n") <= 2 and "--nosuch" in bad.stderr
