"""Bad input around the motion design: ``[optimize]``, law tables (``[motion.law]``) and ``cams solve --save-design``.

The rule: bad input prints ONE line on stderr naming the field and what is allowed, and exits 2 (never a
traceback, a NaN or inf printed as an answer, a hang or a silently wrong answer); a design that fails a check
exits 1; "wrote X" means X holds the data. Each test runs the command line (:func:`cams.cli.main`, in this
process: tests/inprocess.py; the warning test as a separate ``python -m cams.cli``) on a copy of an example with a
snippet added.

The ``test_bug_...`` tests keep the bugs a bad-input sweep of the feature found (each docstring says what
happened); all are fixed, and these tests hold them so.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from tests.inprocess import cams_cli

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
TIMEOUT = 60


# --- helpers -------------------------------------------------------------------------------------------------

def cams(*args, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """``cams ARGS``, captured: :func:`cams.cli.main` in this process (tests/inprocess.py: exit code, stdout,
    stderr with the warnings a fresh process shows); what is tested is what the command prints and returns."""
    return cams_cli(*args, cwd=cwd or ROOT)


def cams_process(*args, cwd: Path | None = None) -> subprocess.CompletedProcess:
    """``python -m cams.cli ARGS`` as a separate process, captured (a hang fails the test at TIMEOUT seconds)."""
    return subprocess.run([sys.executable, "-m", "cams.cli", *map(str, args)], capture_output=True, text=True,
                          timeout=TIMEOUT, cwd=cwd or ROOT)


def design(tmp_path: Path, example: str, extra: str = "", subs: tuple[tuple[str, str], ...] = (),
           name: str = "design.toml") -> Path:
    """A copy of ``examples/EXAMPLE.toml`` in ``tmp_path`` with ``subs`` replaced (each must occur) and
    ``extra`` appended (new tables)."""
    text = (EXAMPLES / f"{example}.toml").read_text(encoding="utf-8")
    for old, new in subs:
        assert old in text, old
        text = text.replace(old, new, 1)
    p = tmp_path / name
    p.write_text(text + "\n" + extra, encoding="utf-8")
    return p


def assert_refused(r: subprocess.CompletedProcess, *fields: str) -> str:
    """Exit 2, no traceback, exactly one line on stderr naming one of ``fields``; returns that line."""
    assert "Traceback" not in r.stderr, r.stderr
    lines = r.stderr.strip().splitlines()
    assert r.returncode == 2, (r.returncode, r.stderr, r.stdout[-2000:])
    assert len(lines) == 1, r.stderr
    assert any(f in lines[0] for f in fields), lines[0]
    return lines[0]


def solve_json(path: Path, *more) -> tuple[int, dict]:
    r = cams("solve", path, "--json", *more)
    assert "Traceback" not in r.stderr, r.stderr

    def refuse(c):
        raise AssertionError(f"not strict JSON: {c} in the report")

    return r.returncode, json.loads(r.stdout, parse_constant=refuse)


TF = "translating_force"
RISE_LAW = 'law = "poly4567"\n'      # the rise of translating_force, replaced by law tables below
# a rise whose law is the given table (motion[0] is the rise)
def with_law(table: str) -> tuple[tuple[str, str], ...]:
    return ((RISE_LAW, ""), ("angle = 150\n", "angle = 150\n" + table + "\n"))


# =============================================================================================================
# Well-behaved: [optimize] values of the wrong type or out of range (one line, exit 2, the key named)
# =============================================================================================================

@pytest.mark.parametrize("snippet, field", [
    ('free = "abc"', "optimize.free"),
    ("free = [1]", "optimize.free"),                 # a dwell
    ("free = [4]", "optimize.free"),                 # out of range
    ('objective = true', "optimize.objective"),
    ('objective = "L"', "optimize.objective"),       # L: rocker only
    ("max_Ca = 0", "optimize.max_Ca"),
    ("max_Ca = nan", "optimize.max_Ca"),
    ('max_Ca = "foo"', "optimize.max_Ca"),
    ("max_Ca = [5, 6]", "optimize.max_Ca"),          # two caps, one free phase
    ('max_Cj = "harmonic"', "optimize.max_Cj"),      # an infinite peak
    ("continuity = 4", "optimize.continuity"),
    ("degree = 3", "optimize.degree"),               # not above the continuity 3
    ("spans = 0", "optimize.spans"),
    ('objective = "snap_squared"\ndegree = 3\ncontinuity = 2', "optimize.degree|optimize.continuity"),
    ("foo = 1", "optimize"),
    ("smoothing_slack = 1", "optimize.smoothing_slack"),          # the share given up: [0, 1)
    ("smoothing_slack = -0.01", "optimize.smoothing_slack"),
    ('smoothing_slack = "0.1"', "optimize.smoothing_slack"),
    ("smoothing_slack = true", "optimize.smoothing_slack"),
    ("smoothing_slack = nan", "optimize.smoothing_slack"),
])
def test_optimize_key_refused(tmp_path, snippet, field):
    p = design(tmp_path, TF, f"[optimize]\n{snippet}\n")
    assert_refused(cams("solve", p), *field.split("|"))


def test_cap_no_law_can_meet_is_refused(tmp_path):
    p = design(tmp_path, TF, "[optimize]\nmax_Ca = 0.5\nspans = 5\n")
    assert_refused(cams("solve", p), "optimize.max_Ca")


def test_optimize_not_a_table(tmp_path):
    p = design(tmp_path, TF, subs=(('name = "translating roller cam"\n', 'name = "translating roller cam"\n'
                                                                         'optimize = 3\n'),))
    assert_refused(cams("solve", p), "optimize")


def test_solve_objective_beside_optimize(tmp_path):
    p = design(tmp_path, TF, '[solve]\nobjective = "R0"\n[optimize]\n')
    assert_refused(cams("solve", p), "solve.objective")


@pytest.mark.parametrize("example, snippet, field", [
    ("translating_flat", 'objective = "pressure_angle"', "optimize.objective"),
    ("translating_flat", "continuity = 1\ndegree = 5", "optimize.continuity"),
    ("rocker_flat", 'objective = "L"', "optimize.objective"),
    ("rocker_flat", "continuity = 1\ndegree = 5", "optimize.continuity"),
    ("rocker_flat", "spans = 41", "optimize.spans"),
    ("rocker_force", "spans = 41", "optimize.spans"),
    ("rocker_force", "smoothing_slack = 0.01", "optimize.smoothing_slack"),    # translating followers only
    ("rocker_flat", "smoothing_slack = 0.01", "optimize.smoothing_slack"),
])
def test_objective_or_space_that_does_not_apply(tmp_path, example, snippet, field):
    p = design(tmp_path, example, f"[optimize]\n{snippet}\n")
    assert_refused(cams("solve", p), field)


def test_chosen_cam_with_R0_objective(tmp_path):
    p = design(tmp_path, TF, "[optimize]\n", subs=(('rotation = "ccw"\n', 'rotation = "ccw"\nbase_radius = 30\n'),
                                                  ("roller_radius = 8.0\n", "roller_radius = 8.0\noffset = 0\n")))
    assert_refused(cams("solve", p), "optimize.objective")


@pytest.mark.parametrize("command", [("check",), ("profile", "--csv", "out.csv"), ("report",)])
def test_other_commands_refuse_the_same(tmp_path, command):
    p = design(tmp_path, TF, "[optimize]\nspans = 0\n")
    out = ("--out", tmp_path / "o") if command[0] in ("plot", "report") else ()
    assert_refused(cams(command[0], p, *command[1:], *out, cwd=tmp_path), "optimize.spans")
    assert not (tmp_path / "out.csv").exists() and not (tmp_path / "o").exists()


# =============================================================================================================
# Well-behaved: law tables
# =============================================================================================================

@pytest.mark.parametrize("table, field", [
    ('[motion.law]\ncoefficients = [[0, 0, 0, 1, 1, 1]]', "motion[0].law.kind"),
    ('[motion.law]\nkind = "spline"\nknots = [0, 1]\ncoefficients = [[0, 0, 0, 1, 1, 1]]', "motion[0].law"),
    ('[motion.law]\nkind = "spline"\nbreaks = [0, 0.5, 1]\ncoefficients = [[0, 0, 0.4], [0.5, 1, 1]]',
     "motion[0].law.coefficients"),                                              # S jumps at 0.5
    ('[motion.law]\nkind = "spline"\ncoefficients = [[0.1, 0, 0, 1, 1, 1]]', "motion[0].law.coefficients"),
    ('[motion.law]\nkind = "spline"\ndegree = 4\ncoefficients = [[0, 0, 0, 1, 1, 1]]', "motion[0].law.coefficients"),
    ('[motion.law]\nkind = "spline"\ndegree = 16\ncoefficients = [[0, 0, 0, 1, 1, 1]]', "motion[0].law.degree"),
    ('[motion.law]\nkind = "spline"\nbreaks = [0, 0.6, 0.4, 1]\ncoefficients = [[0, 0.2], [0.2, 0.5], [0.5, 1]]',
     "motion[0].law.breaks"),
    ('law = { kind = "polynomial", start = [0, 0, 0, 0] }', "motion[0].law.start"),
])
def test_law_table_refused(tmp_path, table, field):
    p = design(tmp_path, TF, subs=with_law(table))
    assert_refused(cams("solve", p), field)


def test_law_table_on_a_dwell(tmp_path):
    p = design(tmp_path, TF, subs=(('phase = "dwell"\nangle = 30\n', 'phase = "dwell"\nangle = 30\n[motion.law]\n'
                                    'kind = "spline"\ncoefficients = [[0, 1]]\n'),))
    assert_refused(cams("solve", p), "motion[1].law")


# =============================================================================================================
# Well-behaved: --save-design
# =============================================================================================================

@pytest.fixture
def return_free(tmp_path):
    """translating_force with its return designed (small space: quick); the cam passes every check."""
    return design(tmp_path, TF, '[optimize]\nfree = ["return"]\nspans = 5\n', name="in.toml")


@pytest.mark.parametrize("target, words", [
    (".", "folder"),
    (str(Path("missing") / "out.toml"), "does not exist"),
    ("-", "standard output"),
    ("in.toml", "input file"),
])
def test_save_design_refused_targets(tmp_path, return_free, target, words):
    before = return_free.read_text()
    line = assert_refused(cams("solve", return_free, "--save-design", target, cwd=tmp_path), "--save-design")
    assert words in line
    assert return_free.read_text() == before


def test_save_design_symlink_to_the_input_is_refused(tmp_path, return_free):
    (tmp_path / "link.toml").symlink_to(return_free)
    assert_refused(cams("solve", return_free, "--save-design", "link.toml", cwd=tmp_path), "--save-design")


def test_save_design_without_optimize_table(tmp_path):
    p = design(tmp_path, TF)
    assert_refused(cams("solve", p, "--save-design", tmp_path / "o.toml"), "--save-design")
    assert not (tmp_path / "o.toml").exists()


def test_save_design_of_a_failing_cam_is_not_written(tmp_path):
    # the laws as given (free = []), too fast for its spring: the follower loses contact ([dynamics])
    p = design(tmp_path, TF, "[optimize]\nfree = []\n[dynamics]\nmass = 5\nspring_rate = 200\npreload = 1\n",
               subs=(('rotation = "ccw"\n', 'rotation = "ccw"\nrpm = 3000\n'),))
    keep = tmp_path / "keep.toml"
    keep.write_text("existing\n")
    r = cams("solve", p, "--save-design", keep)
    assert r.returncode == 1 and "Traceback" not in r.stderr
    assert "not written" in r.stdout and "wrote" not in r.stdout
    assert keep.read_text() == "existing\n"


# =============================================================================================================
# BUGS: each test below failed when it was written
# =============================================================================================================

@pytest.mark.parametrize("objective", ["Ca", "snap_squared"])
def test_bug_no_free_phase_with_a_law_objective_is_a_traceback(tmp_path, objective):
    """free = [] with objective Ca/Cj/jerk_squared/snap_squared: ValueError traceback (max() of an empty
    sequence / concatenate), exit 1. Nothing is free to minimize: bad input."""
    p = design(tmp_path, TF, f'[optimize]\nfree = []\nobjective = "{objective}"\n')
    assert_refused(cams("solve", p), "optimize.free", "optimize.objective")


def test_bug_cj_objective_with_continuity_1_prints_inf(tmp_path):
    """objective = "Cj" with continuity = 1: S'' jumps at the knots, the answer is 'minimized: Cj: inf', exit 0
    (--json: "value": Infinity, not JSON)."""
    p = design(tmp_path, TF, '[optimize]\nobjective = "Cj"\ncontinuity = 1\ndegree = 3\nspans = 5\n')
    r = cams("solve", p, "--json")
    assert "Infinity" not in r.stdout
    assert_refused(r, "optimize.continuity", "optimize.objective")


def test_bug_cj_cap_with_continuity_1_is_exit_1_with_none(tmp_path):
    """max_Cj with continuity = 1 can never hold (S'' jumps): exit 1, 'Cj = None exceeds its cap 100'."""
    p = design(tmp_path, TF, "[optimize]\nmax_Cj = 100\ncontinuity = 1\ndegree = 3\nspans = 5\n")
    r = cams("solve", p)
    assert "None" not in r.stdout
    assert_refused(r, "optimize.max_Cj", "optimize.continuity")


def test_bug_jerk_squared_with_continuity_1_ignores_the_impacts(tmp_path):
    """jerk_squared over a C1 spline (S'' jumps: infinite jerk at the knots) reports ~1e-20, exit 0."""
    p = design(tmp_path, TF, '[optimize]\nobjective = "jerk_squared"\ncontinuity = 1\ndegree = 3\nspans = 5\n')
    assert_refused(cams("solve", p), "optimize.continuity", "optimize.objective")


def test_bug_huge_allowed_cap_fails_the_solver(tmp_path):
    """max_Ca = 1e11 is accepted (a number > 0; the model takes < 1e12), then 'optimize: the conic solver
    failed ... try fewer spans or a lower degree' (even at 5 spans). A loose cap should act as no cap, or be
    refused naming optimize.max_Ca and its range."""
    p = design(tmp_path, TF, "[optimize]\nmax_Ca = 1e11\nspans = 5\n")
    r = cams("solve", p)
    if r.returncode != 0:
        assert_refused(r, "optimize.max_Ca")


def test_bug_duplicate_free_index_is_silently_accepted(tmp_path):
    """free = [2, 2]: accepted as [2] (a typo for [0, 2]?); a per-phase cap list then counts 1 free phase."""
    p = design(tmp_path, TF, "[optimize]\nfree = [2, 2]\nspans = 5\n")
    assert_refused(cams("solve", p), "optimize.free")


def test_bug_min_base_radius_with_held_objective_names_cam_centre(tmp_path):
    """limits.min_base_radius with objective "Ca" (no chosen cam): 'cam.centre: fixes the cam ...' - the file
    has no cam.centre."""
    p = design(tmp_path, TF, '[optimize]\nobjective = "Ca"\nspans = 5\n',
               subs=(('closure = "force"\n', 'closure = "force"\nmin_base_radius = 40\n'),))
    line = assert_refused(cams("solve", p), "limits.min_base_radius", "optimize.objective")
    assert "cam.centre" not in line


def test_bug_flat_held_cam_too_small_blames_caps_and_pressure_limits(tmp_path):
    """A flat face (no pressure-angle limit), a chosen base_radius below convexity, objective "Ca", no caps:
    'optimize: the caps and the pressure-angle limits cannot both hold ...'."""
    p = design(tmp_path, "translating_flat", '[optimize]\nobjective = "Ca"\nspans = 5\n',
               subs=(("rpm = 120\n", "rpm = 120\nbase_radius = 11\n"),))
    r = cams("solve", p)
    assert "Traceback" not in r.stderr
    if r.returncode == 2:
        line = assert_refused(r, "cam.base_radius", "limits.min_radius")
        assert "pressure-angle" not in line
    else:
        assert r.returncode == 1


def test_bug_tiny_rise_angle_blames_caps_that_were_not_given(tmp_path):
    """A rise of 0.001 deg (solves without [optimize]): 'optimize: the caps together admit no law of the space'
    though no cap is given."""
    p = design(tmp_path, TF, "[optimize]\nspans = 5\n", subs=(("angle = 150", "angle = 0.001"),
                                                             ("angle = 30\n", "angle = 29.999\n")))
    r = cams("solve", p)
    assert "Traceback" not in r.stderr
    if r.returncode == 2:
        line = assert_refused(r, "motion[0]", "optimize")
        assert "caps" not in line


@pytest.mark.parametrize("coefficients", ["[[0, 3, 3, 1]]", "[[0, -3, -3, 1]]"])
def test_bug_law_table_leaving_0_1_is_accepted(tmp_path, coefficients):
    """A spline law whose S leaves [0, 1] (S(0.5) = 2.375: the follower travels 71.8 mm on a 30 mm stroke) is
    accepted; docs: the follower must stay within [0, lift]."""
    p = design(tmp_path, TF, subs=with_law(f'[motion.law]\nkind = "spline"\ncoefficients = {coefficients}'))
    assert_refused(cams("solve", p), "motion[0].law")


def test_bug_save_design_to_a_path_under_a_file_does_not_name_the_option(tmp_path, return_free):
    """--save-design in.toml/x.toml: 'cams solve: error: in.toml/x.toml: Not a directory' (profile --csv says
    '--csv: cannot write ...')."""
    assert_refused(cams("solve", return_free, "--save-design", "in.toml/x.toml", cwd=tmp_path), "--save-design")


def test_bug_save_design_name_with_newline_writes_invalid_toml(tmp_path):
    """name = "two\\nlines": the header comment of the saved file breaks; 'wrote out.toml' but out.toml is not
    TOML (solve: 'not valid TOML')."""
    p = design(tmp_path, TF, "[optimize]\nfree = []\n",
               subs=(('name = "translating roller cam"', 'name = "two\\nlines = 5"'),))
    out = tmp_path / "out.toml"
    r = cams("solve", p, "--save-design", out)
    assert r.returncode == 0 and f"wrote {out}" in r.stdout
    back = cams("solve", out)
    assert back.returncode == 0, back.stderr


@pytest.fixture(scope="module")
def default_design(tmp_path_factory):
    """examples/translating_force.toml with an empty [optimize] (the defaults): solved once, saved."""
    tmp = tmp_path_factory.mktemp("default")
    p = design(tmp, TF, "[optimize]\n")
    out = tmp / "designed.toml"
    rc, rep = solve_json(p, "--save-design", out)
    return rc, rep, out


def test_bug_default_optimize_returns_a_larger_cam_than_the_given_laws(default_design):
    """The default space (degree 7, 20 spans, C3) holds poly4567, whose cam (R0 17.58 mm) passes every check;
    the 'optimized' R0 is 23.77 mm (its optimum, 5.4 mm, is below the roller radius 8 mm, then raised by a
    floor), reported 'certified: yes'."""
    rc, rep, _ = default_design
    assert rc == 0
    assert rep["R0"] <= rep["optimize"]["reference"]["R0"] * (1 + 1e-9)


def test_bug_saved_design_of_a_floored_cam_does_not_solve_back(default_design):
    """--save-design drops the floor that made the cam pass: designed.toml solves to R0 = 5.42 mm, no working
    profile, exit 1 (docs: it solves back to the same cam)."""
    rc, rep, out = default_design
    assert rc == 0 and out.exists()
    rc2, back = solve_json(out)
    assert rc2 == 0
    assert back["R0"] == pytest.approx(rep["R0"], rel=1e-6)


def test_bug_saved_design_of_a_held_objective_does_not_solve_back(tmp_path):
    """objective = "Ca" holds R0 (17.52 mm, its centre chosen by the program); the saved design has no centre:
    it solves to R0 = 15.57 mm, another cam."""
    p = design(tmp_path, TF, '[optimize]\nobjective = "Ca"\nspans = 5\n')
    out = tmp_path / "out.toml"
    rc, rep = solve_json(p, "--save-design", out)
    assert rc == 0
    rc2, back = solve_json(out)
    assert rc2 == 0
    assert back["R0"] == pytest.approx(rep["R0"], rel=1e-6)
    assert back["centre"]["x"] == pytest.approx(rep["centre"]["x"], abs=1e-6)


@pytest.fixture(scope="module")
def held_return(tmp_path_factory):
    """free = ["return"], objective "Ca", force closure: the rise (its law unchanged) is the one limited."""
    tmp = tmp_path_factory.mktemp("held")
    p = design(tmp, TF, '[optimize]\nfree = ["return"]\nobjective = "Ca"\nspans = 5\n')
    return solve_json(p)


def test_bug_held_objective_breaks_the_rise_limit_it_did_not_touch(held_return):
    """The original cam passes at this size; the designed one moves the centre and fails: 'rise pressure angle
    30.0001 deg exceeds the limit 30.0000 deg', exit 1."""
    rc, rep = held_return
    assert rc == 0, rep.get("failures")
    assert rep["verified"] is True


def test_bug_certified_while_the_cam_fails(held_return):
    """optimize.certified is true beside verified: false (docs: certified says every check passed)."""
    rc, rep = held_return
    assert not (rep["optimize"]["certified"] and not rep["verified"])


def test_bug_certified_while_the_cam_is_not_buildable(tmp_path):
    """[dynamics] at 600 rpm: the designed cam loses contact (buildable: false, exit 1), yet
    optimize.certified is true ('certified: yes' in the summary)."""
    p = design(tmp_path, TF, '[optimize]\nobjective = "pressure_angle"\nspans = 5\n'
               "[dynamics]\nmass = 0.5\nspring_rate = 2000\npreload = 10\nload = 5\n",
               subs=(('rotation = "ccw"\n', 'rotation = "ccw"\nrpm = 600\n'),))
    rc, rep = solve_json(p)
    assert rc == 1 and rep["buildable"] is False
    # certified is the optimum's certificate (documented in docs/files.md): it implies verified, not usable; the
    # command's one rule says the cam is not usable and exits 1
    assert rep["failures"] and (not rep["optimize"]["certified"] or rep["verified"])


def test_bug_plot_optimized_without_free_phase_warns_on_stderr(tmp_path):
    """plot --only optimized with free = []: a matplotlib UserWarning (two lines) on stderr, exit 0."""
    p = design(tmp_path, TF, "[optimize]\nfree = []\n")
    r = cams_process("plot", p, "--out", tmp_path / "pics", "--only", "optimized")
    assert r.returncode == 0
    assert r.stderr == "", r.stderr


@pytest.mark.parametrize("example, subs", [
    ("rocker_force", (("roller_radius = 10.0 ", "roller_radius = 2.0 "), ('[solve]\nmethod = "exact"\n', ""))),
    ("translating_force", ()),
    ("translating_force", (("roller_radius = 8.0\n", "roller_radius = 8.0\noffset = 2.0\n"),)),
])
def test_least_pressure_angle_saved_keeps_its_cam(tmp_path, example, subs):
    """The least pressure angle holds the cam's size with its own centre: the saved design keeps that centre
    ([cam] centre; the offset or L it replaces dropped) and solves back to the same cam, not to the designed
    laws' smallest one (a regression: the saved file sized a smaller cam, which undercut)."""
    p = design(tmp_path, example, "[optimize]\nobjective = \"pressure_angle\"\nspans = 6\n", subs=subs)
    out = tmp_path / "saved.toml"
    first = cams("solve", p, "--json", "--save-design", out)
    assert first.returncode == 0, first.stdout + first.stderr
    again = cams("solve", out, "--json")
    assert again.returncode == 0, again.stdout + again.stderr
    a, b = json.loads(first.stdout), json.loads(again.stdout)
    assert b["R0"] == a["R0"] and b["centre"] == a["centre"]


def test_least_pressure_angle_with_no_limited_free_phase_says_so(tmp_path):
    p = design(tmp_path, "rocker_force", '[optimize]\nobjective = "pressure_angle"\nfree = ["return"]\nspans = 4\n',
               subs=(('[solve]\nmethod = "exact"\n', ""),))
    r = cams("solve", p, "--json")
    o = json.loads(r.stdout)["optimize"]
    assert o["value"] == pytest.approx(1.0, rel=1e-9)
    assert any("no free phase has a limited pressure angle" in n for n in o["notes"])
