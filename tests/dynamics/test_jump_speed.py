"""The elastic jump speed: searched only when read, and where the steady state's least load first turns negative.

* ``cams check`` and ``cams plot --animate`` of a follower train never search it (the search made to fail);
  ``cams solve`` does, and a second read does not search again;
* the speed read against the steady state's least load computed at speeds around it and below it, one speed at a
  time (the search takes its speeds in batches);
* the batch of least loads (:func:`laws.response.grid_least_loads`) against a periodic steady state found by
  shooting with ``solve_ivp`` (no formula of laws.response), and against one speed at a time; a resonance it
  cannot answer is flagged.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import cams.dynamics.vibration as vib
from cams.cam import Cam
from cams.io.designfile import load_design
from laws.errors import InputError
from laws.program import Phase, Program
from laws.registry import LAWS
from laws.response import Train, grid_least_loads, grid_response, steady_state
from laws.units import rpm_to_omega
from tests.conftest import EXAMPLES
from tests.inprocess import cams_cli

TRAINS = ("slotting_feed_cam_train", "translating_train")


def _refuse(*a, **k):
    raise AssertionError("the dynamic jump speed was searched")


@pytest.mark.parametrize("name", TRAINS)
def test_check_does_not_search_the_jump_speed(monkeypatch, name):
    monkeypatch.setattr(vib, "dynamic_jump_rpm", _refuse)
    r = cams_cli("check", EXAMPLES / f"{name}.toml")
    assert r.returncode == 0, r.stderr
    assert "verified: yes" in r.stdout and "buildable: yes" in r.stdout


def test_animated_plot_does_not_search_the_jump_speed(monkeypatch, tmp_path):
    monkeypatch.setattr(vib, "dynamic_jump_rpm", _refuse)
    r = cams_cli("plot", EXAMPLES / "slotting_feed_cam_train.toml", "--out", tmp_path, "--only", "motion", "--animate")
    assert r.returncode == 0, r.stderr
    assert any(p.suffix == ".gif" for p in tmp_path.iterdir())


def test_solve_reads_it_once(monkeypatch):
    cam = Cam(load_design(EXAMPLES / "translating_train.toml"))
    monkeypatch.setattr(vib, "dynamic_jump_rpm", _refuse)
    with pytest.raises(AssertionError, match="searched"):
        cams_cli("solve", EXAMPLES / "translating_train.toml", "--json")
    calls = []
    monkeypatch.setattr(vib, "dynamic_jump_rpm", lambda *a, **k: calls.append(1) or 123.0)
    v = cam.vibration
    assert v.to_dict()["dynamic_jump_rpm"] == v.jump_rpm == 123.0 and calls == [1]


def _least(program, tm, rpm):
    """The steady state's least Q (N; N m) at ``rpm`` over 720 angles, one speed by itself."""
    tr = tm.train(rpm_to_omega(rpm))
    return float(np.min(grid_response(program, tr, steady_state(program, tr), 720).load)) * tm.total * tm.si


@pytest.mark.parametrize("name", TRAINS)
def test_the_jump_speed_is_the_least_speed_that_loses_contact(name):
    v = Cam(load_design(EXAMPLES / f"{name}.toml")).vibration
    js = v.jump_search
    j = v.jump_rpm
    assert j is not None and js.start_rpm < j < js.top_rpm
    prog, tm = js.program, js.train
    # the bisection's bracket: contact lost at j, held 1e-6 below it (its tolerance)
    assert _least(prog, tm, j) < 0 <= _least(prog, tm, j * (1 - 1.01e-6))
    # held at speeds from the search's start up to it
    for n in np.geomspace(js.start_rpm, j * (1 - 1.01e-6), 25):
        assert _least(prog, tm, n) > 0, n


def _program() -> Program:
    rest = np.pi / 3
    return Program(
        (
            Phase("rise", 2 * np.pi / 3, LAWS["modified_trapezoid"]),
            Phase("dwell", rest),
            Phase("return", 2 * np.pi / 3, LAWS["poly345"]),
            Phase("dwell", rest),
        ),
        1.0,
    )


def _shooting(program: Program, tr: Train) -> tuple[float, float]:
    """The least and the largest load over 720 angles of the periodic steady state, by shooting: the turn's
    affine map of ``(x, dx/dtau)`` from three integrations of the ODE in ``tau`` (solve_ivp), then its fixed
    point."""
    rho, r, z, f = tr.rho, tr.ratio, tr.zeta, tr.offset

    def rhs(tau, y):
        m = program.evaluate(np.mod(tau / rho, 2 * np.pi))
        return [y[1], r * float(m.s) + 2 * z * float(m.ds) / rho - f - y[0] - 2 * z * y[1]]

    end = 2 * np.pi * rho
    grid = np.linspace(0, end, 721)[:-1]

    def run(y0, t_eval=None):
        return solve_ivp(rhs, (0, end), y0, method="DOP853", rtol=1e-12, atol=1e-13, t_eval=t_eval, max_step=0.2)

    g = run([0.0, 0.0]).y[:, -1]  # the map's shift; its matrix from unit starts less the shift
    phi = np.column_stack([run(e).y[:, -1] - g for e in ([1.0, 0.0], [0.0, 1.0])])
    y0 = np.linalg.solve(np.eye(2) - phi, g)
    sol = run(list(y0), grid)
    m = program.evaluate(grid / rho)
    load = r * (m.s - sol.y[0]) + 2 * z * (m.ds / rho - sol.y[1])
    return float(np.min(load)), float(np.max(np.abs(load)))


def test_batch_of_least_loads_against_shooting():
    prog = _program()
    least, size, sure = grid_least_loads(prog, np.array([9.0, 2.7]), 720, ratio=0.8, zeta=0.1, offset=0.4)
    assert sure.all()
    lo, big = _shooting(prog, Train(2.7, 0.8, 0.1, 0.4))
    assert least[1] == pytest.approx(lo, abs=1e-8 * big) and lo < 0.5 * big  # a load that swings
    assert size[1] == pytest.approx(big, rel=1e-8)


@pytest.mark.parametrize("zeta", [0.0, 0.02, 1.0, 1.6])
def test_batch_of_least_loads_equals_one_speed_at_a_time(zeta):
    prog = _program()
    rhos = np.geomspace(0.8, 40.0, 23) + 0.013  # clear of whole numbers: an undamped train has a steady state
    least, size, sure = grid_least_loads(prog, rhos, 360, ratio=0.9, zeta=zeta, offset=0.25)
    assert sure.all()
    for k, rho in enumerate(rhos):
        tr = Train(float(rho), 0.9, zeta, 0.25)
        load = grid_response(prog, tr, steady_state(prog, tr), 360).load
        assert least[k] == pytest.approx(np.min(load), abs=1e-10 * np.max(np.abs(load)))
        assert size[k] == pytest.approx(np.max(np.abs(load)), rel=1e-10)


def test_an_undamped_resonance_is_left_to_one_speed_at_a_time():
    prog = _program()
    with pytest.raises(InputError, match="damping_ratio"):
        steady_state(prog, Train(3.0, 0.9, 0.0, 0.25))
    _, _, sure = grid_least_loads(prog, np.array([2.5, 3.0]), 360, ratio=0.9, zeta=0.0, offset=0.25)
    assert sure.tolist() == [True, False]
