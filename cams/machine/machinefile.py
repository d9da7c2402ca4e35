"""Machine files (TOML): a linkage, its cutting zone, the cam's drive and timing, and the cam.

Lengths in the file's unit (``units``, mm by default), angles in degrees.

Schema (see ``examples/machines/``)::

    name = "slotting machine"
    units = "mm"
    [linkage]   type = "slotting" | "crank_slider" | "slotted_lever_pump"
                crank_rotation ("ccw" | "cw"), rpm (optional)
                course data (synthesis) or lengths, by type:
                  slotting:           time_ratio, stroke, centre_distance, rod_ratio
                                      | crank, centre_distance, bar, rod, guide_x
                                      bar_side ("opposite" | "same"), tool_side ("above" | "below")
                  crank_slider:       stroke, rod | crank, rod; offset, slider_side ("right" | "left"), rod_cg
                  slotted_lever_pump: time_ratio, stroke, centre_distance | crank, centre_distance, lever
                                      lever_side ("opposite" | "same"), guide_x
                time_ratio K (course data) must give the linkage that stroke and K (checked to 1e-9):
                  slotting:           1 < K < K_max(rod_ratio) = (180 + theta) / (180 - theta),
                                      theta = 2 acos(1 / (1 + 2 rod_ratio)) (8.2444 for rod_ratio 1;
                                      cams.machine.linkage.synthesis.slotting_time_ratio_limit), and K <= 1000
                  slotted_lever_pump: 1 < K <= 1000
                  crank_slider:       1e-6 rod <= stroke < the rod's reach
    [cutting]   approach, overrun (fractions of the stroke), working ("slow" | "fast" | "forward" | "backward")
    [drive]     kind ("shaft" | "gears"), z_crank, z_cam, mesh ("external" | "internal")
    [timing]    margin (degrees of crank angle), placement ("centre" | "early" | "late"),
                follower_direction (degrees, frame; optional; only for a cam turning with the
                crank: kind = "shaft" or equal gears meshing internally)
    [follower], [[motion]], [limits], [solve], [dynamics]   as in a design file (cams/io/designfile.py);
                [dynamics] journal_radius for a rocker only
    [cam]       bore_radius and hub_wall only (the feed cam is sized to clear the bore by the wall, and
                cams.machine.design.design_machine checks it): rotation and rpm follow from the crank and the drive
    [forces]    optional: masses, loads, friction and the flywheel's delta of the linkage
                (:func:`force_spec_from_dict`); parsed into ``spec.forces`` and ``spec.force_options``
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

import numpy as np

from cams.io.designfile import design_from_dict
from cams.io.document import check_document, check_keys, read_toml, toml_number, toml_table
from cams.machine.design import MachineSpec
from cams.machine.kinetostatics.loads import (
    WINDOWS,
    ConstantFriction,
    ForceOptions,
    ForceSpec,
    Friction,
    G,
    GasPressure,
    LinkMass,
    Load,
    Resistance,
)
from cams.machine.kinetostatics.model import message_of, pinned_cg_message
from cams.machine.linkage.machines import (
    MACHINES,
    CrankSlider,
    SlottedLeverPump,
    SlottingMachine,
)
from cams.machine.timing import (
    CuttingZone,
    Drive,
    Timing,
    check_follower_direction,
)
from cams.model.design import CamDesign
from cams.model.follower import rotation_word, sense_of
from laws.errors import InputError, check_number, check_option, show_value

__all__ = ["load_machine", "machine_from_dict", "force_spec_from_dict", "LINKAGE_TYPES", "FORCES_KEYS"]

_COMMON = {"type", "crank_rotation", "rpm"}
_LINKAGE = {
    "slotting": (
        {"time_ratio", "stroke", "centre_distance", "rod_ratio"},
        {"crank", "centre_distance", "bar", "rod", "guide_x"},
        {"bar_side", "tool_side"},
    ),
    "crank_slider": ({"stroke", "rod"}, {"crank", "rod"}, {"offset", "slider_side", "rod_cg"}),
    "slotted_lever_pump": (
        {"time_ratio", "stroke", "centre_distance"},
        {"crank", "centre_distance", "lever"},
        {"lever_side", "guide_x"},
    ),
}
LINKAGE_TYPES = tuple(_LINKAGE)
_KEYS = {
    "": {"name", "units", "linkage", "cutting", "drive", "timing", "follower", "cam", "motion", "limits", "solve",
         "dynamics", "forces"},
    "cutting": {"approach", "overrun", "working"},
    "drive": {"kind", "z_crank", "z_cam", "mesh"},
    "timing": {"margin", "placement", "follower_direction"},
    "cam": {"bore_radius", "hub_wall"},
}
_SIDES = {
    "bar_side": {"opposite": -1, "same": 1},
    "lever_side": {"opposite": -1, "same": 1},
    "tool_side": {"above": 1, "below": -1},
    "slider_side": {"right": 1, "left": -1},
}


def _check_keys(table: dict, allowed: set, field: str) -> None:
    check_keys(table, allowed, field or "machine")


def _side(table: dict, key: str, default: str) -> int:
    words = _SIDES[key]
    return words[check_option(f"linkage.{key}", table.get(key, default), tuple(words))]


def _required(table: dict, key: str, field: str) -> float:
    """A required number of the file (:func:`cams.io.document.toml_number` raises when it is missing)."""
    value = toml_number(table, key, field)
    assert value is not None  # required: a missing entry has raised
    return value


def _or(table: dict, key: str, field: str, default: float) -> float:
    """An optional number of the file, ``default`` when it is absent."""
    return _required(table, key, field) if key in table else default


def _linkage(lk: dict) -> SlottingMachine | CrankSlider | SlottedLeverPump:
    if "type" not in lk:
        raise InputError("linkage.type", f"is required, one of {', '.join(map(repr, LINKAGE_TYPES))}")
    kind = check_option("linkage.type", lk.get("type"), LINKAGE_TYPES)
    course, lengths, options = _LINKAGE[kind]
    _check_keys(lk, _COMMON | course | lengths | options, "linkage")
    given_course = sorted((set(lk) & course) - lengths)
    given_lengths = sorted((set(lk) & lengths) - course)
    if given_course and given_lengths:
        raise InputError(
            "linkage",
            f"give either the course data ({', '.join(sorted(course))}) or the lengths "
            f"({', '.join(sorted(lengths))}), not both: got {', '.join(given_course)} and {', '.join(given_lengths)}",
        )
    use_course = bool(given_course)
    need = course if use_course else lengths
    for k in sorted(need):
        if k not in lk:
            raise InputError(f"linkage.{k}",
                             f"is required with the {'course data' if use_course else 'lengths'} of a {kind} linkage")
    f = {k: _required(lk, k, f"linkage.{k}") for k in need}
    crank_sense = sense_of("linkage.crank_rotation",
                           check_option("linkage.crank_rotation", lk.get("crank_rotation", "ccw"), ("ccw", "cw")))
    rpm = toml_number(lk, "rpm", "linkage.rpm", required=False)
    if kind == "slotting":
        bar_side, tool_side = _side(lk, "bar_side", "opposite"), _side(lk, "tool_side", "above")
        if use_course:
            return SlottingMachine.from_course(f["time_ratio"], f["stroke"], f["centre_distance"], f["rod_ratio"],
                                               bar_side=bar_side, tool_side=tool_side,
                                               crank_sense=crank_sense, rpm=rpm)
        return SlottingMachine(crank=f["crank"], centre_distance=f["centre_distance"], bar=f["bar"], rod=f["rod"],
                               guide_x=f["guide_x"], bar_side=bar_side, tool_side=tool_side,
                               crank_sense=crank_sense, rpm=rpm)
    if kind == "crank_slider":
        offset = _or(lk, "offset", "linkage.offset", 0.0)
        slider_side = _side(lk, "slider_side", "right")
        rod_cg = toml_number(lk, "rod_cg", "linkage.rod_cg", required=False)
        if use_course:
            return CrankSlider.from_stroke(f["stroke"], f["rod"], offset=offset, slider_side=slider_side,
                                           rod_cg=rod_cg, crank_sense=crank_sense, rpm=rpm)
        return CrankSlider(crank=f["crank"], rod=f["rod"], offset=offset, slider_side=slider_side, rod_cg=rod_cg,
                           crank_sense=crank_sense, rpm=rpm)
    lever_side = _side(lk, "lever_side", "opposite")
    guide_x = _or(lk, "guide_x", "linkage.guide_x", 0.0)
    if use_course:
        return SlottedLeverPump.from_course(f["time_ratio"], f["stroke"], f["centre_distance"],
                                            lever_side=lever_side, guide_x=guide_x,
                                            crank_sense=crank_sense, rpm=rpm)
    return SlottedLeverPump(crank=f["crank"], centre_distance=f["centre_distance"], lever=f["lever"],
                            lever_side=lever_side, guide_x=guide_x, crank_sense=crank_sense, rpm=rpm)


def _drive(dr: dict) -> Drive:
    _check_keys(dr, _KEYS["drive"], "drive")
    kind = check_option("drive.kind", dr.get("kind", "shaft"), ("shaft", "gears"))
    if kind == "shaft":
        extra = sorted(set(dr) - {"kind"})
        if extra:
            raise InputError("drive", f"{', '.join(extra)} apply to kind = 'gears'")
        return Drive.shaft()
    for k in ("z_crank", "z_cam"):
        if k not in dr:
            raise InputError(f"drive.{k}", "is required for a gear drive (teeth on the crank's and the cam's shaft)")
    return Drive.gears(dr["z_crank"], dr["z_cam"], mesh=dr.get("mesh", "external"))


def machine_from_dict(d: dict) -> MachineSpec:
    """Build a :class:`MachineSpec` from a parsed machine file (degrees, lengths).

    Parameters
    ----------
    d : dict
        The parsed file (schema in the module notes): lengths in mm, angles
        in degrees.

    Returns
    -------
    MachineSpec
        The linkage (lengths in mm, crank sense +1 counter-clockwise, rpm as
        given), the cutting zone, the drive, the timing (margin and
        follower direction in radians) and the cam's design, built by
        :func:`cams.io.designfile.design_from_dict` from the file's cam tables
        with the cam's sense ``crank sense * drive sense`` and speed
        ``linkage.rpm * drive ratio`` (rev/min). With a [forces] table,
        ``forces`` and ``force_options`` (:func:`force_spec_from_dict`).

    Raises
    ------
    InputError
        Unknown keys, missing or invalid values; the field is named. A file
        without a [linkage] table (a design file for ``cams solve``) is
        refused on ``linkage``.
    AssemblyError
        The linkage cannot be assembled at some crank angle.
    """
    if not isinstance(d, dict):
        raise InputError("machine", f"must be a dict of the file's tables, got {type(d).__name__}")
    check_document(d)
    if "linkage" not in d:
        if d.get("follower") is not None or d.get("motion") is not None:
            raise InputError("linkage", "the file has no [linkage] table: it is a cam design file, to be sized "
                             "with `cams solve`; a machine file adds a [linkage] table (see examples/machines/)")
        raise InputError("linkage",
                         "the file has no [linkage] table; a machine file needs one (see examples/machines/)")
    _check_keys(d, _KEYS[""], "")
    name = d.get("name", "machine")
    if not isinstance(name, str):
        raise InputError("name", f"must be a string, got {show_value(name)}")
    units = d.get("units", "mm")
    if units != "mm":
        raise InputError("units", f"{units!r} is not supported: machine files are in mm" if isinstance(units, str)
                         else f"must be the string 'mm', got {units}")
    linkage = _linkage(toml_table(d, "linkage"))
    cu = toml_table(d, "cutting")
    _check_keys(cu, _KEYS["cutting"], "cutting")
    cutting = CuttingZone(
        approach=_or(cu, "approach", "cutting.approach", 0.0),
        overrun=_or(cu, "overrun", "cutting.overrun", 0.0),
        working=cu.get("working", "slow"),
    )
    drive = _drive(toml_table(d, "drive"))
    ti = toml_table(d, "timing")
    _check_keys(ti, _KEYS["timing"], "timing")
    fd = toml_number(ti, "follower_direction", "timing.follower_direction", required=False)
    timing = Timing(
        margin=float(np.radians(_or(ti, "margin", "timing.margin", 0.0))),
        placement=ti.get("placement", "centre"),
        follower_direction=None if fd is None else float(np.radians(fd)),
    )
    check_follower_direction(timing, drive)
    cam = toml_table(d, "cam")
    for k in ("rotation", "rpm"):
        if k in cam:
            raise InputError(f"cam.{k}",
                             "is set by the machine (linkage.crank_rotation, linkage.rpm and [drive]); remove it")
    _check_keys(cam, _KEYS["cam"], "cam")
    cam_sense = linkage.crank_sense * drive.sense
    cam_table = {**cam, "rotation": rotation_word(cam_sense)}
    if linkage.rpm is not None:
        cam_table["rpm"] = linkage.rpm * drive.ratio
    dd = {k: d[k] for k in ("follower", "motion", "limits", "solve", "units", "dynamics") if k in d}
    dd["cam"] = cam_table
    dd["name"] = f"{name}: cam"
    fo = d.get("follower")
    if isinstance(fo, dict) and fo.get("face") == "flat":  # before the follower's own keys are checked
        raise InputError("follower.face", "a machine's feed cam is sized for roller followers only; size a "
                         "flat-faced follower's cam on its own with cams solve")
    design = design_from_dict(dd)  # checks [dynamics] too (journal_radius: a rocker's only)
    assert isinstance(design, CamDesign)  # a flat face was refused above
    forces, force_options = None, ForceOptions()
    if "forces" in d:
        forces, force_options = force_spec_from_dict(d["forces"], linkage.kind, units=units, cutting=cutting)
    return MachineSpec(name=name, linkage=linkage, cutting=cutting, drive=drive, timing=timing, cam=design,
                       units=units, forces=forces, force_options=force_options)


def load_machine(path: str | Path) -> MachineSpec:
    """Read a machine file; raise :class:`InputError` for unreadable or invalid files.

    Parameters
    ----------
    path : str or Path
        A TOML machine file (UTF-8).

    Returns
    -------
    MachineSpec
        As :func:`machine_from_dict`.
    """
    return machine_from_dict(read_toml(path))


# --------------------------------------------------------------------------- [forces]
FORCES_KEYS = ("gravity", "samples", "passes", "delta", "interpolation", "links", "friction", "loads")
"""Keys of a machine file's ``[forces]`` table."""
_LOAD_KEYS = {
    "resistance": {"kind", "body", "force", "window", "approach", "overrun", "working"},
    "gas": {"kind", "body", "angles", "pressure", "bore", "start", "period"},
    "constant_friction": {"kind", "body", "force"},
}


def _keys(table: object, allowed: Iterable[str], field_: str) -> dict:
    """``table`` if it is a table with no key outside ``allowed`` (:func:`cams.io.document.check_keys`)."""
    if not isinstance(table, dict):
        raise InputError(field_, "must be a table")
    check_keys(table, set(allowed), field_)
    return table


def force_spec_from_dict(table: dict, kind: str, *, units: str = "mm", cutting=None) -> tuple[ForceSpec, ForceOptions]:
    """A machine file's ``[forces]`` table.

    Schema (masses kg, moments of inertia kg m^2, forces N, pressures Pa,
    lengths in the file's unit, angles in degrees)::

        [forces]            gravity (m/s^2, default 9.80665), samples (360), passes (2 | "iterate"),
                            delta (flywheel), interpolation ("linear" | "spline")
        [forces.links.NAME] mass, inertia, cg           NAME: the linkage's links (its ``links``)
                            (cg: links that turn only; sliding links refuse it)
        [forces.friction]   revolute = {coefficient, radius}, prismatic = {coefficient},
                            PAIR = {coefficient, radius} (overrides; PAIR: its ``pairs``;
                            radius refused for a prismatic pair)
        [[forces.loads]]    kind = "resistance": body, force, window ("cut" | "working" | "always"),
                                                 approach, overrun (window "cut" only),
                                                 working (not with "always"); default: [cutting]
                            kind = "gas": body, angles, pressure, bore, start, period
                            kind = "constant_friction": body, force
                            body: a link that slides on a guide (its ``guided()``)

    Every value is checked here, with the load's index in the field
    (``forces.loads[1].approach``), not only when the forces are computed.

    Parameters
    ----------
    table : dict
    kind : str
        The linkage's kind (``linkage.type``, a key of :data:`cams.machine.linkage.machines.MACHINES`).
    units : str
        The file's length unit: ``"mm"`` only (:data:`laws.units.LENGTH_UNITS`).
    cutting : cams.machine.timing.CuttingZone or None
        Defaults of a "resistance" load's window.

    Returns
    -------
    (ForceSpec, ForceOptions)

    Examples
    --------
    >>> spec, opt = force_spec_from_dict({"links": {"tool": {"mass": 80}}, "delta": 0.05,
    ...     "loads": [{"kind": "resistance", "body": "tool", "force": 1000}]}, "slotting")
    >>> spec.links["tool"].mass, spec.loads[0].window, opt.delta
    (80.0, 'cut', 0.05)
    """
    from laws.units import LENGTH_UNITS

    t = _keys(table, FORCES_KEYS, "forces")
    if units not in LENGTH_UNITS:
        raise InputError("units", f"{units!r} is not supported: machine files are in mm")
    linkage = MACHINES[kind]  # the machine's own topology: its links, pairs and sliding links
    names, pairs, guided = linkage.links, tuple(p.name for p in linkage.pairs), linkage.guided()
    links = {}
    for nm, lt in _keys(t.get("links", {}), names, "forces.links").items():
        lt = _keys(lt, {"mass", "inertia", "cg"}, f"forces.links.{nm}")
        if "cg" in lt and nm in guided:
            raise InputError(f"forces.links.{nm}.cg", pinned_cg_message(nm, kind))
        vals = {k: check_number(f"forces.links.{nm}.{k}", v) for k, v in lt.items()}
        for k in ("mass", "inertia"):
            if vals.get(k, 0.0) < 0:
                raise InputError(f"forces.links.{nm}.{k}", f"cannot be negative, got {show_value(vals[k])}")
        links[nm] = LinkMass(vals.get("mass", 0.0), vals.get("inertia", 0.0), vals.get("cg"))
    fr = _keys(t.get("friction", {}), {"revolute", "prismatic", *pairs}, "forces.friction")

    def is_prismatic(p):
        return p in pairs and linkage.pair_kind(p) == "prismatic"

    entries = {}
    for name, v in fr.items():  # every entry checked, also one that every pair's own entry overrides
        f = f"forces.friction.{name}"
        v = _keys(v, {"coefficient", "radius"}, f)
        if "coefficient" not in v:
            raise InputError(f"{f}.coefficient", "is required")
        if "radius" in v and (name == "prismatic" or (name != "revolute" and is_prismatic(name))):
            raise InputError(f"{f}.radius", "applies to a revolute pair's journal (friction moment mu r R); "
                             "a prismatic pair's friction is the force mu N along its guide and has no radius: "
                             "remove it")
        c = check_number(f"{f}.coefficient", v["coefficient"], lo=0.0)
        entries[name] = Friction(c, check_number(f"{f}.radius", v.get("radius", 0.0), lo=0.0))

    friction = {}
    for p in pairs:
        prismatic = is_prismatic(p)
        if p in entries:
            friction[p] = entries[p]
        elif prismatic and "prismatic" in entries:
            friction[p] = entries["prismatic"]
        elif not prismatic and "revolute" in entries:
            friction[p] = entries["revolute"]
    loads: list[Load] = []
    raw = t.get("loads", [])
    if not isinstance(raw, list):
        raise InputError("forces.loads", "must be a list of tables ([[forces.loads]])")
    for i, ld in enumerate(raw):
        f = f"forces.loads[{i}]"
        if not isinstance(ld, dict):
            raise InputError(f, "must be a table")
        k = check_option(f"{f}.kind", ld.get("kind"), tuple(_LOAD_KEYS))
        _keys(ld, _LOAD_KEYS[k], f)
        if "body" not in ld:
            raise InputError(f"{f}.body", "is required")
        body = ld["body"]
        if body not in names:
            raise InputError(f"{f}.body", f"{show_value(body)} is not a link of a {kind} linkage; "
                             f"a load acts on a link that slides on a guide: {', '.join(map(repr, guided))}")
        if body not in guided:
            raise InputError(f"{f}.body", f"{body!r} does not slide on a guide; a load acts along a guide, on one of "
                             f"{', '.join(map(repr, guided))}")
        try:
            if k == "gas":
                for key in ("angles", "pressure", "bore"):
                    if key not in ld:
                        raise InputError(f"{f}.{key}", "is required")
                for key in ("angles", "pressure"):
                    if not isinstance(ld[key], list):
                        raise InputError(f"{f}.{key}", f"must be a list of numbers, got {show_value(ld[key])}")
                    for j, x in enumerate(ld[key]):  # each element: no booleans, strings or arrays
                        check_number(f"{f}.{key}[{j}]", x)
                bore = check_number(f"{f}.bore", ld["bore"])
                start = check_number(f"{f}.start", ld.get("start", 0.0))
                period = ld.get("period", 360.0)
                if isinstance(period, bool) or period not in (360, 720):
                    raise InputError(f"{f}.period", f"must be 360 or 720 degrees, got {show_value(period)}")
                # the file's degrees, radians inside
                loads.append(GasPressure(body, tuple(np.radians(np.asarray(ld["angles"], dtype=float))),
                                         tuple(ld["pressure"]), bore, start=float(np.radians(start)),
                                         period=float(np.radians(period))))
            else:
                if "force" not in ld:
                    raise InputError(f"{f}.force", "is required")
                F = check_number(f"{f}.force", ld["force"])
                if k == "constant_friction":
                    loads.append(ConstantFriction(body, F))
                else:
                    cz = cutting
                    window = check_option(f"{f}.window", ld.get("window", "cut"), WINDOWS)
                    if window != "cut":
                        for key in ("approach", "overrun"):
                            if key in ld:
                                raise InputError(f"{f}.{key}", "applies to window = 'cut' only (the part of the "
                                                 f"working stroke in the work); window = {window!r} does not use "
                                                 "it: remove it")
                    if window == "always" and "working" in ld:
                        raise InputError(f"{f}.working", "applies to windows 'cut' and 'working'; window = "
                                         "'always' acts over the whole cycle whichever stroke works: remove it")
                    frac = {key: ld.get(key, 0.0 if cz is None or window != "cut" else getattr(cz, key))
                            for key in ("approach", "overrun")}
                    loads.append(Resistance(body, F, window=window, **frac,
                                            working=ld.get("working", "slow" if cz is None else cz.working)))
        except InputError as e:
            # name the load in the field: forces.loads.angles -> forces.loads[i].angles
            fld = e.field.replace("forces.loads.", f"{f}.") if e.field.startswith("forces.loads.") else e.field
            raise InputError(fld, message_of(e)) from None
    samples = t.get("samples", 360)
    if isinstance(samples, bool) or not isinstance(samples, int) or not 12 <= samples <= 100_000:
        # the bound keeps memory near 0.5 GB (about 4 kB a crank angle)
        raise InputError("forces.samples", f"must be an integer from 12 to 100000, got {show_value(samples)}")
    passes = t.get("passes", 2)
    if passes == "iterate":
        passes = None
    elif isinstance(passes, bool) or not isinstance(passes, int) or passes < 1:
        raise InputError("forces.passes", f"must be an integer >= 1 or 'iterate', got {show_value(passes)}")
    delta = t.get("delta")
    if delta is not None:
        delta = check_number("forces.delta", delta)
        if not 0 < delta < 1:
            raise InputError("forces.delta",
                             f"the coefficient of speed fluctuation must be in (0, 1), got {show_value(delta)}")
    from cams.machine.flywheel import INTERPOLATIONS

    interp = check_option("forces.interpolation", t.get("interpolation", "linear"), INTERPOLATIONS)
    spec = ForceSpec(links=links, loads=tuple(loads), friction=friction,
                     gravity=check_number("forces.gravity", t.get("gravity", G)), length_unit=LENGTH_UNITS[units])
    return spec, ForceOptions(samples=samples, passes=passes, delta=delta, interpolation=interp)
