"""cams.manufacture: CSV, DXF (read back with ezdxf), SVG (parsed as XML); atomic writes."""

from __future__ import annotations

import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import shapely
from shapely.geometry import LineString

from cams.io.files import check_output_path
from cams.manufacture.dxf import write_dxf
from cams.manufacture.points import csv_header, write_csv
from cams.manufacture.svg import write_svg
from cams.profile.roller import build_profile, default_bore_radius
from laws.errors import InputError


@pytest.fixture(scope="module")
def profiles(solved):
    return {n: build_profile(d, O) for n, (d, O) in solved.items()}


def _read_csv(path):
    with open(path, encoding="utf-8") as fh:
        header = fh.readline().strip()
    return header, np.loadtxt(path, delimiter=",", skiprows=1)


@pytest.mark.parametrize("name,groove", [("rocker_force", False), ("rocker_form", True),
                                          ("translating_force", False), ("translating_form_centric", True)])
def test_csv_header_rows_and_values(profiles, tmp_path, name, groove):
    prof = profiles[name]
    out = write_csv(prof, tmp_path / "cam.csv")
    header, data = _read_csv(out)
    cols = "phi_deg,pitch_x,pitch_y,work_x,work_y" + (",outer_x,outer_y" if groove else "")
    assert header == cols == csv_header(prof)
    assert data.shape == (len(prof), 7 if groove else 5)
    assert data[0, 0] == 0.0 and np.all(np.diff(data[:, 0]) > 0) and data[-1, 0] < 360
    assert np.allclose(data[0, 1:3], prof.pitch[0], atol=1e-9)
    assert np.hypot(*data[0, 1:3]) == pytest.approx(prof.R0, abs=1e-8)
    assert np.allclose(data[:, 3:5], prof.work, atol=1e-9)
    if groove:
        assert np.allclose(data[:, 5:7], prof.outer, atol=1e-9)
    assert sorted(os.listdir(tmp_path)) == ["cam.csv"]  # no temporary file left


@pytest.mark.parametrize("name", ["rocker_force", "rocker_form"])
def test_dxf_reads_back_and_matches_the_csv(profiles, tmp_path, name):
    import ezdxf

    prof = profiles[name]
    write_csv(prof, tmp_path / "cam.csv")
    # without a bore radius the file has no bore (a suggested bore is not a dimension); with one, it has
    write_dxf(prof, tmp_path / "nobore.dxf")
    assert "BORE" not in {lay.dxf.name for lay in ezdxf.readfile(tmp_path / "nobore.dxf").layers}
    write_dxf(prof, tmp_path / "cam.dxf", bore_radius=default_bore_radius(prof))
    _, data = _read_csv(tmp_path / "cam.csv")
    doc = ezdxf.readfile(tmp_path / "cam.dxf")
    assert doc.units == ezdxf.units.MM
    layers = {lay.dxf.name for lay in doc.layers}
    assert {"PROFILE", "PITCH", "BASE", "BORE"} <= layers
    msp = doc.modelspace()
    (work,) = msp.query('LWPOLYLINE[layer=="PROFILE"]')
    assert work.closed
    pts = np.array(work.get_points("xy"))
    assert len(pts) == len(data)
    # vertices equal the CSV's; the polylines lie within the chord tolerance of each other
    assert np.max(np.abs(pts - data[:, 3:5])) < 1e-8
    assert shapely.hausdorff_distance(LineString(pts), LineString(data[:, 3:5])) <= prof.tolerance
    (pitch,) = msp.query('LWPOLYLINE[layer=="PITCH"]')
    assert np.max(np.abs(np.array(pitch.get_points("xy")) - data[:, 1:3])) < 1e-8
    (base,) = msp.query('CIRCLE[layer=="BASE"]')
    (bore,) = msp.query('CIRCLE[layer=="BORE"]')
    assert base.dxf.radius == pytest.approx(prof.R0) and tuple(base.dxf.center)[:2] == (0, 0)
    assert bore.dxf.radius == pytest.approx(default_bore_radius(prof))
    assert bore.dxf.radius < prof.min_work_radius
    if prof.groove:
        (outer,) = msp.query('LWPOLYLINE[layer=="OUTER"]')
        assert np.max(np.abs(np.array(outer.get_points("xy")) - data[:, 5:7])) < 1e-8
    else:
        assert "OUTER" not in layers


def test_svg_parses_and_is_to_scale(profiles, tmp_path):
    prof = profiles["rocker_form"]
    write_svg(prof, tmp_path / "cam.svg", bore_radius=5.0)
    root = ET.parse(tmp_path / "cam.svg").getroot()
    ns = {"s": "http://www.w3.org/2000/svg"}
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    x0, y0, w, h = map(float, root.get("viewBox").split())
    # the page is the viewBox in mm: 1 user unit = 1 mm (numbers to 12 significant digits of the cam's size)
    assert root.get("width").endswith("mm") and root.get("height").endswith("mm")
    assert float(root.get("width")[:-2]) == w and float(root.get("height")[:-2]) == h
    ids = [g.get("id") for g in root.findall("s:g", ns)]
    assert ids[:5] == ["PROFILE", "OUTER", "PITCH", "BASE", "BORE"]
    d = root.find("s:g[@id='PROFILE']/s:path", ns).get("d")
    xy = np.array([[float(v) for v in p.strip(" MLZ").split(",")] for p in d.split(" L")])
    assert np.allclose(xy * [1, -1], prof.work, atol=1e-6)  # SVG's y points down
    assert float(root.find("s:g[@id='BORE']/s:circle", ns).get("r")) == 5.0
    # the drawing fits in the view box
    assert x0 < xy[:, 0].min() and xy[:, 0].max() < x0 + w and y0 < xy[:, 1].min() and xy[:, 1].max() < y0 + h


def test_unwritable_outputs_are_input_errors_and_leave_nothing(profiles, tmp_path):
    prof = profiles["translating_force"]
    missing = tmp_path / "no" / "such" / "cam.csv"
    for writer, field in ((write_csv, "--csv"), (write_dxf, "--dxf"), (write_svg, "--svg")):
        with pytest.raises(InputError, match=field):
            writer(prof, missing)
        with pytest.raises(InputError, match=field):
            writer(prof, tmp_path)  # a folder
    with pytest.raises(InputError, match="--csv"):
        check_output_path(missing, "--csv")
    assert os.listdir(tmp_path) == []


def test_a_failing_writer_leaves_no_partial_file(profiles, tmp_path, monkeypatch):
    prof = profiles["translating_force"]
    target = tmp_path / "cam.csv"
    target.write_text("old\n")

    def boom(*a, **k):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(np, "savetxt", boom)
    with pytest.raises(InputError, match="No space left"):
        write_csv(prof, target)
    assert sorted(os.listdir(tmp_path)) == ["cam.csv"] and target.read_text() == "old\n"


def test_bad_bore_radius(profiles, tmp_path):
    with pytest.raises(InputError, match="cam.bore_radius"):
        write_dxf(profiles["rocker_force"], tmp_path / "c.dxf", bore_radius=-1.0)
    assert os.listdir(tmp_path) == []
