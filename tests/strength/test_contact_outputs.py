"""The contact's picture and report section: cams plot --only contact draws p0 and the film the cam has (the
figure's lines hold the contact's arrays), refuses without [contact] in one line; the report has its section and
picture."""

from __future__ import annotations

import numpy as np
import pytest

from cams.cam import Cam
from cams.cli import main
from cams.io.designfile import load_design
from tests.conftest import EXAMPLES


@pytest.mark.parametrize("name", ["translating_contact.toml", "translating_flat_contact.toml"])
def test_plot_only_contact(name, tmp_path, capsys):
    capsys.readouterr()
    assert main(["plot", str(EXAMPLES / name), "--only", "contact", "--out", str(tmp_path), "--quiet"]) == 0
    written = capsys.readouterr().out.split()
    assert len(written) == 2 and all(p.endswith(("_contact.png", "_contact.svg")) for p in written)
    from cams.present.plots import plot_contact

    cam = Cam(load_design(EXAMPLES / name))
    fig = plot_contact(cam)
    ax_p, ax_h = fig.axes[:2]
    co = cam.contact
    o = np.argsort(np.degrees(co.phi))
    p_line = next(ln for ln in ax_p.get_lines() if ln.get_label() == "maximum Hertz pressure p0")
    h_line = next(ln for ln in ax_h.get_lines() if ln.get_label().startswith("minimum film thickness"))
    assert np.allclose(p_line.get_ydata(), co.pressure[o]) and np.allclose(h_line.get_ydata(), co.film[o])
    allow = next(ln for ln in ax_p.get_lines() if ln.get_label().startswith("allowable"))
    assert allow.get_ydata()[0] == co.materials.allowable


def test_plot_only_contact_without_a_contact_table(tmp_path, capsys):
    capsys.readouterr()
    assert main(["plot", str(EXAMPLES / "translating_force.toml"), "--only", "contact", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--only: contact: the design has no [contact] table" in err


@pytest.mark.parametrize("name", ["rocker_contact.toml", "translating_flat_contact.toml"])
def test_the_report_has_the_contact(name):
    from cams.present.faces import presenter

    cam = Cam(load_design(EXAMPLES / name))
    sections = dict(presenter(cam).report_sections(cam))
    rows = dict(sections["Contact stress, film and life"])
    assert rows["largest Hertz pressure p0"].startswith(f"{cam.contact.max_pressure:.6g} MPa at ")
    assert "contact modulus E*" in rows and "E' = 2 E*" in rows["contact modulus E*"]
    notes = [v for k, v in sections["Contact stress, film and life"] if k == "note"]
    assert any("unconservative" in n for n in notes)
    assert ("Contact stress and film", "contact") in presenter(cam).report_pictures
