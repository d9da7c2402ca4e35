"""The report's new tables against what they summarize, computed another way: the ``[dynamics]`` inputs as the file
gives them, the blank's radii against the lift table's own sampling, the lift table's ranges against the design
(the stroke or swing) and the exact extremes of the solve report."""

from __future__ import annotations

import re

import numpy as np
import pytest

from cams.cam import Cam
from cams.present.report import report_sections
from tests.conftest import EXAMPLES


def _section(cam, title: str) -> dict:
    (rows,) = [rows for t, rows in report_sections(cam) if t == title]
    return dict(rows)


def _range(text: str) -> tuple[float, float, str]:
    m = re.fullmatch(r"(\S+) to (\S+) (mm|deg)", text)
    assert m, text
    return float(m.group(1)), float(m.group(2)), m.group(3)


def test_dynamics_inputs_are_the_files():
    inputs = _section(Cam.from_file(EXAMPLES / "slotting_feed_cam.toml"), "Inputs")
    # the file: mass 0.003 (kg m^2, a rocker), load 0.5 (N m), spring_rate 3.0, margin 1.5, friction 0.1, journal 8
    assert inputs["[dynamics] moment of inertia about the pivot"] == "0.003 kg m²"
    assert inputs["[dynamics] load opposing the rise"] == "0.5 N m"
    assert inputs["[dynamics] closing spring"] == "rate 3 N m/rad, preload chosen for the contact margin"
    assert inputs["[dynamics] contact margin"] == "1.5"
    assert inputs["[dynamics] friction μ in the pivot"] == "0.1"
    assert inputs["[dynamics] pivot journal radius"] == "8 mm"
    assert not any(k.startswith("[dynamics]") for k in _section(Cam.from_file(EXAMPLES / "rocker_form.toml"),
                                                                "Inputs"))


@pytest.mark.parametrize("name, lift, unit", [("translating_force", 30.0, "mm"), ("slotting_feed_cam", 15.0, "deg"),
                                              ("translating_flat", 20.0, "mm"), ("rocker_flat", 15.0, "deg")])
def test_lift_table_summary_against_the_design_and_the_blank(name, lift, unit):
    cam = Cam.from_file(EXAMPLES / f"{name}.toml")
    table = _section(cam, "Lift table")
    assert table["rows"].startswith("360, one every 1 deg")
    key = "lift_mm range" if unit == "mm" else "lift_deg range"
    lo, hi, u = _range(table[key])
    assert u == unit and lo == 0.0
    assert hi == pytest.approx(lift, rel=1e-6)  # the file's stroke (mm) or swing (deg), at the far dwell
    # the working profile's radius, sampled every degree, within the blank's exact extremes and near them
    r = cam.solution.to_dict()
    wlo, whi, u = _range(table["work_r_mm range"])
    assert u == "mm"
    small, big = r["smallest_cam_radius"], r["largest_cam_radius"]
    assert small - 1e-5 * big <= wlo <= small + 1e-3 * big
    assert big - 1e-3 * big <= whi <= big + 1e-5 * big
    blank = _section(cam, "Blank")
    assert blank["the cam's largest radius (blank diameter)"].startswith(f"{big:.6f} mm ({2 * big:.6f} mm) at ")
    assert blank["the cam's smallest radius"].startswith(f"{small:.6f} mm at ")


def test_flat_face_smallest_radius_of_curvature_in_the_table_is_the_sampled_minimum():
    cam = Cam.from_file(EXAMPLES / "translating_flat.toml")
    row = _section(cam, "Lift table")["rho_work_mm smallest |ρ|"]
    m = re.fullmatch(r"(\S+) mm at (\S+) deg \(convex there\)", row)
    assert m, row
    rho, at = float(m.group(1)), float(m.group(2))
    sol = cam.solution  # the exact minimum (a search over the cam angle) is below the 1-degree samples' and near
    assert sol.min_rho <= rho <= sol.min_rho * 1.01
    assert abs(at - np.degrees(sol.min_rho_at) % 360) <= 1.0
