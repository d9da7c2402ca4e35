"""Forces at a force-closed cam (cams.dynamics.forces): contact force, torque, spring, jump speed, jamming.

The jump speed is confirmed by a time simulation of the follower on a stiff one-sided
contact (tests/dynamics/sim.py) that knows nothing of the closed-form contact force.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.dynamics.forces import cam_forces, chosen_spring, jamming_limit, spring_for_contact
from cams.dynamics.jump import jump_speed
from cams.io.designfile import design_from_dict, load_design
from cams.model.dynamics import FollowerDynamics, Spring
from cams.solve import solve
from laws.errors import InputError
from tests.conftest import EXAMPLES, rocker_dict
from tests.dynamics.sim import simulate

TRANS = load_design(EXAMPLES / "translating_force.toml")
# a rocker with a rise and a return that differ, so that one position is the most critical
ROCKER = design_from_dict(rocker_dict(motion=[
    {"phase": "rise", "law": "cycloidal", "angle": 100},
    {"phase": "dwell", "angle": 40},
    {"phase": "return", "law": "poly345", "angle": 140},
    {"phase": "dwell"},
]))
CASES = {
    "translating": (TRANS, FollowerDynamics(0.5, load=10.0, friction=0.1)),
    "rocker": (ROCKER, FollowerDynamics(0.004, load=0.5, friction=0.1, journal_radius=6.0)),
}
RATES = {"translating": 200.0, "rocker": 2.0}


@pytest.fixture(scope="module", params=sorted(CASES))
def case(request):
    design, dyn = CASES[request.param]
    res = solve(design)
    spring = spring_for_contact(design, dyn, rpm=300, margin=1.3, rate=RATES[request.param])
    return request.param, design, res.centre, dyn.with_spring(spring)


def test_torque_by_moment_equals_power_balance(case):
    """T = eps N (r x n) (moment about the cam centre) equals N |dA/dq| cos(gamma) dq/dphi (power)."""
    name, design, centre, dyn = case
    for sense in (1, -1):
        d = design.with_(cam_sense=sense)
        c = solve(d).centre
        f = cam_forces(d, c, dyn, rpm=300)
        arm = d.follower.arm * dyn.length_unit if name == "rocker" else 1.0
        power = f.contact * arm * np.cos(f.gamma) * f.dq / f.omega
        assert np.max(np.abs(f.torque - power)) < 1e-9 * np.max(np.abs(f.torque))
        assert f.ok


def test_force_components(case):
    name, design, centre, dyn = case
    f = cam_forces(design, centre, dyn, rpm=300)
    assert np.allclose(np.abs(f.force), f.contact, rtol=1e-12)
    assert np.allclose(f.along**2 + f.lateral**2, f.contact**2, rtol=1e-12)
    # the follower's equation of motion, term by term
    arm = design.follower.arm * dyn.length_unit if name == "rocker" else 1.0
    lhs = f.contact * arm * np.cos(f.gamma) + f.friction
    rhs = f.inertia + f.spring + dyn.load
    assert np.max(np.abs(lhs - rhs)) < 1e-9 * np.max(np.abs(rhs))
    # friction opposes the motion
    assert np.all(f.friction * f.dq <= 1e-12)


def test_pressure_angle_matches_cams_pressure(case):
    from cams.verify.pressure import pressure_angle

    name, design, centre, dyn = case
    f = cam_forces(design, centre, dyn, rpm=300)
    i = 0  # the rise
    u = np.linspace(0.01, 0.99, 7)
    phi = design.program.starts[i] + u * design.program.phases[i].angle
    g = cam_forces(design, centre, dyn, rpm=300, phi=phi).gamma
    assert np.allclose(g, pressure_angle(design, centre, i, u), atol=1e-12)
    assert np.max(f.gamma[design.program.phase_of(f.phi) == 0]) <= design.limits.pressure_angle + 1e-6


def test_spring_keeps_contact_with_margin(case):
    name, design, centre, dyn = case
    f = cam_forces(design, centre, dyn, rpm=300, samples=3600)  # the grid spring_for_contact checks
    assert np.all(f.contact > 0)
    # the margin is tight: the spring equals 1.3 x what pulls the follower off somewhere
    pull = -(f.inertia + dyn.load)
    assert dyn.spring.preload > 0
    assert np.min(f.spring - 1.3 * pull) == pytest.approx(0.0, abs=1e-6 * np.max(np.abs(f.spring)))


def test_jump_speed_scales_with_margin():
    """No load: the contact force is F0 + k q + m omega^2 q'', so the jump speed is sqrt(margin) x the design speed."""
    for design, dyn in CASES.values():
        free = FollowerDynamics(dyn.mass, load=0.0, length_unit=dyn.length_unit)
        for rate in (None, 0.0, 1e-3):
            sp = spring_for_contact(design, free, rpm=400, margin=1.44, rate=rate)
            assert sp.preload > 0  # the margin binds somewhere
            j = jump_speed(design, free.with_spring(sp))
            assert j.rpm == pytest.approx(400 * 1.2, rel=1e-6)


@pytest.mark.parametrize("name", sorted(CASES))
def test_jump_speed_confirmed_by_simulation(name):
    design, dyn = CASES[name]
    dyn = dyn.with_spring(spring_for_contact(design, dyn, rpm=300, margin=1.3, rate=RATES[name]))
    j = jump_speed(design, dyn)
    below = simulate(design, dyn, 0.98 * j.rpm)
    assert below.first_lift_off is None and below.max_gap < 0 and not below.lifted
    above = simulate(design, dyn, 1.02 * j.rpm)
    assert above.lifted and above.first_lift_off is not None
    # it leaves the cam near the predicted angle (a little before: 2 % over the speed)
    assert np.degrees(abs(np.angle(np.exp(1j * (above.first_lift_off - j.phi))))) < 6.0


def test_contact_lost_above_jump_speed(case):
    name, design, centre, dyn = case
    j = jump_speed(design, dyn)
    assert cam_forces(design, centre, dyn, rpm=0.999 * j.rpm).ok
    f = cam_forces(design, centre, dyn, rpm=1.01 * j.rpm)
    assert not f.ok and np.any(f.lost)
    lost_at = f.phi[f.lost]
    assert np.min(np.abs(np.angle(np.exp(1j * (lost_at - j.phi))))) < np.radians(2)


def test_jamming_force_grows_without_bound():
    """Translating follower, guide friction mu: N = need / (cos g - mu sin g) -> inf as g -> atan(1/mu)."""
    design, dyn = CASES["translating"]
    res = solve(design)
    sp = Spring(1000.0, 20.0)
    gmax = design.limits.pressure_angle  # 30 deg, reached on the rise
    mus = [0.0, 0.5, 1.0, 1.5, 1 / np.tan(gmax) * 0.999]
    peaks = []
    for mu in mus:
        d = FollowerDynamics(0.5, load=10.0, friction=mu, spring=sp)
        f = cam_forces(design, res.centre, d, rpm=100, samples=3600)
        rise = (design.program.phase_of(f.phi) == 0) & (f.dq > 1e-9)
        assert np.allclose(f.amplification[rise], 1 / (np.cos(f.gamma[rise]) - mu * np.sin(f.gamma[rise])))
        assert jamming_limit(design, d) == pytest.approx(np.arctan2(1, mu))
        assert not np.any(f.jammed)
        peaks.append(np.max(f.amplification[rise]))
    assert np.all(np.diff(peaks) > 0) and peaks[-1] > 100 * peaks[0]
    # beyond the limit the cam cannot drive
    d = FollowerDynamics(0.5, load=10.0, friction=2.0, spring=sp)
    f = cam_forces(design, res.centre, d, rpm=100)
    assert np.degrees(jamming_limit(design, d)) < 30.0
    assert np.any(f.jammed) and not f.ok and np.all(np.isinf(f.contact[f.jammed]))


def test_rocker_jamming_limit():
    d = FollowerDynamics(0.004, friction=0.2, journal_radius=10.0)
    assert jamming_limit(ROCKER, d) == pytest.approx(np.arccos(0.2 * 10 / 125))
    assert jamming_limit(ROCKER, FollowerDynamics(0.004)) == pytest.approx(np.pi / 2)


@pytest.mark.parametrize(
    "make, field",
    [
        (lambda: FollowerDynamics(-1.0), "dynamics.mass"),
        (lambda: FollowerDynamics(0.0), "dynamics.mass"),
        (lambda: FollowerDynamics(1.0, friction=-0.1), "dynamics.friction"),
        (lambda: Spring(-5.0, 1.0), "dynamics.spring_rate"),
        (lambda: Spring(5.0, -1.0), "dynamics.preload"),
        (lambda: spring_for_contact(TRANS, FollowerDynamics(0.5), rpm=300, margin=0.9), "dynamics.margin"),
        (lambda: spring_for_contact(TRANS, FollowerDynamics(0.5), rpm=300, rate=-1.0), "dynamics.spring_rate"),
        (lambda: spring_for_contact(TRANS, FollowerDynamics(0.5, max_spring_force=5.0), rpm=300, rate=2000.0), "dynamics.spring_rate"),
        (lambda: spring_for_contact(TRANS, FollowerDynamics(0.5, max_spring_force=5.0), rpm=300), "dynamics.max_spring_force"),
        (lambda: spring_for_contact(TRANS, FollowerDynamics(0.5)), "cam.rpm"),
        (lambda: jump_speed(TRANS, FollowerDynamics(0.5, load=-20.0, spring=Spring(100.0, 5.0))), "dynamics.preload"),
        (lambda: cam_forces(TRANS, (0.0, -30.0), FollowerDynamics(0.5), rpm=100), "dynamics.spring_rate"),
    ],
)
def test_bad_input_is_one_line(make, field):
    with pytest.raises(InputError) as e:
        make()
    assert e.value.field == field and "\n" not in str(e.value)


def test_spring_that_cannot_keep_contact_message():
    with pytest.raises(InputError, match="cannot keep contact at 300 rpm with margin 1.2 at any preload"):
        spring_for_contact(TRANS, FollowerDynamics(0.5, max_spring_force=5.0), rpm=300, rate=2000.0)


def test_design_file_dynamics_table():
    d = design_from_dict(rocker_dict(cam={"rpm": 300}, dynamics={"mass": 0.004, "load": 0.5, "spring_rate": 2.0, "friction": 0.1,
                                                                  "journal_radius": 6.0, "margin": 1.3}))
    ds = d.dynamics
    dyn = ds.dynamics
    assert ds.margin == 1.3 and ds.rate == 2.0 and dyn.spring is None and dyn.length_unit == 1e-3 and dyn.journal_radius == 6.0
    sp = chosen_spring(ds, d)
    assert sp == spring_for_contact(d, dyn, margin=1.3, rate=2.0)
    assert sp.rate == 2.0 and sp.preload > 0
    assert design_from_dict(rocker_dict()).dynamics is None


@pytest.mark.parametrize(
    "table, units, field",
    [
        ({"mass": -0.1}, "mm", "dynamics.mass"),
        ({"load": 1.0}, "mm", "dynamics.mass"),
        ({"mass": 0.1, "spring": 3}, "mm", "dynamics"),
        ({"mass": 0.1, "preload": 3}, "mm", "dynamics.spring_rate"),
        ({"mass": 0.1, "spring_rate": -3}, "mm", "dynamics.spring_rate"),
        ({"mass": 0.1, "margin": 0.5}, "mm", "dynamics.margin"),
        ({"mass": 0.1, "friction": "a lot"}, "mm", "dynamics.friction"),
        ({"mass": 0.1}, "furlong", "units"),
    ],
)
def test_design_file_bad_dynamics(table, units, field):
    with pytest.raises(InputError) as e:
        design_from_dict(rocker_dict(dynamics=table, units=units))
    assert e.value.field == field and "\n" not in str(e.value)
