"""``cams plot`` and ``cams report``: a failure leaves no picture or page behind; ``--only`` checked."""

import os
import shutil

import pytest

from cams.cli import main
from tests.conftest import EXAMPLES


@pytest.fixture
def unsolvable(tmp_path):
    """A design that loads (its motion can be drawn) but has no feasible cam centre."""
    text = (EXAMPLES / "rocker_force.toml").read_text()
    text = text.replace("swing = 15.0", "swing = 170.0").replace('closure = "force"', 'closure = "form"')
    p = tmp_path / "bad.toml"
    p.write_text(text)
    return p


def _run(capsys, *argv):
    rc = main([*map(str, argv)])
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


@pytest.mark.parametrize("exists", [False, True])
def test_plot_leaves_no_picture_when_a_later_one_fails(tmp_path, capsys, unsolvable, exists):
    out = tmp_path / "pics"
    if exists:
        out.mkdir()
    rc, stdout, err = _run(capsys, "plot", unsolvable, "--out", out)
    assert rc == 2 and err.startswith("cams plot: error: limits.") and err.count("\n") == 1
    assert stdout == ""
    if exists:
        assert os.listdir(out) == []
    else:
        assert not out.exists()  # the folder it made is removed again
    assert sorted(os.listdir(tmp_path)) == (["bad.toml", "pics"] if exists else ["bad.toml"])


def test_plot_writes_everything_when_nothing_fails(tmp_path, capsys):
    rc, stdout, _ = _run(capsys, "plot", EXAMPLES / "rocker_force.toml", "--out", tmp_path / "a" / "b",
                         "--only", "motion, profile")
    assert rc == 0
    names = sorted(os.listdir(tmp_path / "a" / "b"))
    assert names == [f"rocker_cam_force_closure_{w}.{e}" for w in ("motion", "profile") for e in ("png", "svg")]
    assert len(stdout.splitlines()) == 4


@pytest.mark.parametrize("only", ["", ",", "zone,", ",motion", "motion,,zone", " "])
def test_plot_empty_only_entry_is_refused(tmp_path, capsys, only):
    rc, _, err = _run(capsys, "plot", EXAMPLES / "rocker_force.toml", "--out", tmp_path, "--only", only)
    assert rc == 2 and err.startswith("cams plot: error: --only: ") and "empty" in err
    for name in ("motion", "zone", "pressure", "curvature", "profile"):
        assert name in err
    assert os.listdir(tmp_path) == []


def test_plot_unknown_only_entry_lists_the_pictures(tmp_path, capsys):
    rc, _, err = _run(capsys, "plot", EXAMPLES / "rocker_force.toml", "--out", tmp_path, "--only", "motion,cake")
    assert rc == 2 and "--only: 'cake'" in err and "motion, zone, pressure, curvature, profile" in err
    assert os.listdir(tmp_path) == []


def test_report_refuses_an_output_that_is_a_folder_before_computing(tmp_path, capsys):
    (tmp_path / "report.html").mkdir()
    rc, stdout, err = _run(capsys, "report", EXAMPLES / "rocker_force.toml", "--out", tmp_path)
    assert rc == 2 and err.startswith("cams report: error: --out: ") and "folder" in err and err.count("\n") == 1
    assert stdout == ""
    assert os.listdir(tmp_path) == ["report.html"] and os.listdir(tmp_path / "report.html") == []
    rc, _, err = _run(capsys, "report", EXAMPLES / "rocker_force.toml", "--out", "")
    assert rc == 2 and "--out" in err and "empty" in err


def test_report_leaves_no_pdf_when_the_html_fails(tmp_path, capsys, monkeypatch):
    """The disk fills up while the page is written: the PDF, written first, must not remain."""
    import cams.present.report

    def full_disk(*a, **k):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(cams.present.report.base64, "b64encode", full_disk)
    rc, stdout, err = _run(capsys, "report", EXAMPLES / "rocker_force.toml", "--out", tmp_path / "r")
    assert rc == 2 and err.startswith("cams report: error: --out: ") and "No space" in err
    assert stdout == ""
    assert os.listdir(tmp_path) == []


def test_report_of_an_unsolvable_design_leaves_nothing(tmp_path, capsys, unsolvable):
    rc, _, err = _run(capsys, "report", unsolvable, "--out", tmp_path / "rep")
    assert rc == 2 and "limits." in err
    assert sorted(os.listdir(tmp_path)) == ["bad.toml"]


def test_report_writes_both(tmp_path, capsys):
    shutil.copy(EXAMPLES / "translating_force.toml", tmp_path / "t.toml")
    rc, stdout, _ = _run(capsys, "report", tmp_path / "t.toml", "--out", tmp_path / "r")
    assert rc in (0, 1)
    assert sorted(os.listdir(tmp_path / "r")) == ["report.html", "report.pdf"]
    assert len(stdout.splitlines()) == 2
