"""Bad input in design and machine files: one line on stderr naming the field, exit code 2, never a traceback.

Every numeric key documented in docs/files.md is walked (design and machine files) with a value no key allows:
an integer beyond 64 bits, ``nan``, ``inf``, a string, a boolean. The list of keys is read from the document
itself, so a key documented later without a place here fails the test.
"""

from __future__ import annotations

import copy
import json
import math
import re
from pathlib import Path

import pytest

from cams.cli import main
from cams.io.designfile import MAX_SAMPLES, design_from_dict, load_design
from cams.io.document import MAX_NUMBER
from cams.machine.machinefile import load_machine
from laws.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
HUGE = 99999999999999999999999  # beyond 64 bits
BAD = {"huge": HUGE, "nan": math.nan, "inf": math.inf, "-inf": -math.inf, "string": "abc", "bool": True}


# --- a TOML writer for the test documents (the project reads TOML, it has no writer) -----------------------

def _scalar(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf") if math.isinf(v) else repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, list):
        return "[" + ", ".join(_scalar(x) for x in v) + "]"
    raise TypeError(v)


def to_toml(d: dict, path: str = "") -> str:
    """``d`` as TOML: scalars and arrays of scalars inline, tables as [a.b], arrays of tables as [[a]]."""
    lines = []
    subs = []
    for k, v in d.items():
        if isinstance(v, dict):
            subs.append((k, v, False))
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            subs.append((k, v, True))
        else:
            lines.append(f"{k} = {_scalar(v)}")
    out = "\n".join(lines) + "\n"
    for k, v, many in subs:
        p = f"{path}.{k}" if path else k
        for t in (v if many else [v]):
            out += (f"[[{p}]]\n" if many else f"[{p}]\n") + to_toml(t, p)
    return out


# --- base documents: every numeric key of docs/files.md has a home in one of them -------------------------

MOTION = [
    {"phase": "rise", "law": "cycloidal", "angle": 120, "height": 15.0},
    {"phase": "dwell", "angle": 30},
    {"phase": "return", "law": "cycloidal", "angle": 120},
    {"phase": "dwell", "angle": 90},
]
ROCKER_FORM = {
    "name": "rocker form",
    "follower": {"kind": "rocker", "arm": 125.0, "swing": 15.0, "roller_radius": 10.0, "rise_direction": "cw"},
    "cam": {"rotation": "ccw", "rpm": 60, "bore_radius": 8.0},
    "motion": MOTION,
    "limits": {"pressure_angle": 40, "return_pressure_angle": 50, "closure": "form", "safety_factor": 1.1,
               "min_base_radius": 30.0},
    "solve": {"method": "exact", "samples": 360},
    "profile": {"tolerance": 0.001, "min_curvature_radius": 2.0},
}
ROCKER_FORCE = {
    "name": "rocker force",
    "follower": {"kind": "rocker", "arm": 125.0, "swing": 15.0, "roller_radius": 10.0},
    "cam": {"rpm": 60},
    "motion": MOTION,
    "limits": {"pressure_angle": 45, "centre_distance": 120.0},
    "dynamics": {"mass": 0.003, "load": 0.5, "spring_rate": 3.0, "preload": 1.0, "friction": 0.1,
                 "journal_radius": 8.0, "margin": 1.5, "max_spring_force": 100.0},
}
#: a spring to choose within bounds on its installed twist (rocker) or compression (translating)
ROCKER_SPRING = {**ROCKER_FORCE, "dynamics": {"mass": 0.003, "load": 0.5, "margin": 1.5, "min_installed_twist": 2.0,
                                              "max_installed_twist": 10.0}}
#: a chosen cam ([cam] base_radius with L, or [cam] centre), checked instead of sized
ROCKER_CHOSEN_R0 = {
    "follower": {"kind": "rocker", "arm": 125.0, "swing": 15.0, "roller_radius": 10.0},
    "cam": {"rpm": 60, "base_radius": 60.0},
    "motion": MOTION,
    "limits": {"pressure_angle": 45, "centre_distance": 120.0},
}
ROCKER_CHOSEN_CENTRE = {**ROCKER_CHOSEN_R0, "cam": {"rpm": 60, "centre": [100.0, -60.0]},
                        "limits": {"pressure_angle": 45}}
TRANSLATING = {
    "follower": {"kind": "translating", "stroke": 20.0, "offset": 5.0, "roller_radius": 5.0},
    "motion": [dict(m, height=20.0) if m["phase"] == "rise" else m for m in MOTION],
    "limits": {"pressure_angle": 30},
}
TRANSLATING_SPRING = {**TRANSLATING, "cam": {"rpm": 300},
                      "dynamics": {"mass": 0.5, "load": 5.0, "min_installed_compression": 5.0,
                                   "max_installed_compression": 25.0}}
#: a translating roller with an elastic follower train (its keys need cam.rpm)
TRANSLATING_TRAIN = {**TRANSLATING, "cam": {"rpm": 300},
                     "dynamics": {"mass": 0.5, "load": 5.0, "train_stiffness": 2.0e5, "damping_ratio": 0.05}}
FLAT_ROCKER = {
    "follower": {"kind": "rocker", "face": "flat", "swing": 15.0, "centre_distance": 120.0, "face_offset": 0.0},
    "cam": {"rpm": 60, "bore_radius": 5.0, "base_radius": 80.0},
    "motion": MOTION,
    "limits": {"min_radius": 5.0},
    "profile": {"tolerance": 0.001},
}
#: a flat-faced rocker with every [dynamics] key a flat face takes (face_friction: a flat face's only)
FLAT_ROCKER_FORCE = {**FLAT_ROCKER, "dynamics": {**ROCKER_FORCE["dynamics"], "face_friction": 0.1}}
#: a rocker with its contact: every numeric [contact] key (the moduli and ratios given beside the materials)
CONTACT_NUMBERS = {"cam_modulus": 206.0, "cam_poisson": 0.3, "follower_modulus": 208.0, "follower_poisson": 0.3,
                   "allowable_stress": 1500.0, "cam_roughness": 0.3, "follower_roughness": 0.2, "viscosity": 0.1,
                   "pressure_viscosity": 20.0, "min_film_parameter": 1.0, "bearing_rating": 5000.0,
                   "life_hours": 1000.0}
ROCKER_CONTACT = {**ROCKER_FORCE, "cam": {"rpm": 60, "width": 10.0},
                  "contact": {"cam_material": "steel", "follower_material": "bearing_steel", **CONTACT_NUMBERS}}
FLAT_ROCKER_WIDTH = {**FLAT_ROCKER, "cam": {**FLAT_ROCKER["cam"], "width": 10.0}}
FLAT_ROCKER_FLOOR = {  # a floor on R0 sizes the cam: it goes without a chosen [cam] base_radius
    **FLAT_ROCKER, "cam": {"rpm": 60, "bore_radius": 5.0}, "limits": {"min_radius": 5.0, "min_base_radius": 10.0},
}
FLAT_TRANSLATING = {
    "follower": {"kind": "translating", "face": "flat", "stroke": 20.0, "offset": 1.0},
    "motion": [dict(m, height=20.0) if m["phase"] == "rise" else m for m in MOTION],
    "limits": {"min_radius": 2.0},
}
FEED_CAM = {
    "follower": {"kind": "rocker", "arm": 125.0, "swing": 15.0, "roller_radius": 15.0, "rise_direction": "cw"},
    "motion": [{"phase": "rise", "law": "parabolic", "angle": 60}, {"phase": "dwell", "angle": 10},
               {"phase": "return", "law": "harmonic", "angle": 60}, {"phase": "dwell"}],
    "limits": {"pressure_angle": 40},
}
SLOTTING = {
    "name": "slotting",
    "linkage": {"type": "slotting", "time_ratio": 2.0, "stroke": 100.0, "centre_distance": 150.0, "rod_ratio": 1.0,
                "rpm": 60},
    "cutting": {"approach": 0.05, "overrun": 0.05},
    "drive": {"kind": "gears", "z_crank": 20, "z_cam": 20, "mesh": "internal"},
    "timing": {"margin": 5.0, "placement": "early", "follower_direction": 90.0},
    "cam": {"bore_radius": 10.0},
    **FEED_CAM,
    "forces": {
        "gravity": 9.81, "samples": 360, "passes": 2, "delta": 0.05,
        "links": {"bar": {"mass": 20.4, "inertia": 1.1, "cg": 50.0}},
        "friction": {"revolute": {"coefficient": 0.1, "radius": 15.0}, "prismatic": {"coefficient": 0.15}},
        "loads": [{"kind": "resistance", "body": "tool", "force": 1000.0, "window": "cut", "approach": 0.1,
                   "overrun": 0.1}],
    },
}
SLOTTING_LENGTHS = {**SLOTTING, "linkage": {"type": "slotting", "crank": 75.0, "centre_distance": 150.0,
                                            "bar": 100.0, "rod": 100.0, "guide_x": -243.3}}
# the hub wall goes with a bore
ROCKER_WALL = {**ROCKER_FORM, "cam": {**ROCKER_FORM["cam"], "hub_wall": 2.0}}
FLAT_WALL = {**FLAT_ROCKER, "cam": {**FLAT_ROCKER["cam"], "hub_wall": 2.0}}
SLOTTING_WALL = {**SLOTTING, "cam": {"bore_radius": 10.0, "hub_wall": 2.0}}
# a keyway goes with a bore
ROCKER_KEYWAY = {**ROCKER_FORM, "cam": {**ROCKER_FORM["cam"], "keyway_width": 3.0, "keyway_depth": 1.0,
                                        "keyway_angle": 90.0}}
CRANK_SLIDER = {
    "linkage": {"type": "crank_slider", "stroke": 100.0, "rod": 300.0, "offset": 0.0, "rod_cg": 100.0, "rpm": 60},
    "cutting": {"working": "forward"},
    **FEED_CAM,
    "forces": {"loads": [{"kind": "gas", "body": "slider", "angles": [0.0, 180.0, 360.0],
                          "pressure": [1e5, 5e5, 1e5], "bore": 80.0, "start": 0.0, "period": 360}]},
}
CRANK_SLIDER_LENGTHS = {**CRANK_SLIDER, "linkage": {"type": "crank_slider", "crank": 50.0, "rod": 300.0}}
PUMP = {
    "linkage": {"type": "slotted_lever_pump", "time_ratio": 2.0, "stroke": 250.0, "centre_distance": 525.0,
                "guide_x": 0.0},
    **FEED_CAM,
}
PUMP_LENGTHS = {**PUMP, "linkage": {"type": "slotted_lever_pump", "crank": 262.5, "centre_distance": 525.0,
                                    "lever": 250.0}}

#: (section of docs/files.md, table column, key) -> (base document, path of the key in it)
HOMES = {
    ("`[follower]`", "", "arm"): (ROCKER_FORM, "follower.arm"),
    ("`[follower]`", "", "swing"): (ROCKER_FORM, "follower.swing"),
    ("`[follower]`", "", "stroke"): (TRANSLATING, "follower.stroke"),
    ("`[follower]`", "", "offset"): (TRANSLATING, "follower.offset"),
    ("`[follower]`", "", "roller_radius"): (ROCKER_FORM, "follower.roller_radius"),
    ("`[cam]`", "", "rpm"): (ROCKER_FORM, "cam.rpm"),
    ("`[cam]`", "", "bore_radius"): (ROCKER_FORM, "cam.bore_radius"),
    ("`[cam]`", "", "hub_wall"): (ROCKER_WALL, "cam.hub_wall"),
    **{("`[cam]`", "", k): (ROCKER_KEYWAY, f"cam.{k}") for k in ("keyway_width", "keyway_depth", "keyway_angle")},
    ("`[cam]`", "", "base_radius"): (ROCKER_CHOSEN_R0, "cam.base_radius"),
    ("`[cam]`", "", "centre"): (ROCKER_CHOSEN_CENTRE, "cam.centre[0]"),
    ("`[cam]`", "", "width"): (ROCKER_CONTACT, "cam.width"),
    **{("`[contact]`", "", k): (ROCKER_CONTACT, f"contact.{k}") for k in CONTACT_NUMBERS},
    ("Flat-faced followers (`face = \"flat\"`)", "`[cam]`", "width"): (FLAT_ROCKER_WIDTH, "cam.width"),
    ("`[[motion]]`", "", "angle"): (ROCKER_FORM, "motion[2].angle"),
    ("`[[motion]]`", "", "height"): (ROCKER_FORM, "motion[0].height"),
    ("`[limits]`", "", "pressure_angle"): (ROCKER_FORM, "limits.pressure_angle"),
    ("`[limits]`", "", "return_pressure_angle"): (ROCKER_FORM, "limits.return_pressure_angle"),
    ("`[limits]`", "", "safety_factor"): (ROCKER_FORM, "limits.safety_factor"),
    ("`[limits]`", "", "centre_distance"): (ROCKER_FORCE, "limits.centre_distance"),
    ("`[limits]`", "", "min_base_radius"): (ROCKER_FORM, "limits.min_base_radius"),
    ("`[solve]`", "", "samples"): (ROCKER_FORM, "solve.samples"),
    ("`[profile]`", "", "tolerance"): (ROCKER_FORM, "profile.tolerance"),
    ("`[profile]`", "", "min_curvature_radius"): (ROCKER_FORM, "profile.min_curvature_radius"),
    **{("`[dynamics]`", "", k): (ROCKER_FORCE, f"dynamics.{k}") for k in ROCKER_FORCE["dynamics"]},
    ("`[dynamics]`", "", "face_friction"): (FLAT_ROCKER_FORCE, "dynamics.face_friction"),
    **{("`[dynamics]`", "", k): (TRANSLATING_TRAIN, f"dynamics.{k}") for k in ("train_stiffness", "damping_ratio")},
    **{("`[dynamics]`", "", k): (ROCKER_SPRING, f"dynamics.{k}") for k in ("min_installed_twist", "max_installed_twist")},
    **{("`[dynamics]`", "", k): (TRANSLATING_SPRING, f"dynamics.{k}")
       for k in ("min_installed_compression", "max_installed_compression")},
    **{("Flat-faced followers (`face = \"flat\"`)", "`[follower]`", k): (FLAT_ROCKER, f"follower.{k}")
       for k in ("swing", "centre_distance", "face_offset")},
    **{("Flat-faced followers (`face = \"flat\"`)", "`[follower]`", k): (FLAT_TRANSLATING, f"follower.{k}")
       for k in ("stroke", "offset")},
    **{("Flat-faced followers (`face = \"flat\"`)", "`[cam]`", k): (FLAT_ROCKER, f"cam.{k}")
       for k in ("rpm", "bore_radius", "base_radius")},
    ("Flat-faced followers (`face = \"flat\"`)", "`[cam]`", "hub_wall"): (FLAT_WALL, "cam.hub_wall"),
    **{("Flat-faced followers (`face = \"flat\"`)", "`[limits]`", k): (FLAT_ROCKER_FLOOR, f"limits.{k}")
       for k in ("min_radius", "min_base_radius")},
    ("Flat-faced followers (`face = \"flat\"`)", "`[profile]`", "tolerance"): (FLAT_ROCKER, "profile.tolerance"),
    ("Flat-faced followers (`face = \"flat\"`)", "`[dynamics]`", "face_friction"):
        (FLAT_ROCKER_FORCE, "dynamics.face_friction"),
    ("`[linkage]`", "", "rpm"): (SLOTTING, "linkage.rpm"),
    **{("`type = \"slotting\"`", "", k): (SLOTTING, f"linkage.{k}")
       for k in ("time_ratio", "stroke", "centre_distance", "rod_ratio")},
    **{("`type = \"slotting\"`", "", k): (SLOTTING_LENGTHS, f"linkage.{k}")
       for k in ("crank", "bar", "rod", "guide_x")},
    **{("`type = \"crank_slider\"`", "", k): (CRANK_SLIDER, f"linkage.{k}")
       for k in ("stroke", "rod", "offset", "rod_cg")},
    ("`type = \"crank_slider\"`", "", "crank"): (CRANK_SLIDER_LENGTHS, "linkage.crank"),
    **{("`type = \"slotted_lever_pump\"`", "", k): (PUMP, f"linkage.{k}")
       for k in ("time_ratio", "stroke", "centre_distance", "guide_x")},
    **{("`type = \"slotted_lever_pump\"`", "", k): (PUMP_LENGTHS, f"linkage.{k}") for k in ("crank", "lever")},
    **{("`[cutting]`", "", k): (SLOTTING, f"cutting.{k}") for k in ("approach", "overrun")},
    **{("`[drive]`", "", k): (SLOTTING, f"drive.{k}") for k in ("z_crank", "z_cam")},
    **{("`[timing]`", "", k): (SLOTTING, f"timing.{k}") for k in ("margin", "follower_direction")},
    ("`[cam]`", "", "bore_radius", "machine"): (SLOTTING, "cam.bore_radius"),
    ("`[cam]`", "", "hub_wall", "machine"): (SLOTTING_WALL, "cam.hub_wall"),
    **{("`[forces]`", "", k): (SLOTTING, f"forces.{k}") for k in ("gravity", "samples", "passes", "delta")},
    **{("`[forces.links.NAME]`", "", k): (SLOTTING, f"forces.links.bar.{k}") for k in ("mass", "inertia", "cg")},
    ("`[forces.friction]`", "", "coefficient"): (SLOTTING, "forces.friction.prismatic.coefficient"),
    ("`[forces.friction]`", "", "radius"): (SLOTTING, "forces.friction.revolute.radius"),
    **{("`[[forces.loads]]`", "", k): (SLOTTING, f"forces.loads[0].{k}") for k in ("force", "approach", "overrun")},
    **{("`[[forces.loads]]`", "", k): (CRANK_SLIDER, f"forces.loads[0].{k}") for k in ("bore", "start", "period")},
    ("`[[forces.loads]]`", "", "angles"): (CRANK_SLIDER, "forces.loads[0].angles[1]"),
    ("`[[forces.loads]]`", "", "pressure"): (CRANK_SLIDER, "forces.loads[0].pressure[1]"),
}
MACHINES = [SLOTTING, SLOTTING_LENGTHS, CRANK_SLIDER, CRANK_SLIDER_LENGTHS, PUMP, PUMP_LENGTHS]


def documented_numeric_keys() -> list[tuple]:
    """The rows of docs/files.md's key tables whose allowed values are numbers: (section, table, key[, "machine"])."""
    text = (ROOT / "docs" / "files.md").read_text(encoding="utf-8")
    keys, section, header, machine = [], None, None, False
    for line in text.splitlines():
        if line.startswith("#"):
            section, header = line.lstrip("#").strip(), None
            machine = machine or section == "Machine files"
            continue
        if not line.startswith("|"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells[0] in ("key", "table"):
            header = cells
            continue
        if header is None or "key" not in header or set(cells[0]) <= set("-"):
            continue
        row = dict(zip(header, cells, strict=False))  # a row may have fewer cells
        m = re.fullmatch(r"`([a-z_0-9]+)`", row["key"])
        allowed = re.sub(r'`"[^"]*"`', "", row.get("allowed", ""))  # words are options, not numbers
        if m and "table" not in allowed and re.search(r"\d|number|integer|[<>≤≥]", allowed):
            k = (section, row.get("table", ""), m.group(1))
            keys.append((*k, "machine") if machine and k in HOMES and HOMES[k][0] not in MACHINES else k)
    return keys


def _set(doc: dict, path: str, value) -> dict:
    """A deep copy of ``doc`` with the entry at dotted ``path`` (``a.b[2].c``) set to ``value``."""
    doc = copy.deepcopy(doc)
    parts = re.findall(r"[^.\[\]]+|\[\d+\]", path)
    t = doc
    for p in parts[:-1]:
        t = t[int(p[1:-1])] if p.startswith("[") else t[p]
    last = parts[-1]
    if last.startswith("["):
        t[int(last[1:-1])] = value
    else:
        t[last] = value
    return doc


def _run(tmp_path: Path, doc: dict, capsys, command: str | None = None) -> tuple[int, str]:
    f = tmp_path / "in.toml"
    f.write_text(to_toml(doc), encoding="utf-8")
    command = command or ("machine" if "linkage" in doc else "solve")
    capsys.readouterr()
    rc = main([command, str(f)])
    return rc, capsys.readouterr().err


def test_every_documented_numeric_key_has_a_home():
    keys = documented_numeric_keys()
    assert len(keys) > 70  # the parser found the tables
    assert [k for k in keys if k not in HOMES] == []


def _bases_in_use() -> list[dict]:
    """The base documents that hold a documented key (each once), the machines always."""
    bases = [HOMES[k][0] for k in documented_numeric_keys() if k in HOMES] + MACHINES
    return [b for i, b in enumerate(bases) if not any(b is c for c in bases[:i])]


@pytest.mark.parametrize("base", _bases_in_use(), ids=lambda d: str(d["follower"]) + str(d.get("cam", ""))
                         + str(d.get("linkage", "")))
def test_base_documents_load(base, tmp_path):
    f = tmp_path / "base.toml"
    f.write_text(to_toml(base), encoding="utf-8")
    (load_machine if "linkage" in base else load_design)(f)


@pytest.mark.parametrize("key", documented_numeric_keys(),
                         ids=lambda k: ".".join(x.strip("`[]") for x in k[1:3]) + k[0][:12])
def test_every_numeric_key_refuses_values_no_key_allows(key, tmp_path, capsys):
    base, path = HOMES[key]
    field = re.sub(r"\[\d+\]$", "", path)  # an array element is named by its array at least
    for what, value in BAD.items():
        rc, err = _run(tmp_path, _set(base, path, value), capsys)
        assert rc == 2, (path, what, err)
        assert err.count("\n") == 1 and "Traceback" not in err, (path, what, err)
        assert f" {field}" in err, (path, what, err)


@pytest.mark.parametrize("samples", [MAX_SAMPLES + 1, 10 ** 9, 10 ** 30, 1, 2.5])
def test_samples_has_an_upper_bound(samples, tmp_path, capsys):
    rc, err = _run(tmp_path, _set(ROCKER_FORM, "solve.samples", samples), capsys)
    assert rc == 2 and err.count("\n") == 1
    # beyond the size of any number in a file the general bound speaks, else the range of samples
    assert "solve.samples" in err and (f"{MAX_SAMPLES}" in err or (samples > MAX_NUMBER and "too large" in err))


def test_samples_at_the_bound_is_accepted():
    d = design_from_dict(_set(ROCKER_FORM, "solve.samples", MAX_SAMPLES))
    assert d.samples == MAX_SAMPLES


@pytest.mark.parametrize("command", ["solve", "check", "profile", "plot", "report", "sweep", "machine"])
def test_deep_nesting_is_refused_in_one_line(command, tmp_path, capsys):
    f = tmp_path / "deep.toml"
    f.write_text("a = " + "[" * 5000 + "]" * 5000 + "\n", encoding="utf-8")
    argv = [command, str(f)] + (["--vary", "limits.pressure_angle=30:40:2", "--out", str(tmp_path / "s.csv")]
                                if command == "sweep" else [])
    capsys.readouterr()
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "nested too deeply" in err


def test_moderate_nesting_parsed_then_refused_by_the_walk(tmp_path):
    """Nesting tomllib can parse (100 levels) is refused by the document check, naming the key."""
    f = tmp_path / "deep.toml"
    f.write_text(to_toml(ROCKER_FORM).replace('name = "rocker form"', "name = " + "[" * 100 + "]" * 100))
    with pytest.raises(InputError, match=r"^name(\[0\])*: arrays or tables nested too deeply"):
        load_design(f)


def test_api_refuses_huge_integers_too():
    """design_from_dict (the API, no file) goes through the same check as the files."""
    with pytest.raises(InputError, match=r"^limits\.pressure_angle: .* too large"):
        design_from_dict(_set(ROCKER_FORM, "limits.pressure_angle", HUGE))


def test_phase_angles_below_the_sum_tolerance_are_refused(tmp_path, capsys):
    """A phase of 1e-300 degrees gave divide-by-zero warnings and "did not converge"; it is refused in one line,
    and the smallest accepted phase (1e-6 degrees, the tolerance of the 360-degree sum) still solves."""
    tiny = _set(_set(TRANSLATING, "motion[0].angle", 1e-300), "motion[3].angle", 90.0 + 120.0 - 1e-300)
    rc, err = _run(tmp_path, tiny, capsys)
    assert rc == 2 and err.count("\n") == 1 and "motion[0].angle: must be at least 1e-06 degrees" in err
    smallest = _set(_set(TRANSLATING, "motion[0].angle", 1e-6), "motion[3].angle", 210.0 - 1e-6)
    f = tmp_path / "smallest.toml"
    f.write_text(to_toml(smallest), encoding="utf-8")
    capsys.readouterr()
    rc = main(["solve", str(f)])
    out, err = capsys.readouterr()
    # sized and verified; its profile (a rise in 1e-6 degrees) is a step no tolerance can follow: not buildable
    assert rc == 1 and err == "", err
    assert "verified: yes" in out and "buildable: NO" in out and "no profile: profile.tolerance" in out, out


def _truncated(doc: dict, before: str) -> str:
    """``doc`` as TOML cut in the middle of the key ``before``."""
    return to_toml(doc).split(before)[0] + before[:3]


#: malformed files of every kind met in a sample of 600: garbage types, missing tables, wrong table kinds, arrays
#: where numbers go, unknown phases, truncated text; each with the field its one-line message must name
MALFORMED = [
    ({**ROCKER_FORM, "follower": [1, 2]}, "follower: must be a table"),
    ({**ROCKER_FORM, "motion": {"phase": "rise"}}, "motion: needs a list of phases"),
    ({**ROCKER_FORM, "motion": [1, 2]}, "motion[0]: must be a table"),
    ({**ROCKER_FORM, "limits": "x"}, "limits: must be a table"),
    ({k: v for k, v in ROCKER_FORM.items() if k != "limits"}, "limits.pressure_angle: is required"),
    ({k: v for k, v in ROCKER_FORM.items() if k != "motion"}, "motion: needs a list of phases"),
    (_set(ROCKER_FORM, "motion[1].phase", "hold"), "motion[1].phase: 'hold' is not a valid option"),
    (_set(ROCKER_FORM, "motion[0].law", ["cycloidal"]), "motion[0].law: unknown law"),
    (_set(ROCKER_FORM, "follower.arm", [125.0, 125.0]), "follower.arm: must be a number, got an array"),
    (_set(ROCKER_FORM, "cam.rpm", {"a": 1}), "cam.rpm: must be a number, got a table"),
    (_set(ROCKER_FORCE, "dynamics.mass", [1, 2]), "dynamics.mass: must be a finite number"),
    (_set(ROCKER_FORM, "name", 3), "name: must be a string"),
    (_truncated(ROCKER_FORM, "swing"), "FILE: "),
    ("[follower\nkind = 1", "FILE: "),
]


@pytest.mark.parametrize("command", ["solve", "check", "profile", "plot", "report", "sweep"])
def test_malformed_design_files_one_line_in_every_command(command, tmp_path, capsys):
    for doc, expected in MALFORMED:
        f = tmp_path / "bad.toml"
        f.write_text(doc if isinstance(doc, str) else to_toml(doc), encoding="utf-8")
        options = {"sweep": ["--vary", "profile.tolerance=0.001:0.002:2", "--out", str(tmp_path / "s.csv")],
                   "profile": ["--csv", str(tmp_path / "p.csv")],
                   "plot": ["--out", str(tmp_path / "pl")],
                   "report": ["--out", str(tmp_path / "rp")]}
        argv = [command, str(f), *options.get(command, [])]
        capsys.readouterr()
        assert main(argv) == 2, (command, expected)
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and f"cams {command}: error: {expected}" in err, (command, err)
    assert not (tmp_path / "s.csv").exists() and not (tmp_path / "p.csv").exists()


@pytest.mark.parametrize("doc, expected", [
    ({**SLOTTING, "linkage": [1]}, "linkage: must be a table"),
    ({**SLOTTING, "forces": {**SLOTTING["forces"], "loads": [1]}}, "forces.loads[0]: must be a table"),
    (_set(SLOTTING, "forces.links.bar.mass", [1, 2]), "forces.links.bar.mass: must be a finite number"),
    (_set(SLOTTING, "timing.placement", 3), "timing.placement: 3 is not a valid option"),
    (_set(CRANK_SLIDER, "forces.loads[0].angles", 3), "forces.loads[0].angles: must be a list of numbers"),
    (_set(SLOTTING, "motion[0].phase", "hold"), "motion[0].phase: 'hold' is not a valid option"),
    ({k: v for k, v in SLOTTING.items() if k != "follower"}, "follower: the file has no [follower] table"),
])
def test_malformed_machine_files_one_line(doc, expected, tmp_path, capsys):
    f = tmp_path / "in.toml"
    f.write_text(to_toml(doc), encoding="utf-8")
    for forces in ([], ["--forces"]):
        capsys.readouterr()
        rc, err = main(["machine", str(f), *forces]), capsys.readouterr().err
        assert rc == 2 and err.count("\n") == 1 and f"cams machine: error: {expected}" in err, err


@pytest.mark.parametrize("samples", [100_001, 10 ** 9, 11])
def test_forces_samples_has_an_upper_bound(samples, tmp_path, capsys):
    """[forces] samples = 1e9 would need some 4 TB; the bound is in the message (100000: about 0.4 GB)."""
    rc, err = _run(tmp_path, _set(SLOTTING, "forces.samples", samples), capsys)
    assert rc == 2 and err.count("\n") == 1 and "forces.samples: must be an integer from 12 to 100000" in err


def test_api_number_check_refuses_integers_beyond_floats():
    """laws.errors.check_number (the API's classes: springs, loads, links) took a 400-digit int to a TypeError."""
    from laws.errors import check_number

    with pytest.raises(InputError, match=r"^dynamics\.load: must be a finite number, got 1\.00000e\+400, too large"):
        check_number("dynamics.load", 10 ** 400)
    assert check_number("dynamics.load", 10 ** 20) == 1e20  # representable: a float, as any number
