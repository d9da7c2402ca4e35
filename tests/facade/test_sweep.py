"""Sweeps: every combination solved, equal to solving one by one; bad specs are one-line errors."""

import csv
import tomllib

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import design_from_dict
from cams.solve import solve
from cams.sweep import MAX_DESIGNS, parse_vary, sweep
from laws.errors import InputError
from tests.conftest import EXAMPLES, rocker_dict


def test_parse_vary():
    k, v = parse_vary("limits.pressure_angle=30:50:5")
    assert k == "limits.pressure_angle" and np.allclose(v, [30, 35, 40, 45, 50])
    assert np.allclose(parse_vary("follower.arm=100,150")[1], [100, 150])
    # words are values too (laws, closures...): checked against the design file's schema by the sweep
    assert parse_vary("motion[0].law=cycloidal, poly345") == ("motion[0].law", ("cycloidal", "poly345"))
    for bad in ("limits.pressure_angle", "x=1:2", "=1,2", "x=1:2:0", "x=1:2:2.5", "x=1,,2"):
        with pytest.raises(InputError, match="--vary"):
            parse_vary(bad)


@pytest.mark.parametrize("workers", [1, 2])
def test_sweep_equals_one_by_one(workers):
    base = rocker_dict()
    res = sweep(base, [("limits.pressure_angle", np.array([35.0, 45.0])), ("follower.arm", np.array([100.0, 150.0]))],
                workers=workers)
    assert len(res.rows) == 4 and res.per_second > 0
    for row in res.rows:
        d = design_from_dict(rocker_dict(limits={"pressure_angle": row["limits.pressure_angle"]},
                                         follower={"arm": row["follower.arm"]}))
        assert row["R0"] == pytest.approx(solve(d).R0, rel=1e-12)
        assert row["verified"] is True and row["error"] is None
        assert row["buildable"] is (row["R0"] > 10.0)  # the example's roller radius


def test_infeasible_rows_are_recorded_not_fatal():
    base = rocker_dict(limits={"closure": "form"})
    res = sweep(base, [("follower.swing", np.array([15.0, 170.0])), ("limits.pressure_angle", np.array([10.0]))],
                workers=1)
    errs = [r["error"] for r in res.rows]
    assert errs[0] is None and "limits." in errs[1]
    assert res.rows[1]["R0"] is None


def test_sweep_cli_writes_csv(tmp_path, capsys):
    out = tmp_path / "s.csv"
    rc = main(["sweep", str(EXAMPLES / "rocker_force.toml"), "--vary", "limits.pressure_angle=40:50:3",
               "--out", str(out), "--jobs", "1", "--quiet"])
    assert rc == 0
    rows = list(csv.DictReader(out.open()))
    assert [float(r["limits.pressure_angle"]) for r in rows] == [40.0, 45.0, 50.0]
    R0 = [float(r["R0_mm"]) for r in rows]  # headers carry their units
    assert R0[0] > R0[1] > R0[2]  # a larger allowable angle: a smaller cam
    with open(EXAMPLES / "rocker_force.toml", "rb") as fh:
        base = tomllib.load(fh)
    assert R0[1] == pytest.approx(solve(design_from_dict(base)).R0, rel=1e-12)
    assert "designs/s" in capsys.readouterr().err


def test_sweep_cli_bad_key(tmp_path, capsys):
    rc = main(["sweep", str(EXAMPLES / "rocker_force.toml"), "--vary", "limits.pressure_angel=40:50:2",
               "--out", str(tmp_path / "s.csv"), "--jobs", "1", "--quiet"])
    assert rc == 2
    assert "limits" in capsys.readouterr().err
    assert not (tmp_path / "s.csv").exists()


def test_unknown_table_in_vary_is_an_error_and_integers_stay_integers(tmp_path, capsys):
    rc = main(["sweep", str(EXAMPLES / "rocker_force.toml"), "--vary", "limit.pressure_angle=30,40",
               "--out", str(tmp_path / "s.csv"), "--jobs", "1", "--quiet"])
    assert rc == 2 and "--vary" in capsys.readouterr().err
    res = sweep(rocker_dict(), [("solve.samples", np.array([60.0, 120.0]))], method="convex", workers=1)
    assert [r["error"] for r in res.rows] == [None, None]
    assert res.rows[0]["solve.samples"] == 60 and isinstance(res.rows[0]["solve.samples"], int)


def test_number_of_designs_is_bounded(tmp_path, capsys):
    # issue 12, item 5: a count of 1e11 ran out of memory ("use fewer samples"), a product of ranges ran for days
    out = tmp_path / "s.csv"
    rc = main(["sweep", str(EXAMPLES / "rocker_force.toml"), "--vary", "follower.arm=100:120:100000000000",
               "--out", str(out), "--jobs", "1", "--quiet"])
    err = capsys.readouterr().err
    assert rc == 2 and "--vary" in err and f"{MAX_DESIGNS:,}" in err and "samples" not in err
    assert not out.exists()
    big = np.linspace(30.0, 50.0, 1000)
    with pytest.raises(InputError, match=f"--vary.*{MAX_DESIGNS:,}"):
        sweep(rocker_dict(), [("limits.pressure_angle", big), ("follower.arm", big + 70.0)], workers=1)
