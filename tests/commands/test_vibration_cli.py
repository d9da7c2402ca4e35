"""The follower train on the command line: ``cams solve`` (text, ``--json``'s ``vibration``), the exit code's rule,
bad input, ``cams plot --only vibration``; the translating example with a train and the slotting feed cam with
one (a test-side edit)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from cams.cli import main
from tests.conftest import EXAMPLES

KEYS = {
    "natural_frequency_hz",
    "phases",
    "dynamic_max_contact_force",
    "dynamic_min_contact_force",
    "contact_lost",
    "contact_lost_at_deg",
    "dynamic_jump_rpm",
}
PHASE_KEYS = {"phase", "kind", "period_ratio", "residual_from_rest", "residual"}
TRAIN = EXAMPLES / "translating_train.toml"


def _run(capsys, *argv):
    rc = main([*map(str, argv)])
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


def _edited(tmp_path, src, name, *pairs):
    text = src.read_text()
    for old, new in pairs:
        assert old in text
        text = text.replace(old, new)
    p = tmp_path / name
    p.write_text(text)
    return p


def test_vibration_json_has_the_issue_keys(capsys):
    rc, out, _ = _run(capsys, "solve", TRAIN, "--json")
    assert rc == 0
    rep = json.loads(out)
    vi = rep["vibration"]
    assert set(vi) == KEYS
    assert [p["phase"] for p in vi["phases"]] == [0, 2] and all(set(p) == PHASE_KEYS for p in vi["phases"])
    k = 2.0e5 + rep["forces"]["spring"]["rate"]
    assert vi["natural_frequency_hz"] == pytest.approx(np.sqrt(k / 0.5) / (2 * np.pi), rel=1e-12)
    assert not vi["contact_lost"] and vi["contact_lost_at_deg"] is None
    # the elastic jump speed beside the rigid one, which stays in forces
    assert 0 < vi["dynamic_jump_rpm"] < rep["forces"]["jump_rpm"]
    assert vi["dynamic_min_contact_force"] > 0


def test_vibration_text(capsys):
    rc, out, _ = _run(capsys, "solve", TRAIN)
    assert rc == 0
    assert "natural frequency" in out and "Hz" in out and "phase 0 (rise): period ratio" in out
    assert "jump speed: elastic" in out and "rpm (rigid" in out


def test_vibration_no_train_no_key(capsys):
    rc, out, _ = _run(capsys, "solve", EXAMPLES / "translating_flat.toml", "--json")
    assert "vibration" not in json.loads(out)


def test_vibration_lost_contact_fails_the_cam(tmp_path, capsys):
    """A spring that holds the rigid follower at 345 rpm (its rigid jump speed is above) but not the elastic one."""
    p = _edited(
        tmp_path,
        TRAIN,
        "lost.toml",
        ("margin = 1.5", "spring_rate = 425.6\npreload = 12.77"),
        ("rpm = 300", "rpm = 345"),
    )
    rc, out, _ = _run(capsys, "solve", p, "--json")
    rep = json.loads(out)
    assert rc == 1
    assert rep["forces"]["contact_lost"] is False and rep["vibration"]["contact_lost"] is True
    assert rep["buildable"] is False and any("elastic follower train" in f for f in rep["failures"])
    assert rep["vibration"]["dynamic_min_contact_force"] < 0
    rc, out, _ = _run(capsys, "solve", p)
    assert rc == 1 and "FAIL: dynamics: the elastic follower train leaves the cam" in out


@pytest.mark.parametrize(
    "line, field",
    [
        ("train_stiffness = 2.0e5", "train_stiffness = 0"),
        ("train_stiffness = 2.0e5", "train_stiffness = -3.0"),
        ("damping_ratio = 0.05", "damping_ratio = -0.01"),
        ("mass = 0.5", "mass = 0.0"),
    ],
)
def test_vibration_bad_input(tmp_path, capsys, line, field):
    key = field.split(" = ")[0]
    src = TRAIN.read_text()
    old = next(x for x in src.splitlines() if x.startswith(line))
    p = _edited(tmp_path, TRAIN, "bad.toml", (old, field))
    rc, out, err = _run(capsys, "solve", p)
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and f"dynamics.{key}" in err and "Traceback" not in err


def test_vibration_train_without_rpm_says_what_is_missing(tmp_path, capsys):
    src = TRAIN.read_text()
    old = next(x for x in src.splitlines() if x.startswith("rpm"))
    p = _edited(tmp_path, TRAIN, "norpm.toml", (old + "\n", ""))
    rc, out, err = _run(capsys, "solve", p)
    assert rc == 2 and err.count("\n") == 1 and "cam.rpm" in err and "train_stiffness" in err


def test_vibration_damping_without_train_is_refused(tmp_path, capsys):
    src = TRAIN.read_text()
    old = next(x for x in src.splitlines() if x.startswith("train_stiffness"))
    p = _edited(tmp_path, TRAIN, "damp.toml", (old + "\n", ""))
    rc, _, err = _run(capsys, "solve", p)
    assert rc == 2 and "dynamics.damping_ratio" in err


def test_vibration_slotting_feed_cam_with_a_train(tmp_path, capsys):
    """The slotting machine's feed cam (a roller rocker) with a torsional train: 2000 N m/rad about the pivot."""
    p = _edited(
        tmp_path,
        EXAMPLES / "slotting_feed_cam.toml",
        "feed.toml",
        ("journal_radius = 8.0", "journal_radius = 8.0\ntrain_stiffness = 2000.0\ndamping_ratio = 0.02"),
    )
    rc, out, _ = _run(capsys, "solve", p, "--json")
    rep = json.loads(out)
    vi = rep["vibration"]
    assert set(vi) == KEYS
    assert vi["natural_frequency_hz"] == pytest.approx(
        np.sqrt((2000.0 + rep["forces"]["spring"]["rate"]) / 0.003) / (2 * np.pi), rel=1e-12
    )
    # the rise lasts 60 deg of a turn at 60 rpm: 1/6 s
    assert vi["phases"][0]["period_ratio"] == pytest.approx(vi["natural_frequency_hz"] / 6, rel=1e-12)
    assert vi["dynamic_jump_rpm"] is not None and rep["forces"]["jump_rpm"] > 0
    rc2, text, _ = _run(capsys, "solve", p)
    assert rc2 == rc and "follower train: natural frequency" in text and "jump speed: elastic" in text


def test_vibration_plot(tmp_path, capsys):
    rc, _, _ = _run(capsys, "plot", TRAIN, "--only", "vibration", "--out", tmp_path, "--quiet")
    assert rc == 0
    assert sorted(f.suffix for f in tmp_path.iterdir()) == [".png", ".svg"]
    assert all(f.stat().st_size > 1000 for f in tmp_path.iterdir())
    rc, _, err = _run(capsys, "plot", EXAMPLES / "translating_flat.toml", "--only", "vibration", "--out", tmp_path)
    assert rc == 2 and "train_stiffness" in err
