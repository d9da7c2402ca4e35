"""The report's forces page at a rigid impact (a linear law): unbounded forces said so, never ``inf N`` or ``0 rpm``."""

from __future__ import annotations

from cams.cam import Cam
from cams.present.report import report_sections, write_report
from tests.conftest import EXAMPLES

FEED = EXAMPLES / "slotting_feed_cam.toml"


def forces_page(cam) -> dict:
    (rows,) = [rows for title, rows in report_sections(cam) if title == "Forces at the cam"]
    return dict(rows)


def test_linear_law_forces_are_unbounded_not_inf(linear_feed):
    cam = Cam.from_file(linear_feed)
    page = forces_page(cam)
    text = " ".join(page.values())
    assert "inf" not in text.replace("infinite", "")
    assert page["largest contact force"] == "unbounded (rigid impact at 0.0000 deg)"
    # the linear rise starts from the near dwell: the cam's impulse speeds the follower up, a driving torque
    assert page["camshaft torque"].startswith("largest driving torque unbounded (rigid impact at 0.0000 deg); "
                                              "largest braking torque ")
    assert page["smallest contact force"] == "unbounded negative: contact lost (rigid impact at 60.0000 deg)"
    assert page["jump speed"].startswith("any speed: the follower leaves the cam") and "60.0000 deg" in page["jump speed"]
    assert "0 rpm" not in page["jump speed"]
    bi = cam.forces.to_dict()["between_impacts"]
    assert f"contact force max {bi['max_contact_force']:.6g} N" in page["between the rigid impacts"]
    assert f"jump speed {bi['jump_rpm']:.6g} rpm" in page["between the rigid impacts"]
    assert page["contact lost / jammed"] == "yes / no"
    assert page["note"].startswith("rigid impacts")


def test_smooth_law_forces_are_numbers():
    cam = Cam.from_file(FEED)
    page = forces_page(cam)
    fo = cam.forces.to_dict()
    assert page["largest contact force"] == f"{fo['max_contact_force']:.6g} N at {fo['max_contact_at_deg']:.4f} deg"
    assert page["jump speed"] == f"{fo['jump_rpm']:.6g} rpm (first at {fo['jump_at_deg']:.4f} deg)"
    assert "between the rigid impacts" not in page and "note" not in page


def test_written_report_says_unbounded(linear_feed, tmp_path):
    page, _ = write_report(Cam.from_file(linear_feed), tmp_path / "out")
    html = page.read_text(encoding="utf-8")
    assert "unbounded (rigid impact at 0.0000 deg)" in html and "inf N" not in html
