"""A sweep's table read back: units split from the headers, cells typed, a cut line dropped, rows copied whole."""

from __future__ import annotations

import csv
import sys

import numpy as np
import pytest

from cams.sweep.outfile import read_table, split_unit, write_rows
from laws.errors import InputError

TEXT = """index,follower.arm,R0_mm,max_pressure_angle_rise_deg,verified,failures,error
0,100,10.592634426831411,45,True,,
1,150,12.5,44.999999999,False,curvature below the roller,
2,200,,,,,no admissible centre
3,250,13.1,4"""


@pytest.fixture
def table(tmp_path):
    p = tmp_path / "s.csv"
    p.write_text(TEXT, encoding="utf-8")
    return read_table(p)


def test_units_split_from_result_columns_not_from_keys():
    assert split_unit("R0_mm") == ("R0", "mm")
    assert split_unit("error_bound_mm") == ("error_bound", "mm")
    assert split_unit("max_contact_stress_MPa") == ("max_contact_stress", "MPa")
    assert split_unit("failures") == ("failures", "")
    assert split_unit("motion[0].angle_deg") == ("motion[0].angle_deg", "")


def test_columns_typed_and_the_cut_line_dropped(table):
    assert table.names == ("index", "follower.arm", "R0", "max_pressure_angle_rise", "verified", "failures", "error")
    assert table.units["R0"] == "mm" and table.units["max_pressure_angle_rise"] == "deg"
    assert table.units["follower.arm"] == ""
    assert table.dropped == 1 and len(table) == 3  # "3,250,13.1,4": 4 cells of 7, an interrupted write
    assert table.columns["R0"][:2].tolist() == [10.592634426831411, 12.5]
    assert np.isnan(table.columns["R0"][2])
    assert table.columns["verified"] == [True, False, None]
    assert table.columns["failures"] == [None, "curvature below the roller", None]
    assert table.label("R0") == "R0 (mm)" and table.label("verified") == "verified"


def test_a_column_named_with_or_without_its_unit(table):
    assert table.column("R0") == "R0" == table.column("R0_mm")
    with pytest.raises(
        InputError,
        match=r"^--pareto: 'Rb' is not a column of .*s\.csv; the columns are: index, "
        r"follower\.arm, R0, max_pressure_angle_rise, verified, failures, error",
    ):
        table.column("Rb")


def test_rows_copied_with_every_digit(table, tmp_path):
    out = write_rows(tmp_path / "f.csv", table, [1, 0], "--pareto")
    with open(out, newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == TEXT.splitlines()[0].split(",")
    assert rows[1] == TEXT.splitlines()[2].split(",")
    assert rows[2] == TEXT.splitlines()[1].split(",")


def test_unreadable_tables_are_input_errors(tmp_path, monkeypatch):
    with pytest.raises(InputError, match="^--from: cannot read"):
        read_table(tmp_path / "none.csv")
    (tmp_path / "empty.csv").write_text("", encoding="utf-8")
    with pytest.raises(InputError, match="no header"):
        read_table(tmp_path / "empty.csv", "--from")
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    monkeypatch.setitem(sys.modules, "pyarrow.parquet", None)
    (tmp_path / "s.parquet").write_bytes(b"PAR1" + bytes(8) + b"PAR1")  # Parquet's marks: read as Parquet
    with pytest.raises(InputError, match=r"^TABLE: .*s\.parquet is Parquet: install pyarrow"):
        read_table(tmp_path / "s.parquet", "TABLE")
