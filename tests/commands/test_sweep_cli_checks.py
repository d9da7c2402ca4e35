"""``cams sweep``: --jobs and --vary checked, a wrong base design refused, Ctrl-C one line, a bar only on a terminal."""

import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import cams.sweep
import cams.sweep.engine
from cams.cli import main
from cams.sweep import key_parts, parse_vary, sweep
from laws.errors import InputError
from tests.conftest import EXAMPLES, rocker_dict

ROCKER = EXAMPLES / "rocker_force.toml"
ROOT = Path(__file__).resolve().parents[2]


def _run(capsys, *argv):
    rc = main(["sweep", *map(str, argv)])
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


@pytest.mark.parametrize("jobs", ["-1", "0"])
def test_jobs_must_be_at_least_one(tmp_path, capsys, jobs):
    out = tmp_path / "s.csv"
    rc, _, err = _run(capsys, ROCKER, "--vary", "follower.arm=100,120", "--out", out, "--jobs", jobs, "--quiet")
    assert rc == 2 and err == f"cams sweep: error: --jobs: must be an integer >= 1 (processes), got {jobs}\n"
    assert not out.exists()


@pytest.mark.parametrize("workers", [0, -1, 1.5, True, "2"])
def test_workers_checked_in_the_api(workers):
    with pytest.raises(InputError, match="^workers: "):
        sweep(rocker_dict(), [("follower.arm", np.array([100.0]))], workers=workers)


def test_pool_never_larger_than_the_designs(monkeypatch):
    res = sweep(rocker_dict(), [("follower.arm", np.array([100.0, 120.0]))], method="convex", workers=64)
    assert res.workers == 2 and [r["error"] for r in res.rows] == [None, None]
    monkeypatch.setattr("cams.sweep.engine.cores", lambda: 1)  # one core, as the engine counts them
    res = sweep(rocker_dict(), [("follower.arm", np.linspace(100, 120, 12))], method="convex", workers=1000)
    assert res.workers == cams.sweep.MAX_WORKERS_PER_CPU
    res = sweep(rocker_dict(), [("follower.arm", np.array([100.0]))], method="convex")
    assert res.workers == 1


def test_ctrl_c_keeps_the_rows_done(tmp_path, capsys, monkeypatch):
    calls = []
    real = cams.sweep.engine.evaluate

    def solve_then_interrupt(job):
        calls.append(job)
        if len(calls) == 3:  # the two timed designs are written, then Ctrl-C
            raise KeyboardInterrupt
        return real(job)

    monkeypatch.setattr(cams.sweep.engine, "evaluate", solve_then_interrupt)
    out = tmp_path / "s.csv"
    rc, stdout, err = _run(capsys, ROCKER, "--vary", "follower.arm=100:120:4", "--out", out, "--jobs", "1", "--quiet",
                           "--per-design")  # one design a call (the batch would time all four at once)
    assert rc == 130 and stdout == ""
    assert err == f"cams sweep: interrupted; {out} holds 2 row(s): run again with --resume to go on\n"
    lines = out.read_text().splitlines()
    assert len(lines) == 3 and {r["index"] for r in csv.DictReader(out.open())} == {"0", "3"}
    assert sorted(os.listdir(tmp_path)) == ["s.csv", "s.csv.sweep.json"]


def _interrupt_at_once(job):
    raise KeyboardInterrupt


def test_ctrl_c_before_a_row_with_resume_and_nothing_to_resume(tmp_path, capsys, monkeypatch):
    """``--resume`` on a Parquet table not there yet, then Ctrl-C while the first design is solved: the run began the
    sidecar and the parts folder, so it removes them (they were left behind: "nothing written" was not so)."""
    pytest.importorskip("pyarrow", reason="Parquet tables need pyarrow (the test extra installs it)")
    monkeypatch.setattr(cams.sweep.engine, "evaluate", _interrupt_at_once)
    rc, stdout, err = _run(capsys, ROCKER, "--vary", "follower.arm=100,120", "--out", tmp_path / "s.parquet",
                           "--jobs", "1", "--quiet", "--per-design", "--resume")
    assert (rc, stdout) == (130, "")
    assert err == "cams sweep: interrupted before a row was solved; nothing written\n"
    assert os.listdir(tmp_path) == []


def test_ctrl_c_before_a_row_keeps_a_header_only_table_it_resumed(tmp_path, capsys, monkeypatch):
    """``--resume`` on a header-only table and its sidecar, left by an earlier run, then Ctrl-C before a row: this run
    did not create them, so both stay as they were (they were deleted)."""
    out = tmp_path / "s.csv"
    argv = [ROCKER, "--vary", "follower.arm=100,120", "--out", out, "--jobs", "1", "--quiet", "--per-design"]
    assert _run(capsys, *argv)[0] == 0
    out.write_text(out.read_text(encoding="utf-8").splitlines(keepends=True)[0], encoding="utf-8")  # the header
    before = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert sorted(before) == ["s.csv", "s.csv.sweep.json"] and before["s.csv"].startswith(b"index,")
    monkeypatch.setattr(cams.sweep.engine, "evaluate", _interrupt_at_once)
    rc, stdout, err = _run(capsys, *argv, "--resume")
    assert (rc, stdout) == (130, "")
    assert err == "cams sweep: interrupted before a row was solved; nothing written\n"
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == before


@pytest.mark.skipif(not (sys.platform.startswith("linux") and Path("/proc").is_dir()), reason="needs /proc")
def test_ctrl_c_stops_the_pool(tmp_path):
    """SIGINT to the whole process group, as a terminal sends it: one line, exit 130, no worker left."""
    code = ("import signal, sys; signal.signal(signal.SIGINT, signal.default_int_handler); "
            "from cams.cli import main; sys.exit(main())")
    out = tmp_path / "s.csv"
    p = subprocess.Popen([sys.executable, "-c", code, "sweep", str(ROCKER), "--vary", "limits.pressure_angle=30:50:60",
                          "--vary", "follower.arm=100:200:60", "--out", str(out), "--jobs", "2"],
                         stderr=subprocess.PIPE, text=True, start_new_session=True, cwd=ROOT)

    def children():
        kids = []
        for d in Path("/proc").iterdir():
            if d.name.isdigit():
                try:
                    if int((d / "stat").read_text().rsplit(")", 1)[1].split()[1]) == p.pid:
                        kids.append(int(d.name))
                except (OSError, ValueError, IndexError):
                    pass
        return kids

    try:
        deadline = time.monotonic() + 60
        while len(children()) < 2 and p.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.5)
        assert p.poll() is None, "the sweep ended before it could be interrupted"
        os.killpg(p.pid, signal.SIGINT)
        _, err = p.communicate(timeout=30)
    finally:
        if p.poll() is None:
            p.kill()
            p.wait()
    assert p.returncode == 130 and err.splitlines()[-1].startswith("cams sweep: interrupted")
    text = out.read_text() if out.exists() else ""
    assert text == "" or text.endswith("\n")  # whole lines only
    assert children() == []


def test_a_base_design_wrong_whatever_the_keys_is_refused(tmp_path, capsys):
    empty = tmp_path / "empty.toml"
    empty.write_text("")
    out = tmp_path / "s.csv"
    rc, _, err = _run(capsys, empty, "--vary", "follower.arm=100,120", "--out", out, "--jobs", "1", "--quiet")
    assert rc == 2 and err == "cams sweep: error: follower.swing: is required\n"
    assert not out.exists()
    with pytest.raises(InputError, match="^limits.pressure_angle: "):
        sweep(rocker_dict(limits={"pressure_angle": 95}), [("follower.arm", np.array([100.0, 120.0]))], workers=1)
    with pytest.raises(InputError, match="^limits: unknown key"):
        sweep(rocker_dict(limits={"pressure_angel": 40}), [("follower.arm", np.array([100.0]))], workers=1)


def test_errors_of_the_varied_keys_stay_rows():
    # the base lacks the varied key: the varied values supply it
    base = rocker_dict()
    del base["follower"]["arm"]
    res = sweep(base, [("follower.arm", np.array([100.0, 120.0]))], method="convex", workers=1)
    assert [r["error"] for r in res.rows] == [None, None]
    # a bad value of a varied key, a phase angle that leaves nothing to the other phases: rows
    res = sweep(rocker_dict(), [("motion[0].angle", np.array([400.0, 120.0]))], method="convex", workers=1)
    assert "motion[3].angle" in res.rows[0]["error"] and res.rows[1]["error"] is None
    res = sweep(rocker_dict(), [("follower.swing", np.array([-5.0, 15.0]))], method="convex", workers=1)
    assert res.rows[0]["error"].startswith("follower.swing") and res.rows[1]["error"] is None


@pytest.mark.parametrize("second", ["follower.arm=130,140", " follower.arm =130,140"])
def test_a_key_varied_twice_is_refused(tmp_path, capsys, second):
    out = tmp_path / "s.csv"
    rc, _, err = _run(capsys, ROCKER, "--vary", "follower.arm=100,120", "--vary", second, "--out", out, "--quiet")
    assert rc == 2 and err.startswith("cams sweep: error: --vary: 'follower.arm' is varied twice")
    assert not out.exists()
    with pytest.raises(InputError, match="^--vary: 'motion.0.angle' is varied twice"):
        sweep(rocker_dict(), [("motion[0].angle", np.array([100.0])), ("motion.0.angle", np.array([110.0]))])


def test_no_progress_bar_unless_stderr_is_a_terminal(tmp_path, capsys, monkeypatch):
    argv = [ROCKER, "--vary", "follower.arm=100,120", "--out", tmp_path / "s.csv", "--jobs", "1"]
    rc, _, err = _run(capsys, *argv)
    assert rc == 0 and "\r" not in err and "solving the designs" not in err and len(err.splitlines()) == 2
    assert err.startswith("cams sweep: 2 designs, about ")  # the estimate, then the summary
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    monkeypatch.setattr("cams.commands.progress.DELAY_S", 0.0)  # the bar at once, not after two seconds
    rc, _, err = _run(capsys, *argv)
    assert rc == 0 and "\rsolving the designs:" in err and "2/2" in err
    monkeypatch.setattr(sys.stderr, "isatty", lambda: True, raising=False)
    rc, _, err = _run(capsys, *argv, "--quiet")
    assert rc == 0 and "\r" not in err and len(err.splitlines()) == 1


def test_list_items_by_index_in_either_form(tmp_path, capsys):
    k, _ = parse_vary("motion[2].angle=100,120")
    assert k == "motion[2].angle"
    for bad in ("motion[x].angle=1", "motion..angle=1", "motion[0.angle=1"):
        with pytest.raises(InputError, match="^--vary: "):
            parse_vary(bad)
    a = sweep(rocker_dict(), [("motion[0].angle", np.array([100.0, 130.0]))], method="convex", workers=1)
    b = sweep(rocker_dict(), [("motion.0.angle", np.array([100.0, 130.0]))], method="convex", workers=1)
    assert [r["R0"] for r in a.rows] == [r["R0"] for r in b.rows]
    assert a.rows[0]["R0"] != a.rows[1]["R0"] and all(r["error"] is None for r in a.rows)
    assert key_parts("motion[0].angle") == key_parts("motion.0.angle") == ("motion", "0", "angle")
    out = tmp_path / "s.csv"
    rc, _, _ = _run(capsys, ROCKER, "--vary", "motion[0].angle=100,130", "--out", out, "--jobs", "1", "--quiet")
    assert rc == 0
    rows = list(csv.DictReader(out.open()))
    assert [r["motion[0].angle"] for r in rows] == ["100", "130"] and all(r["error"] == "" for r in rows)
    rc, _, err = _run(capsys, ROCKER, "--vary", "motion[9].angle=100", "--out", out, "--quiet")
    assert rc == 2 and "--vary" in err and "index" in err


def test_sweep_output_is_not_the_design_file(tmp_path, capsys):
    design = tmp_path / "d.toml"
    design.write_text(ROCKER.read_text())
    rc, _, err = _run(capsys, design, "--vary", "follower.arm=100,120", "--out", design, "--quiet")
    assert rc == 2 and err.startswith("cams sweep: error: --out: ") and "input file" in err
    assert design.read_text() == ROCKER.read_text()


def test_out_never_writes_over_another_sweeps_sidecar(tmp_path, capsys):
    """A sidecar's name as --out, or an --out whose sidecar's place holds another file: one line, exit 2,
    the other sweep's files byte for byte as they were and nothing new written."""
    first = tmp_path / "a.csv"
    rc, _, _ = _run(capsys, ROCKER, "--vary", "follower.arm=100,120", "--out", first, "--quiet")
    assert rc == 0
    side = tmp_path / "a.csv.sweep.json"
    kept = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    assert set(kept) == {"a.csv", "a.csv.sweep.json"} and json.loads(kept[side.name])["format"] == "csv"
    # the other sweep's sidecar itself, any name of that form, and a table whose sidecar's place is a.csv's table
    table_named_like_a_sidecar = tmp_path / "b.sweep.json"
    table_named_like_a_sidecar.write_bytes(kept["a.csv"])
    kept[table_named_like_a_sidecar.name] = kept["a.csv"]
    for out in (side, tmp_path / "new.CSV.SWEEP.JSON", tmp_path / "b"):
        rc, stdout, err = _run(capsys, ROCKER, "--vary", "follower.arm=100,130", "--out", out, "--quiet")
        assert rc == 2 and stdout == "" and err.count("\n") == 1, err
        assert err.startswith("cams sweep: error: --out: ") and ("give the table another name" in err or
                                                                  "give --out another name" in err)
        assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == kept
    # the same --out again writes over its own sidecar: allowed
    rc, _, _ = _run(capsys, ROCKER, "--vary", "follower.arm=100,130", "--out", first, "--quiet")
    assert rc == 0 and json.loads(side.read_text())["values"] == [[100, 130]]


def test_the_front_never_writes_over_another_sweeps_table(tmp_path, capsys):
    """--pareto saves OUT's front as NAME.pareto.csv: when that is another sweep's table (its sidecar beside it),
    one line naming --pareto, exit 2, that sweep's files as they were; cams front refuses it the same way."""
    other = tmp_path / "a.pareto.csv"
    rc, _, _ = _run(capsys, ROCKER, "--vary", "follower.arm=100,120", "--out", other, "--quiet")
    assert rc == 0
    kept = {p.name: p.read_bytes() for p in tmp_path.iterdir()}
    rc, stdout, err = _run(capsys, ROCKER, "--vary", "follower.arm=100,130", "--out", tmp_path / "a.csv",
                           "--pareto", "R0,L", "--quiet")
    assert rc == 2 and stdout == "" and err.count("\n") == 1 and err.startswith("cams sweep: error: --pareto: ")
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == kept
    (tmp_path / "a.csv").write_bytes(kept["a.pareto.csv"])
    rc = main(["front", str(tmp_path / "a.csv"), "--pareto", "R0,L"])
    err = capsys.readouterr().err
    assert rc == 2 and err.startswith("cams front: error: --pareto: ") and "another sweep's table" in err
    assert (tmp_path / "a.pareto.csv").read_bytes() == kept["a.pareto.csv"]
