"""The forces picture (``cams plot --only forces``): each curve's data against the same quantity computed another
way, the units on every axis, and the one line a design without forces gets.

The independent quantities: the follower's motion differentiated numerically from the program's displacement,
the pressure angle from the roller centre's velocity relative to the cam (its direction is the pitch curve's
tangent), the contact force from the balance along the follower's axis, and the camshaft torque by the power
balance ``T = Q dq/dphi`` (frictionless: the shaft's power is what the follower takes).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from cams.cam import Cam
from cams.cli import main
from cams.present import plots
from tests.conftest import EXAMPLES

MASS, LOAD, RPM = 0.5, 5.0, 600.0


@pytest.fixture
def translating_dynamics(tmp_path):
    """examples/translating_force.toml at 600 rpm with a [dynamics] table (mass 0.5 kg, load 5 N, no friction)."""
    text = (EXAMPLES / "translating_force.toml").read_text(encoding="utf-8")
    text = text.replace('rotation = "ccw"', f'rotation = "ccw"\nrpm = {RPM:g}')
    text += f"\n[dynamics]\nmass = {MASS}\nload = {LOAD}\n"
    path = tmp_path / "translating_dynamics.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _line(ax, starts: str):
    (line,) = [ln for ln in ax.get_lines() if ln.get_label().startswith(starts)]
    return np.asarray(line.get_xdata(), float), np.asarray(line.get_ydata(), float)


def _motion_numeric(design, phi, h=1e-4):
    """s, ds/dphi, d2s/dphi2 (design units) by central differences of the program's displacement alone."""
    s = lambda p: design.program.evaluate(np.mod(p, 2 * np.pi)).s  # noqa: E731
    return s(phi), (s(phi + h) - s(phi - h)) / (2 * h), (s(phi + h) - 2 * s(phi) + s(phi - h)) / h**2


def _away_from_joints(design, phi_deg, width=0.6):
    """True away from the phases' joints (where the numerical derivatives straddle a change of law)."""
    starts = np.degrees(np.asarray(design.program.starts))
    d = np.abs((phi_deg[:, None] - np.concatenate([starts, [360.0]])[None, :] + 180) % 360 - 180)
    return np.all(d > width, axis=1)


def test_translating_curves_are_the_forces_computed_another_way(translating_dynamics):
    cam = Cam.from_file(translating_dynamics)
    fig = plots.plot_forces(cam)
    ax_f, ax_t = fig.axes
    x, contact = _line(ax_f, "contact force")
    _, spring = _line(ax_f, "spring")
    _, load = _line(ax_f, "load")
    _, torque = _line(ax_t, "camshaft torque")
    assert x[0] == 0.0 and x[-1] < 360.0 and np.all(np.diff(x) > 0)
    d = cam.design
    phi = np.radians(x)
    s, ds, d2s = _motion_numeric(d, phi)
    w = RPM * 2 * np.pi / 60
    k, F0 = cam.forces.spring.rate, cam.forces.spring.preload
    assert k > 0 or F0 > 0
    np.testing.assert_allclose(spring, F0 + k * s * 1e-3, rtol=1e-12, atol=1e-9)  # F0 + k s, s in metres
    np.testing.assert_array_equal(load, LOAD)
    Q = MASS * w**2 * d2s * 1e-3 + F0 + k * s * 1e-3 + LOAD  # what the follower needs along its axis, N
    ok = _away_from_joints(d, x)
    # torque by the power balance (no friction): T omega = Q v, i.e. T = Q ds/dphi (m per rad)
    np.testing.assert_allclose(torque[ok], (Q * ds * 1e-3)[ok], rtol=0, atol=2e-6 * np.max(np.abs(torque)))
    # contact force: its component along the axis carries Q; the normal's angle to the axis from the roller
    # centre's velocity relative to the cam (the pitch curve's tangent), differentiated numerically
    O = np.asarray(cam.solution.centre, float)
    A = np.stack([np.zeros_like(s), s], axis=-1)  # roller centre on the follower's axis x = 0, mm
    eps = d.cam_sense
    v = np.stack([np.zeros_like(ds), ds], axis=-1) - eps * np.stack([-(A - O)[:, 1], (A - O)[:, 0]], axis=-1)
    cos_g = np.abs(v[:, 0]) / np.linalg.norm(v, axis=1)  # |t x u| with u = (0, 1) the axis
    np.testing.assert_allclose(contact[ok], (Q / cos_g)[ok], rtol=0, atol=2e-6 * np.nanmax(contact))
    # units on every axis
    assert ax_f.get_ylabel() == "force, N" and ax_t.get_ylabel() == "camshaft torque, N·m"
    assert ax_t.get_xlabel() == "cam angle φ from the timing datum, deg"
    assert "k = " in next(ln.get_label() for ln in ax_f.get_lines() if ln.get_label().startswith("spring"))


def test_rocker_moments_have_their_own_axes():
    cam = Cam.from_file(EXAMPLES / "slotting_feed_cam.toml")  # rocker: torsional spring, load in N m
    fig = plots.plot_forces(cam)
    ax_n, ax_m, ax_t = fig.axes
    assert [a.get_ylabel() for a in fig.axes] == ["contact force, N", "moment about the pivot, N·m",
                                                  "camshaft torque, N·m"]
    x, spring = _line(ax_m, "spring moment")
    _, load = _line(ax_m, "load")
    psi = cam.design.program.evaluate(np.radians(x)).s  # swing, rad
    sp = cam.forces.spring
    np.testing.assert_allclose(spring, sp.preload + sp.rate * psi, rtol=1e-12, atol=1e-12)
    np.testing.assert_array_equal(load, 0.5)  # the file's load, N m
    assert sp.rate == 3.0  # the file's spring_rate, N m/rad
    _, contact = _line(ax_n, "contact force")
    assert np.nanmin(contact) > 0  # the example keeps contact
    assert not [ln for ln in ax_n.get_lines() if ln.get_label().startswith(("spring", "load"))]


def test_plot_only_forces_writes_it(translating_dynamics, tmp_path, capsys):
    out = tmp_path / "p"
    assert main(["plot", str(translating_dynamics), "--out", str(out), "--only", "forces"]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["translating_roller_cam_forces.png",
                                                     "translating_roller_cam_forces.svg"]
    # every picture by default: the forces among them when there are forces, and not otherwise
    assert main(["plot", str(translating_dynamics), "--out", str(tmp_path / "all")]) == 0
    assert (tmp_path / "all" / "translating_roller_cam_forces.png").exists()
    assert main(["plot", str(EXAMPLES / "translating_force.toml"), "--out", str(tmp_path / "none")]) == 0
    assert not list((tmp_path / "none").glob("*forces*")) and capsys.readouterr().err == ""


@pytest.mark.parametrize("edit, why", [
    (lambda t: t, "no [dynamics] table"),
    (lambda t: t.replace('closure = "force"', 'closure = "form"') + "\n[dynamics]\nmass = 0.5\n", "form-closed"),
    (lambda t: t + "\n[dynamics]\nmass = 0.5\n", "cam.rpm"),
])
def test_plot_only_forces_without_forces_is_one_line(tmp_path, capsys, edit, why):
    path = tmp_path / "d.toml"
    path.write_text(edit((EXAMPLES / "translating_force.toml").read_text(encoding="utf-8")), encoding="utf-8")
    rc = main(["plot", str(path), "--out", str(tmp_path / "p"), "--only", "motion,forces"])
    err = capsys.readouterr().err
    assert rc == 2 and err.startswith("cams plot: error: --only: forces: ") and why in err and err.count("\n") == 1
    assert not (tmp_path / "p").exists() or not list((tmp_path / "p").iterdir())
