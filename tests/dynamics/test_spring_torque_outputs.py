"""What `cams solve` says of the spring and the camshaft torque, checked against an independent evaluation.

The forces are recomputed here from the lift ``s(phi)`` alone (central finite differences, never the program's
derivatives) and from the cam's geometry (the pitch curve drawn by inverting the follower's positions about the
solved centre, its normal by differences of its points), never through :func:`cams.dynamics.forces.cam_forces`:

* contact with margin: ``k (d0 + q) >= margin (-m q'' - P)``, with ``k`` and ``d0`` as printed;
* the contact force: ``N = (m q'' + k (d0 + q) + P) / cos(gamma)`` (no friction), ``gamma`` between the pitch
  curve's normal and the follower's direction;
* the camshaft torque by the power balance ``T omega = (m q'' + F + P) q'`` (no friction): the power the shaft
  puts into the follower, driving where positive.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import load_design
from laws.units import rpm_to_omega
from tests.conftest import EXAMPLES

MASS, LOAD = 0.5, 5.0


@pytest.fixture
def at600(tmp_path):
    """The issue's case: examples/translating_force.toml at 600 rpm with [dynamics] mass 0.5 kg, load 5 N."""
    text = (EXAMPLES / "translating_force.toml").read_text(encoding="utf-8")
    assert 'rotation = "ccw"\n' in text
    text = text.replace('rotation = "ccw"\n', 'rotation = "ccw"\nrpm = 600\n', 1)
    f = tmp_path / "at600.toml"
    f.write_text(text + f"[dynamics]\nmass = {MASS}\nload = {LOAD}\n", encoding="utf-8")
    return f


def _json(capsys, *argv) -> dict:
    capsys.readouterr()
    assert main(["solve", *argv, "--json"]) == 0
    return json.loads(capsys.readouterr().out)


def _lift(design, phi, si):
    """q, dq/dphi, d2q/dphi2 by central differences of the lift alone (m or rad); a step of 1e-4 rad balances the
    truncation (~1e-9 relative) and the round-off."""
    dx = 1e-4

    def s(x):
        return design.program.evaluate(np.mod(x, 2 * np.pi)).s * si

    q = s(phi)
    return q, (s(phi + dx) - s(phi - dx)) / (2 * dx), (s(phi + dx) - 2 * q + s(phi - dx)) / dx**2


def _rot(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s], [s, c]]).transpose(2, 0, 1)


def _cos_gamma(design, centre, phi):
    """cos of the pressure angle of a translating roller follower, from its pitch curve in the cam's frame."""
    eps = design.cam_sense
    dx = 1e-6

    def pitch(x):  # the roller centre seen from the cam, which has turned by eps x
        s = design.program.evaluate(np.mod(x, 2 * np.pi)).s
        A = np.stack([np.zeros_like(s), s], axis=-1) - centre
        return np.einsum("nij,nj->ni", _rot(-eps * x), A)

    t = (pitch(phi + dx) - pitch(phi - dx)) / (2 * dx)
    n = np.stack([t[:, 1], -t[:, 0]], axis=-1) / np.linalg.norm(t, axis=1)[:, None]
    rise = np.einsum("nij,j->ni", _rot(-eps * phi), np.array([0.0, 1.0]))  # the follower's axis, in the cam frame
    return np.abs(np.sum(n * rise, axis=1))


def test_spring_at_600_rpm_has_a_rate_and_keeps_contact(at600, capsys):
    """Done when: the chosen spring has a positive rate and keeps contact with its margin (1.2), by the lift and the
    profile alone; the contact force printed is the profile's."""
    rep = _json(capsys, str(at600))
    fo, sp = rep["forces"], rep["forces"]["spring"]
    assert sp["rate"] > 0 and sp["preload"] > 0 and sp["note"] is None
    k, d0 = sp["rate"], sp["installed_compression"] * 1e-3
    assert sp["preload"] == pytest.approx(k * d0, rel=1e-12)
    assert sp["max_force"] == pytest.approx(k * (d0 + 30e-3), rel=1e-12)
    assert 30e-3 / 4 <= d0 <= 30e-3 * (1 + 1e-9)  # the default range: preload 20 % to 50 % of the largest force
    design = load_design(at600)
    w = rpm_to_omega(600.0)
    # contact with margin, on a grid 50 times finer than the printed one (away from the phase joints)
    phi = np.linspace(0, 2 * np.pi, 36000, endpoint=False)
    q, _, q2 = _lift(design, phi, 1e-3)
    joints = np.min(np.abs(np.angle(np.exp(1j * (phi[:, None] - design.program.starts[None, :])))), axis=1)
    keep = joints > 1e-4
    spring = k * (d0 + q)
    pull = -MASS * w**2 * q2 - LOAD
    assert np.min((spring - 1.2 * pull)[keep]) >= -1e-6 * np.max(spring)
    assert np.min((spring - 1.2 * pull)[keep]) <= 1e-3 * np.max(spring)  # and it binds somewhere: no waste
    # the contact force by the profile, at the printed angles
    phi = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    q, _, q2 = _lift(design, phi, 1e-3)
    centre = np.array([rep["centre"]["x"], rep["centre"]["y"]])
    cg = _cos_gamma(design, centre, phi)
    rise = design.program.phase_of(phi) == 0
    assert np.degrees(np.max(np.arccos(np.minimum(cg[rise], 1.0)))) == pytest.approx(30.0, abs=1e-3)  # the limit
    N = (MASS * w**2 * q2 + k * (d0 + q) + LOAD) / cg
    assert np.min(N) > 0 and not fo["contact_lost"]
    assert fo["max_contact_force"] == pytest.approx(np.max(N), rel=1e-6)
    assert fo["min_contact_force"] == pytest.approx(np.min(N), rel=1e-6)
    assert fo["max_contact_at_deg"] == pytest.approx(np.degrees(phi[np.argmax(N)]), abs=1e-9)


def _power_torque(design, phi, sp, mass, load, si):
    """The camshaft torque by the power balance, frictionless: T = (m q'' + F0 + k q + P) dq/dphi (N m)."""
    w = rpm_to_omega(design.rpm)
    q, q1, q2 = _lift(design, phi, si)
    return (mass * w**2 * q2 + sp["preload"] + sp["rate"] * q + load) * q1


@pytest.mark.parametrize("kind", ["translating", "rocker"])
def test_driving_and_braking_torque_by_power_balance(kind, at600, tmp_path, capsys):
    if kind == "translating":
        f, mass, load, si = at600, MASS, LOAD, 1e-3
    else:
        text = (EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8")
        f, mass, load, si = tmp_path / "rocker.toml", 0.004, 0.5, 1.0
        assert "\nrpm = 60\n" in text
        text = text.replace("\nrpm = 60\n", "\nrpm = 300\n", 1)
        f.write_text(text + f"[dynamics]\nmass = {mass}\nload = {load}\n", encoding="utf-8")
    rep = _json(capsys, str(f))
    fo = rep["forces"]
    design = load_design(f)
    phi = np.linspace(0, 2 * np.pi, 720, endpoint=False)  # the angles the forces are given at
    T = _power_torque(design, phi, fo["spring"], mass, load, si)
    scale = np.max(np.abs(T))
    assert fo["max_driving_torque"] == pytest.approx(np.max(T), abs=1e-6 * scale)
    assert fo["max_driving_torque_at_deg"] == pytest.approx(np.degrees(phi[np.argmax(T)]), abs=1e-9)
    assert fo["max_braking_torque"] == pytest.approx(np.min(T), abs=1e-6 * scale)
    assert fo["max_braking_torque_at_deg"] == pytest.approx(np.degrees(phi[np.argmin(T)]), abs=1e-9)
    assert np.max(T) > 0 > np.min(T)
    assert abs(fo["max_torque"]) == pytest.approx(scale, abs=1e-6 * scale)
    # the words: "largest driving torque X N·m at Y deg; largest braking torque |Z| N·m at W deg"
    capsys.readouterr()
    assert main(["solve", str(f)]) == 0
    out = capsys.readouterr().out
    m = re.search(
        r"largest driving torque ([\d.e+-]+) N·m at ([\d.]+) deg; largest braking torque ([\d.e+-]+) N·m "
        r"at ([\d.]+) deg",
        out,
    )
    assert m, out
    assert float(m.group(1)) == pytest.approx(np.max(T), rel=1e-5)
    assert float(m.group(3)) == pytest.approx(-np.min(T), rel=1e-5)
    assert float(m.group(2)) == pytest.approx(np.degrees(phi[np.argmax(T)]), abs=1e-4)
    assert float(m.group(4)) == pytest.approx(np.degrees(phi[np.argmin(T)]), abs=1e-4)
    assert "max -" not in out and "camshaft torque max" not in out
    # the spring's words carry its units
    sp = fo["spring"]
    if kind == "translating":
        assert (
            f"installed compression {sp['installed_compression']:.6g} mm, largest force {sp['max_force']:.6g} N" in out
        )
    else:
        assert f"installed twist {sp['installed_twist']:.6g} deg, largest force {sp['max_force']:.6g} N m" in out


def test_an_impulse_is_driving_where_the_follower_speeds_up(tmp_path, capsys):
    """A linear rise from a dwell: the cam's impulse speeds the follower up (driving, unbounded); a linear return
    into a dwell: the impulse stops it (braking, unbounded). Work of an impulse: m (v+^2 - v-^2) / 2."""
    text = (EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8")
    assert "\nrpm = 60\n" in text
    parts = text.split('law = "cycloidal"')
    assert len(parts) == 3  # the rise's law, then the return's
    dyn = "[dynamics]\nmass = 0.004\nload = 0.5\n"
    rise = tmp_path / "rise.toml"
    rise.write_text(parts[0] + 'law = "linear"' + parts[1] + 'law = "cycloidal"' + parts[2] + dyn, encoding="utf-8")
    ret = tmp_path / "return.toml"
    ret.write_text(parts[0] + 'law = "cycloidal"' + parts[1] + 'law = "linear"' + parts[2] + dyn, encoding="utf-8")
    for f, unbounded, finite in ((rise, "driving", "braking"), (ret, "braking", "driving")):
        capsys.readouterr()
        main(["solve", str(f), "--json"])  # exits 1: rigid impacts
        fo = json.loads(capsys.readouterr().out)["forces"]
        design = load_design(f)
        starts = np.degrees(design.program.starts)
        jump_up = [i["cam_angle_deg"] for i in fo["impacts"] if i["effect"] == "impulse"]
        assert len(jump_up) == 1
        expected = starts[0] if unbounded == "driving" else starts[3] % 360  # the rise's start, the return's end
        assert jump_up[0] == pytest.approx(expected, abs=1e-9)
        assert fo[f"max_{unbounded}_torque"] is None  # unbounded: null in strict JSON
        assert fo[f"max_{unbounded}_torque_at_deg"] == pytest.approx(expected, abs=1e-9)
        assert fo[f"max_{finite}_torque"] is not None and np.isfinite(fo[f"max_{finite}_torque"])
        bi = fo["between_impacts"]
        assert bi["max_driving_torque"] > 0 > bi["max_braking_torque"]


@pytest.mark.parametrize(
    "kind, table, field",
    [
        (
            "translating",
            "min_installed_compression = 20\nmax_installed_compression = 10\n",
            "dynamics.max_installed_compression",
        ),
        ("translating", "max_installed_compression = -1\n", "dynamics.max_installed_compression"),
        ("translating", 'min_installed_compression = "short"\n', "dynamics.min_installed_compression"),
        ("translating", "max_installed_twist = 10\n", "dynamics.max_installed_twist"),
        (
            "translating",
            "spring_rate = 2000\npreload = 20\nmin_installed_compression = 5\n",
            "dynamics.min_installed_compression",
        ),
        ("translating", "spring_rate = 100\nmax_installed_compression = 40\n", "dynamics.max_installed_compression"),
        ("rocker", "min_installed_compression = 5\n", "dynamics.min_installed_compression"),
        ("rocker", "min_installed_twist = 9\nmax_installed_twist = 3\n", "dynamics.max_installed_twist"),
    ],
)
def test_bad_spring_bounds_exit_2_naming_the_field(kind, table, field, at600, tmp_path, capsys):
    """Bounds reversed, negative, not numbers, of the other follower's kind, beside a given spring, or too tight for
    a given rate: one line naming the field, exit 2."""
    if kind == "translating":
        text = at600.read_text(encoding="utf-8")
    else:
        text = (EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8") + "[dynamics]\nmass = 0.004\nload = 0.5\n"
    f = tmp_path / "bad.toml"
    f.write_text(text + table, encoding="utf-8")
    capsys.readouterr()
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err and f" {field}" in err, err
