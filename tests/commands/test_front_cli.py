"""``cams sweep --pareto --plot`` and ``cams front``: the front printed and saved is the definition's, read back from
the written table; bad options are one line and exit 2 before anything is solved."""

from __future__ import annotations

import csv

import pytest

from cams.cli import main
from tests.conftest import EXAMPLES

VARY = ["--vary", "limits.pressure_angle=30:50:3", "--vary", "follower.arm=100,150"]


def _run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def _read(path):
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


def _brute(rows, cols):
    """The definition over usable rows: no other row <= on every column and < on one."""
    ok = [r for r in rows if not r["error"] and not r["failures"]]
    pts = [tuple(float(r[c]) for c in cols) for r in ok]
    return [
        r
        for r, a in zip(ok, pts, strict=True)
        if not any(
            all(b_ <= a_ for a_, b_ in zip(a, b, strict=True)) and any(b_ < a_ for a_, b_ in zip(a, b, strict=True))
            for b in pts
        )
    ]


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    d = tmp_path_factory.mktemp("front")
    out = d / "s.csv"
    code = main(
        [
            "sweep",
            str(EXAMPLES / "rocker_force.toml"),
            *VARY,
            "--out",
            str(out),
            "--pareto",
            "R0,L",
            "--plot",
            str(d / "s.png"),
            "--quiet",
            "--jobs",
            "1",
        ]
    )
    return d, out, code


def test_sweep_saves_and_draws_the_front(swept):
    d, out, code = swept
    rows = _read(out)
    assert code == 0 and len(rows) == 6
    front = _read(d / "s.pareto.csv")
    assert front  # the rows of the front, whole (every column, as in the table)
    expected = _brute(rows, ["R0_mm", "L_mm"])
    assert sorted(map(tuple, (r.values() for r in front))) == sorted(map(tuple, (r.values() for r in expected)))
    assert [float(r["R0_mm"]) for r in front] == sorted(float(r["R0_mm"]) for r in front)  # best R0 first
    assert (d / "s.png").read_bytes()[:4] == b"\x89PNG"


def test_front_of_a_written_table_printed_with_units(swept, capsys):
    d, out, _ = swept
    rows = _read(out)
    header = list(rows[0])
    rise = next(h for h in header if h.startswith("max_pressure") and "rise" in h)  # the rise's peak pressure angle
    name = rise.removesuffix("_deg")
    code, text, err = _run(
        capsys, "front", out, "--pareto", f"R0,{name}", "--plot", d / "f.svg", "--axes", f"R0_mm,{name},follower.arm"
    )
    assert code == 0, err
    expected = _brute(rows, ["R0_mm", rise])
    lines = text.splitlines()
    assert lines[0].startswith(f"Pareto front over R0 (mm), {name} (deg)")
    assert f"{len(expected)} of 6 rows" in lines[0]
    assert "R0 (mm)" in lines[1] and f"{name} (deg)" in lines[1]
    printed = [ln.split() for ln in lines[2 : 2 + len(expected)]]
    assert sorted(p[-2] for p in printed) == sorted(r["R0_mm"] for r in expected)  # the written digits
    assert sorted(p[-1] for p in printed) == sorted(r[rise] for r in expected)
    assert "wrote" in err and (d / "f.svg").read_bytes().startswith(b"<?xml")
    # the same names with their unit suffix
    code, text2, _ = _run(capsys, "front", out, "--pareto", f"R0_mm,{rise}")
    assert code == 0 and text2.splitlines()[2:] == lines[2:]


def test_objective_not_a_column_is_one_line(swept, capsys):
    _, out, _ = swept
    code, text, err = _run(capsys, "front", out, "--pareto", "R0,Rb")
    assert code == 2
    assert err.count("\n") == 1 and "--pareto: 'Rb' is not a column of" in err and "R0, L," in err


def test_an_all_unusable_table_has_an_empty_front(tmp_path, capsys):
    t = tmp_path / "t.csv"
    t.write_text("R0_mm,L_mm,failures,error\n1,2,,no admissible centre\n3,4,curvature,\n", encoding="utf-8")
    code, text, err = _run(capsys, "front", t, "--pareto", "R0,L")
    assert code == 1
    assert "0 of 2 rows (2 unusable" in text and "no usable row" in err
    assert _read(tmp_path / "t.pareto.csv") == []


@pytest.mark.parametrize(
    ("extra", "field"),
    [
        (["--plot", "c.jpg", "--pareto", "R0,L"], "--plot"),
        (["--plot", "c.png"], "--plot"),  # no axes
        (["--plot", "c.png", "--pareto", "R0"], "--plot"),  # one objective: no axes either
        (["--axes", "R0,L"], "--axes"),  # axes without a chart
        (["--plot", "c.png", "--axes", "R0"], "--axes"),  # one axis
        (["--pareto", "R0,,L"], "--pareto"),
        (["--dask", "somewhere"], "--dask"),
    ],
)
def test_bad_options_refused_before_solving(tmp_path, capsys, monkeypatch, extra, field):
    import cams.sweep

    def never(*a, **k):
        raise AssertionError("solved before checking the options")

    monkeypatch.setattr(cams.sweep, "sweep", never)
    code, _, err = _run(
        capsys,
        "sweep",
        EXAMPLES / "rocker_force.toml",
        *VARY,
        "--out",
        tmp_path / "s.csv",
        *[str(tmp_path / e) if e.endswith((".jpg", ".png")) else e for e in extra],
    )
    assert code == 2, err
    assert err.count("\n") == 1 and f" {field}: " in err, err
    assert not (tmp_path / "s.csv").exists()


def test_front_needs_a_file_to_read_back(capsys):
    code, _, err = _run(capsys, "sweep", EXAMPLES / "rocker_force.toml", *VARY, "--out", "-", "--pareto", "R0,L")
    assert code == 2 and err.count("\n") == 1 and "--out: '-': a sweep streams its rows into a regular file" in err


def test_dask_local_writes_the_process_pools_table(tmp_path, capsys):
    """``--dask local --jobs 2`` runs the sweep on a local cluster of two workers: the same table as the pool's."""
    tables = []
    for extra in ((), ("--dask", "local")):
        out = tmp_path / f"s{len(tables)}.csv"
        code, _, err = _run(capsys, "sweep", EXAMPLES / "rocker_force.toml", "--vary", "follower.arm=100,150",
                            "--out", out, "--jobs", "2", "--quiet", *extra)
        assert code == 0, err
        tables.append(out.read_text())
    assert tables[0] == tables[1] and tables[0].count("\n") == 3


def test_a_bad_axis_writes_nothing(swept, capsys, tmp_path):
    _, out, _ = swept
    t = tmp_path / "t.csv"
    t.write_bytes(out.read_bytes())
    code, text, err = _run(capsys, "front", t, "--pareto", "R0,L", "--plot", tmp_path / "c.png", "--axes", "R0,zz")
    assert code == 2 and text == "" and "--axes: 'zz' is not a column of" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t.csv"]


@pytest.mark.parametrize(
    "option, said",
    [
        (["--pareto", "R0,R0_mm"], "--pareto: 'R0,R0_mm': column 'R0' is given twice"),
        (["--pareto", "offset_mm,R0"], "--pareto: 'offset' is empty in every usable row"),
        (["--pareto", "error,R0"], "--pareto: 'error' is not a column of numbers"),
        (["--pareto", "verified,R0"], "--pareto: 'verified' is not a column of numbers"),
        (["--pareto", "file,R0"], "--pareto: 'file' is not a column of numbers"),
        (["--axes", "file,R0"], "--axes: 'file' is not a column of numbers"),
        (["--axes", "offset,R0"], "--axes: 'offset' is empty in every usable row"),
        (["--axes", "R0,L,failures"], "--axes: 'failures' is not a column of numbers"),
    ],
)
def test_a_column_that_cannot_be_compared_is_one_line(swept, capsys, tmp_path, option, said):
    """A rocker's offset (empty), words, flags, or one column named twice through its unit: refused naming the
    option (they gave an empty front, exit 1, or a blank chart, exit 0, or an --x the command does not have);
    nothing written."""
    _, out, _ = swept
    t = tmp_path / "t.csv"
    t.write_bytes(out.read_bytes())
    plot = ["--plot", tmp_path / "c.png"] if option[0] == "--axes" else []
    code, text, err = _run(capsys, "front", t, *option, *plot)
    assert code == 2 and text == "" and err == f"cams front: error: {said}" + err.split(said, 1)[1]
    assert err.count("\n") == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t.csv"]


@pytest.fixture(scope="module")
def parquet_txt(swept):
    """The same sweep as ``swept``'s, written as Parquet under a name that is not ``.parquet``."""
    pytest.importorskip("pyarrow.parquet", reason="Parquet tables need pyarrow (the test extra installs it)")
    d = swept[0] / "pq"
    d.mkdir()
    out = d / "x.txt"
    code = main(["sweep", str(EXAMPLES / "rocker_force.toml"), *VARY, "--out", str(out), "--format", "parquet",
                 "--quiet", "--jobs", "1"])
    assert code == 0 and out.read_bytes()[:4] == b"PAR1"
    return out


def test_parquet_under_any_name_is_read_as_parquet(swept, parquet_txt, capsys):
    """``--format parquet --out x.txt`` then ``cams front x.txt``: read as the Parquet it holds (it was read as a
    CSV by its name), its front the definition's over the rows pyarrow reads, the same designs as the CSV's."""
    import pyarrow.parquet as pq

    code, text, err = _run(capsys, "front", parquet_txt, "--pareto", "R0,L")
    assert code == 0, err
    rows = [{k: ("" if v is None else str(v)) for k, v in r.items()} for r in pq.read_table(parquet_txt).to_pylist()]
    expected = _brute(rows, ["R0_mm", "L_mm"])
    front = _read(parquet_txt.with_name("x.pareto.csv"))
    assert sorted(int(r["index"]) for r in front) == sorted(int(r["index"]) for r in expected)
    from_csv = _brute(_read(swept[1]), ["R0_mm", "L_mm"])  # the same sweep written as a CSV
    assert sorted(int(r["index"]) for r in front) == sorted(int(r["index"]) for r in from_csv)
    assert f"{len(expected)} of 6 rows" in text


def _front_err(capsys, table):
    code, _, err = _run(capsys, "front", table, "--pareto", "R0,L")
    assert code == 2 and err.count("\n") == 1 and err.startswith("cams front: error: TABLE: "), err
    return err


def test_a_garbled_table_is_never_read_silently(swept, parquet_txt, capsys, tmp_path):
    """Parquet cut short, a CSV named .parquet, a table its sidecar says is another format, binary data: one line
    naming TABLE, exit 2."""
    data = parquet_txt.read_bytes()
    cut = tmp_path / "cut.txt"
    cut.write_bytes(data[: len(data) // 2])
    assert "does not end as one (cut short)" in _front_err(capsys, cut)
    named = tmp_path / "t.parquet"
    named.write_bytes((swept[0] / "s.csv").read_bytes())
    assert "named as Parquet, but it is not" in _front_err(capsys, named)
    replaced = tmp_path / "x.txt"  # the Parquet sweep's table replaced by a CSV, its sidecar kept
    replaced.write_bytes((swept[0] / "s.csv").read_bytes())
    replaced.with_name("x.txt.sweep.json").write_bytes(parquet_txt.with_name("x.txt.sweep.json").read_bytes())
    assert "holds csv, but its sidecar says the sweep wrote parquet" in _front_err(capsys, replaced)
    binary = tmp_path / "b.csv"
    binary.write_bytes(b"R0_mm,L_mm\n\x00\x01,2\n")
    assert "binary data" in _front_err(capsys, binary)


def test_a_stream_is_not_a_table(capsys, tmp_path):
    """Standard input, a descriptor and a FIFO are streams: refused before reading (a FIFO was opened and waited
    for a writer); a table is a file or a folder of parts."""
    import os

    fifo = tmp_path / "t.csv"
    os.mkfifo(fifo)
    for table in ("-", "/dev/stdin", "/dev/fd/0", fifo):
        code, _, err = _run(capsys, "front", table, "--pareto", "R0,L")
        assert code == 2 and err.count("\n") == 1, err
        assert "--pareto: the front and the chart are read back from the table: give TABLE a file, not a stream" in err


def test_a_line_with_another_count_of_cells_is_left_out_and_said(tmp_path, capsys):
    """A line with a cell too many (an edit) and one cut short (an interrupted writer): both left out, counted in
    one line that names neither as the other."""
    from cams.cli import main

    out = tmp_path / "t.csv"
    assert main(["sweep", "examples/rocker_force.toml", "--vary", "limits.pressure_angle=30,35,40", "--out", str(out),
                 "--quiet"]) == 0
    lines = out.read_text().splitlines()
    lines[1] += ",extra"
    lines[2] = lines[2][: len(lines[2]) // 2]
    out.write_text("\n".join(lines) + "\n")
    capsys.readouterr()
    assert main(["front", str(out), "--pareto", "R0,max_pressure_angle_rise"]) == 0
    err = capsys.readouterr().err
    assert "2 line(s) left out: another count of cells than the header's" in err
