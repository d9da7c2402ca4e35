"""The elastic follower train at a speed (cams.dynamics.vibration) against independent figures.

* the natural frequency and period ratios from their definitions;
* the steady state against a time integration of the physical equation (newtons, metres, seconds) from rest, run
  until the damping has forgotten the start (no formula of laws.response);
* the rigid limit: as the train stiffens, the dynamic contact force and the elastic jump speed tend to the rigid
  forces stage's (cams.dynamics.forces);
* the event-driven integrator: equal to the steady state where contact holds, leaving the cam where the steady
  state's load first turns negative;
* bad inputs: one line naming the field.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from cams.cam import Cam
from cams.dynamics.vibration import simulate, train_model, vibration
from cams.io.designfile import load_design
from cams.model.dynamics import FollowerDynamics, Spring
from laws.errors import InputError
from laws.response import steady_state

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "translating_train.toml"


@pytest.fixture(scope="module")
def cam():
    return Cam(load_design(EXAMPLE))


def _dyn(cam, **kw):
    dyn = cam.design.dynamics.dynamics.with_spring(cam.forces.spring)
    return replace(dyn, **kw)


def test_frequency_and_period_ratios(cam):
    v = cam.vibration
    dyn = _dyn(cam)
    k = dyn.train_stiffness + cam.forces.spring.rate
    assert v.natural_frequency == pytest.approx(np.sqrt(k / dyn.mass) / (2 * np.pi), rel=1e-12)
    t_turn = 60.0 / cam.design.rpm
    for p in v.phases:
        dur = cam.design.program.phases[p.phase].angle / (2 * np.pi) * t_turn
        assert p.period_ratio == pytest.approx(dur * v.natural_frequency, rel=1e-12)
    assert [p.phase for p in v.phases] == [0, 2] and [p.kind for p in v.phases] == ["rise", "return"]


def _integrate_from_rest(design, dyn, rpm, turns):
    """m q'' = k_t (s - q) + c (s' - q') - F0 - k_s q - P, in SI, from rest at q = 0; the last turn's q and Q."""
    w = rpm * 2 * np.pi / 60
    m, kt, sp = dyn.mass, dyn.train_stiffness, dyn.spring
    c = 2 * dyn.damping_ratio * np.sqrt((kt + sp.rate) * m)

    def rhs(t, y):
        mo = design.program.evaluate(w * t)
        s, ds = float(mo.s) * 1e-3, float(mo.ds) * 1e-3 * w
        return [y[1], (kt * (s - y[0]) + c * (ds - y[1]) - sp.preload - sp.rate * y[0] - dyn.load) / m]

    period = 2 * np.pi / w
    t_eval = (turns - 1) * period + period * np.arange(720) / 720
    sol = solve_ivp(rhs, (0, turns * period), [0.0, 0.0], method="DOP853", rtol=1e-11, atol=1e-15, t_eval=t_eval)
    mo = design.program.evaluate(w * t_eval)
    q_load = kt * (mo.s * 1e-3 - sol.y[0]) + c * (mo.ds * 1e-3 * w - sol.y[1])
    return sol.y[0] * 1e3, q_load


def test_steady_state_against_integration_from_rest(cam):
    dyn = _dyn(cam, damping_ratio=0.2)  # the start forgotten within a few turns (exp(-zeta omega_n T) ~ 1e-11)
    v = vibration(cam.design, dyn, cam.forces.forces.amplification, rigid_jump_rpm=None)
    q, load = _integrate_from_rest(cam.design, dyn, cam.design.rpm, turns=3)
    assert np.max(np.abs(v.q - q)) < 1e-7 * cam.design.program.lift
    assert np.max(np.abs(v.load - load)) < 1e-6 * np.max(np.abs(load))
    assert np.allclose(v.contact, v.load * cam.forces.forces.amplification)


def test_rigid_limit(cam):
    rigid = cam.forces.forces.contact
    errs = []
    for kt in (1e6, 1e8, 1e10):
        v = vibration(
            cam.design,
            _dyn(cam, train_stiffness=kt),
            cam.forces.forces.amplification,
            rigid_jump_rpm=cam.forces.jump.rpm,
        )
        errs.append(np.max(np.abs(v.contact - rigid)) / np.max(rigid))
        last = v
    assert errs[0] > errs[1] > errs[2] and errs[2] < 2e-3
    assert last.jump_rpm == pytest.approx(cam.forces.jump.rpm, rel=2e-3)


def test_flight_equals_steady_state_where_contact_holds(cam):
    d, dyn = cam.design, _dyn(cam)
    tm = train_model(d, dyn)
    w = d.rpm * 2 * np.pi / 60
    tr = tm.train(w)
    y0 = steady_state(d.program, tr)
    f = simulate(d.program, tm, w, (y0[0], y0[1] * tr.rho * w), turns=2)
    v = cam.vibration
    assert f.intervals == () and f.max_gap < 0
    assert np.max(np.abs(f.q - v.q)) < 1e-7 * d.program.lift
    assert np.max(np.abs(f.load - v.load)) < 1e-6 * np.max(v.load)


def test_loss_of_contact_and_the_flight(cam):
    d = cam.design
    dyn = _dyn(cam)
    rpm = 0.5 * (cam.vibration.jump_rpm + cam.forces.jump.rpm)  # above the elastic jump, below the rigid one
    v = vibration(d, dyn, cam.forces.forces.amplification, rpm=rpm, rigid_jump_rpm=cam.forces.jump.rpm)
    assert v.contact_lost and v.flight is not None
    assert np.min(v.load) < 0 and v.load[np.searchsorted(v.phi, v.contact_lost_at)] < 0
    assert np.all(v.flight.load >= 0)
    # one turn from the steady state: the follower leaves where the steady state's load first turns negative
    tm = train_model(d, dyn)
    w = rpm * 2 * np.pi / 60
    tr = tm.train(w)
    y0 = steady_state(d.program, tr)
    f = simulate(d.program, tm, w, (y0[0], y0[1] * tr.rho * w), turns=1)
    leave = f.intervals[0][0]
    assert abs(np.degrees(leave - v.contact_lost_at)) <= 0.5 + 1e-9  # within a sample (0.5 deg)
    # below the elastic jump speed contact holds
    below = vibration(d, dyn, cam.forces.forces.amplification, rpm=0.99 * cam.vibration.jump_rpm)
    assert not below.contact_lost and np.min(below.load) > 0


def test_jump_speed_is_where_the_least_load_crosses_zero(cam):
    d, dyn = cam.design, _dyn(cam)
    j = cam.vibration.jump_rpm
    amp = cam.forces.forces.amplification
    at = [vibration(d, dyn, amp, rpm=n, rigid_jump_rpm=1.0) for n in (j * (1 - 1e-4), j * (1 + 1e-4))]
    assert np.min(at[0].load) > 0 > np.min(at[1].load)


def test_form_closure_never_loses_contact(tmp_path):
    text = EXAMPLE.read_text().replace('closure = "force"', 'closure = "form"').replace("margin = 1.5", "")
    p = tmp_path / "form.toml"
    p.write_text(text)
    c = Cam(load_design(p))
    v = c.vibration
    assert v is not None and not v.contact_lost and v.jump_rpm is None and not v.force_closed
    assert np.min(v.load) < 0  # the groove pulls the follower back on the return


@pytest.mark.parametrize(
    "kw, field",
    [
        ({"mass": 0.0}, "dynamics.mass"),
        ({"mass": -1.0}, "dynamics.mass"),
        ({"train_stiffness": 0.0}, "dynamics.train_stiffness"),
        ({"train_stiffness": -5.0}, "dynamics.train_stiffness"),
        ({"damping_ratio": -0.1, "train_stiffness": 1e5}, "dynamics.damping_ratio"),
        ({"damping_ratio": 0.1}, "dynamics.damping_ratio"),
    ],
)
def test_bad_train_inputs(kw, field):
    args = {"mass": 0.5, "spring": Spring(100.0, 5.0)} | kw
    with pytest.raises(InputError) as e:
        FollowerDynamics(**args)
    assert e.value.field == field


def test_train_without_rpm_names_it(tmp_path):
    p = tmp_path / "norpm.toml"
    p.write_text("\n".join(line for line in EXAMPLE.read_text().splitlines() if not line.startswith("rpm")))
    with pytest.raises(InputError) as e:
        load_design(p)
    assert e.value.field == "cam.rpm" and "train_stiffness" in str(e.value)


@pytest.mark.parametrize("name", ["translating_flat", "rocker_flat"])
def test_flat_faces_take_the_forces_stage_geometry_and_tend_to_the_rigid_forces(tmp_path, name):
    """A flat face (translating: the normal along the motion; rocker: the lever along the face, torsional train
    about the pivot): the dynamic contact force is Q times the forces stage's geometry, and with a very stiff,
    well damped train it is the rigid one."""
    src = ROOT / "examples" / f"{name}.toml"
    lines = src.read_text().splitlines()
    k = next(i for i, line in enumerate(lines) if line.startswith("face_friction"))
    stiff = "1.0e10" if name == "translating_flat" else "1.0e7"  # N/m; N m/rad about the pivot
    lines.insert(k + 1, f"train_stiffness = {stiff}\ndamping_ratio = 0.3")
    p = tmp_path / f"{name}.toml"
    p.write_text("\n".join(lines) + "\n")
    c = Cam(load_design(p))
    v, cf = c.vibration, c.forces.forces
    assert np.allclose(v.contact, v.load * cf.amplification, rtol=1e-12, atol=0)
    assert np.max(np.abs(v.contact - cf.contact)) < 5e-3 * np.max(np.abs(cf.contact))
    assert v.jump_rpm == pytest.approx(c.forces.jump.rpm, rel=5e-3)
