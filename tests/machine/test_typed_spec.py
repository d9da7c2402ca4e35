"""A machine file's [forces] table lands in typed fields of :class:`MachineSpec`, checked once; no untyped ``extra``."""

from __future__ import annotations

import dataclasses
import tomllib
from pathlib import Path

import pytest

from cams.machine.kinetostatics import ForceSpec
from cams.machine.kinetostatics.loads import ForceOptions
from cams.machine.machinefile import machine_from_dict
from laws.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
SLOTTING = ROOT / "examples" / "machines" / "slotting_machine.toml"
FORCES = ROOT / "tests" / "machine" / "forces" / "data" / "slotting_forces.toml"


def _raw(path: Path) -> dict:
    with path.open("rb") as f:
        return tomllib.load(f)


def test_forces_table_gives_typed_fields():
    d = _raw(FORCES)
    spec = machine_from_dict(d)
    assert isinstance(spec.forces, ForceSpec) and isinstance(spec.force_options, ForceOptions)
    assert spec.force_options.samples == d["forces"].get("samples", 360)
    assert not hasattr(spec, "extra")


def test_no_forces_table():
    spec = machine_from_dict(_raw(SLOTTING))
    assert spec.forces is None and spec.force_options == ForceOptions()


@pytest.mark.parametrize("change, words", [
    ({"forces": {"links": {}}}, "forces: must be a ForceSpec or None, got dict"),
    ({"force_options": (360, 2)}, "forces: options must be a ForceOptions, got tuple"),
])
def test_spec_checks_its_forces_once(change, words):
    spec = machine_from_dict(_raw(SLOTTING))
    with pytest.raises(InputError) as e:
        dataclasses.replace(spec, **change)
    assert str(e.value) == words


def test_forces_unknown_key_message_is_the_projects():
    d = _raw(FORCES)
    d["forces"]["spin"] = 1
    with pytest.raises(InputError) as e:
        machine_from_dict(d)
    assert str(e.value).startswith("forces: unknown key(s) spin; allowed: delta, friction, gravity, interpolation, links")
