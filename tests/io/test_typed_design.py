"""A design built in Python carries everything a design file can: the same design, the same outputs.

Each example of ``examples/`` is written here as Python objects (no file, no dict) and compared with what
:func:`cams.io.designfile.load_design` makes of the file; a rocker cam with every optional table
(``[solve] objective``, ``[profile]``, ``[cam] bore_radius``, ``[dynamics]``) too. The options are typed
fields checked by the model, with the message the file's key gets.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from cams.cam import Cam
from cams.io.designfile import design_from_dict, load_design
from cams.model.contact import ContactSpec
from cams.model.design import CamDesign, FlatFaceDesign, Limits
from cams.model.dynamics import DynamicsSpec, FollowerDynamics, Spring
from cams.model.follower import Rocker, Translating
from cams.model.motiondesign import MotionDesignSpec
from cams.model.options import ProfileOptions
from cams.profile.flat import FlatRocker, FlatTranslating
from laws.errors import InputError
from laws.program import Phase, Program
from laws.registry import get_law

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CW, CCW = -1, 1


def program(lift: float, *phases: tuple) -> Program:
    """Phases as ``(kind, degrees, law name or None)``, the angles scaled to sum to 2 pi as a file's are."""
    angles = np.radians([p[1] for p in phases])
    angles *= 2 * np.pi / angles.sum()
    return Program(tuple(Phase(p[0], float(a), None if p[2] is None else get_law(p[2]))
                         for p, a in zip(phases, angles, strict=True)), lift)


def _cycle(rise: str, rise_deg: float, dwell_deg: float, ret: str, ret_deg: float) -> tuple:
    return (("rise", rise_deg, rise), ("dwell", dwell_deg, None), ("return", ret_deg, ret),
            ("dwell", 360.0 - rise_deg - dwell_deg - ret_deg, None))


BUILT = {
    "rocker_force": CamDesign(
        Rocker(125.0, 10.0, sense=CW), program(np.radians(15.0), *_cycle("cycloidal", 120, 30, "cycloidal", 120)),
        Limits(np.radians(45.0), closure="force", safety_factor=1.0), cam_sense=CCW, rpm=60.0,
        name="rocker cam, force closure", method="exact"),
    "rocker_form": CamDesign(
        Rocker(125.0, 10.0, sense=CW), program(np.radians(15.0), *_cycle("poly345", 120, 30, "cycloidal", 100)),
        Limits(np.radians(45.0), np.radians(50.0), closure="form", safety_factor=1.1), cam_sense=CCW,
        name="rocker groove cam, form closure", method="exact"),
    "translating_force": CamDesign(
        Translating(8.0, stroke_scale=30.0), program(30.0, *_cycle("poly4567", 150, 30, "cycloidal", 120)),
        Limits(np.radians(30.0)), cam_sense=CCW, name="translating roller cam"),
    "translating_train": CamDesign(
        Translating(8.0, stroke_scale=30.0), program(30.0, *_cycle("poly4567", 150, 30, "cycloidal", 120)),
        Limits(np.radians(30.0)), cam_sense=CCW, rpm=300.0, name="translating roller cam with a train",
        dynamics=DynamicsSpec(FollowerDynamics(0.5, load=5.0, train_stiffness=2.0e5, damping_ratio=0.05),
                              margin=1.5)),
    "translating_designed_rise": CamDesign(
        Translating(8.0, stroke_scale=30.0), program(30.0, *_cycle("poly4567", 150, 30, "cycloidal", 120)),
        Limits(np.radians(30.0)), cam_sense=CCW, name="translating roller cam, rise designed",
        optimize=MotionDesignSpec(free=("rise",), objective="R0", max_Ca=("poly4567",), max_Cj=("poly4567",),
                                  continuity=3, degree=7, spans=20, smoothing_slack=0.001)),
    "translating_form_centric": CamDesign(
        Translating(6.0, offset=0.0, stroke_scale=20.0), program(20.0, *_cycle("cycloidal", 120, 60, "poly345", 120)),
        Limits(np.radians(30.0), closure="form"), cam_sense=CW, name="centric translating groove cam"),
    "slotting_feed_cam": CamDesign(
        Rocker(125.0, 15.0, sense=CW), program(np.radians(15.0), *_cycle("parabolic", 60, 10, "harmonic", 60)),
        Limits(np.radians(40.0)), cam_sense=CCW, rpm=60.0, name="slotting machine feed cam",
        dynamics=DynamicsSpec(FollowerDynamics(0.003, load=0.5, friction=0.1, journal_radius=8.0), margin=1.5,
                              rate=3.0)),
    "slotting_feed_cam_train": CamDesign(
        Rocker(125.0, 15.0, sense=CW), program(np.radians(15.0), *_cycle("parabolic", 60, 10, "harmonic", 60)),
        Limits(np.radians(40.0)), cam_sense=CCW, rpm=60.0, name="slotting machine feed cam with its follower train",
        dynamics=DynamicsSpec(FollowerDynamics(0.003, load=0.5, friction=0.1, journal_radius=8.0,
                                               train_stiffness=2000.0, damping_ratio=0.02), margin=1.5, rate=3.0)),
    "translating_flat": FlatFaceDesign(
        FlatTranslating(0.0, stroke_scale=20.0), program(20.0, *_cycle("cycloidal", 120, 60, "poly345", 120)),
        min_radius=10.0, cam_sense=CCW, rpm=120.0, name="translating flat-face cam",
        dynamics=DynamicsSpec(FollowerDynamics(0.5, load=1.0, friction=0.1, face_friction=0.08))),
    "rocker_flat": FlatFaceDesign(
        FlatRocker(120.0, 0.0, sense=CW), program(np.radians(15.0), *_cycle("cycloidal", 120, 40, "poly345", 120)),
        min_radius=5.0, cam_sense=CCW, rpm=60.0, name="rocker flat-face cam",
        dynamics=DynamicsSpec(FollowerDynamics(0.004, load=0.05, friction=0.1, journal_radius=6.0,
                                               face_friction=0.08))),
    "translating_contact": CamDesign(
        Translating(12.0, stroke_scale=30.0), program(30.0, *_cycle("poly4567", 150, 30, "cycloidal", 120)),
        Limits(np.radians(30.0), min_base_radius=30.0), cam_sense=CCW, rpm=300.0,
        name="translating roller cam, contact stress",
        dynamics=DynamicsSpec(FollowerDynamics(1.2, load=300.0, friction=0.05)), width=12.0,
        contact=ContactSpec(cam_material="through_hardened_steel", follower_material="bearing_steel",
                            cam_roughness=0.4, follower_roughness=0.2, viscosity=0.19, pressure_viscosity=20.0,
                            min_film_parameter=1.0, bearing_rating=3500.0, bearing_rating_type="track_roller",
                            life_hours=5000.0)),
    "rocker_contact": CamDesign(
        Rocker(125.0, 10.0, sense=CW), program(np.radians(15.0), *_cycle("cycloidal", 120, 30, "cycloidal", 120)),
        Limits(np.radians(45.0), min_base_radius=40.0), cam_sense=CCW, rpm=250.0, name="rocker cam, contact stress",
        dynamics=DynamicsSpec(FollowerDynamics(0.004, load=100.0, friction=0.05, journal_radius=8.0)), width=10.0,
        contact=ContactSpec(cam_material="case_hardened_steel", follower_material="bearing_steel",
                            cam_roughness=0.3, follower_roughness=0.2, viscosity=0.19, pressure_viscosity=20.0,
                            bearing_rating=6000.0, bearing_rating_type="track_roller", life_hours=8000.0)),
    "translating_flat_contact": FlatFaceDesign(
        FlatTranslating(0.0, stroke_scale=20.0), program(20.0, *_cycle("cycloidal", 120, 60, "poly345", 120)),
        min_radius=10.0, min_base_radius=65.0, cam_sense=CCW, rpm=300.0,
        name="translating flat-face cam, contact stress",
        dynamics=DynamicsSpec(FollowerDynamics(0.5, load=100.0, friction=0.1, face_friction=0.08)), width=10.0,
        contact=ContactSpec(cam_material="nitrided_steel", follower_material="case_hardened_steel",
                            cam_roughness=0.3, follower_roughness=0.3, viscosity=0.19, pressure_viscosity=20.0,
                            min_film_parameter=0.5)),
}


def test_every_example_is_built():
    assert sorted(BUILT) == sorted(p.stem for p in EXAMPLES.glob("*.toml"))


@pytest.mark.parametrize("name", sorted(BUILT))
def test_an_example_built_in_python_is_the_file_s_design(name):
    loaded = load_design(EXAMPLES / f"{name}.toml")
    built = BUILT[name]
    # field by field first, so that a difference names its field
    for f in dataclasses.fields(built):
        assert getattr(built, f.name) == getattr(loaded, f.name), f.name
    assert built == loaded


@pytest.mark.parametrize("name", ["rocker_force", "slotting_feed_cam", "translating_flat", "rocker_flat",
                                  "translating_designed_rise", "rocker_contact", "translating_flat_contact",
                                  "translating_train"])
def test_an_example_built_in_python_gives_the_file_s_outputs(name):
    a, b = Cam(BUILT[name]), Cam(load_design(EXAMPLES / f"{name}.toml"))
    assert _solved(a) == _solved(b)
    assert a.checks.to_dict() == b.checks.to_dict()
    assert a.assessment.to_dict() == b.assessment.to_dict()
    if a.forces is not None or b.forces is not None:
        assert a.forces.to_dict() == b.forces.to_dict()
    if a.contact is not None or b.contact is not None:
        assert a.contact.to_dict() == b.contact.to_dict()
    if a.vibration is not None or b.vibration is not None:
        assert a.vibration.to_dict() == b.vibration.to_dict()


def _solved(cam: Cam) -> dict:
    """The solution's report less its run time."""
    out = {k: v for k, v in cam.solution.to_dict().items() if k != "seconds"}
    if "optimize" in out:  # the motion design's run time too
        out["optimize"] = {k: v for k, v in out["optimize"].items() if k != "seconds"}
    return out


def _every_option() -> tuple[CamDesign, dict]:
    """A rocker cam with every optional table, in Python and as a file's tables."""
    import tomllib

    d = tomllib.loads((EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8"))
    d["cam"]["bore_radius"] = 4.0
    d["solve"]["objective"] = "L"
    d["profile"] = {"tolerance": 0.002, "min_curvature_radius": 1.5}
    d["dynamics"] = {"mass": 0.004, "load": 0.5, "spring_rate": 2.0, "preload": 0.3, "friction": 0.1,
                     "journal_radius": 6.0, "max_spring_force": 40.0}
    built = dataclasses.replace(
        BUILT["rocker_force"], objective="L", tolerance=0.002, min_curvature_radius=1.5, bore_radius=4.0,
        dynamics=DynamicsSpec(FollowerDynamics(0.004, load=0.5, spring=Spring(2.0, 0.3), friction=0.1,
                                               journal_radius=6.0, max_spring_force=40.0)))
    return built, d


def test_every_option_built_in_python_as_in_a_file():
    built, d = _every_option()
    loaded = design_from_dict(d)
    assert built == loaded
    assert Cam(built).options == Cam(loaded).options == ProfileOptions(0.002, 1.5, 4.0)
    a, b = Cam(built), Cam(loaded)
    assert _solved(a) == _solved(b) and _solved(a)["L"] < 134.0  # L minimized (134.69 for the least R0)
    assert a.checks.to_dict() == b.checks.to_dict() and a.checks.to_dict()["bore_radius"] == 4.0
    assert a.forces.to_dict() == b.forces.to_dict()


@pytest.mark.parametrize("change, field, words", [
    ({"objective": "Q"}, "solve.objective", "'Q' is not a valid option, must be one of 'R0', 'L'"),
    ({"tolerance": 0.0}, "profile.tolerance", "chord tolerance must be a number > 0 (length unit), got 0.0"),
    ({"min_curvature_radius": -1.0}, "profile.min_curvature_radius", "must be a number > 0, got -1.0"),
    ({"bore_radius": float("nan")}, "cam.bore_radius", "must be a number > 0, got nan"),
    ({"base_radius": 20.0, "objective": "L"}, "solve.objective", "nothing is minimized"),
])
def test_the_model_checks_each_option_with_the_file_s_message(change, field, words):
    with pytest.raises(InputError) as e:
        dataclasses.replace(BUILT["rocker_force"], **({"limits": Limits(np.radians(45.0), centre_distance=120.0)}
                                                       if "base_radius" in change else {}), **change)
    assert e.value.field == field and words in str(e.value)


def test_a_translating_follower_refuses_L_and_a_journal_in_the_api():
    t = BUILT["translating_force"]
    with pytest.raises(InputError, match="solve.objective: 'L' .* applies to rocker followers"):
        dataclasses.replace(t, objective="L")
    with pytest.raises(InputError, match="dynamics.journal_radius: applies to a rocker's pivot journal"):
        dataclasses.replace(t, dynamics=DynamicsSpec(FollowerDynamics(0.5, journal_radius=5.0)))
    with pytest.raises(InputError, match="dynamics.margin: must be >= 1"):
        DynamicsSpec(FollowerDynamics(0.5), margin=0.5)


@pytest.mark.parametrize("bad", [10**400, float("nan"), "3", True, -1.0])
def test_a_flat_follower_built_in_python_refuses_a_bad_length_in_one_line(bad):
    """The model's length check is laws.errors' number check: a 400-digit integer was a TypeError from numpy."""
    from cams.model.follower import FlatRocker

    with pytest.raises(InputError, match=r"^follower\.centre_distance: must be a number > 0, got "):
        FlatRocker(centre_distance=bad)
