"""``cams plot``, ``report`` and ``new`` as a user runs them."""

import shutil
import subprocess
import sys

import pytest

from cams.cli import build_parser, main
from cams.io.designfile import load_design
from tests.conftest import EXAMPLES


def test_plot_only_what_is_asked(tmp_path, capsys):
    assert main(["plot", str(EXAMPLES / "rocker_force.toml"), "--out", str(tmp_path), "--only", "motion"]) == 0
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["rocker_cam_force_closure_motion.png", "rocker_cam_force_closure_motion.svg"]


def test_plot_bad_picture_name(tmp_path, capsys):
    assert main(["plot", str(EXAMPLES / "rocker_force.toml"), "--out", str(tmp_path), "--only", "cake"]) == 2
    assert "--only" in capsys.readouterr().err


@pytest.mark.parametrize("example", sorted(p.name for p in EXAMPLES.glob("*.toml")))
def test_report_html_and_pdf(tmp_path, capsys, example):
    rc = main(["report", str(EXAMPLES / example), "--out", str(tmp_path)])
    assert rc == 0
    html = (tmp_path / "report.html").read_text()
    for word in ("Inputs", "Results", "Checks", "base radius R0", "data:image/svg+xml;base64,"):
        assert word in html
    import pdfplumber  # the test extra installs it

    from cams.cam import Cam

    cam = Cam.from_file(EXAMPLES / example)
    pictures = 4 + (cam.forces is not None if cam.design.dynamics is not None else 0)  # forces with [dynamics]
    pictures += getattr(cam.solution, "optimization", None) is not None  # a motion design adds its own
    pictures += cam.design.contact is not None and cam.contact is not None  # [contact]: p0 and the film
    pictures += cam.vibration is not None  # a follower train's vibration
    pdf = (tmp_path / "report.pdf").read_bytes()
    assert pdf[:5] == b"%PDF-"
    with pdfplumber.open(tmp_path / "report.pdf") as doc:
        pages = len(doc.pages)
        text = "\n".join(page.extract_text() for page in doc.pages)
    assert pages >= 2 and text.split("\n")[1].startswith("PASS")  # after the running header: the banner
    for title in ("Inputs", "Results", "Blank", "Lift table", "Checks", "Motion diagrams", "Cam profile"):
        assert title in text
    assert html.count("data:image/svg+xml;base64,") == pictures
    if shutil.which("pdftoppm"):
        r = subprocess.run(["pdftoppm", "-png", "-r", "30", str(tmp_path / "report.pdf"), str(tmp_path / "pg")],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        assert len(list(tmp_path.glob("pg-*.png"))) == pages


def test_new_writes_a_design_that_solves(tmp_path, capsys):
    for kind in ("rocker", "translating"):
        out = tmp_path / f"{kind}.toml"
        assert main(["new", kind, "--out", str(out)]) == 0
        d = load_design(out)
        assert d.follower.kind == kind
    assert main(["new", "rocker", "--out", str(tmp_path / "rocker.toml")]) == 2
    assert "exists" in capsys.readouterr().err


def test_every_help_fits_a_terminal_and_shows_an_example():
    p = build_parser()
    text = p.format_help()
    assert "example:" in text
    sub = next(a for a in p._actions if a.__class__.__name__ == "_SubParsersAction")
    for name, sp in sub.choices.items():
        h = sp.format_help()
        assert "example: cams " + name in h, name
        assert len(h.splitlines()) <= 40 and max(len(line) for line in h.splitlines()) <= 100


def test_no_command_prints_help_and_exits_2():
    r = subprocess.run([sys.executable, "-m", "cams.cli"], capture_output=True, text=True)
    assert r.returncode == 2 and "COMMAND" in r.stdout


def test_written_files_have_the_usual_permissions(tmp_path):
    import os
    import stat

    assert main(["new", "rocker", "--out", str(tmp_path / "a.toml")]) == 0
    mode = stat.S_IMODE(os.stat(tmp_path / "a.toml").st_mode)
    m = os.umask(0)
    os.umask(m)
    assert mode == 0o666 & ~m


def test_animation_gif(tmp_path):
    from cams.cam import Cam
    from cams.present.plots import animate_profile

    p = animate_profile(Cam.from_file(EXAMPLES / "translating_force.toml"), tmp_path / "a.gif", frames=4)
    data = p.read_bytes()
    assert data[:6] in (b"GIF89a", b"GIF87a")
    from PIL import Image

    with Image.open(p) as im:
        assert im.n_frames == 4


def test_ctrl_c_is_one_line_with_the_shells_code(monkeypatch, capsys):
    """Ctrl-C in any command: `cams CMD: interrupted` and exit code 130, no traceback."""
    import cams.commands.laws as laws_cmd
    from cams.cli import main

    def interrupted(args):
        raise KeyboardInterrupt

    monkeypatch.setattr(laws_cmd, "run", interrupted)
    assert main(["laws"]) == 130
    assert capsys.readouterr().err == "cams laws: interrupted\n"
