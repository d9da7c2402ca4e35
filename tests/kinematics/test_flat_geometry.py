"""Flat-faced followers from design files, against brute force independent of cams.profile.flat.

The brute force knows only the mechanism: the face is a line that the motion
program (laws' evaluation) places in the fixed frame; turned into the cam's
frame, consecutive lines intersect in the vertices of the cam (the envelope),
and an edge's length over the turn of its line is the radius of curvature.
The exported profile (``cams profile --csv``) is checked on its own: its
points' circumradii, and that at every cam angle the face touches it without
cutting into it.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import load_design
from tests.conftest import EXAMPLES

TRANSLATING = EXAMPLES / "translating_flat.toml"
ROCKER = EXAMPLES / "rocker_flat.toml"


def _json(capsys, *argv) -> tuple[int, dict]:
    rc = main([*argv, "--json"])
    return rc, json.loads(capsys.readouterr().out)


def _with(path, tmp_path, name, **tables) -> str:
    """A copy of a design file with lines added to its tables (``cam="base_radius = 20"``)."""
    text = path.read_text(encoding="utf-8")
    for table, line in tables.items():
        text = text.replace(f"[{table}]\n", f"[{table}]\n{line}\n", 1)
    out = tmp_path / name
    out.write_text(text, encoding="utf-8")
    return str(out)


def _dense_motion(prog, n=20_000):
    """Cam angle and motion on a dense grid, each phase with both its ends (one-sided values)."""
    phi, s, ds, d2s = [], [], [], []
    for i, p in enumerate(prog.phases):
        u = np.linspace(0.0, 1.0, max(int(n * p.angle / (2 * np.pi)), 50))
        m = prog.evaluate_phase(i, u)
        phi.append(prog.starts[i] + u * p.angle)
        s.append(m.s)
        ds.append(m.ds)
        d2s.append(m.d2s)
    return tuple(np.concatenate(v) for v in (phi, s, ds, d2s))


def _face_lines(design, R0, phi):
    """The face lines in the cam frame: normal angles theta and distances p from the cam centre.

    Translating: the face is the line y = s of the follower's frame, the cam
    centre at (-e, -R0). Rocker: pivot at the origin, cam centre at (L, 0),
    the face the line m . X = f with m = (cos a, sin a), a = a0 + sigma psi,
    touching the base circle at psi = 0 and moving away from the cam as psi grows.
    The cam frame turns with the cam: a fixed direction at angle b is b - eps phi there.
    """
    f_ = design.follower
    eps = design.cam_sense
    s = design.program.evaluate(phi).s
    if f_.kind == "translating":
        return np.pi / 2 - eps * phi, R0 + s
    L, f, sigma = f_.centre_distance, f_.face_offset, f_.sense
    a0 = sigma * np.arccos((f - R0) / L)
    a = a0 + sigma * s
    return a - eps * phi, f - L * np.cos(a)


def _vertices(th, p):
    """Vertex k of the envelope: the intersection of line k (normal angle th, distance p) with line k + 1."""
    n1 = np.stack([np.cos(th), np.sin(th)], axis=1)
    n2 = np.roll(n1, -1, axis=0)
    p2 = np.roll(p, -1)
    det = n1[:, 0] * n2[:, 1] - n1[:, 1] * n2[:, 0]
    return np.stack([(p * n2[:, 1] - p2 * n1[:, 1]) / det, (n1[:, 0] * p2 - n2[:, 0] * p) / det], axis=1)


def _brute_rho(design, R0, n=200_000):
    """Smallest radius of curvature of the envelope of n face lines (vertices of consecutive lines)."""
    phi = np.linspace(0, 2 * np.pi, n, endpoint=False)
    th, p = _face_lines(design, R0, phi)
    W = _vertices(th, p)
    edge = W - np.roll(W, 1, axis=0)  # on line k, from its vertex with line k-1 to the one with line k+1
    t = np.stack([-np.sin(th), np.cos(th)], axis=1)
    dth = np.angle(np.exp(1j * (np.roll(th, -1) - np.roll(th, 1)))) / 2
    rho = np.sum(edge * t, axis=1) / dth
    return float(rho.min()), phi[int(np.argmin(rho))]


def _csv(path) -> tuple[np.ndarray, np.ndarray]:
    with open(path, encoding="utf-8") as fh:
        assert fh.readline().strip() == "phi_deg,work_x,work_y"
        data = np.loadtxt(fh, delimiter=",")
    return np.radians(data[:, 0]), data[:, 1:]


def _circumradius(P) -> np.ndarray:
    """Radius of the circle through each point and its two neighbours (closed curve), signed by turn."""
    a, b, c = np.roll(P, 1, axis=0), P, np.roll(P, -1, axis=0)
    ab, bc, ca = (np.linalg.norm(x - y, axis=1) for x, y in ((a, b), (b, c), (c, a)))
    cross = (b - a)[:, 0] * (c - b)[:, 1] - (b - a)[:, 1] * (c - b)[:, 0]
    return ab * bc * ca / (2 * cross)


def _export(tmp_path, capsys, file, name="cam.csv", *, tolerance, failing=False):
    """The exported profile; a failing cam's is refused (exit 1, no file) unless asked for with --allow-failed."""
    out = tmp_path / name
    argv = ["profile", str(file), "--csv", str(out), "--tolerance", tolerance]
    if failing:
        assert main(argv) == 1 and not out.exists()
        assert main([*argv, "--allow-failed"]) == 1
    else:
        assert main(argv) == 0
    capsys.readouterr()
    return _csv(out)


def test_translating_minimum_is_the_textbook_condition(capsys):
    rc, rep = _json(capsys, "solve", str(TRANSLATING))
    assert rc == 0
    d = load_design(TRANSLATING)
    _, s, ds, d2s = _dense_motion(d.program, 400_000)
    textbook = rep["min_radius"] - np.min(s + d2s)  # R0 >= rho_min - min(s + s'')
    assert rep["min_radius"] == 10.0
    assert rep["R0"] == pytest.approx(textbook, abs=1e-7)
    assert rep["R0_min"] == rep["R0"] and rep["R0_source"] == "convexity"
    # the face: the contact lies at x = -e + eps s' (e = 0, ccw): both sides of its travel
    assert rep["face_range"]["from"] == pytest.approx(ds.min(), abs=1e-7)
    assert rep["face_range"]["to"] == pytest.approx(ds.max(), abs=1e-7)
    assert rep["face_width"] == pytest.approx(ds.max() - ds.min(), abs=1e-7)
    assert rep["face_width_centred"] == pytest.approx(2 * np.max(np.abs(ds)), abs=1e-7)
    assert rep["pressure_angle"] == {"min": 0.0, "max": 0.0, "max_at_deg": 0.0}


@pytest.mark.parametrize("file", [TRANSLATING, ROCKER], ids=["translating", "rocker"])
def test_minimum_base_radius_against_the_envelope_of_the_face_lines(capsys, file):
    rc, rep = _json(capsys, "solve", str(file))
    assert rc == 0 and rep["verified"]
    d = load_design(file)
    R0, rmin = rep["R0"], rep["min_radius"]
    at_min, where = _brute_rho(d, R0)
    assert at_min == pytest.approx(rmin, rel=1e-4)
    assert np.degrees(where) == pytest.approx(rep["binding_deg"], abs=0.1)
    assert rep["min_rho"] == pytest.approx(rmin, abs=1e-9)
    assert rep["min_rho_at_deg"] == pytest.approx(rep["binding_deg"])
    assert _brute_rho(d, R0 - 0.02 * rmin)[0] < rmin - 0.005 * rmin  # slightly smaller: not convex enough
    assert _brute_rho(d, R0 + 0.02 * rmin)[0] > rmin


@pytest.mark.parametrize("file", [TRANSLATING, ROCKER], ids=["translating", "rocker"])
def test_exported_profile_curvature_and_face_contact(tmp_path, capsys, file):
    rc, rep = _json(capsys, "solve", str(file))
    d = load_design(file)
    rmin = rep["min_radius"]
    # circumradii of three neighbours: a chord tolerance of 0.1 um keeps both the discretization and
    # the CSV's 1e-9 mm rounding (amplified by rho^2 / spacing^2) near 1e-4 of rho
    phi, P = _export(tmp_path, capsys, file, tolerance="1e-4")
    assert phi[0] == 0.0 and np.all(np.diff(phi) > 0)
    rho = _circumradius(P)
    # the profile runs round in the sense opposite to the cam's: convex means turning that way
    rho = -d.cam_sense * rho
    assert rho.min() == pytest.approx(rmin, rel=3e-4)
    assert np.linalg.norm(P[0]) == pytest.approx(rep["R0"], abs=1e-8)  # the face touches the base circle at 0
    phi, P = _export(tmp_path, capsys, file, tolerance="1e-5")

    # the face touches the exported cam at every cam angle without cutting it, and the touching
    # points travel over the face range the solve reports
    f_ = d.follower
    check = np.linspace(0, 2 * np.pi, 2000, endpoint=False)
    th, p = _face_lines(d, rep["R0"], check)
    n = np.stack([np.cos(th), np.sin(th)], axis=1)
    proj = P @ n.T  # (points, angles): support of the cam in the face's normal direction
    k = np.argmax(proj, axis=0)
    assert np.max(np.abs(proj[k, np.arange(len(check))] - p)) < 2e-5 * rep["R0"]
    touch = P[k]
    tangent = np.stack([-np.sin(th), np.cos(th)], axis=1)
    if f_.kind == "translating":
        # along the face (+X of the follower's frame: -t in the cam frame) from the axis through O + (e, 0)
        along = np.sum(touch * -tangent, axis=1) - f_.offset
    else:
        # along the face from the pivot's foot, positive towards the cam: the cam centre is at -L sin(a)
        # along J m from the foot, hence the sign -sigma
        a = th + d.cam_sense * check
        along = -f_.sense * (np.sum(touch * tangent, axis=1) - f_.centre_distance * np.sin(a))
    spacing = np.max(np.linalg.norm(np.diff(P, axis=0), axis=1))
    fr = rep["face_range"]
    assert along.min() == pytest.approx(fr["from"], abs=spacing)
    assert along.max() == pytest.approx(fr["to"], abs=spacing)
    assert rep["face_width"] == pytest.approx(along.max() - along.min(), abs=2 * spacing)


@pytest.mark.parametrize("file", [TRANSLATING, ROCKER], ids=["translating", "rocker"])
def test_a_smaller_chosen_base_radius_fails_the_check(tmp_path, capsys, file):
    rc, rep = _json(capsys, "solve", str(file))
    R0, rmin = rep["R0"], rep["min_radius"]
    small = _with(file, tmp_path, "small.toml", cam=f"base_radius = {R0 - 0.02 * rmin!r}")
    rc, chk = _json(capsys, "check", small)
    assert rc == 1 and not chk["passed"]
    conv = next(c for c in chk["checks"] if c["name"] == "convexity")
    assert not conv["passed"] and conv["worst"] < rmin and conv["limit"] == rmin
    rc, sol = _json(capsys, "solve", small)
    assert rc == 1 and not sol["verified"] and sol["R0"] == pytest.approx(R0 - 0.02 * rmin)
    assert sol["R0_source"] == "cam.base_radius" and sol["R0_min"] == pytest.approx(R0, abs=1e-9)
    # the exported profile of the smaller cam: its points' radii of curvature go below the limit
    phi, P = _export(tmp_path, capsys, small, "small.csv", tolerance="1e-4", failing=True)
    rho = -load_design(small).cam_sense * _circumradius(P)
    assert rho.min() < rmin - 0.005 * rmin
    assert rho.min() == pytest.approx(conv["worst"], rel=3e-4)
    # and a larger one passes
    big = _with(file, tmp_path, "big.toml", cam=f"base_radius = {R0 + 1.0!r}")
    assert main(["check", big]) == 0
    capsys.readouterr()


def test_a_velocity_drop_is_a_cusp_whatever_the_size(tmp_path, capsys):
    """A constant-velocity rise: its start is a straight edge, its end a cusp (negative edge) at any R0."""
    text = TRANSLATING.read_text(encoding="utf-8").replace('law = "cycloidal"', 'law = "linear"')
    f = tmp_path / "linear.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "motion[1]" in err and "cusp" in err and "120" in err
    d = load_design(f)
    assert _brute_rho(d, 1000.0, n=7200)[0] < -1e3  # swallowtail at the end of the rise, even for a huge cam


# -- every sense and offset: cam rotation, the rocker's rise direction, face and axis offsets ----------------

SENSE = {"ccw": 1, "cw": -1}
ROCKER_CASES = [(rot, rise, f) for rot in ("ccw", "cw") for rise in ("cw", "ccw") for f in (0.0, 20.0, -20.0)]
TRANSLATING_CASES = [(rot, e) for rot in ("ccw", "cw") for e in (0.0, 5.0, -5.0)]


def _variant(path, tmp_path, **keys) -> str:
    """A copy of a design file with its ``key = value`` lines replaced (each key must be there once)."""
    text = path.read_text(encoding="utf-8")
    for key, value in keys.items():
        text, n = re.subn(rf"(?m)^{key}\s*=.*$", f"{key} = {value}", text)
        assert n == 1, key
    out = tmp_path / f"{path.stem}_variant.toml"
    out.write_text(text, encoding="utf-8")
    return str(out)


def _brute_contact(design, R0, n):
    """Contact points of the envelope of n face lines, in the fixed frame.

    The contact on line k is the middle of its edge (its vertices with lines
    k - 1 and k + 1), turned back from the cam frame to the fixed frame
    (a cam-frame vector w is R(eps phi) w there) and placed at the cam centre
    O: (-e, -R0) translating, (L, 0) rocker. Returns the cam angles, the
    contact points X, the face normals m (fixed frame), the cam centre and the
    face's fixed-frame normal angle a = theta + eps phi.
    """
    phi = np.linspace(0, 2 * np.pi, n, endpoint=False)
    th, p = _face_lines(design, R0, phi)
    W = _vertices(th, p)
    M = 0.5 * (W + np.roll(W, 1, axis=0))  # on line k
    eps = design.cam_sense
    c, s = np.cos(eps * phi), np.sin(eps * phi)
    f_ = design.follower
    O = np.array([-f_.offset, -R0]) if f_.kind == "translating" else np.array([f_.centre_distance, 0.0])
    X = O + np.stack([c * M[:, 0] - s * M[:, 1], s * M[:, 0] + c * M[:, 1]], axis=1)
    a = th + eps * phi
    m = np.stack([np.cos(a), np.sin(a)], axis=1)
    return phi, X, m, O, a


def _angle_diff_deg(x, y) -> float:
    return abs((x - y + 180.0) % 360.0 - 180.0)


def _check_sizing(rep, d, n):
    """R0 is the brute force's minimum: rho_min = min_radius there, below it a little smaller; the binding angle."""
    R0, rmin = rep["R0"], rep["min_radius"]
    at_min, where = _brute_rho(d, R0, n)
    assert at_min == pytest.approx(rmin, rel=1e-4)
    assert _angle_diff_deg(np.degrees(where), rep["binding_deg"]) < 0.1
    assert rep["min_rho"] == pytest.approx(rmin, abs=1e-9)
    assert _angle_diff_deg(rep["min_rho_at_deg"], rep["binding_deg"]) < 1e-6
    assert _brute_rho(d, R0 - 0.02 * rmin, n)[0] < rmin - 0.005 * rmin  # slightly smaller: not convex enough
    assert _brute_rho(d, R0 + 0.02 * rmin, n)[0] > rmin


@pytest.mark.parametrize(("rotation", "offset"), TRANSLATING_CASES,
                         ids=[f"cam_{r}-e{e:+g}" for r, e in TRANSLATING_CASES])
def test_translating_senses_and_offsets_against_the_brute_force(tmp_path, capsys, rotation, offset):
    file = _variant(TRANSLATING, tmp_path, rotation=f'"{rotation}"', offset=repr(offset))
    rc, rep = _json(capsys, "solve", file)
    assert rc == 0 and rep["verified"] and rep["R0_source"] == "convexity"
    d = load_design(file)
    assert d.cam_sense == SENSE[rotation] and d.follower.offset == offset
    assert rep["offset"] == offset
    _check_sizing(rep, d, 40_000)

    # the contact travels along the face: its x in the follower's frame (the axis at x = 0)
    phi, X, m, O, _ = _brute_contact(d, rep["R0"], 40_000)
    s = d.program.evaluate(phi).s
    assert np.max(np.abs(X[:, 1] - s)) < 1e-6  # the brute force's contact lies on the face y = s
    fr = rep["face_range"]
    assert fr["from"] == pytest.approx(X[:, 0].min(), abs=1e-4)
    assert fr["to"] == pytest.approx(X[:, 0].max(), abs=1e-4)
    assert rep["face_width"] == pytest.approx(X[:, 0].max() - X[:, 0].min(), abs=2e-4)
    assert rep["face_width_centred"] == pytest.approx(2 * np.max(np.abs(X[:, 0])), abs=2e-4)
    assert _angle_diff_deg(np.degrees(phi[np.argmin(X[:, 0])]), fr["from_at_deg"]) < 0.1
    assert _angle_diff_deg(np.degrees(phi[np.argmax(X[:, 0])]), fr["to_at_deg"]) < 0.1
    # the face's normal is the follower's direction of motion: no pressure angle
    assert rep["pressure_angle"]["min"] == 0.0 and rep["pressure_angle"]["max"] == 0.0


@pytest.mark.parametrize(("rotation", "rise", "face_offset"), ROCKER_CASES,
                         ids=[f"cam_{r}-rise_{s}-f{f:+g}" for r, s, f in ROCKER_CASES])
def test_rocker_senses_and_face_offsets_against_the_brute_force(tmp_path, capsys, rotation, rise, face_offset):
    file = _variant(ROCKER, tmp_path, rotation=f'"{rotation}"', rise_direction=f'"{rise}"',
                    face_offset=repr(face_offset))
    rc, rep = _json(capsys, "solve", file)
    assert rc == 0 and rep["verified"] and rep["R0_source"] == "convexity"
    d = load_design(file)
    f_ = d.follower
    assert d.cam_sense == SENSE[rotation] and f_.sense == SENSE[rise] and f_.face_offset == face_offset
    assert rep["face_offset"] == face_offset
    _check_sizing(rep, d, 40_000)

    phi, X, m, O, a = _brute_contact(d, rep["R0"], 40_000)
    f = face_offset
    assert np.max(np.abs(np.sum(X * m, axis=1) - f)) < 1e-6  # on the face line m . X = f
    # the face range: along the face from the pivot's foot f m, positive towards the cam (the side of the face
    # on which the cam centre's foot lies)
    Jm = np.stack([-m[:, 1], m[:, 0]], axis=1)
    towards = np.sign(Jm @ O)
    assert np.all(towards == towards[0])
    along = towards * np.sum((X - f * m) * Jm, axis=1)
    fr = rep["face_range"]
    assert fr["from"] == pytest.approx(along.min(), abs=1e-4)
    assert fr["to"] == pytest.approx(along.max(), abs=1e-4)
    assert rep["face_width"] == pytest.approx(along.max() - along.min(), abs=2e-4)
    assert _angle_diff_deg(np.degrees(phi[np.argmin(along)]), fr["from_at_deg"]) < 0.1
    assert _angle_diff_deg(np.degrees(phi[np.argmax(along)]), fr["to_at_deg"]) < 0.1

    # the pressure angle: between the face normal and the contact point's velocity v = omega x r, the rocker
    # turning about its pivot (the origin) at omega = da/dt (a: the face's normal angle in the fixed frame;
    # per unit cam speed, a central difference). Where the rocker rests (omega = 0) the velocity has no
    # direction; the moving positions come arbitrarily close to those, so the range is the same.
    h = phi[1] - phi[0]
    omega = (np.roll(a, -1) - np.roll(a, 1)) / (2 * h)
    v = omega[:, None] * np.stack([-X[:, 1], X[:, 0]], axis=1)
    speed = np.linalg.norm(v, axis=1)
    moving = np.abs(omega) > 1e-9
    cosg = np.abs(np.sum(v * m, axis=1))[moving] / speed[moving]
    gamma = np.degrees(np.arccos(np.clip(cosg, 0.0, 1.0)))
    pa = rep["pressure_angle"]
    assert pa["min"] == pytest.approx(gamma.min(), abs=1e-3)
    assert pa["max"] == pytest.approx(gamma.max(), abs=1e-3)
