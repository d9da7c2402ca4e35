"""Law tables in design files (``[motion.law]``): read, written back exactly, bad input named by its field."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import design_from_dict, load_design
from cams.io.lawtable import LAW_KEYS, law_from_table, law_to_table, toml_law_lines
from cams.solve import solve
from laws.bernstein import subdivision
from laws.errors import InputError
from laws.polynomial import PolynomialLaw
from laws.registry import get_law
from laws.spline import SplineLaw
from laws.table import TableLaw
from tests.conftest import rocker_dict

HEAD = """name = "law table"
[follower]
kind = "rocker"
arm = 125.0
swing = 15.0
roller_radius = 10.0
rise_direction = "cw"
[cam]
rotation = "ccw"
[[motion]]
phase = "rise"
angle = 120
"""
TAIL = """[[motion]]
phase = "dwell"
angle = 30
[[motion]]
phase = "return"
law = "cycloidal"
angle = 120
[[motion]]
phase = "dwell"
[limits]
pressure_angle = 45
"""
U = np.linspace(0, 1, 501)


def design_file(tmp_path, law_lines: list[str] | str, name: str = "cam.toml"):
    """The rocker of HEAD/TAIL with its rise's law given by ``law_lines`` (a ``law = ...`` line or a table)."""
    lines = [law_lines] if isinstance(law_lines, str) else law_lines
    f = tmp_path / name
    f.write_text(HEAD + "\n".join(lines) + "\n" + TAIL, encoding="utf-8")
    return f


def r0(path) -> float:
    return float(solve(load_design(path)).R0)


# --------------------------------------------------------------------------- the same cam, however its law is given
@pytest.fixture(scope="module")
def r0_poly345(tmp_path_factory):
    return r0(design_file(tmp_path_factory.mktemp("named"), 'law = "poly345"'))


@pytest.mark.parametrize("lines", [
    ["[motion.law]", 'kind = "spline"', "degree = 5", "coefficients = [[0, 0, 0, 1, 1, 1]]"],
    ['law = { kind = "spline", breaks = [0.0, 1.0], coefficients = [[0, 0, 0, 1, 1, 1]] }'],
    ["[motion.law]", 'kind = "spline"', "breaks = [0, 0.5, 1]",
     "coefficients = " + repr((subdivision(5, 2) @ np.array([0, 0, 0, 1, 1, 1.0])).tolist())],
    ["[motion.law]", 'kind = "polynomial"', "start = [0, 0]", "end = [0, 0]"],
    ['law = { kind = "polynomial", start = [0.0, 0.0], end = [0.0, 0.0], name = "3-4-5" }'],
], ids=["spline", "spline-inline", "spline-2-spans", "polynomial", "polynomial-inline"])
def test_a_law_table_equal_to_poly345_gives_the_same_cam(lines, tmp_path, r0_poly345):
    f = design_file(tmp_path, lines)
    law = load_design(f).program.phases[0].law
    assert isinstance(law, (SplineLaw, PolynomialLaw))
    np.testing.assert_allclose(law.evaluate(U), get_law("poly345").evaluate(U), rtol=0, atol=1e-9)
    assert r0(f) == pytest.approx(r0_poly345, rel=1e-9)


def test_kind_and_name():
    t = {"kind": "spline", "coefficients": [[0, 0.5, 1]]}
    law = law_from_table(t, "motion[0].law")
    assert isinstance(law, SplineLaw) and law.name == "spline" and law.breaks == (0.0, 1.0) and law.degree == 2
    law = law_from_table({"kind": "polynomial", "name": "my law"}, "motion[0].law")
    assert isinstance(law, PolynomialLaw) and law.name == "my law" and law.coefficients == (0.0, 1.0)
    law = law_from_table({"kind": "polynomial", "start": [0, 0, 0], "end": [0, 0, 0]}, "motion[0].law")
    np.testing.assert_allclose(law.evaluate(U), get_law("poly4567").evaluate(U), atol=1e-10)


def test_a_law_table_on_the_return_and_the_name_in_the_program():
    motion = rocker_dict()["motion"]
    motion[2] = {**motion[2], "law": {"kind": "spline", "name": "slow start", "breaks": [0, 0.5, 1],
                                      "coefficients": [[0, 0, 0.5], [0.5, 1, 1]]}}
    d = design_from_dict(rocker_dict(motion=motion))
    law = d.program.phases[2].law
    assert isinstance(law, SplineLaw) and law.name == "slow start" and law.breakpoints == (0.5,)


# --------------------------------------------------------------------------- written and read back
def test_spline_round_trips_bit_for_bit(tmp_path):
    rng = np.random.default_rng(3)
    rows = rng.uniform(0.0, 1.0, size=(3, 8))  # within [0, 1]: S stays there (a law table must; convex hull)
    rows[0, 0], rows[-1, -1] = 0.0, 1.0
    rows[1, 0], rows[2, 0] = rows[0, -1], rows[1, -1]
    law = SplineLaw((0.0, 0.1 + 0.2, 2 / 3, 1.0), rows.tolist(), name='odd "name" \\ é')
    table = law_to_table(law)
    assert isinstance(table, dict) and table["kind"] == "spline" and table["degree"] == 7
    assert all(type(x) is float for r in table["coefficients"] for x in r)
    back = load_design(design_file(tmp_path, toml_law_lines(table))).program.phases[0].law
    assert isinstance(back, SplineLaw)
    assert back.coefficients == law.coefficients and back.breaks == law.breaks and back.name == law.name
    assert back == law


def test_polynomial_written_as_a_one_span_spline(tmp_path):
    law = PolynomialLaw.from_boundary(start=(0, 0, 0), end=(0.5, 0), name="eased")
    table = law_to_table(law)
    assert isinstance(table, dict)
    assert (table["kind"], table["name"], table["degree"], table["breaks"]) == ("spline", "eased", law.degree,
                                                                                [0.0, 1.0])
    back = load_design(design_file(tmp_path, toml_law_lines(table))).program.phases[0].law
    np.testing.assert_allclose(back.evaluate(U), law.evaluate(U), rtol=0, atol=1e-12)


def test_named_law_written_as_its_name(tmp_path):
    assert law_to_table(get_law("modified_sine")) == "modified_sine"
    back = load_design(design_file(tmp_path, toml_law_lines("modified_sine"))).program.phases[0].law
    assert back is get_law("modified_sine")


def test_other_laws_are_not_written():
    with pytest.raises(InputError, match="TableLaw cannot be written") as e:
        law_to_table(TableLaw([0, 1], [0, 1], clamped=True))
    assert e.value.field == "law"
    with pytest.raises(InputError, match="degree 16"):
        law_to_table(PolynomialLaw((0.0,) * 16 + (1.0,)))


def test_toml_lines():
    assert toml_law_lines({"kind": "spline", "degree": 1, "coefficients": [[0.0, 1.0]]}) == [
        "[motion.law]", 'kind = "spline"', "degree = 1", "coefficients = [[0.0, 1.0]]"]
    assert toml_law_lines({"name": 'a "b"\n'}, "x.y") == ["[x.y]", 'name = "a \\"b\\"\\u000A"']


# --------------------------------------------------------------------------- bad input: one error naming the field
F = "motion[0].law"
BAD = [
    ({"coefficients": [[0, 1]]}, f"{F}.kind", "is required"),
    ({"kind": "bezier"}, f"{F}.kind", "'spline', 'polynomial'"),
    ({"kind": 5}, f"{F}.kind", "not a valid option"),
    ({"kind": "spline", "coefficients": [[0, 1]], "knots": [0, 1]}, F, "unknown key.*knots.*allowed: kind"),
    ({"kind": "polynomial", "coefficients": [[0, 1]]}, F, "unknown key.*coefficients.*allowed: kind, name, start"),
    ({"kind": "spline"}, f"{F}.coefficients", "is required"),
    ({"kind": "spline", "coefficients": "0 1"}, f"{F}.coefficients", "array of arrays"),
    ({"kind": "spline", "coefficients": []}, f"{F}.coefficients", "non-empty"),
    ({"kind": "spline", "coefficients": [0, 1]}, f"{F}.coefficients[0]", "array of numbers"),
    ({"kind": "spline", "coefficients": [[0, "a", 1]]}, f"{F}.coefficients[0][1]", "finite number"),
    ({"kind": "spline", "coefficients": [[0, True, 1]]}, f"{F}.coefficients[0][1]", "finite number"),
    ({"kind": "spline", "coefficients": [[0, 0, 0.5], [0.5, 1]]}, f"{F}.coefficients", "same number"),
    ({"kind": "spline", "coefficients": [[1]]}, f"{F}.coefficients", "degree 1 to 15"),
    ({"kind": "spline", "coefficients": [[0.5, 1]]}, f"{F}.coefficients", r"S\(0\) = 0"),
    ({"kind": "spline", "coefficients": [[0, 0.9]]}, f"{F}.coefficients", r"S\(1\) = 1"),
    ({"kind": "spline", "coefficients": [[0, 0, 0.5], [0.6, 1, 1]]}, f"{F}.coefficients", r"jumps.*u = 0\.5"),
    ({"kind": "spline", "degree": 4, "coefficients": [[0, 0, 0, 1, 1, 1]]}, f"{F}.coefficients",
     "degree 4 takes 5"),
    ({"kind": "spline", "degree": 5.0, "coefficients": [[0, 0, 0, 1, 1, 1]]}, f"{F}.degree", "integer from 1 to 15"),
    ({"kind": "spline", "degree": 16, "coefficients": [[0, 1]]}, f"{F}.degree", "integer from 1 to 15"),
    ({"kind": "spline", "degree": 0, "coefficients": [[0, 1]]}, f"{F}.degree", "integer from 1 to 15"),
    ({"kind": "spline", "breaks": "uniform", "coefficients": [[0, 1]]}, f"{F}.breaks", "array of numbers"),
    ({"kind": "spline", "breaks": [0, "b", 1], "coefficients": [[0, 1]]}, f"{F}.breaks[1]", "finite number"),
    ({"kind": "spline", "breaks": [0, 1], "coefficients": [[0, 0.5], [0.5, 1]]}, f"{F}.breaks", "one more break"),
    ({"kind": "spline", "breaks": [0, 0.5, 0.5, 1], "coefficients": [[0, 0.2], [0.2, 0.5], [0.5, 1]]},
     f"{F}.breaks", "strictly increasing"),
    ({"kind": "spline", "breaks": [0, 2], "coefficients": [[0, 1]]}, f"{F}.breaks", "end at 1"),
    ({"kind": "spline", "name": 3, "coefficients": [[0, 1]]}, f"{F}.name", "string"),
    ({"kind": "polynomial", "name": ""}, f"{F}.name", "non-empty string"),
    ({"kind": "polynomial", "start": [0, 0, 0, 0]}, f"{F}.start", "at most 3 numbers.*got 4"),
    ({"kind": "polynomial", "start": 0}, f"{F}.start", "array of numbers"),
    ({"kind": "polynomial", "end": [0, "a"]}, f"{F}.end[1]", "finite number"),
    ({"kind": "polynomial", "end": [0, False]}, f"{F}.end[1]", "finite number"),
]


@pytest.mark.parametrize("law, field, match", BAD, ids=[f"{i}-{b[1].rsplit('.', 1)[-1]}" for i, b in enumerate(BAD)])
def test_bad_law_table(law, field, match):
    motion = rocker_dict()["motion"]
    motion[0] = {**motion[0], "law": law}
    with pytest.raises(InputError, match=match) as e:
        design_from_dict(rocker_dict(motion=motion))
    assert e.value.field == field
    assert str(e.value).startswith(f"{field}: ")


def test_every_key_of_each_kind_is_tested():
    tested = {k for law, _, _ in BAD if isinstance(law, dict) for k in law}
    assert set().union(*map(set, LAW_KEYS.values())) <= tested


def test_a_dwell_takes_no_law_table():
    motion = rocker_dict()["motion"]
    motion[1] = {**motion[1], "law": {"kind": "spline", "coefficients": [[0, 1]]}}
    with pytest.raises(InputError, match="a dwell takes no law") as e:
        design_from_dict(rocker_dict(motion=motion))
    assert e.value.field == "motion[1].law"


def test_not_a_table_is_not_a_name():
    """Only a table goes to law_from_table; anything else is a law name, as before."""
    motion = rocker_dict()["motion"]
    motion[0] = {**motion[0], "law": ["poly345"]}
    with pytest.raises(InputError, match="unknown law") as e:
        design_from_dict(rocker_dict(motion=motion))
    assert e.value.field == "motion[0].law"
    with pytest.raises(InputError, match="must be a law name or a law table") as e:
        law_from_table(["poly345"], F)  # type: ignore[arg-type]
    assert e.value.field == F


# --------------------------------------------------------------------------- the command line: one line, exit 2
@pytest.mark.parametrize("law, field, match", BAD[::3], ids=[str(i) for i in range(0, len(BAD), 3)])
def test_bad_law_table_on_the_command_line(law, field, match, tmp_path, capsys):
    f = design_file(tmp_path, toml_law_lines(law))
    capsys.readouterr()
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert f" {field}: " in err


@pytest.mark.parametrize("key, value", [
    ("degree", "99999999999999999999999"), ("degree", "nan"), ("degree", "true"), ("degree", '"5"'),
    ("breaks", "[0.0, inf]"), ("breaks", "[0, 99999999999999999999999]"), ("breaks", "[0, true]"),
    ("coefficients", "[[0, nan, 1]]"), ("coefficients", "[[0, -inf, 1]]"), ("coefficients", '[[0, "x", 1]]'),
    ("coefficients", "[[0, 99999999999999999999999, 1]]"),
])
def test_numbers_no_key_allows(key, value, tmp_path, capsys):
    table = {"kind": '"spline"', "coefficients": "[[0, 0.5, 1]]", key: value}
    f = design_file(tmp_path, ["[motion.law]", *(f"{k} = {v}" for k, v in table.items())])
    capsys.readouterr()
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert f" {F}.{key}" in err


@pytest.mark.parametrize("key, value", [("start", "[nan]"), ("start", "[true]"), ("end", "[0, 99999999999999999999999]"),
                                        ("end", '["0"]')])
def test_polynomial_numbers_no_key_allows(key, value, tmp_path, capsys):
    f = design_file(tmp_path, ["[motion.law]", 'kind = "polynomial"', f"{key} = {value}"])
    capsys.readouterr()
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f" {F}.{key}" in err


def test_python_m_cams_cli(tmp_path):
    """``python -m cams.cli solve FILE``: a bad law table is one line on stderr and exit code 2."""
    f = design_file(tmp_path, ["[motion.law]", 'kind = "spline"', "coefficients = [[0, 0, 0.5], [0.6, 1, 1]]"])
    r = subprocess.run([sys.executable, "-m", "cams.cli", "solve", str(f)], capture_output=True, text=True,
                       cwd=tmp_path, check=False)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1
    assert f"{F}.coefficients: S must be continuous" in r.stderr
    good = design_file(tmp_path, ["[motion.law]", 'kind = "spline"', "coefficients = [[0, 0, 0, 1, 1, 1]]"], "ok.toml")
    r = subprocess.run([sys.executable, "-m", "cams.cli", "solve", str(good)], capture_output=True, text=True,
                       cwd=tmp_path, check=False)
    assert r.returncode == 0 and "R0" in r.stdout
