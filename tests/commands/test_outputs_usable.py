"""One definition of a usable cam (cams.assess), the same answer from every command.

Five unbuildable designs, each failing for a reason checked here against an independent reference (a
numerical radius of curvature of the exported pitch curve, the exported profile's distance from the centre,
the jamming limit written out), go through solve, check, profile, plot and sweep: every one reports
``buildable`` false beside ``verified`` and exits 1; the manufacturing files are written only with
``--allow-failed`` and then marked as failing (never the CSV's columns); the pictures are drawn, titled as failing.
The undercut, the roller above R0 and the bore are sized by the pressure angle alone (``[solve] constraints =
"pressure_angle"``): sized to the part (the default) they would grow until they pass.
"""

import csv
import json
import shutil
import tomllib
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from tests.conftest import EXAMPLES

DATA = Path(__file__).resolve().parents[1] / "data"

#: A translating cam whose fast rise bends the pitch curve tighter than the roller (undercut), R0 > roller.
UNDERCUT = """name = "undercut cam"
[follower]
kind = "translating"
stroke = 30.0
roller_radius = 12.0
[cam]
rotation = "ccw"
[[motion]]
phase = "rise"
law = "cycloidal"
angle = 60
[[motion]]
phase = "return"
law = "cycloidal"
angle = 60
[[motion]]
phase = "dwell"
[limits]
pressure_angle = 60
closure = "force"
[solve]
constraints = "pressure_angle"
"""

#: The pressure angle alone sizes it: a cam that fails its profile's checks is kept, to be judged.
ALONE = '[solve]\nconstraints = "pressure_angle"\n'


def _designs(tmp_path) -> dict[str, Path]:
    rf = (EXAMPLES / "rocker_force.toml").read_text().replace("[solve]\n", ALONE)
    feed = (EXAMPLES / "slotting_feed_cam.toml").read_text()
    texts = {
        "undercut": UNDERCUT,
        "roller_above_R0": rf.replace("roller_radius = 10.0", "roller_radius = 20.0"),
        "bore": rf.replace("rpm = 60", "rpm = 60\nbore_radius = 30.0"),
        # friction 0.9 on a journal of 120 mm: the rocker jams above arccos(0.9 * 120 / 125) = 30.2 deg < 40 deg
        "dynamics": feed.replace("friction = 0.1", "friction = 0.9").replace("journal_radius = 8.0",
                                                                             "journal_radius = 120.0"),
    }
    out = {}
    for name, text in texts.items():
        assert text != rf or name == "undercut"
        p = tmp_path / f"{name}.toml"
        p.write_text(text)
        out[name] = p
    out["knife_groove"] = tmp_path / "knife_groove.toml"
    shutil.copy(DATA / "knife_groove.toml", out["knife_groove"])
    return out


@pytest.fixture
def designs(tmp_path):
    return _designs(tmp_path)


NAMES = ["undercut", "roller_above_R0", "bore", "knife_groove", "dynamics"]
#: What each must be refused for (the assessment's short names).
REASON = {"undercut": "undercut", "roller_above_R0": "no working profile", "bore": "bore",
          "knife_groove": "knife edge in a groove", "dynamics": "dynamics"}


def _json(capsys, *argv):
    rc = main([*map(str, argv), "--json"])
    return rc, json.loads(capsys.readouterr().out)


def _circumradius(P) -> np.ndarray:
    """Radius of the circle through each point and its two neighbours of a closed polyline (unsigned)."""
    a, b, c = np.roll(P, 1, axis=0), P, np.roll(P, -1, axis=0)
    ab, bc, ca = (np.linalg.norm(x - y, axis=1) for x, y in ((a, b), (b, c), (c, a)))
    cross = np.abs((b - a)[:, 0] * (c - b)[:, 1] - (b - a)[:, 1] * (c - b)[:, 0])
    with np.errstate(divide="ignore"):
        return ab * bc * ca / (2 * cross)


@pytest.mark.parametrize("name", NAMES)
def test_solve_and_check_say_not_buildable_and_exit_1(designs, capsys, name):
    f = designs[name]
    rc, sol = _json(capsys, "solve", f)
    assert rc == 1 and sol["verified"] is True and sol["buildable"] is False, sol["failures"]
    assert sol["failures"]
    rc, chk = _json(capsys, "check", f)
    assert rc == 1 and chk["verified"] is True and chk["buildable"] is False and chk["passed"] is False
    assert chk["failures"] == sol["failures"]  # one definition: the same reasons from both commands
    rc = main(["solve", str(f)])
    out = capsys.readouterr().out
    assert rc == 1 and "buildable: NO" in out


def test_each_failure_against_an_independent_reference(designs, capsys, tmp_path):
    # undercut: the exported pitch curve's smallest radius of curvature (three-point circles) is below the roller
    csv_path = tmp_path / "u.csv"
    assert main(["profile", str(designs["undercut"]), "--csv", str(csv_path), "--allow-failed",
                 "--tolerance", "1e-4"]) == 1
    capsys.readouterr()
    data = np.loadtxt(csv_path, delimiter=",", skiprows=1)
    rho = _circumradius(data[:, 1:3])
    assert rho.min() < 12.0 * 0.9 and np.linalg.norm(data[0, 1:3]) > 12.0  # undercut, yet R0 above the roller
    # roller above R0: R0 (the pitch curve's distance from the centre at the start) against the roller
    rc, sol = _json(capsys, "solve", designs["roller_above_R0"])
    assert sol["R0"] < 20.0 and any(s.startswith("no working profile") for s in sol["failures"])
    # bore: the exported working profile comes nearer the centre than the bore
    csv_path = tmp_path / "b.csv"
    assert main(["profile", str(designs["bore"]), "--csv", str(csv_path), "--allow-failed"]) == 1
    capsys.readouterr()
    work = np.loadtxt(csv_path, delimiter=",", skiprows=1)[:, 3:5]
    assert np.hypot(work[:, 0], work[:, 1]).min() < 30.0
    # dynamics: the rise's largest pressure angle above the rocker's jamming limit arccos(mu r_j / l)
    rc, sol = _json(capsys, "solve", designs["dynamics"])
    limit = np.degrees(np.arccos(0.9 * 120.0 / 125.0))
    assert sol["max_pressure_angle"]["rise"] > limit and sol["forces"]["jammed"] is True
    assert any(s.startswith("dynamics:") for s in sol["failures"])
    # knife groove: no roller and form closure, by the file's own keys
    with open(designs["knife_groove"], "rb") as fh:
        d = tomllib.load(fh)
    assert d["limits"]["closure"] == "form" and d["follower"].get("roller_radius", 0.0) == 0.0


@pytest.mark.parametrize("name", NAMES)
def test_profile_writes_nothing_unless_allowed_then_marks_dxf_and_svg(designs, capsys, tmp_path, name):
    f = designs[name]
    outs = {ext: tmp_path / f"cam.{ext}" for ext in ("csv", "dxf", "svg")}
    argv = ["profile", str(f)] + [a for ext, p in outs.items() for a in (f"--{ext}", str(p))]
    rc = main(argv)
    cap = capsys.readouterr()
    assert rc == 1 and "wrote" not in cap.out and "buildable: NO" in cap.out
    assert not any(p.exists() for p in outs.values())
    assert cap.err.startswith("cams profile: no file written: ") and cap.err.count("\n") == 1
    rc = main([*argv, "--allow-failed"])
    cap = capsys.readouterr()
    assert rc == 1
    if name == "knife_groove":  # no profile at all: nothing to write even when allowed
        assert not any(p.exists() for p in outs.values())
        return
    assert cap.out.count("wrote") == 3
    svg = outs["svg"].read_text()
    assert "<title>FAILED" in svg and "<desc>FAILED" in svg
    import ezdxf

    doc = ezdxf.readfile(outs["dxf"])
    assert "FAILED" in doc.layers
    assert any(e.dxf.layer == "FAILED" for e in doc.modelspace())
    assert doc.header.custom_vars.get("CAMS_STATUS").startswith("FAILED")
    rows = list(csv.reader(outs["csv"].open()))
    assert rows[0][0] == "phi_deg" and all(len(r) == len(rows[0]) for r in rows)  # the CSV is never marked
    assert all(float(x) == float(x) for r in rows[1:] for x in r)


def test_a_usable_cam_is_not_marked(capsys, tmp_path):
    svg, dxf = tmp_path / "ok.svg", tmp_path / "ok.dxf"
    assert main(["profile", str(EXAMPLES / "rocker_force.toml"), "--svg", str(svg), "--dxf", str(dxf)]) == 0
    capsys.readouterr()
    assert "FAILED" not in svg.read_text() and "FAILED" not in dxf.read_text()
    rc, sol = _json(capsys, "solve", EXAMPLES / "rocker_force.toml")
    assert rc == 0 and sol["buildable"] is True and sol["failures"] == []


@pytest.mark.parametrize("name", ["undercut", "knife_groove"])
def test_plot_draws_the_pictures_titled_failing_and_exits_1(designs, capsys, tmp_path, name, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    from cams.present import plots

    titles = []
    real = plots.mark_failing

    def spy(fig, title):
        titles.append(title)
        return real(fig, title)

    monkeypatch.setattr(plots, "mark_failing", spy)
    out = tmp_path / "pics"
    # drawn here (--jobs 1), where the spy sees them: a forked process's calls stay in that process
    rc = main(["plot", str(designs[name]), "--out", str(out), "--only", "pressure,profile", "--jobs", "1"])
    cap = capsys.readouterr()
    assert rc == 1 and "buildable: NO" in cap.out
    pngs = sorted(p.name for p in out.glob("*.png"))
    assert pngs and any(p.endswith("_pressure.png") for p in pngs)
    assert titles and all(t.startswith("FAILS: ") and REASON[name] in t for t in titles)


def test_sweep_counts_unbuildable_rows_and_exits_1(capsys, tmp_path):
    """Rows whose R0 is below the 20 mm roller are verified but not buildable: counted as infeasible, exit 1."""
    out = tmp_path / "s.csv"
    f = tmp_path / "d.toml"
    f.write_text((EXAMPLES / "rocker_force.toml").read_text().replace("roller_radius = 10.0", "roller_radius = 20.0")
                 .replace("[solve]\n", ALONE))
    rc = main(["sweep", str(f), "--vary", "limits.pressure_angle=40,45", "--out", str(out), "--jobs", "1",
               "--quiet"])
    err = capsys.readouterr().err
    rows = list(csv.DictReader(out.open()))
    assert all(float(r["R0_mm"]) < 20.0 for r in rows)  # no working profile in either row
    assert all(r["buildable"] == "False" and "no working profile" in r["failures"] for r in rows)
    assert rc == 1 and "(2 infeasible" in err
    # the same rows one by one: the same answer as cams solve
    for r in rows:
        g = tmp_path / "one.toml"
        g.write_text(f.read_text().replace("pressure_angle = 45", f"pressure_angle = {r['limits.pressure_angle']}"))
        rc1, sol = _json(capsys, "solve", g)
        assert rc1 == 1 and sol["failures"] == r["failures"].split("; ")


def test_sweep_checks_dynamics_as_solve_does(designs, capsys, tmp_path):
    out = tmp_path / "s.csv"
    rc = main(["sweep", str(designs["dynamics"]), "--vary", "limits.pressure_angle=40", "--out", str(out),
               "--jobs", "1", "--quiet"])
    capsys.readouterr()
    (row,) = list(csv.DictReader(out.open()))
    assert rc == 1 and row["buildable"] == "False" and row["failures"].startswith("dynamics:")


def test_report_reports_buildable_and_exits_1(designs, capsys, tmp_path):
    from cams.cam import Cam
    from cams.io.designfile import load_design
    from cams.present.report import report_sections

    cam = Cam(load_design(designs["bore"]))
    rows = dict(report_sections(cam)[1][1])
    assert rows["usable (verified and buildable)"] == "NO" and rows["fails"].startswith("bore")
    rc = main(["report", str(designs["knife_groove"]), "--out", str(tmp_path / "rep")])
    assert rc == 1 and "buildable: NO" in capsys.readouterr().out
    assert (tmp_path / "rep" / "report.pdf").exists()


def test_plot_animation_of_a_failing_cam_is_titled(designs, capsys, tmp_path, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    from cams.present import plots

    titles = []
    real = plots.mark_failing
    monkeypatch.setattr(plots, "mark_failing", lambda fig, title: titles.append(title) or real(fig, title))
    monkeypatch.setattr(plots.animate_profile, "__kwdefaults__", {"frames": 2, "fps": 12, "title": ""})
    # drawn here (--jobs 1), where the spy sees them: a forked process's calls stay in that process
    rc = main(["plot", str(designs["bore"]), "--out", str(tmp_path / "a"), "--only", "motion", "--animate",
               "--jobs", "1"])
    capsys.readouterr()
    assert rc == 1 and len(list((tmp_path / "a").glob("*_turn.gif"))) == 1
    assert titles and all(t == "FAILS: bore" for t in titles)


def test_a_result_that_is_not_certified_is_not_usable():
    """The exact method's bounds disagreeing (certified False) makes the cam unusable in every command's rule."""
    import dataclasses

    from cams.assess import assess
    from cams.cam import Cam
    from cams.io.designfile import load_design

    cam = Cam(load_design(EXAMPLES / "rocker_force.toml"))
    ok = assess(cam.design, cam.solution, checks=cam.checks)
    assert ok.usable and ok.certified and "certified" not in ok.to_dict()
    bad = dataclasses.replace(cam.solution, certified=False,
                              detail=dataclasses.replace(cam.solution.detail, error_bound=1e-3))
    a = assess(cam.design, bad, checks=cam.checks)
    assert not a.usable and not a.certified and a.verified and a.buildable
    assert a.to_dict()["certified"] is False
    assert a.failures[0] == "not certified: the exact method's bounds on the size differ by 0.001 mm"


@pytest.mark.parametrize("command", ["check", "profile"])
def test_a_not_certified_answer_is_never_printed_usable(tmp_path, capsys, monkeypatch, command):
    """``usable`` printed beside ``buildable`` is the exit code's rule (:attr:`Assessment.usable`): an exact answer whose
    bounds disagree is not usable even when it is verified and buildable."""
    import dataclasses

    import cams.solve as solve_module

    real = solve_module.solve
    monkeypatch.setattr(solve_module, "solve", lambda *a, **k: dataclasses.replace(real(*a, **k), certified=False))
    argv = [command, str(EXAMPLES / "rocker_force.toml")]
    if command == "profile":
        argv += ["--csv", str(tmp_path / "p.csv"), "--allow-failed"]
    code = main(argv)
    out = capsys.readouterr().out
    assert code == 1
    line = next(ln for ln in out.splitlines() if "usable:" in ln)
    assert "buildable: yes" in line and line.rstrip().endswith("usable: NO"), out
    assert "FAIL: not certified" in out


def test_sweep_counts_a_not_certified_row_as_failing(capsys, tmp_path, monkeypatch):
    """A row whose exact answer is not certified is not usable (:attr:`Assessment.usable`): counted, exit 1."""
    import dataclasses

    import cams.solve as solve_module
    from cams.io.document import read_toml
    from cams.sweep import sweep

    real = solve_module.solve
    monkeypatch.setattr(solve_module, "solve", lambda *a, **k: dataclasses.replace(real(*a, **k), certified=False))
    res = sweep(read_toml(EXAMPLES / "rocker_force.toml"), [("limits.pressure_angle", np.array([44.0, 45.0]))],
                workers=1, per_design=True)  # each design by itself: the path whose solve is patched
    assert all(r["verified"] and r["buildable"] and "not certified" in r["failures"] for r in res.rows)
    assert res.failed == 2


def test_a_roller_past_the_centre_has_no_smallest_radius_and_is_said_once(capsys, tmp_path):
    """A roller larger than R0: Rmin is 'none' (no negative radius), the missing base circle one FAIL line."""
    f = tmp_path / "d.toml"
    f.write_text((EXAMPLES / "rocker_force.toml").read_text().replace("roller_radius = 10.0", "roller_radius = 20.0")
                 .replace("[solve]\n", ALONE))
    rc = main(["solve", str(f)])
    out = capsys.readouterr().out
    rc_json = main(["solve", str(f), "--json"])
    rep = json.loads(capsys.readouterr().out)
    assert rc == rc_json == 1 and rep["R0"] < 20.0
    # the JSON keeps the signed value: the smallest pitch radius (about R0 here) less the roller
    assert rep["smallest_cam_radius"] < 0 and rep["smallest_cam_radius"] == pytest.approx(rep["R0"] - 20.0, abs=1e-6)
    (line,) = [ln for ln in out.splitlines() if ln.lstrip().startswith("Rmin")]
    assert "none: the roller reaches past the cam centre" in line
    assert sum("R0 = " in ln and "roller radius" in ln for ln in out.splitlines()) == 1
