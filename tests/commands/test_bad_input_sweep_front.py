"""Bad input to ``cams sweep`` and ``cams front`` that a hostile pass found misbehaving: one line naming the option
or the table, exit 2, nothing written (in process: tests/inprocess.py).

- ``--pareto``/``--axes`` naming a column the table will not have, or one of words, was refused only after the
  whole sweep was solved (hours, for a typo); now before anything is solved or written.
- ``cams front`` on an edited table: a ``nan``/``inf`` cell in an objective was counted among the "empty"
  objectives (``-inf``, the best a minimised column can hold, silently left out); a table without its ``error``
  column had every row usable; a row edited to ``verified = False`` (its ``failures`` left empty) was offered on
  the front; a header naming a column twice was called "not a column"; a Parquet table's NaN read as empty.
- Ctrl-C before a row was solved left a header-only table and its sidecar behind.
"""

from __future__ import annotations

import csv
import os

import pytest

import cams.sweep
import cams.sweep.engine
from tests.conftest import EXAMPLES
from tests.inprocess import cams_cli

ROCKER = EXAMPLES / "rocker_force.toml"
VARY = ["--vary", "limits.pressure_angle=30,40,50"]


def _rows(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.reader(fh))


def _write(path, rows):
    with open(path, "w", newline="", encoding="utf-8") as fh:
        csv.writer(fh).writerows(rows)


def _one_line(r, start: str) -> str:
    assert r.returncode == 2 and r.stdout == "", (r.returncode, r.stdout, r.stderr)
    assert r.stderr.count("\n") == 1 and r.stderr.startswith(start), r.stderr
    return r.stderr


@pytest.fixture(scope="module")
def table(tmp_path_factory):
    """A written sweep of three usable rocker designs (the header and three rows)."""
    out = tmp_path_factory.mktemp("front") / "s.csv"
    r = cams_cli("sweep", ROCKER, *VARY, "--out", out, "--jobs", "1", "--quiet")
    assert r.returncode == 0, r.stderr
    rows = _rows(out)
    assert len(rows) == 4 and all(row[rows[0].index("verified")] == "True" for row in rows[1:])
    return rows


@pytest.mark.parametrize(
    ("option", "said"),
    [
        (["--pareto", "R0,Rb"], "--pareto: 'Rb' is not a column of"),
        (["--pareto", "R0,file"], "--pareto: 'file' is not a column of numbers"),
        (["--pareto", "buildable,R0"], "--pareto: 'buildable' is not a column of numbers"),
        (["--pareto", "R0,R0_mm"], "--pareto: 'R0,R0_mm': column 'R0' is given twice"),
        (["--pareto", "R0,motion[0].law"], "--pareto: 'motion[0].law' is not a column of numbers"),
        (["--plot", "c.png", "--axes", "R0,zz"], "--axes: 'zz' is not a column of"),
        (["--plot", "c.png", "--axes", "R0,L,error"], "--axes: 'error' is not a column of numbers"),
    ],
)
def test_a_front_column_is_checked_before_solving(tmp_path, monkeypatch, option, said):
    """The columns are those of the header the sweep is about to write (the varied keys among them; a law's
    name is a word): a wrong one is one line before any design is solved, and no file is left."""

    def never(*a, **k):
        raise AssertionError("solved before the front's columns were checked")

    monkeypatch.setattr(cams.sweep, "run_grid", never)
    opts = [str(tmp_path / o) if o.endswith(".png") else o for o in option]
    r = cams_cli(
        "sweep",
        ROCKER,
        *VARY,
        "--vary",
        "motion[0].law=cycloidal,poly345",
        "--out",
        tmp_path / "s.csv",
        "--quiet",
        *opts,
    )
    _one_line(r, f"cams sweep: error: {said}")
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("text", ["nan", "NaN", "inf", "-inf", "1e400"])
def test_a_non_finite_cell_in_an_objective_is_refused(table, tmp_path, text):
    """A sweep leaves a cell without a value empty: ``nan``/``inf`` in a column the front compares is an edit,
    neither empty nor comparable (``-inf`` would be the best R0): one line naming TABLE, the row and the
    column; nothing written."""
    rows = [list(r) for r in table]
    j = rows[0].index("L_mm")
    rows[2][j] = text
    t = tmp_path / "t.csv"
    _write(t, rows)
    err = _one_line(cams_cli("front", t, "--pareto", "R0,L"), "cams front: error: TABLE: ")
    assert f"data row 2, column 'L_mm' holds '{text}'" in err
    assert os.listdir(tmp_path) == ["t.csv"]
    # a chart's colour column is read the same way
    err = _one_line(
        cams_cli("front", t, "--plot", tmp_path / "c.png", "--axes", "R0,max_pressure_angle_rise,L"),
        "cams front: error: TABLE: ",
    )
    assert "column 'L_mm' holds" in err and os.listdir(tmp_path) == ["t.csv"]


def test_an_empty_cell_is_the_empty_objective_the_summary_counts(table, tmp_path):
    """The summary's "with an empty objective" counts the usable rows whose objective cell is empty, nothing
    else: one emptied cell, one counted, and the front is the definition's over the rest."""
    rows = [list(r) for r in table]
    j = rows[0].index("R0_mm")
    rows[1][j] = ""
    t = tmp_path / "t.csv"
    _write(t, rows)
    r = cams_cli("front", t, "--pareto", "R0")
    assert r.returncode == 0, r.stderr
    assert "3 rows (0 unusable and 1 with an empty objective left out)" in r.stdout
    best = min(rows[2:], key=lambda row: float(row[j]))  # one objective: the front is the least R0
    assert _rows(tmp_path / "t.pareto.csv")[1:] == [best]


def test_a_row_edited_to_fail_is_not_offered(table, tmp_path):
    """``verified = False`` (or ``buildable``) with ``failures`` left empty: the row is not usable, whatever
    the rest says; the front is the least R0 of the others, the summary counts it unusable."""
    rows = [list(r) for r in table]
    j, v = rows[0].index("R0_mm"), rows[0].index("verified")
    best = min(range(1, 4), key=lambda i: float(rows[i][j]))
    rows[best][v] = "False"
    t = tmp_path / "t.csv"
    _write(t, rows)
    r = cams_cli("front", t, "--pareto", "R0")
    assert r.returncode == 0, r.stderr
    assert "(1 unusable and 0 with an empty objective left out)" in r.stdout
    others = [rows[i] for i in range(1, 4) if i != best]
    assert _rows(tmp_path / "t.pareto.csv")[1:] == [min(others, key=lambda row: float(row[j]))]


@pytest.mark.parametrize("drop", ["error", "failures"])
def test_a_table_without_its_verdict_columns_is_refused(table, tmp_path, drop):
    """Without ``error`` or ``failures`` the table cannot say which rows are usable (every row was)."""
    j = table[0].index(drop)
    t = tmp_path / "t.csv"
    _write(t, [r[:j] + r[j + 1 :] for r in table])
    err = _one_line(cams_cli("front", t, "--pareto", "R0,L"), "cams front: error: TABLE: ")
    assert f"has no {drop!r} column" in err and os.listdir(tmp_path) == ["t.csv"]


def test_a_header_naming_a_column_twice_is_refused(table, tmp_path):
    j = table[0].index("R0_mm")
    t = tmp_path / "t.csv"
    _write(t, [[*r, r[j]] for r in table])
    err = _one_line(cams_cli("front", t, "--pareto", "R0,L"), "cams front: error: TABLE: ")
    assert "names the column 'R0_mm' twice" in err and os.listdir(tmp_path) == ["t.csv"]


def test_a_parquet_nan_is_not_an_empty_cell(table, tmp_path):
    """Parquet's empty cell is null; a float NaN there is an edit, refused as in a CSV (it was read as empty)."""
    pa = pytest.importorskip("pyarrow", reason="Parquet tables need pyarrow (the test extra installs it)")
    pq = pytest.importorskip("pyarrow.parquet")
    head, body = table[0], table[1:]
    cols = {}
    for j, h in enumerate(head):
        cells = [r[j] for r in body]
        try:
            cols[h] = pa.array([None if c == "" else float(c) for c in cells], pa.float64())
        except ValueError:
            cols[h] = pa.array([c or None for c in cells], pa.string())
    cols["R0_mm"] = pa.array([1.0, float("nan"), 2.0], pa.float64())
    t = tmp_path / "t.parquet"
    pq.write_table(pa.table(cols), t)
    err = _one_line(cams_cli("front", t, "--pareto", "R0,L"), "cams front: error: TABLE: ")
    assert "data row 2, column 'R0_mm' holds 'nan'" in err


def test_ctrl_c_before_a_row_leaves_nothing(tmp_path, monkeypatch):
    """Interrupted while the first design is solved: exit 130, one line, neither a header-only table nor its
    sidecar left behind (a sweep with rows keeps them: tests/commands/test_sweep_cli_checks.py)."""

    def interrupt(job):
        raise KeyboardInterrupt

    monkeypatch.setattr(cams.sweep.engine, "evaluate", interrupt)
    r = cams_cli("sweep", ROCKER, *VARY, "--out", tmp_path / "s.csv", "--jobs", "1", "--quiet", "--per-design")
    assert (r.returncode, r.stdout) == (130, "")
    assert r.stderr == "cams sweep: interrupted before a row was solved; nothing written\n"
    assert os.listdir(tmp_path) == []


@pytest.mark.parametrize("rng", ["nan:120:3", "100:inf:3", "100:120:nan", "-inf:1e400:2"])
def test_a_range_of_non_finite_numbers_is_said_so(tmp_path, rng):
    """A range's ends and count are finite numbers: said so, naming the option or the sweep file's entry (it was
    read as one word, "must be a number, got the string 'nan:120:3'", and a sweep file's range named --vary)."""
    r = cams_cli("sweep", ROCKER, "--vary", f"follower.arm={rng}", "--out", tmp_path / "s.csv", "--quiet")
    _one_line(r, f"cams sweep: error: --vary: 'follower.arm={rng}': a range a:b:n takes finite numbers")
    sf = tmp_path / "sweep.toml"
    sf.write_text(f'files = ["{ROCKER.as_posix()}"]\n[vary]\n"follower.arm" = "{rng}"\n', encoding="utf-8")
    r = cams_cli("sweep", "--sweep-file", sf, "--out", tmp_path / "s.csv", "--quiet")
    _one_line(r, f"cams sweep: error: --sweep-file: vary.follower.arm = '{rng}': a range a:b:n takes finite numbers")
    assert sorted(os.listdir(tmp_path)) == ["sweep.toml"]


def test_a_sweep_files_missing_design_is_its_files_entry(tmp_path):
    """The design files a sweep file names are its ``files``: a missing one names --sweep-file (it named FILE,
    an argument the command line did not have)."""
    sf = tmp_path / "sweep.toml"
    sf.write_text('files = ["absent.toml"]\n[vary]\n"follower.arm" = [100, 120]\n', encoding="utf-8")
    r = cams_cli("sweep", "--sweep-file", sf, "--out", tmp_path / "s.csv", "--quiet")
    err = _one_line(r, f"cams sweep: error: --sweep-file: {sf}: files: cannot read ")
    assert "absent.toml" in err and sorted(os.listdir(tmp_path)) == ["sweep.toml"]


def test_a_whole_motion_list_replaced_by_a_number_is_one_line(tmp_path):
    """``--vary motion=1,2`` is a value of the wrong kind for its key, as ``follower=1`` is: one line before
    solving (it was a table of rows each with the same error, exit 1)."""
    r = cams_cli("sweep", ROCKER, "--vary", "motion=1,2", "--out", tmp_path / "s.csv", "--quiet")
    _one_line(r, "cams sweep: error: motion: needs a list of phases ([[motion]] tables), got 1 (--vary motion=1)")
    assert os.listdir(tmp_path) == []


def test_a_grid_too_large_is_refused_at_once(tmp_path):
    """Two keys of 100,000 values (10^10 designs): refused by its count, in a moment. The values were first
    compared pair by pair (5 x 10^9 comparisons a key): the command hung for minutes before saying so."""
    import time

    t0 = time.perf_counter()
    r = cams_cli(
        "sweep",
        ROCKER,
        "--vary",
        "follower.arm=100:200:100000",
        "--vary",
        "follower.swing=10:20:100000",
        "--out",
        tmp_path / "s.csv",
        "--quiet",
    )
    assert time.perf_counter() - t0 < 20
    _one_line(r, "cams sweep: error: --vary: the sweep has 10,000,000,000 designs; at most 100,000 are accepted")
    assert os.listdir(tmp_path) == []


def test_a_value_twice_among_many_is_found_at_once(tmp_path):
    """100,000 listed values, the last equal to the first written another way (1e2 for 100): said in a moment."""
    import time

    values = ",".join([*(str(100 + k) for k in range(99_999)), "1e2"])
    t0 = time.perf_counter()
    r = cams_cli("sweep", ROCKER, "--vary", f"follower.arm={values}", "--out", tmp_path / "s.csv", "--quiet")
    assert time.perf_counter() - t0 < 20
    _one_line(r, "cams sweep: error: --vary: 'follower.arm': the value 100 is given twice; give each once")
    assert os.listdir(tmp_path) == []


def test_a_word_in_a_column_of_numbers_names_the_cell(table, tmp_path):
    """One cell of R0 edited to a word: said as that cell of TABLE (it was "'R0' is not a column of numbers", of
    the column every front is drawn over)."""
    rows = [list(r) for r in table]
    rows[3][rows[0].index("R0_mm")] = "abc"
    t = tmp_path / "t.csv"
    _write(t, rows)
    err = _one_line(cams_cli("front", t, "--pareto", "R0,L"), "cams front: error: TABLE: ")
    assert "data row 3, column 'R0_mm' holds 'abc', not a number" in err and os.listdir(tmp_path) == ["t.csv"]


def test_a_chart_that_cannot_be_written_leaves_no_front(table, tmp_path, monkeypatch):
    """The chart's place refused only when written (a folder of a file system that takes no file: checked paths
    cannot tell): the front's CSV was already saved and printed, exit 2 after it; now neither is left."""
    import cams.present.sweepplot
    from laws.errors import InputError

    def refuse(fig, path, field="--plot"):
        raise InputError("--plot", f"cannot write {str(path)!r}: No such file or directory")

    monkeypatch.setattr(cams.present.sweepplot, "save_chart", refuse)
    t = tmp_path / "t.csv"
    _write(t, table)
    r = cams_cli("front", t, "--pareto", "R0,L", "--plot", tmp_path / "c.png")
    _one_line(r, "cams front: error: --plot: cannot write ")
    assert os.listdir(tmp_path) == ["t.csv"]
