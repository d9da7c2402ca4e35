"""Design files: the schema of the issue works as written; bad input names its field."""

import numpy as np
import pytest

from cams.io.designfile import design_from_dict, load_design
from cams.model.follower import Rocker, Translating
from laws.errors import InputError
from tests.conftest import EXAMPLES, rocker_dict


def test_examples_load():
    for p in sorted(EXAMPLES.glob("*.toml")):
        d = load_design(p)
        assert d.program.starts[-1] == pytest.approx(2 * np.pi, abs=1e-12)


def test_schema_values_and_units():
    d = design_from_dict(rocker_dict(limits={"safety_factor": 1.1, "centre_distance": 115.0}))
    assert isinstance(d.follower, Rocker) and d.follower.sense == -1 and d.cam_sense == 1
    assert d.program.lift == pytest.approx(np.radians(15))
    assert d.limits.pressure_angle == pytest.approx(np.pi / 4)
    assert d.program.phases[3].angle == pytest.approx(np.radians(90))  # the remainder
    assert d.limits.centre_distance == 115.0


@pytest.mark.parametrize(
    "over, field",
    [
        ({"limits": {"pressure_angle": 90}}, "limits.pressure_angle"),
        ({"limits": {"pressure_angle": 0}}, "limits.pressure_angle"),
        ({"limits": {"return_pressure_angle": -5}}, "limits.return_pressure_angle"),
        ({"limits": {"safety_factor": 0.9}}, "limits.safety_factor"),
        ({"limits": {"closure": "glue"}}, "limits.closure"),
        ({"limits": {"centre_distance": -1.0}}, "limits.centre_distance"),
        ({"follower": {"swing": 180.0}}, "follower.swing"),
        ({"follower": {"arm": 0.0}}, "follower.arm"),
        ({"follower": {"rise_direction": "up"}}, "follower.rise_direction"),
        ({"follower": {"stroke": 10.0}}, "follower.stroke"),
        ({"follower": {"kind": "sliding"}}, "follower.kind"),
        ({"cam": {"rotation": "left"}}, "cam.rotation"),
        ({"cam": {"rpm": -3}}, "cam.rpm"),
        ({"solve": {"method": "magic"}}, "solve.method"),
        ({"solve": {"samples": 1}}, "solve.samples"),
        ({"limits": {"pressure_angle": "45"}}, "limits.pressure_angle"),
        ({"limitz": {}}, "design"),
    ],
)
def test_bad_values_name_the_field(over, field):
    with pytest.raises(InputError) as e:
        design_from_dict(rocker_dict(**over))
    assert str(e.value).startswith(field)


def test_motion_errors():
    bad = rocker_dict()
    bad["motion"] = [{"phase": "rise", "law": "cycloidal", "angle": 120}, {"phase": "dwell", "angle": 30},
                     {"phase": "return", "law": "cycloidal", "angle": 120}, {"phase": "dwell", "angle": 100}]
    with pytest.raises(InputError, match="motion: phase angles sum to 370"):
        design_from_dict(bad)
    bad["motion"][3]["angle"] = -10
    with pytest.raises(InputError, match=r"motion\[3\].angle"):
        design_from_dict(bad)
    bad["motion"][3] = {"phase": "dwell"}
    bad["motion"][0]["law"] = "sinusoid"
    with pytest.raises(InputError, match=r"motion\[0\].law.*unknown law"):
        design_from_dict(bad)
    bad["motion"][0] = {"phase": "rise", "angle": 120}
    with pytest.raises(InputError, match=r"motion\[0\].law"):
        design_from_dict(bad)


def test_translating_rejects_rocker_keys_and_kc():
    t = {"follower": {"kind": "translating", "stroke": 10.0, "arm": 5.0},
         "motion": rocker_dict()["motion"], "limits": {"pressure_angle": 30}}
    with pytest.raises(InputError, match="follower.arm"):
        design_from_dict(t)
    t["follower"].pop("arm")
    d = design_from_dict(t)
    assert isinstance(d.follower, Translating) and d.follower.offset is None
    t["limits"]["safety_factor"] = 1.2
    with pytest.raises(InputError, match="limits.safety_factor"):
        design_from_dict(t)


def test_unreadable_and_invalid_files(tmp_path):
    with pytest.raises(InputError, match="cannot read"):
        load_design(tmp_path / "missing.toml")
    p = tmp_path / "bad.toml"
    p.write_text("name = [")
    with pytest.raises(InputError, match="not valid TOML"):
        load_design(p)


def test_units_other_than_mm_are_refused():
    with pytest.raises(InputError, match="^units"):
        design_from_dict({**rocker_dict(), "units": "m"})
    assert design_from_dict({**rocker_dict(), "units": "mm"}).follower.arm == 125.0


def _motion(*phases):
    return [dict(p) for p in phases]


RISE = {"phase": "rise", "law": "cycloidal", "angle": 120}
RET = {"phase": "return", "law": "cycloidal", "angle": 120}


@pytest.mark.parametrize(
    "motion, message",
    [
        # a rocker's heights and levels are in degrees in the messages, as in the file (swing 15 deg)
        (_motion(RISE, {"phase": "dwell"}), "motion: the follower ends the cycle 15 degrees above where it started"),
        (_motion({**RISE, "height": -5}, {"phase": "dwell"}), "motion[0].height: must be in (0, 15] degrees (the swing), got -5"),
        (_motion({**RISE, "height": 20}, RET, {"phase": "dwell"}), "motion[0].height: must be in (0, 15] degrees"),
        (_motion({**RISE, "height": 5}, {**RET, "height": 10}, {"phase": "dwell"}), "motion[1]: takes the follower to -5 degrees"),
        (_motion({**RISE, "height": 10}, {**RET, "height": 10}, {"phase": "dwell"}), "motion: the follower reaches only 10 degrees, the swing is 15"),
        (_motion(RISE, {"phase": "dwell", "angle": 59.99999}, RET, {"phase": "dwell", "angle": 60}),
         "motion: phase angles sum to 359.99999 degrees, must sum to 360"),
        (_motion(RISE, {"phase": "dwell", "height": 3}, RET, {"phase": "dwell"}), "motion[1].height: a dwell takes no height"),
    ],
)
def test_motion_messages_in_the_files_units(motion, message):
    d = rocker_dict()
    d["motion"] = motion
    with pytest.raises(InputError) as e:
        design_from_dict(d)
    assert str(e.value).startswith(message), str(e.value)
    assert "np.float64" not in str(e.value) and "0.2617" not in str(e.value)


def test_heights_in_degrees_become_radians():
    d = rocker_dict()
    d["motion"] = _motion({**RISE, "height": 5}, {"phase": "dwell", "angle": 10}, {**RISE, "height": 10},
                          {"phase": "dwell", "angle": 10}, {**RET, "angle": 100})
    p = design_from_dict(d).program
    assert p.phases[0].height == pytest.approx(np.radians(5)) and p.phases[2].height == pytest.approx(np.radians(10))


def test_return_limit_needs_form_closure():
    with pytest.raises(InputError) as e:
        design_from_dict(rocker_dict(limits={"return_pressure_angle": 40}))
    assert str(e.value).startswith("limits.return_pressure_angle: applies to form closure")
    d = design_from_dict(rocker_dict(limits={"return_pressure_angle": 40, "closure": "form"}))
    assert d.limits.return_pressure_angle == pytest.approx(np.radians(40))


@pytest.mark.parametrize("table, key, value", [("follower", "arm", 1e300), ("follower", "roller_radius", 1e-12),
                                               ("limits", "centre_distance", 2e9), ("cam", "bore_radius", 1e12)])
def test_lengths_outside_the_usable_range(table, key, value):
    with pytest.raises(InputError) as e:
        design_from_dict(rocker_dict(**{table: {key: value}}))
    assert str(e.value).startswith(f"{table}.{key}: ") and "outside the lengths" in str(e.value)


@pytest.mark.parametrize("over, field", [({"cam": {"bore_radius": -5.0}}, "cam.bore_radius"),
                                         ({"profile": {"tolerance": 0.0}}, "profile.tolerance"),
                                         ({"profile": {"min_curvature_radius": -1.0}}, "profile.min_curvature_radius")])
def test_profile_and_bore_checked_on_loading(over, field, tmp_path, capsys):
    """cams solve refuses what cams check refuses (both load the file the same way)."""
    import tomllib

    from cams.cli import main

    with pytest.raises(InputError) as e:
        design_from_dict(rocker_dict(**over))
    assert str(e.value).startswith(field)
    text = (EXAMPLES / "rocker_force.toml").read_text(encoding="utf-8")
    table, (key, value) = next(iter(over.items()))[0], next(iter(next(iter(over.values())).items()))
    assert tomllib.loads(text)  # the example parses
    path = tmp_path / "bad.toml"
    path.write_text(text + f"\n[{table}]\n{key} = {value}\n" if f"[{table}]" not in text
                    else text.replace(f"[{table}]\n", f"[{table}]\n{key} = {value}\n"), encoding="utf-8")
    for cmd in ("solve", "check"):
        assert main([cmd, str(path)]) == 2
        assert capsys.readouterr().err.startswith(f"cams {cmd}: error: {field}")


def test_objective_L_is_refused_for_a_translating_follower_on_loading():
    from tests.stress.helpers import translating_dict

    with pytest.raises(InputError) as e:
        design_from_dict(translating_dict(solve={"objective": "L"}))
    assert str(e.value).startswith("solve.objective: 'L' (least centre distance) applies to rocker followers")
    assert design_from_dict(rocker_dict(solve={"objective": "L"})).objective == "L"


def test_journal_radius_refused_for_a_translating_follower_in_design_files():
    from tests.stress.helpers import translating_dict

    with pytest.raises(InputError) as e:
        design_from_dict(translating_dict(dynamics={"mass": 0.5, "journal_radius": 5.0}))
    assert str(e.value).startswith("dynamics.journal_radius: applies to a rocker's pivot journal")
    d = design_from_dict(rocker_dict(dynamics={"mass": 0.003, "journal_radius": 5.0}))
    assert d.dynamics is not None


def test_limits_refuse_a_return_limit_under_force_closure_in_the_api():
    """The rule lives in Limits, so designs built in Python obey it as files do."""
    from cams.model.design import Limits

    with pytest.raises(InputError) as e:
        Limits(np.radians(45), return_pressure_angle=np.radians(40))
    assert str(e.value).startswith("limits.return_pressure_angle: applies to form closure")
    assert Limits(np.radians(45), return_pressure_angle=np.radians(40), closure="form").return_limit == pytest.approx(np.radians(40))
