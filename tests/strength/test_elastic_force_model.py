"""``[contact] force_model = "elastic"``: the stresses under the follower train's dynamic contact force (issue 24,
with issue 23's train). Checked against Hertz's line contact written here (p0 = sqrt(N E* / (pi w R')), the
contact modulus 1/E* = sum (1 - nu^2) / E; Johnson, Contact Mechanics, sec. 4.2) at the dynamic force the
vibration gives, and against the rigid model in the limit of a stiff train."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CONTACT = """
[contact]
cam_modulus = 206.0
cam_poisson = 0.3
follower_modulus = 206.0
follower_poisson = 0.3
allowable_stress = 1500.0
force_model = "{model}"
"""


def _file(tmp_path: Path, model: str, stiffness: float | None = None) -> Path:
    text = (EXAMPLES / "translating_train.toml").read_text(encoding="utf-8")
    text = text.replace('rotation = "ccw"', 'rotation = "ccw"\nwidth = 10.0', 1)
    if stiffness is not None:
        text = text.replace("train_stiffness = 2.0e5", f"train_stiffness = {stiffness!r}")
    path = tmp_path / f"{model}.toml"
    path.write_text(text + CONTACT.format(model=model), encoding="utf-8")
    return path


def _solve(capsys, path: Path) -> tuple[int, dict]:
    rc = main(["solve", str(path), "--json"])
    return rc, json.loads(capsys.readouterr().out)


def _hertz_p0(force: float, r_cam: float, r_follower: float, width: float) -> float:
    """Hertz's maximum pressure (MPa) of two parallel cylinders (mm, N; a concave radius negative)."""
    e_star = 1.0 / (2 * (1 - 0.3**2) / 206.0e3)  # MPa
    r_eff = 1.0 / (1.0 / r_cam + 1.0 / r_follower)
    return float(np.sqrt(force * e_star / (np.pi * width * r_eff)))


def test_the_elastic_model_takes_the_dynamic_contact_force(tmp_path, capsys):
    rc, rep = _solve(capsys, _file(tmp_path, "elastic"))
    assert rc == 0
    co, vib = rep["contact"], rep["vibration"]
    assert co["force_model"] == "elastic"
    at = co["at_max"]
    # the force at the largest pressure is the dynamic one: within the vibration's range, not the rigid one's
    assert vib["dynamic_min_contact_force"] - 1e-9 <= at["force"] <= vib["dynamic_max_contact_force"] + 1e-9
    assert co["max_pressure"] == pytest.approx(
        _hertz_p0(at["force"], at["cam_curvature_radius"], at["follower_radius"], 10.0), rel=1e-9)
    _, rigid = _solve(capsys, _file(tmp_path, "rigid"))
    assert rigid["contact"]["force_model"] == "rigid"
    # the train's vibration changes the largest pressure (the two models differ at this train's stiffness)
    assert co["max_pressure"] != pytest.approx(rigid["contact"]["max_pressure"], rel=1e-6)


def test_a_stiff_train_gives_the_rigid_stresses(tmp_path, capsys):
    _, rigid = _solve(capsys, _file(tmp_path, "rigid", 1e12))
    _, elastic = _solve(capsys, _file(tmp_path, "elastic", 1e12))
    assert elastic["contact"]["max_pressure"] == pytest.approx(rigid["contact"]["max_pressure"], rel=2e-3)


def test_elastic_without_a_train_is_refused_in_one_line(tmp_path, capsys):
    path = _file(tmp_path, "elastic")
    text = path.read_text(encoding="utf-8")
    text = "\n".join(ln for ln in text.splitlines() if not ln.startswith(("train_stiffness", "damping_ratio")))
    path.write_text(text + "\n", encoding="utf-8")
    rc = main(["solve", str(path)])
    err = capsys.readouterr().err
    assert rc == 2 and len(err.strip().splitlines()) == 1 and "contact.force_model" in err
