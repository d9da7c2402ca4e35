"""Design files: the schema of the issue works as written; bad input names its field."""

import numpy as np
import pytest

from cams.designfile import design_from_dict, load_design
from cams.follower import Rocker, Translating
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
