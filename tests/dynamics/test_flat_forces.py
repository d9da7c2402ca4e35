"""Forces of flat-faced followers, checked against the sampled profile by mechanics written here.

Nothing here uses the implementation's formulas (:mod:`cams.dynamics.flat_forces`): the contact point is the
generated profile's (:func:`cams.profile.flat.flat_face_cam`, turned with the cam), every velocity is a central
difference of positions, the face's direction is the profile's tangent at the contact, and the laws are the
definitions:

* power: the shaft's power ``T omega`` equals the power the cam's push delivers to the follower plus the power the
  sliding friction dissipates, ``mu_f N |v_sl|``, with ``v_sl`` the cam's material velocity at the contact less
  the face's;
* a rocker's moment balance about its pivot: the moment of the push (lever arms from the profile's contact point),
  less the pivot's friction, drives the inertia, the spring and the load; a translating face's force balance along
  its axis likewise;
* the jump speed: the lowest speed at which the contact force, computed here from the motion read off the profile,
  touches zero somewhere, by bisection.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from cams.cam import Cam
from cams.cli import main
from cams.dynamics.flat_forces import flat_cam_forces
from cams.dynamics.forces import chosen_spring
from cams.io.designfile import design_from_dict
from cams.io.document import read_toml
from cams.model.design import FlatFaceDesign
from cams.model.dynamics import DynamicsSpec, FollowerDynamics, Spring
from cams.model.follower import FlatTranslating
from cams.profile.flat import flat_face_cam
from cams.solve import solve
from laws.errors import InputError
from tests.conftest import EXAMPLES

H = 1e-4  # the central differences' step in cam angle, rad
MM = 1e-3  # metres per mm


def _design(name: str, **over) -> FlatFaceDesign:
    d = read_toml(EXAMPLES / name)
    for table, values in over.items():
        d[table] = {**d.get(table, {}), **values}
    design = design_from_dict(d)
    assert isinstance(design, FlatFaceDesign)
    return design


def _rot(angle: np.ndarray, v: np.ndarray) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def _grid(n: int = 360) -> np.ndarray:
    """Cam angles off the phase joints (the joints of the examples are whole degrees)."""
    return np.linspace(0.0, 2 * np.pi, n, endpoint=False) + np.radians(0.3711)


class Mechanics:
    """The contact read off the generated profile at cam angles ``phi`` (fixed frame, mm; per radian of cam).

    A translating face's height and its rates are the contact point's ``y`` and its central differences; a rocker's
    swing and its rates are the program's (the motion the design asks for), its face turning about the pivot.
    """

    def __init__(self, design: FlatFaceDesign, R0: float, phi: np.ndarray):
        self.design, self.phi = design, phi
        eps = design.cam_sense
        fo = design.follower
        # the cam centre in the frame of the profile's axes at phi = 0 (the follower's frame, or a rocker's
        # line-of-centres frame with the pivot at the origin)
        self.rocker = not isinstance(fo, FlatTranslating)
        self.O = np.array([fo.centre_distance, 0.0]) if self.rocker else np.array([-fo.offset, -R0])
        Xm, X, Xp = (
            self.O + _rot(eps * (phi + d), flat_face_cam(design, R0, phi=phi + d).point) for d in (-H, 0.0, H)
        )  # the cam turned by eps phi: the fixed frame
        self.X = X
        # the profile's tangent at the contact, turned into the fixed frame: the face's direction
        dP = (flat_face_cam(design, R0, phi=phi + H).point - flat_face_cam(design, R0, phi=phi - H).point) / (2 * H)
        t = _rot(eps * phi, dP)
        self.t = t / np.linalg.norm(t, axis=-1, keepdims=True)
        m = np.stack([self.t[:, 1], -self.t[:, 0]], axis=-1)
        self.m = m * np.sign(np.sum((X - self.O) * m, axis=-1))[:, None]  # away from the cam
        self.v_cam = eps * np.stack([-(X - self.O)[:, 1], (X - self.O)[:, 0]], axis=-1)
        if self.rocker:
            mo = design.program.evaluate(phi)
            self.q, self.dq, self.d2q = mo.s, mo.ds, mo.d2s
            sigma = fo.sense
            self.v_face = sigma * self.dq[:, None] * np.stack([-X[:, 1], X[:, 0]], axis=-1)
        else:
            self.q = X[:, 1] * MM  # the face's height: the contact's y, m
            self.dq = (Xp[:, 1] - Xm[:, 1]) / (2 * H) * MM
            self.d2q = (Xp[:, 1] - 2 * X[:, 1] + Xm[:, 1]) / H**2 * MM
            self.v_face = np.stack([np.zeros_like(phi), self.dq / MM], axis=-1)
        self.v_sl = self.v_cam - self.v_face  # mm per rad of cam angle
        # contact holds: the sliding is along the face
        assert np.max(np.abs(np.sum(self.v_sl * self.m, axis=-1))) < 1e-6 * np.max(np.abs(self.v_sl))

    def push(self, N: np.ndarray, mu_f: float) -> np.ndarray:
        """The cam's push on the follower: N along the normal, the sliding friction dragging the face along."""
        drag = np.sign(np.sum(self.v_sl * self.t, axis=-1))[:, None] * self.t
        return N[:, None] * (self.m + mu_f * drag)

    def driving(self, push: np.ndarray) -> np.ndarray:
        """The push's generalized force along the rise: a rocker's moment about its pivot (the origin; lever arms
        from the contact point), N m, or a translating face's force along its axis, N."""
        if self.rocker:
            return self.design.follower.sense * (self.X[:, 0] * push[:, 1] - self.X[:, 1] * push[:, 0]) * MM
        return push[:, 1]

    def rubbing(self, push: np.ndarray, dyn: FollowerDynamics) -> np.ndarray:
        """The guide's or pivot's friction against the motion: mu times the guide's lateral load, or mu r_j times
        the journal's load (the push), N or N m; none where the follower stands."""
        moving = np.where(np.abs(self.dq) > 1e-9, np.sign(self.dq), 0.0)
        if self.rocker:
            return dyn.friction * dyn.journal_radius * MM * np.linalg.norm(push, axis=-1) * moving
        return dyn.friction * np.abs(push[:, 0]) * moving

    def resisting(self, dyn: FollowerDynamics, w: float) -> np.ndarray:
        """Inertia, spring and load along the rise at the cam speed ``w`` (rad/s)."""
        assert dyn.spring is not None
        return dyn.mass * w**2 * self.d2q + dyn.spring.force(self.q) + dyn.load


CASES = [
    (
        "translating_flat.toml",
        {},
        dict(mass=0.5, load=1.0, spring=Spring(800.0, 12.0), friction=0.1, face_friction=0.08),
    ),
    (
        "translating_flat.toml",
        {"cam": {"rotation": "cw"}, "follower": {"offset": 6.0}},
        dict(mass=0.3, load=-2.0, spring=Spring(1500.0, 20.0), friction=0.2, face_friction=0.15),
    ),
    (
        "rocker_flat.toml",
        {},
        dict(mass=0.004, load=0.05, spring=Spring(2.0, 0.3), friction=0.1, journal_radius=6.0, face_friction=0.08),
    ),
    (
        "rocker_flat.toml",
        {"follower": {"face_offset": 12.0, "rise_direction": "ccw"}, "cam": {"rotation": "cw"}},
        dict(mass=0.01, load=0.2, spring=Spring(5.0, 0.5), friction=0.15, journal_radius=8.0, face_friction=0.2),
    ),
    (
        "rocker_flat.toml",
        {"follower": {"face_offset": -10.0}},
        dict(mass=0.01, load=0.0, spring=Spring(1.0, 0.8), friction=0.0, face_friction=0.1),
    ),
]


@pytest.fixture(scope="module", params=range(len(CASES)), ids=lambda i: f"{CASES[i][0]}-{i}")
def case(request):
    name, over, kw = CASES[request.param]
    design = _design(name, **over)
    R0 = float(solve(design).R0)
    phi = _grid()
    dyn = FollowerDynamics(**kw)
    return design, R0, phi, dyn, Mechanics(design, R0, phi), flat_cam_forces(design, R0, dyn, phi=phi)


def test_camshaft_torque_by_the_power_balance(case):
    design, R0, phi, dyn, mech, cf = case
    N = cf.contact
    assert np.all(N > 0)
    push = mech.push(N, dyn.face_friction)
    follower_power = np.sum(push * mech.v_face, axis=-1)  # N mm per rad of cam
    loss = dyn.face_friction * N * np.linalg.norm(mech.v_sl, axis=-1)
    T = (follower_power + loss) * MM  # T omega = power, per omega
    assert cf.torque == pytest.approx(T, rel=1e-5, abs=1e-8 * np.max(np.abs(T)))
    # the sliding loss is the difference of the shaft's and the follower's power: the torque includes it
    if dyn.face_friction > 0:
        assert np.mean(cf.torque) > np.mean(follower_power * MM)
    w = cf.omega
    assert cf.sliding_loss == pytest.approx(loss * MM * w, rel=1e-6, abs=1e-12)
    assert np.abs(cf.sliding) == pytest.approx(np.linalg.norm(mech.v_sl, axis=-1) * MM * w, rel=1e-6, abs=1e-12)
    rep = cf.to_dict()
    assert rep["max_sliding_speed"] == pytest.approx(np.max(np.linalg.norm(mech.v_sl, axis=-1)) * MM * w, rel=1e-6)
    assert rep["mean_sliding_loss"] == pytest.approx(np.mean(loss) * MM * w, rel=1e-6)
    assert rep["jammed"] is None and rep["jamming_limit_deg"] is None


def test_moment_or_force_balance_of_the_follower(case):
    """A rocker's moments about its pivot (lever arms from the profile's contact point) or a translating face's
    forces along its axis balance with the contact force computed."""
    design, R0, phi, dyn, mech, cf = case
    push = mech.push(cf.contact, dyn.face_friction)
    resist = mech.resisting(dyn, cf.omega)
    assert mech.driving(push) - mech.rubbing(push, dyn) == pytest.approx(
        resist, rel=1e-6, abs=1e-7 * np.max(np.abs(resist))
    )
    assert np.abs(cf.force) == pytest.approx(np.linalg.norm(push, axis=-1), rel=1e-6)
    if not mech.rocker:
        assert cf.lateral == pytest.approx(np.abs(push[:, 0]), rel=1e-6)  # what the guide takes


def _independent_contact(rpm: float, dyn: FollowerDynamics, mech: Mechanics) -> np.ndarray:
    """The contact force of the test's own balance at ``rpm`` (as :func:`test_moment_or_force_balance_of_the_follower`,
    linear in the contact force: solved with the push of a unit force)."""
    unit = mech.push(np.ones_like(mech.phi), dyn.face_friction)
    return mech.resisting(dyn, rpm * 2 * np.pi / 60) / (mech.driving(unit) - mech.rubbing(unit, dyn))


@pytest.mark.parametrize("name", ["translating_flat.toml", "rocker_flat.toml"])
def test_the_examples_print_spring_contact_force_torque_and_jump_speed(capsys, name):
    """``cams solve`` on each flat example: its numbers against the test's own mechanics."""
    assert main(["solve", str(EXAMPLES / name), "--json"]) == 0
    fo = json.loads(capsys.readouterr().out)["forces"]
    assert main(["solve", str(EXAMPLES / name)]) == 0
    text = capsys.readouterr().out
    for words in (
        "spring: rate",
        "contact force: max",
        "largest driving torque",
        "largest braking torque",
        "follower jumps above",
        "sliding at the face",
    ):
        assert words in text
    cam = Cam.from_file(EXAMPLES / name)
    design, R0 = cam.design, float(cam.solution.R0)
    assert isinstance(design, FlatFaceDesign) and design.rpm
    spec = design.dynamics
    assert spec is not None
    spring = chosen_spring(spec, design)
    assert fo["spring"]["rate"] == spring.rate and fo["spring"]["preload"] == spring.preload
    dyn = spec.dynamics.with_spring(spring)
    # the reported extremes are the forces' on the default grid of 720 cam angles a turn
    grid = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)
    mech = Mechanics(design, R0, grid)
    N = _independent_contact(design.rpm, dyn, mech)
    assert fo["max_contact_force"] == pytest.approx(np.max(N), rel=1e-5)
    assert fo["min_contact_force"] == pytest.approx(np.min(N), rel=1e-5)
    push = mech.push(N, dyn.face_friction)
    T = (np.sum(push * mech.v_face, axis=-1) + dyn.face_friction * N * np.linalg.norm(mech.v_sl, axis=-1)) * MM
    k = int(np.argmax(np.abs(T)))
    assert fo["max_torque"] == pytest.approx(T[k], rel=1e-5)
    assert fo["max_torque_at_deg"] == pytest.approx(np.degrees(grid[k]), abs=1e-5)
    assert fo["mean_torque"] == pytest.approx(np.mean(T), rel=1e-4)
    # the largest driving (T > 0) and braking (T < 0) torques and their cam angles
    kd, kb = int(np.argmax(T)), int(np.argmin(T))
    assert fo["max_driving_torque"] == pytest.approx(T[kd], rel=1e-5)
    assert fo["max_driving_torque_at_deg"] == pytest.approx(np.degrees(grid[kd]), abs=1e-5)
    assert fo["max_braking_torque"] == pytest.approx(T[kb], rel=1e-5) and T[kb] < 0
    assert fo["max_braking_torque_at_deg"] == pytest.approx(np.degrees(grid[kb]), abs=1e-5)
    assert fo["jammed"] is None and fo["jamming_limit_deg"] is None and fo["contact_lost"] is False
    # the jump speed: the speed at which the independent contact force first touches 0, by bisection
    dense = _grid(7200)
    mech = Mechanics(design, R0, dense)
    lo, hi = float(design.rpm), 50.0 * float(design.rpm)
    assert np.min(_independent_contact(lo, dyn, mech)) > 0
    assert np.min(_independent_contact(hi, dyn, mech)) < 0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if np.min(_independent_contact(mid, dyn, mech)) > 0 else (lo, mid)
    assert fo["jump_rpm"] == pytest.approx(lo, rel=1e-4)
    assert fo["jump_rpm"] > design.rpm  # the chosen spring holds at the design's speed
    # said in the text, with units
    assert f"follower jumps above {fo['jump_rpm']:.6g} rpm" in text


def test_frictionless_translating_torque_is_the_lift_rate_times_the_force():
    """Without friction the face pushes along the axis only: T = N ds/dphi (a closed form of the definition)."""
    design = _design("translating_flat.toml")
    R0 = float(solve(design).R0)
    phi = _grid(97)
    dyn = FollowerDynamics(0.5, 1.0, Spring(500.0, 10.0))
    cf = flat_cam_forces(design, R0, dyn, phi=phi)
    mo = design.program.evaluate(phi)
    assert cf.torque == pytest.approx(cf.contact * mo.ds * MM, rel=1e-12, abs=1e-15)
    assert cf.contact == pytest.approx(0.5 * cf.omega**2 * mo.d2s * MM + 10.0 + 500.0 * mo.s * MM + 1.0, rel=1e-12)


def test_friction_that_locks_the_follower_is_refused():
    design = _design("translating_flat.toml")
    R0 = float(solve(design).R0)
    dyn = FollowerDynamics(0.5, 1.0, Spring(500.0, 10.0), friction=2.0, face_friction=0.6)
    with pytest.raises(
        InputError, match=r"^dynamics\.face_friction: the follower locks at cam angle .* the friction outweighs"
    ):
        flat_cam_forces(design, R0, dyn)


@pytest.mark.parametrize(
    "kw, field",
    [
        (dict(face_friction=-0.01), "dynamics.face_friction"),
        (dict(face_friction=float("inf")), "dynamics.face_friction"),
        (dict(face_friction="0.1"), "dynamics.face_friction"),
    ],
)
def test_bad_face_friction_in_the_api(kw, field):
    with pytest.raises(InputError, match=rf"^{field}: "):
        FollowerDynamics(0.5, **kw)


def test_journal_radius_of_a_translating_face_is_refused_in_the_api():
    design = _design("translating_flat.toml")
    spec = DynamicsSpec(FollowerDynamics(0.5, journal_radius=5.0))
    with pytest.raises(InputError, match=r"^dynamics\.journal_radius: applies to a rocker's pivot"):
        FlatFaceDesign(design.follower, design.program, design.min_radius, dynamics=spec)
    rocker = _design("rocker_flat.toml")
    FlatFaceDesign(rocker.follower, rocker.program, rocker.min_radius, dynamics=spec)  # a rocker takes it


def test_face_friction_of_a_roller_is_refused_in_the_api():
    from cams.model.design import CamDesign

    roller = Cam.from_file(EXAMPLES / "slotting_feed_cam.toml").design
    assert isinstance(roller, CamDesign) and roller.dynamics is not None
    spec = DynamicsSpec(FollowerDynamics(0.5, face_friction=0.1))
    with pytest.raises(InputError, match=r"^dynamics\.face_friction: applies to a flat-faced follower"):
        roller.with_(dynamics=spec)


def test_the_flat_face_needs_cam_rpm_for_its_forces(capsys):
    d = read_toml(EXAMPLES / "translating_flat.toml")
    del d["cam"]["rpm"]
    cam = Cam(design_from_dict(d))
    assert cam.forces is None and cam.forces_note == "[dynamics] needs cam.rpm for the forces"


@pytest.mark.parametrize("name", ["translating_flat.toml", "rocker_flat.toml"])
def test_the_report_and_the_text_say_the_flat_forces_with_units(capsys, name):
    from cams.dynamics.jump import jump_text
    from cams.present.report import report_sections

    assert main(["solve", str(EXAMPLES / name), "--json"]) == 0
    fo = json.loads(capsys.readouterr().out)["forces"]
    assert main(["solve", str(EXAMPLES / name)]) == 0
    text = capsys.readouterr().out
    sliding = f"up to {fo['max_sliding_speed']:.6g} m/s, mean friction loss {fo['mean_sliding_loss']:.6g} W"
    assert f"sliding at the face: {sliding}" in text and "jammed: cannot (a flat face)" in text
    sections = dict(report_sections(Cam.from_file(EXAMPLES / name)))
    rows = dict(sections["Forces at the cam"])
    assert rows["sliding at the face"] == sliding
    assert rows["jump speed"].startswith(jump_text(fo["jump_rpm"]))
    assert rows["contact lost"] == "no" and "contact lost / jammed" not in rows
    unit = "N m/rad" if "rocker" in name else "N/m"
    assert f" {unit}, preload " in rows["closing spring"]
