"""``cams sweep`` of any key (issue 26): words as values, zip, several files, flat faces, [optimize], the sweep file;
streamed rows, Parquet, resume, and a sweep killed and resumed without losing or repeating a row.

Each result column is checked on at least one row against ``cams solve --json`` of the same design (written as
its own file), or a closed form (Ca of the standard laws); the rows of a resumed sweep against a straight run's.
"""

import contextlib
import csv
import json
import math
import os
import signal
import subprocess
import sys
import time
import tomllib
from pathlib import Path

import pytest

import cams.sweep.engine
from cams.cli import main
from cams.io.tomlwrite import dumps
from tests.conftest import EXAMPLES

ROCKER = EXAMPLES / "rocker_force.toml"
ROOT = Path(__file__).resolve().parents[2]
#: Norton's Ca (largest |S''| of the normalized law) in closed form: cycloidal 2 pi; 3-4-5 at u = (3 - sqrt 3)/6,
#: 60 u (1 - u)(1 - 2 u) = 10 / sqrt 3; modified sine 4 pi^2 / (4 + pi).
CA = {"cycloidal": 2 * math.pi, "poly345": 10 / math.sqrt(3), "modified_sine": 4 * math.pi**2 / (4 + math.pi)}
GRID = ["--vary", "motion[0].law=cycloidal,poly345,modified_sine", "--vary", "limits.closure=force,form",
        "--vary", "follower.arm=100:160:4"]


def _sweep(capsys, *argv):
    rc = main(["sweep", *map(str, argv)])
    return rc, capsys.readouterr().err


def _rows(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _solve_json(capsys, tmp_path, base: Path, name: str, **keys) -> dict:
    """``cams solve --json`` of ``base`` with dotted ``keys`` set (``motion__0__law`` for motion[0].law)."""
    with open(base, "rb") as fh:
        d = tomllib.load(fh)
    for k, v in keys.items():
        node = d
        parts = k.split("__")
        for p in parts[:-1]:
            node = node[int(p)] if p.isdigit() else node[p]
        node[parts[-1]] = v
    f = tmp_path / f"{name}.toml"
    f.write_text(dumps(d), encoding="utf-8")
    main(["solve", str(f), "--json"])
    return json.loads(capsys.readouterr().out)


def _same(cell: str, value, rel=1e-12):
    if value is None:
        return cell == ""
    if isinstance(value, bool):
        return cell == str(value)
    return float(cell) == pytest.approx(value, rel=rel, abs=1e-9)


def _check_row(row: dict, rep: dict):
    """A row's result cells against a solve's JSON report."""
    assert _same(row["R0_mm"], rep["R0"]) and _same(row["L_mm"], rep["L"]) and _same(row["offset_mm"], rep["offset"])
    assert _same(row["centre_x_mm"], rep["centre"]["x"]) and _same(row["centre_y_mm"], rep["centre"]["y"])
    assert _same(row["blank_diameter_mm"], 2 * rep["largest_cam_radius"])  # the blank's radius, doubled
    pa = rep.get("max_pressure_angle") or {}
    assert _same(row["max_pressure_angle_rise_deg"], pa.get("rise"), rel=1e-11)
    assert _same(row["max_pressure_angle_return_deg"], pa.get("return"), rel=1e-11)
    assert _same(row["error_bound_mm"], rep.get("error_bound"), rel=1e-11)
    assert row["verified"] == str(rep["verified"]) and row["buildable"] == str(rep["buildable"])
    assert row["failures"] == "; ".join(rep["failures"])


@pytest.fixture(scope="module")
def straight(tmp_path_factory):
    """laws x closures x arms on the rocker example, straight through (2 processes): 24 rows."""
    out = tmp_path_factory.mktemp("straight") / "s.csv"
    rc = main(["sweep", str(ROCKER), *GRID, "--out", str(out), "--jobs", "2", "--quiet"])
    return rc, out


@pytest.fixture(scope="module")
def straight_per_design(tmp_path_factory):
    """The same sweep, each design by itself (--per-design): the path the interrupted sweep below takes."""
    out = tmp_path_factory.mktemp("straight_per_design") / "s.csv"
    rc = main(["sweep", str(ROCKER), *GRID, "--out", str(out), "--jobs", "2", "--quiet", "--per-design"])
    return rc, out


def test_laws_closures_arms(straight, tmp_path, capsys):
    rc, out = straight
    rows = _rows(out)
    assert rc == 0 and [int(r["index"]) for r in rows] == list(range(24))  # in index order when finished
    assert list(rows[0])[:5] == ["index", "file", "motion[0].law", "limits.closure", "follower.arm"]
    # the grid's order: the last key fastest
    assert [(r["motion[0].law"], r["limits.closure"], r["follower.arm"]) for r in rows[:5]] == [
        ("cycloidal", "force", a) for a in ("100", "120", "140", "160")] + [("cycloidal", "form", "100")]
    assert {r["file"] for r in rows} == {str(ROCKER)}
    text = out.read_text(encoding="utf-8")
    assert "0000000001" not in text and "99999999" not in text  # no float noise in any cell
    for r in rows:
        assert float(r["Ca_rise"]) == pytest.approx(CA[r["motion[0].law"]], rel=1e-9)
        assert r["max_contact_stress_MPa"] == r["residual_vibration"] == ""  # no [contact], no train
    row = rows[1 * 8 + 1 * 4 + 1]  # poly345, form, arm 120
    assert (row["motion[0].law"], row["limits.closure"], row["follower.arm"]) == ("poly345", "form", "120")
    rep = _solve_json(capsys, tmp_path, ROCKER, "d", motion__0__law="poly345", limits__closure="form",
                      follower__arm=120)
    _check_row(row, rep)
    # a larger arm, the same law and closure: a larger cam (the sizes scale with the arm)
    R0 = [float(r["R0_mm"]) for r in rows if (r["motion[0].law"], r["limits.closure"]) == ("cycloidal", "form")]
    assert R0 == sorted(R0) and R0[0] < R0[-1]


def test_several_files_zipped(tmp_path, capsys):
    out = tmp_path / "z.csv"
    tr = EXAMPLES / "translating_force.toml"
    rc, err = _sweep(capsys, ROCKER, tr, "--vary", "limits.pressure_angle=35,45", "--vary",
                     "motion[0].law=cycloidal,poly345", "--zip", "--out", out, "--jobs", "1", "--quiet")
    rows = _rows(out)
    assert rc == 0, err
    assert [(r["index"], r["file"], r["limits.pressure_angle"], r["motion[0].law"]) for r in rows] == [
        ("0", str(ROCKER), "35", "cycloidal"), ("1", str(ROCKER), "45", "poly345"),
        ("2", str(tr), "35", "cycloidal"), ("3", str(tr), "45", "poly345")]
    rep = _solve_json(capsys, tmp_path, tr, "t", limits__pressure_angle=45, motion__0__law="poly345")
    _check_row(rows[3], rep)
    assert rows[3]["L_mm"] == "" and rows[0]["offset_mm"] == ""  # a translating follower has no L, a rocker no offset
    rc, err = _sweep(capsys, ROCKER, "--vary", "follower.arm=100,120", "--vary", "limits.closure=form",
                     "--zip", "--out", out)
    assert rc == 2 and err == ("cams sweep: error: --zip: zipped keys give as many values each, got "
                               "follower.arm: 2, limits.closure: 1\n")


@pytest.mark.parametrize(("vary", "said"), [
    ("motion[0].law=cycloidal,cycloidl", "motion[0].law: unknown law 'cycloidl'"),
    ("limits.closure=force,3", "limits.closure: 3 is not a valid option, must be one of 'force', 'form'"),
    ("follower.arm=100,long", "follower.arm: must be a number, got the string 'long'"),
    ("limits.closur=force", "--vary: limits: unknown key(s) closur; allowed: "),
])
def test_a_value_of_the_wrong_kind_is_one_line(tmp_path, capsys, vary, said):
    out = tmp_path / "s.csv"
    rc, err = _sweep(capsys, ROCKER, "--vary", vary, "--out", out, "--jobs", "1")
    assert rc == 2 and err.startswith(f"cams sweep: error: {said}") and len(err.splitlines()) == 1
    assert not out.exists()


def test_flat_faces_sweep(tmp_path, capsys):
    out = tmp_path / "f.csv"
    flat = EXAMPLES / "translating_flat.toml"
    rc, err = _sweep(capsys, flat, "--vary", "motion[0].law=cycloidal,poly345", "--out", out, "--jobs", "1",
                     "--quiet")
    rows = _rows(out)
    assert rc == 0, err
    assert len(rows) == 2 and all(r["error"] == "" for r in rows)
    rep = _solve_json(capsys, tmp_path, flat, "f", motion__0__law="poly345")
    _check_row(rows[1], rep)  # no pressure-angle limit and no error bound: empty cells


def test_optimize_design(tmp_path, capsys):
    # [optimize]: seconds a design; fewer spans than the example's to keep it short
    opt = EXAMPLES / "translating_designed_rise.toml"
    out = tmp_path / "o.csv"
    rc, err = _sweep(capsys, opt, "--vary", "optimize.spans=8", "--out", out, "--jobs", "1")
    (row,) = _rows(out)
    assert rc == 0 and err.startswith("cams sweep: 1 design, about ")
    rep = _solve_json(capsys, tmp_path, opt, "o", optimize__spans=8)
    _check_row(row, rep)
    # the designed law's own Ca, not the starting 4-5-6-7 law's (its cap: the designed one stays below it)
    assert rep["optimize"]["objective"] == "R0" and float(row["Ca_rise"]) <= 7.5132 + 1e-6


def test_sweep_file_contact_and_train(tmp_path, capsys):
    """Two files from a sweep file (paths relative to it): the contact stress and the residual vibration."""
    for f in ("rocker_contact.toml", "translating_train.toml"):
        (tmp_path / f).write_text((EXAMPLES / f).read_text(encoding="utf-8"), encoding="utf-8")
    s = tmp_path / "s.toml"
    s.write_text('files = ["rocker_contact.toml", "translating_train.toml"]\nmode = "grid"\n'
                 '[vary]\n"limits.closure" = ["force"]\n', encoding="utf-8")
    out = tmp_path / "s.csv"
    rc, err = _sweep(capsys, "--sweep-file", s, "--out", out, "--jobs", "1", "--quiet")
    c, t = _rows(out)
    assert rc == (0 if c["failures"] == t["failures"] == "" else 1) and c["file"] == str(tmp_path / "rocker_contact.toml")
    rep = _solve_json(capsys, tmp_path, EXAMPLES / "rocker_contact.toml", "c")
    _check_row(c, rep)
    assert float(c["max_contact_stress_MPa"]) == pytest.approx(rep["contact"]["max_pressure"], rel=1e-11)
    assert c["residual_vibration"] == ""
    rep = _solve_json(capsys, tmp_path, EXAMPLES / "translating_train.toml", "t")
    _check_row(t, rep)
    worst = max(p["residual"] for p in rep["vibration"]["phases"])
    assert float(t["residual_vibration"]) == pytest.approx(worst, rel=1e-11) and t["max_contact_stress_MPa"] == ""
    s.write_text('files = ["rocker_contact.toml"]\n[vary]\n"limits.closure" = [3]\n', encoding="utf-8")
    rc, err = _sweep(capsys, "--sweep-file", s, "--out", out)
    assert rc == 2 and err.startswith("cams sweep: error: limits.closure: 3 is not a valid option")
    rc, err = _sweep(capsys, ROCKER, "--sweep-file", s, "--out", out)
    assert rc == 2 and err.startswith("cams sweep: error: --sweep-file: names the files")


def _interrupt_after(monkeypatch, calls_before: int):
    calls = []
    real = cams.sweep.engine.evaluate

    def evaluate(job):
        calls.append(job)
        if len(calls) > calls_before:
            raise KeyboardInterrupt
        return real(job)

    monkeypatch.setattr(cams.sweep.engine, "evaluate", evaluate)


def test_parquet_round_trip_and_resume(tmp_path, capsys, monkeypatch):
    pq = pytest.importorskip("pyarrow.parquet", reason="Parquet tables need pyarrow (the test extra installs it)")
    # each design by itself (--per-design): one design a call, so that the interruption falls between designs (the
    # streaming is the engine's, the same on both paths)
    argv = [ROCKER, "--vary", "follower.arm=100:130:4", "--vary", "motion[0].law=cycloidal", "--jobs", "1",
            "--quiet", "--per-design"]
    rc, _ = _sweep(capsys, *argv, "--out", tmp_path / "s.csv")
    rows = _rows(tmp_path / "s.csv")
    _interrupt_after(monkeypatch, 2)  # two designs timed and written, a part each, then Ctrl-C
    out = tmp_path / "s.parquet"
    rc, err = _sweep(capsys, *argv, "--out", out)
    assert rc == 130 and not out.exists() and len(list((tmp_path / "s.parquet.parts").iterdir())) == 2
    monkeypatch.undo()
    rc, err = _sweep(capsys, *argv, "--out", out, "--resume")
    assert rc == 0 and not (tmp_path / "s.parquet.parts").exists()
    t = pq.read_table(out)
    assert t.column_names == list(rows[0])
    assert str(t.schema.field("index").type) == "int64" and str(t.schema.field("verified").type) == "bool"
    for a, b in zip(t.to_pylist(), rows, strict=True):  # the same numbers as the CSV's cells
        for k, v in b.items():
            w = a[k]
            assert (v == "" and w is None) or (str(w) == v if isinstance(w, (bool, str, int)) else w == float(v))


def test_resume_drops_a_partial_line_and_checks_the_identity(tmp_path, capsys):
    base = tmp_path / "rocker.toml"
    base.write_text(ROCKER.read_text(encoding="utf-8"), encoding="utf-8")
    argv = [base, "--vary", "follower.arm=100:130:4", "--jobs", "1", "--quiet", "--per-design"]
    full = tmp_path / "full.csv"
    assert _sweep(capsys, *argv, "--out", full)[0] == 0
    lines = full.read_text(encoding="utf-8").splitlines(keepends=True)
    part = tmp_path / "part.csv"
    part.write_text("".join(lines[:3]) + lines[3][:25], encoding="utf-8")  # rows 0, 1, and half of row 2
    (tmp_path / "part.csv.sweep.json").write_text((tmp_path / "full.csv.sweep.json").read_text())
    rc, err = _sweep(capsys, *argv, "--out", part, "--resume")
    assert rc == 0 and "2 resumed" in err
    assert part.read_text(encoding="utf-8") == full.read_text(encoding="utf-8")
    # another sweep's file: refused, untouched
    before = part.read_text(encoding="utf-8")
    rc, err = _sweep(capsys, base, "--vary", "follower.arm=100:130:5", "--out", part, "--resume")
    assert rc == 2 and err.startswith("cams sweep: error: --resume: ") and "values differ" in err
    base.write_text(base.read_text(encoding="utf-8") + "# edited\n", encoding="utf-8")  # the same keys, a new file
    rc, err = _sweep(capsys, *argv, "--out", part, "--resume")
    assert rc == 2 and err.startswith("cams sweep: error: --resume: ") and "files differ" in err
    assert part.read_text(encoding="utf-8") == before


def _start(out: Path, *extra: str) -> subprocess.Popen:
    code = ("import signal, sys; signal.signal(signal.SIGINT, signal.default_int_handler); "
            "from cams.cli import main; sys.exit(main())")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    # each design by itself (--per-design): slow enough to be interrupted mid-sweep (the batch solver sizes these
    # 24 designs in a fraction of a second); the streaming, the interruption and the resume are the engine's
    return subprocess.Popen([sys.executable, "-c", code, "sweep", str(ROCKER), *GRID, "--out", str(out), "--jobs", "2",
                             "--quiet", "--per-design", *extra], stderr=subprocess.PIPE, text=True, start_new_session=True, cwd=ROOT,
                            env=env)


def _wait_rows(p: subprocess.Popen, out: Path, at_least: int) -> bool:
    """Wait until ``out`` holds ``at_least`` rows; False when the sweep ended first."""
    deadline = time.monotonic() + 120
    while p.poll() is None and time.monotonic() < deadline:
        n = out.read_bytes().count(b"\n") - 1 if out.exists() else 0
        if n >= at_least:
            return True
        time.sleep(0.02)
    return False


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="the test sends SIGINT to a process group (Linux)")
def test_killed_and_resumed_loses_and_repeats_no_row(straight_per_design, tmp_path, capsys):
    """The issue's test: interrupted (Ctrl-C, then kill -9), resumed, equal to a straight run."""
    out = tmp_path / "k.csv"
    p = _start(out)
    try:
        assert _wait_rows(p, out, 3), "the sweep ended before it could be interrupted"
        os.killpg(p.pid, signal.SIGINT)
        _, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    assert p.returncode == 130 and "--resume" in err.splitlines()[-1]
    text = out.read_text(encoding="utf-8")
    first = len(_rows(out))
    assert text.endswith("\n") and 3 <= first < 24
    p = _start(out, "--resume")
    try:
        _wait_rows(p, out, first + 2)
    finally:
        with contextlib.suppress(ProcessLookupError):  # (on a fast machine it may have ended)
            os.killpg(p.pid, signal.SIGKILL)  # a power cut: no handler runs
        p.wait()
    with open(out, "a", encoding="utf-8") as fh:
        fh.write("23,/half/a/li")  # as if killed in the middle of a write
    rc, err = _sweep(capsys, ROCKER, *GRID, "--out", out, "--jobs", "2", "--quiet", "--resume", "--per-design")
    assert rc == 0, err
    rows = _rows(out)
    assert [int(r["index"]) for r in rows] == list(range(24))  # every index exactly once
    assert rows == _rows(straight_per_design[1])  # and the same rows as the straight run's


def _one_line(err: str, field: str) -> None:
    assert err.count("\n") == 1 and err.startswith(f"cams sweep: error: {field}: ") and "Traceback" not in err


@pytest.mark.parametrize(
    "edit, said",
    [
        (lambda side, table: side.write_text("[]"), "is not a sweep's identity"),
        (lambda side, table: table.write_text(table.read_text() + "abc" + "," * 18 + "\n"), "index 'abc'"),
        (lambda side, table: table.write_text(table.read_text().replace("\n0,", "\n7,", 1)), "index '7', not one"),
        (lambda side, table: table.write_text(table.read_text().replace("\n1,", "\n0,", 1)), "held twice"),
    ],
)
def test_resume_refuses_an_edited_sidecar_or_index(tmp_path, capsys, edit, said):
    """An identity that is not a JSON object, a row index that is no integer, out of the sweep's range or
    repeated: one line naming --resume, exit 2, the table left as it is (it was: a traceback, or rows kept
    beyond the sweep's and counted as resumed)."""
    argv = [ROCKER, "--vary", "follower.arm=100,110", "--jobs", "1", "--quiet", "--out", tmp_path / "t.csv"]
    assert _sweep(capsys, *argv)[0] == 0
    table, side = tmp_path / "t.csv", tmp_path / "t.csv.sweep.json"
    edit(side, table)
    before = table.read_text()
    rc, err = _sweep(capsys, *argv, "--resume")
    assert rc == 2 and said in err
    _one_line(err, "--resume")
    assert table.read_text() == before


@pytest.mark.parametrize("name, fmt", [("t.csv", "parquet"), ("t.parquet", "csv"), ("t.pq", "csv")])
def test_a_format_against_the_out_name_is_refused(tmp_path, capsys, name, fmt):
    """``--format parquet --out t.csv`` wrote Parquet under a CSV name (read back as CSV by its name)."""
    rc, err = _sweep(capsys, ROCKER, "--vary", "follower.arm=100", "--out", tmp_path / name, "--format", fmt)
    assert rc == 2
    _one_line(err, "--format")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("text, said", [(None, "cannot read"), ('files = ["a.toml"\n', "not valid TOML")])
def test_an_unreadable_sweep_file_names_the_option(tmp_path, capsys, text, said):
    s = tmp_path / "s.toml"
    if text is not None:
        s.write_text(text)
    rc, err = _sweep(capsys, "--sweep-file", s, "--out", tmp_path / "t.csv")
    assert rc == 2 and said in err
    _one_line(err, "--sweep-file")


def test_an_unreachable_cluster_is_said_before_any_design(tmp_path, capsys, monkeypatch):
    """A sweep small enough to be all timed in this process never asked for the cluster (exit 0 on this
    machine); a larger one wrote its timed rows, then failed. Now: one line, exit 2, no file left."""
    pytest.importorskip("distributed", reason="--dask needs dask.distributed (the test extra installs it)")
    import cams.sweep.cluster

    monkeypatch.setattr(cams.sweep.cluster, "CONNECT_TIMEOUT", 0.2)
    out = tmp_path / "t.csv"
    rc, err = _sweep(capsys, ROCKER, "--vary", "follower.arm=100,110", "--out", out, "--jobs", "1", "--quiet",
                     "--dask", "tcp://127.0.0.1:1")
    assert rc == 2 and "cannot reach the Dask scheduler" in err.splitlines()[-1]
    assert err.splitlines()[-1].startswith("cams sweep: error: --dask: ")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "vary, said",
    [
        ("follower.arm=100:120:1", "a range of one value has a == b"),  # was: 100 alone, 120 dropped
        ("follower.arm=100,1e2", "the value 100 is given twice"),  # was: the same design solved twice
        ("follower.arm=90:90:3", "the value 90 is given twice"),
        ("motion[0].law=cycloidal,cycloidal", "the value 'cycloidal' is given twice"),
    ],
)
def test_a_range_dropping_its_end_or_a_repeated_value_is_one_line(tmp_path, capsys, vary, said):
    rc, err = _sweep(capsys, ROCKER, "--vary", vary, "--out", tmp_path / "t.csv", "--jobs", "1", "--quiet")
    assert rc == 2 and said in err
    _one_line(err, "--vary")
    assert list(tmp_path.iterdir()) == []


def test_a_file_twice_or_a_sweep_file_as_file_is_one_line(tmp_path, capsys):
    """One design file twice solved its designs twice; a sweep file given as FILE was blamed on --vary."""
    base = tmp_path / "rocker.toml"
    base.write_text(ROCKER.read_text(encoding="utf-8"), encoding="utf-8")
    out = tmp_path / "t.csv"
    rc, err = _sweep(capsys, base, f"{tmp_path}/./rocker.toml", "--vary", "follower.arm=100", "--out", out)
    assert rc == 2 and "is given twice (as " in err
    _one_line(err, "FILE")
    s = tmp_path / "s.toml"
    s.write_text('files = ["rocker.toml", "./rocker.toml"]\n[vary]\n"follower.arm" = [100]\n', encoding="utf-8")
    rc, err = _sweep(capsys, "--sweep-file", s, "--out", out)
    assert rc == 2 and "is given twice" in err
    _one_line(err, "--sweep-file")
    rc, err = _sweep(capsys, s, "--vary", "follower.arm=100", "--out", out)
    assert rc == 2 and f"is a sweep file: give it as --sweep-file {s}" in err
    _one_line(err, "FILE")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["rocker.toml", "s.toml"]


@pytest.mark.parametrize(
    "vary, field, said",
    [
        ('"motion[0].law" = ["cycloidal", "nosuchlaw"]', "motion[0].law", "[vary] motion[0].law = 'nosuchlaw'"),
        ('"limits.pressure_angle" = ["30", "35"]', "limits.pressure_angle", "[vary] limits.pressure_angle = '30'"),
        ('"follower.arm" = [100, 100]', None, "given twice"),
    ],
)
def test_a_sweep_files_wrong_value_names_the_sweep_file_not_vary(tmp_path, capsys, vary, field, said):
    """A value given in a sweep file's [vary] is refused naming that file and its [vary] key, not --vary (which the
    user did not type)."""
    s = tmp_path / "s.toml"
    s.write_text(f'files = ["{ROCKER.as_posix()}"]\n[vary]\n{vary}\n')
    rc, err = _sweep(capsys, "--sweep-file", s, "--out", tmp_path / "t.csv")
    assert rc == 2 and said in err and "--vary" not in err
    _one_line(err, field or f"--sweep-file {s}")
    assert not (tmp_path / "t.csv").exists()
