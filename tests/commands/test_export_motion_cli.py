"""``cams profile``'s ``export_motion``: the motion each written drawing's curve gives, and ``--max-accel-error``.

The numbers are checked against the test's own follower: the drawing's points read with ezdxf and the largest
``s`` at which the roller comes within its radius of the polyline (distance to each segment, bisection), at the
same cam angles, against the law; the share against the cycloidal law's peak acceleration by hand.
"""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

from cams.cli import main
from tests.conftest import EXAMPLES

KEYS = {"format", "curve", "tolerance", "elements", "max_ds", "max_dv", "max_da", "max_da_ratio"}


def _run(capsys, *argv):
    # these measure the polyline (the roller rounding its vertices); the arcs and the spline: --curve given
    curve = () if "--curve" in argv else ("--curve", "polyline")
    rc = main(["profile", *map(str, argv), *curve])
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


@pytest.fixture
def translating(tmp_path):
    p = tmp_path / "tf.toml"
    shutil.copy(EXAMPLES / "translating_force.toml", p)
    return p


def _segment_distance(q: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance from points q (n, 2) to every segment a-b (m, 2): shape (n, m)."""
    d = b - a
    t = np.clip(((q[:, None, :] - a) * d).sum(-1) / (d * d).sum(-1), 0.0, 1.0)
    foot = a + t[..., None] * d
    return np.hypot(*(q[:, None, :] - foot).transpose(2, 0, 1))


def _brute_positions(pts: np.ndarray, centre: np.ndarray, r: float, phi: np.ndarray, cam_sense: int) -> np.ndarray:
    """The translating roller's largest touching s on the closed polyline ``pts`` (cam frame) at each angle: down
    from outside in steps under r to the first touch, then bisection on the nearest distance to the segments that
    come within r of the roller's line."""
    a, b = pts, np.roll(pts, -1, axis=0)
    out = np.empty(len(phi))
    top = float(np.max(np.hypot(*pts.T))) + r + float(np.hypot(*centre))
    for k, ph in enumerate(phi):
        c, s_ = np.cos(-cam_sense * ph), np.sin(-cam_sense * ph)
        q0 = np.array([c * -centre[0] - s_ * -centre[1], s_ * -centre[0] + c * -centre[1]])
        u = np.array([-s_, c])  # (0, 1) turned
        da = (a - q0) @ np.array([u[1], -u[0]])
        db = (b - q0) @ np.array([u[1], -u[0]])
        near = (np.minimum(np.abs(da), np.abs(db)) <= r) | (da * db < 0)
        aa, bb = a[near], b[near]

        def touching(s, aa=aa, bb=bb, q0=q0, u=u):
            return _segment_distance((q0 + s * u)[None, :], aa, bb).min() <= r

        lo = top
        while not touching(lo):
            lo -= 0.25 * r
        hi = lo + 0.25 * r
        for _ in range(55):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if touching(mid) else (lo, mid)
        out[k] = lo
    return out


def test_export_motion_json_against_brute_force(translating, tmp_path, capsys):
    import ezdxf

    from cams.cam import Cam
    from cams.kinematics.exported import check_angles

    rc, out, _ = _run(capsys, translating, "--dxf", tmp_path / "c.dxf", "--svg", tmp_path / "c.svg", "--json")
    assert rc == 0
    rep = json.loads(out)
    em = rep["export_motion"]
    assert [e["format"] for e in em] == ["dxf", "svg"]
    for e in em:
        assert set(e) == KEYS and e["curve"] == "polyline" and e["tolerance"] == rep["tolerance"]
    pl = next(iter(ezdxf.readfile(tmp_path / "c.dxf").modelspace().query('LWPOLYLINE[layer=="PROFILE"]')))
    pts = np.array([(x, y) for x, y in pl.get_points("xy")])
    assert em[0]["elements"] == len(pts) == rep["points"]
    cam = Cam.from_file(translating)
    d = cam.design
    phi = check_angles(d, len(pts))
    s = _brute_positions(
        pts, np.array([rep["centre"]["x"], rep["centre"]["y"]]), d.follower.roller_radius, phi, d.cam_sense
    )
    law = d.program.evaluate(phi)
    assert em[0]["max_ds"] == pytest.approx(float(np.max(np.abs(s - law.s))), abs=1e-9)
    assert em[1]["max_ds"] == pytest.approx(em[0]["max_ds"], abs=1e-8)
    # the largest acceleration of the law: poly4567's 7.5 h / beta^2 or the cycloidal's 2 pi h / beta^2 (by hand)
    peaks = []
    for ph in d.program.phases:
        if ph.law is None:
            continue
        k = {"cycloidal": 2 * np.pi, "poly4567": 7.5132}[ph.law.name]
        peaks.append(k * d.program.lift / ph.angle**2)
    assert em[0]["max_da_ratio"] == pytest.approx(em[0]["max_da"] / max(peaks), rel=1e-3)
    assert em[0]["max_da_ratio"] > 1  # a polyline: the roller rounds each vertex


def test_export_motion_text_has_units(tmp_path, capsys):
    rc, out, _ = _run(capsys, EXAMPLES / "rocker_force.toml", "--dxf", tmp_path / "r.dxf")
    assert rc == 0
    line = next(ln for ln in out.splitlines() if "the motion the DXF's polyline gives" in ln)
    for unit in (
        "tolerance 0.001 mm",
        "elements",
        " deg (",
        "deg/rad (",
        "deg/rad² (",
        "% of the law's lift",
        "% of the law's peak",
    ):
        assert unit in line
    rc, out, _ = _run(capsys, EXAMPLES / "rocker_force.toml", "--csv", tmp_path / "r.csv", "--json")
    assert json.loads(out)["export_motion"] == []  # a CSV holds points: no curve to follow


def test_stream_output_is_measured_on_a_copy(translating, tmp_path, capfd):
    rc = main(["profile", str(translating), "--svg", "-", "--json", "--curve", "polyline"])
    out, err = capfd.readouterr()
    assert rc == 0 and out.startswith("<?xml")
    em = json.loads(err)["export_motion"]
    assert len(em) == 1 and em[0]["format"] == "svg" and em[0]["curve"] == "polyline"


def test_max_accel_error_picks_the_coarsest(translating, tmp_path, capsys):
    from cams.profile.roller import MAX_TOLERANCE_FRACTION

    rc, out, _ = _run(capsys, translating, "--dxf", tmp_path / "c.dxf", "--json", "--max-accel-error", "1000")
    assert rc == 0
    rep = json.loads(out)
    e = rep["export_motion"][0]
    # every tolerance meets 1000 times the peak: the coarsest accepted, just inside 5 % of the smallest radius
    assert e["tolerance"] == pytest.approx(MAX_TOLERANCE_FRACTION * rep["smallest_cam_radius"], rel=2e-3)
    assert e["tolerance"] == rep["tolerance"] and e["max_da_ratio"] <= 1000
    assert (tmp_path / "c.dxf").exists()


def test_max_accel_error_a_polyline_cannot_meet(tmp_path, capsys):
    out_file = tmp_path / "f.dxf"
    rc, out, err = _run(capsys, EXAMPLES / "translating_flat.toml", "--dxf", out_file, "--max-accel-error", "0.05")
    assert rc == 2 and err.count("\n") == 1
    assert err.startswith(
        "cams profile: error: --max-accel-error: no polyline export keeps the acceleration error "
        "within 5 % of the law's peak"
    )
    assert "finest tolerance tried" in err and not out_file.exists()


@pytest.mark.parametrize(
    "argv, words",
    [
        (["--max-accel-error", "0.05"], "give --dxf OUT or --svg OUT too"),
        (["--dxf", "X", "--max-accel-error", "0.05", "--tolerance", "0.01"], "not both"),
        (["--dxf", "X", "--max-accel-error", "-1"], "must be a share"),
        (["--dxf", "X", "--max-accel-error", "nan"], "must be a share"),
    ],
)
def test_max_accel_error_bad_input(argv, words, tmp_path, capsys):
    argv = [str(tmp_path / "o.dxf") if a == "X" else a for a in argv]
    rc, _, err = _run(capsys, EXAMPLES / "translating_flat.toml", *argv)
    assert rc == 2 and err.count("\n") == 1 and "--max-accel-error" in err and words in err
    assert not (tmp_path / "o.dxf").exists()


def test_flat_face_export_motion_against_the_support(tmp_path, capsys):
    """A translating flat face touches the polyline at its support: s = max over the vertices of V . m - R0, m the
    face's normal (pi/2 - eps phi in the cam frame): the test's own, at the same angles."""
    import ezdxf

    from cams.cam import Cam
    from cams.kinematics.exported import check_angles

    src = EXAMPLES / "translating_flat.toml"
    rc, out, _ = _run(capsys, src, "--dxf", tmp_path / "f.dxf", "--json")
    assert rc == 0
    e = json.loads(out)["export_motion"][0]
    pl = next(iter(ezdxf.readfile(tmp_path / "f.dxf").modelspace().query('LWPOLYLINE[layer=="PROFILE"]')))
    pts = np.array([(x, y) for x, y in pl.get_points("xy")])
    cam = Cam.from_file(src)
    d = cam.design
    phi = check_angles(d, len(pts))
    th = np.pi / 2 - d.cam_sense * phi
    s = np.max(np.cos(th)[:, None] * pts[:, 0] + np.sin(th)[:, None] * pts[:, 1], axis=1) - cam.solution.R0
    assert e["max_ds"] == pytest.approx(float(np.max(np.abs(s - d.program.evaluate(phi).s))), abs=1e-12)
    assert e["elements"] == len(pts) and e["curve"] == "polyline"


def test_coarsest_tolerance_search():
    """Against an error that grows as the tolerance (share = tolerance): the coarsest tolerance found meets the
    share and is within the bisections' last step of it; a share nothing meets names the finest tried."""
    from cams.manufacture.motion import REFINE_STEPS, SEARCH_STEPS, Trial, coarsest_tolerance
    from laws.errors import InputError

    tried = []

    def evaluate(t):
        tried.append(t)
        return Trial(t, t, int(1 / t))

    got = coarsest_tolerance(evaluate, 1.0, 1e-3, 0.3, curve="arcs")
    step = (10 ** (1 / SEARCH_STEPS)) ** (1 / 2**REFINE_STEPS)  # the last bisection's ratio
    assert got.tolerance <= 0.3 < got.tolerance * step * (1 + 1e-12)
    with pytest.raises(InputError, match=r"no polyline export .* finest tolerance tried, 0\.001 mm \(1000 elements\)"):
        coarsest_tolerance(lambda t: Trial(t, 5.0, int(1 / t)), 1.0, 1e-3, 0.05, curve="polyline")


def test_an_svg_of_tangent_arcs_moves_the_follower_as_its_dxf(tmp_path, capsys):
    """The SVG writes the arcs' ends to 12 significant digits, which leaves kinks of about 1e-10 rad at their joints
    (the DXF's bulges share exact vertices). A roller resting on such a joint would read the vertex's curvature 1/r
    at the cam angles that fall on it (a phase start at a joint): 318 % of the law's peak on rocker_force, against
    the DXF's 12.8 %. A joint within SMOOTH_JOINT is smooth: both drawings give the same motion."""
    from cams.kinematics.exported import SMOOTH_JOINT, _joint_turns
    from cams.manufacture.readback import read_profile

    rc, out, _ = _run(capsys, EXAMPLES / "rocker_force.toml", "--dxf", tmp_path / "a.dxf", "--svg",
                      tmp_path / "a.svg", "--curve", "arcs", "--json")
    assert rc == 0
    dxf, svg = json.loads(out)["export_motion"]
    turns = _joint_turns(read_profile(tmp_path / "a.svg", "--svg"))
    assert 0 < turns.max() <= SMOOTH_JOINT  # the rounding kinks are there, and within the smooth joints' bound
    for key in ("max_ds", "max_dv", "max_da"):
        assert svg[key] == pytest.approx(dxf[key], rel=1e-6)
    assert svg["max_da_ratio"] < 1.0


def test_rocker_force_arcs_keep_the_motion_where_its_polyline_cannot(tmp_path, capsys):
    """Issue 25, done when: the arcs of rocker_force at the default tolerance move the follower within a few
    percent of the law's peak acceleration (their curvature kept near the curve's: curves.CURVATURE_SHARE), while
    the polyline's error, the roller rounding each vertex, is reported as what it is: several times the peak."""
    rc, out, _ = _run(capsys, EXAMPLES / "rocker_force.toml", "--dxf", tmp_path / "a.dxf", "--curve", "arcs", "--json")
    (arcs,) = json.loads(out)["export_motion"]
    rc2, out, _ = _run(capsys, EXAMPLES / "rocker_force.toml", "--dxf", tmp_path / "p.dxf", "--json")
    (poly,) = json.loads(out)["export_motion"]
    assert rc == rc2 == 0 and arcs["curve"] == "arcs" and poly["curve"] == "polyline"
    assert arcs["tolerance"] == poly["tolerance"] == pytest.approx(0.001)
    assert arcs["max_da_ratio"] < 0.05 < 1.0 < poly["max_da_ratio"]


def test_a_failing_cam_written_anyway_is_not_followed(tmp_path, capsys):
    """--allow-failed writes an undercut cam's drawings, marked; their curve is not a cam's working profile, so no
    motion is measured on it (export_motion is empty)."""
    from tests.commands.test_outputs_usable import UNDERCUT

    f = tmp_path / "undercut.toml"
    f.write_text(UNDERCUT, encoding="utf-8")
    rc, out, _ = _run(capsys, f, "--dxf", tmp_path / "u.dxf", "--allow-failed", "--json")
    rep = json.loads(out)
    assert rc == 1 and (tmp_path / "u.dxf").exists() and rep["export_motion"] == []
