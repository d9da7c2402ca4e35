"""Design files (TOML): lengths in the file's unit (mm by default), angles in degrees.

Schema (see ``examples/``)::

    name = "feed cam"
    units = "mm"  (the only length unit)
    [follower]   kind, face ("roller" default | "flat"), arm, swing (rocker) | stroke, offset
                 (translating), roller_radius, rise_direction ("cw" | "ccw", rocker)
    [cam]        rotation ("cw" | "ccw"), rpm (optional), bore_radius and hub_wall (optional),
                 keyway_width, keyway_depth (mm) and keyway_angle (degrees from the datum; optional),
                 base_radius (a chosen R0, with follower.offset or limits.centre_distance)
                 or centre ([x, y] in the follower's fixed frame): a chosen cam, checked not sized
    [[motion]]   phase ("rise" | "dwell" | "return"), law, angle (degrees),
                 height (optional, part of the lift); one dwell may omit angle
    [limits]     pressure_angle, return_pressure_angle, closure ("force" | "form"),
                 safety_factor, centre_distance, min_base_radius
    [solve]      method ("exact" | "convex" | "exhaustive"), samples, objective ("R0" | "L", rocker),
                 constraints ("all" | "pressure_angle")
    [profile]    tolerance (chord, mm; default 0.001), min_curvature_radius (optional)
    [dynamics]   optional, force closure: mass, load, spring_rate, preload, friction,
                 journal_radius, margin, max_spring_force, the bounds on the spring's
                 installed compression or twist (see :func:`dynamics_from_dict`);
                 mapped onto ``design.dynamics`` (a :class:`cams.model.dynamics.DynamicsSpec`)

Every table maps onto a typed field of the design (``[solve] objective`` onto ``objective``,
``[profile]`` onto ``tolerance`` and ``min_curvature_radius``, ``[cam] bore_radius`` and ``hub_wall`` onto
``bore_radius`` and ``hub_wall``): the loader checks the file's shape (tables, known keys, numbers where numbers
belong) and the model's ``__post_init__`` checks the values, with one message each.

A flat-faced follower (``face = "flat"``) gives a :class:`cams.model.design.FlatFaceDesign`
instead: its size is limited by convexity, not by a pressure angle::

    [follower]   kind, face = "flat"; translating: stroke, offset (default 0: it only
                 moves the contact); rocker: swing, rise_direction, centre_distance
                 (L, pivot to cam centre, required), face_offset (signed distance
                 pivot to face line, positive with the pivot on the cam's side; default 0)
    [cam]        rotation, rpm, bore_radius, hub_wall, keyway_width, keyway_depth, keyway_angle,
                 base_radius (optional: a chosen R0 to
                 check instead of the smallest)
    [[motion]]   as above
    [limits]     min_radius (smallest radius of curvature of the profile, default a
                 tenth of the stroke, or of L times the swing in radians), min_base_radius,
                 closure = "force" (the only one)
    [profile]    tolerance
    [dynamics]   as above, with face_friction (the face's sliding friction); a
                 translating face takes no journal_radius

No roller_radius, arm, pressure-angle limits, safety_factor or [solve]
for a flat face: each is refused with a one-line error naming it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from cams.io.document import check_document, check_keys, read_toml, toml_integer
from cams.io.document import toml_number as _num
from cams.io.document import toml_table as _table
from cams.io.lawtable import law_from_table
from cams.model.contact import CONTACT_KEYS, ContactSpec
from cams.model.design import (
    MAX_SAMPLES,
    OBJECTIVE_SUPERSEDED,
    CamDesign,
    FlatFaceDesign,
    Limits,
    check_lift,
)
from cams.model.dynamics import (
    DynamicsSpec,
    FollowerDynamics,
    Spring,
    face_friction_error,
    installed_error,
    journal_error,
)
from cams.model.follower import (
    FlatRocker,
    FlatTranslating,
    Rocker,
    Translating,
    sense_of,
)
from laws.base import Law
from laws.errors import InputError, check_number, check_option, show_value
from laws.program import Phase, Program
from laws.registry import get_law
from laws.units import LENGTH_UNITS

__all__ = ["load_design", "design_from_dict", "dynamics_from_dict", "designed_document", "MAX_SAMPLES"]

_KEYS = {
    "": {"name", "units", "follower", "cam", "motion", "limits", "solve", "profile", "dynamics", "optimize",
         "contact"},
    "follower": {"kind", "face", "arm", "swing", "stroke", "offset", "roller_radius", "rise_direction"},
    "cam": {"rotation", "rpm", "bore_radius", "hub_wall", "base_radius", "centre", "width", "keyway_width",
            "keyway_depth", "keyway_angle"},
    "motion": {"phase", "law", "angle", "height"},
    "limits": {"pressure_angle", "return_pressure_angle", "closure", "safety_factor",
               "centre_distance", "min_base_radius"},
    "solve": {"method", "samples", "objective", "constraints"},
    "profile": {"tolerance", "min_curvature_radius"},
    # flat-faced followers
    "flat_rocker": {"kind", "face", "swing", "rise_direction", "centre_distance", "face_offset"},
    "flat_translating": {"kind", "face", "stroke", "offset"},
    "flat_cam": {"rotation", "rpm", "bore_radius", "hub_wall", "base_radius", "width", "keyway_width", "keyway_depth",
                 "keyway_angle"},
    "flat_limits": {"min_radius", "min_base_radius", "closure"},
    "flat_profile": {"tolerance"},
}

#: Keys of roller designs a flat face does not take, and why (one line each).
_NOT_FLAT = {
    "follower.roller_radius": "does not apply to a flat-faced follower (face = \"flat\"); remove it",
    "follower.arm": "does not apply to a flat-faced rocker: give follower.centre_distance (pivot to cam centre) "
                    "and follower.face_offset (pivot to face line, default 0)",
    "limits.pressure_angle": "does not apply to a flat-faced follower: its pressure angle is fixed by the geometry "
                             "(cams solve reports it); its size is limited by limits.min_radius",
    "limits.return_pressure_angle": "does not apply to a flat-faced follower: its pressure angle is fixed by the "
                                    "geometry (cams solve reports it); its size is limited by limits.min_radius",
    "limits.safety_factor": "does not apply to a flat-faced follower (K_C widens a roller rocker's pressure-angle "
                            "limit); remove it",
    "limits.centre_distance": "for a flat-faced rocker the centre distance L is follower.centre_distance",
    "profile.min_curvature_radius": "for a flat-faced follower the profile's smallest radius of curvature is "
                                    "limits.min_radius",
}

#: Keys only flat-faced followers take, and what a roller design uses instead.
_ONLY_FLAT = {
    "follower.centre_distance": "applies to flat-faced rockers (face = \"flat\"); a roller rocker's fixed centre "
                                "distance is limits.centre_distance",
    "follower.face_offset": "applies to flat-faced rockers (face = \"flat\")",
    "limits.min_radius": "applies to flat-faced followers (face = \"flat\"); for a roller cam use [profile] "
                         "min_curvature_radius",
}

#: The keys of a design file's [dynamics] table, in their documented order.
DYNAMICS_KEYS = ("mass", "load", "spring_rate", "preload", "friction", "face_friction", "journal_radius", "margin",
                 "max_spring_force", "train_stiffness", "damping_ratio",
                 "min_installed_compression", "max_installed_compression", "min_installed_twist", "max_installed_twist")


def _refuse(table: dict, where: str, reasons: dict) -> None:
    """Raise for the first key of ``table`` that ``reasons`` (by ``where.key``) refuses."""
    for k in table:
        why = reasons.get(f"{where}.{k}")
        if why:
            raise InputError(f"{where}.{k}", why)


def _check_keys(table: dict, where: str, field: str) -> None:
    check_keys(table, _KEYS[where], field or "design")


#: The smallest phase angle (degrees): the phase angles' sum is checked against 360 to this, so a shorter phase
#: would be lost in that round-off.
MIN_PHASE_ANGLE = 1e-6

#: Lengths (mm) a design may use: from a picometre to 1000 km; outside, round-off or overflow would
#: make the answers meaningless (the solvers work to 1e-12 of the design's scale).
LENGTH_RANGE = (1e-9, 1e9)
_LENGTH_KEYS = {
    "follower": ("arm", "stroke", "offset", "roller_radius", "centre_distance", "face_offset"),
    "limits": ("centre_distance", "min_base_radius", "min_radius"),
    "cam": ("bore_radius", "hub_wall", "base_radius", "width", "keyway_width", "keyway_depth"),
    "profile": ("tolerance", "min_curvature_radius"),
}


def _check_length_range(d: dict) -> None:
    """Refuse a non-zero length outside :data:`LENGTH_RANGE` (one-line error naming the field)."""
    lo, hi = LENGTH_RANGE
    for table, keys in _LENGTH_KEYS.items():
        t = d.get(table)
        if not isinstance(t, dict):
            continue
        for k in keys:
            v = t.get(k)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or (isinstance(v, float) and math.isnan(v)):
                continue  # not a number: the loader says so
            if v != 0 and not lo <= abs(v) <= hi:  # ints of any size; inf is outside too
                raise InputError(f"{table}.{k}", f"{show_value(v)} mm is outside the lengths a design may use "
                                 f"({lo:g} to {hi:g} mm in size)")


def design_from_dict(d: dict) -> CamDesign | FlatFaceDesign:
    """Build a :class:`CamDesign` from a parsed design file (degrees, lengths).

    Parameters
    ----------
    d : dict
        The parsed file (schema in the module notes): lengths in mm, angles
        in degrees, senses as ``"cw"``/``"ccw"``.

    Returns
    -------
    CamDesign or FlatFaceDesign
        A :class:`FlatFaceDesign` for ``follower.face = "flat"`` (see the
        module notes), else a :class:`CamDesign`:
        lengths kept in mm; the rocker's swing and heights, the phase angles
        (scaled to sum to exactly 2 pi) and the pressure-angle limits in
        radians; ``rise_direction`` and ``rotation`` as senses (+1
        counter-clockwise); ``[solve] objective``, ``[profile]``, ``[cam]
        bore_radius`` and ``[dynamics]`` as the design's typed fields.

    Raises
    ------
    InputError
        Unknown keys, missing or invalid values, units other than mm; the
        field is named (e.g. ``"motion[2].angle"``).
    """
    if not isinstance(d, dict):
        raise InputError("design", f"must be a dict of the file's tables, got {type(d).__name__}")
    _check_length_range(d)  # before the general check: the lengths' own range is the clearer message
    check_document(d)
    if "linkage" in d:
        raise InputError("linkage", "the file has a [linkage] table: it is a machine file, to be run with "
                         "`cams machine`; a design file describes the cam alone (see examples/)")
    if "follower" not in d:
        raise InputError("follower", "the file has no [follower] table; a cam needs its [follower], [[motion]] "
                         "and [limits] tables (see examples/ or `cams new`)")
    _check_keys(d, "", "")
    if d.get("units", "mm") != "mm":
        raise InputError("units", f"{d['units']!r} is not supported: design files are in mm (the "
                         "[dynamics] table's journal_radius too; its other values are SI)")
    fo = _table(d, "follower")
    kind = check_option("follower.kind", fo.get("kind", "rocker"), ("rocker", "translating"))
    if check_option("follower.face", fo.get("face", "roller"), ("roller", "flat")) == "flat":
        return _flat_design(d, fo, kind)
    _refuse(fo, "follower", _ONLY_FLAT)
    _check_keys(fo, "follower", "follower")
    roller = _num(fo, "roller_radius", "follower.roller_radius", required=False, default=0.0)
    follower: Rocker | Translating
    if kind == "rocker":
        for k in ("stroke", "offset"):
            if k in fo:
                raise InputError(f"follower.{k}", "applies to translating followers; a rocker takes arm and swing")
        arm = _num(fo, "arm", "follower.arm")
        swing = _num(fo, "swing", "follower.swing")
        follower = Rocker(arm, roller, sense=sense_of("follower.rise_direction", fo.get("rise_direction", "cw")))
        lift = np.radians(swing)
        check_lift(lift, True)  # the model's rule, before the motion's heights are read against the swing
    else:
        for k in ("arm", "swing", "rise_direction"):
            if k in fo:
                raise InputError(f"follower.{k}",
                                 "applies to rocker followers; a translating follower takes stroke and offset")
        stroke = _num(fo, "stroke", "follower.stroke")
        check_lift(stroke, False)  # the model's rule, before the motion's heights are read against the stroke
        offset = _num(fo, "offset", "follower.offset", required=False)
        follower = Translating(roller, offset=offset, stroke_scale=stroke)
        lift = stroke

    cam = _table(d, "cam")
    _refuse(cam, "cam", _ONLY_FLAT)
    _check_keys(cam, "cam", "cam")
    cam_sense = sense_of("cam.rotation", cam.get("rotation", "ccw"))
    rpm = _num(cam, "rpm", "cam.rpm", required=False)
    base_radius, centre = _chosen(cam)
    program = _program(d, kind, lift)

    li = _table(d, "limits")
    _refuse(li, "limits", _ONLY_FLAT)
    _check_keys(li, "limits", "limits")
    pa = _num(li, "pressure_angle", "limits.pressure_angle")
    rpa = _num(li, "return_pressure_angle", "limits.return_pressure_angle", required=False)
    closure = li.get("closure", "force")  # checked with the return limit by Limits
    limits = Limits(
        pressure_angle=np.radians(pa),
        return_pressure_angle=None if rpa is None else np.radians(rpa),
        closure=closure,
        safety_factor=_num(li, "safety_factor", "limits.safety_factor", required=False, default=1.0),
        centre_distance=_num(li, "centre_distance", "limits.centre_distance", required=False),
        min_base_radius=_num(li, "min_base_radius", "limits.min_base_radius", required=False),
    )
    pt = _table(d, "profile")
    _check_keys(pt, "profile", "profile")
    so = _table(d, "solve")
    _check_keys(so, "solve", "solve")
    samples = so.get("samples", 360)
    if isinstance(samples, bool) or not isinstance(samples, int):  # a whole number: its range is the model's
        toml_integer(so, "samples", "solve.samples", default=360, lo=2, hi=MAX_SAMPLES)
    # the values of [solve] objective, [profile] and the bore are the model's to check (one message each)
    return CamDesign(
        follower=follower, program=program, limits=limits, cam_sense=cam_sense, rpm=rpm, name=_name(d),
        method=so.get("method", "exact"), samples=samples, base_radius=base_radius, centre=centre,
        objective=so.get("objective", "R0"), tolerance=_value(pt, "tolerance"),
        min_curvature_radius=_value(pt, "min_curvature_radius"), bore_radius=_value(cam, "bore_radius"),
        hub_wall=_value(cam, "hub_wall"), constraints=so.get("constraints", "all"),
        dynamics=_dynamics(d, kind), optimize=_optimize(d, so),
        width=_num(cam, "width", "cam.width", required=False), contact=_contact(d), **_keyway(cam),
    )


def _keyway(cam: dict) -> dict:
    """``[cam] keyway_width``, ``keyway_depth`` (mm) and ``keyway_angle`` (degrees, here radians) as the design's
    fields; the model checks them (:func:`cams.model.options.check_keyway`)."""
    angle = _value(cam, "keyway_angle")
    if isinstance(angle, (int, float)) and not isinstance(angle, bool):
        angle = float(np.radians(angle))
    return {"keyway_width": _value(cam, "keyway_width"), "keyway_depth": _value(cam, "keyway_depth"),
            "keyway_angle": angle}


def _optimize(d: dict, solve_table: dict):
    """The optional ``[optimize]`` table (None without one); ``[solve] objective`` beside it is refused."""
    if "optimize" not in d:
        return None
    if "objective" in solve_table:
        raise InputError("solve.objective", OBJECTIVE_SUPERSEDED)
    from cams.io.optimizetable import optimize_from_table

    return optimize_from_table(d["optimize"])


def _value(table: dict, key: str):
    """``table[key]`` as given (None when absent): the model checks it, and names it as it stands in the file."""
    return table.get(key)


def _chosen(cam: dict) -> tuple[float | None, tuple[float, float] | None]:
    """``[cam] base_radius`` and ``[cam] centre`` (a chosen cam, checked by :class:`CamDesign`), or None."""
    base_radius = _num(cam, "base_radius", "cam.base_radius", required=False)
    centre = cam.get("centre")
    if centre is None:
        return base_radius, None
    if not isinstance(centre, list) or len(centre) != 2:
        raise InputError("cam.centre", f"must be [x, y] in mm (the follower's fixed frame), got {centre!r}")
    x, y = (_num({"v": v}, "v", f"cam.centre[{i}]") for i, v in enumerate(centre))
    xy = (x, y)
    hi = LENGTH_RANGE[1]
    if not max(abs(v) for v in xy) <= hi:
        raise InputError("cam.centre", f"{list(xy)!r} mm is outside the lengths a design may use (up to {hi:g} mm)")
    return base_radius, xy


def _name(d: dict) -> str:
    name = d.get("name", "cam")
    if not isinstance(name, str):
        raise InputError("name", f"must be a string, got {show_value(name)}")
    return name


def _program(d: dict, kind: str, lift: float) -> Program:
    """The ``[[motion]]`` phases as a :class:`Program` (heights of a rocker in degrees in the file)."""
    motion = d.get("motion")
    if not isinstance(motion, list) or not motion:
        raise InputError("motion", "needs a list of phases ([[motion]] tables)"
                         + ("" if motion is None else f", got {show_value(motion)}"))
    # the lift as the file gives it, for messages: a rocker's swing in degrees, a stroke in the length unit
    shown_lift, unit, lift_name = (np.degrees(lift), "degrees", "swing") if kind == "rocker" else (lift, "mm", "stroke")
    specs: list[tuple[str, float | None, Law | None, float | None]] = []  # phase, degrees, law, height
    missing = []
    for i, m in enumerate(motion):
        f = f"motion[{i}]"
        if not isinstance(m, dict):
            raise InputError(f, f"must be a table ([[motion]] with phase, law, angle), got {show_value(m)}")
        _check_keys(m, "motion", f)
        ph = check_option(f"{f}.phase", m.get("phase"), ("rise", "dwell", "return"))
        ang = _num(m, "angle", f"{f}.angle", required=False)
        if ang is None:
            if ph != "dwell":
                raise InputError(f"{f}.angle", "is required (only one dwell may omit it)")
            missing.append(i)
        elif ang <= 0:
            raise InputError(f"{f}.angle", f"must be > 0 degrees, got {ang!r}")
        elif ang < MIN_PHASE_ANGLE:
            raise InputError(f"{f}.angle", f"must be at least {MIN_PHASE_ANGLE:g} degrees (the angles' sum is "
                             f"checked to that), got {ang:g}")
        law: Law | None = None
        if ph != "dwell":
            if "law" not in m:
                raise InputError(f"{f}.law", f"a {ph} needs a law")
            law = (law_from_table(m["law"], f"{f}.law") if isinstance(m["law"], dict)
                   else get_law(m["law"], f"{f}.law"))
        elif "law" in m:
            raise InputError(f"{f}.law", "a dwell takes no law")
        h = _num(m, "height", f"{f}.height", required=False)
        if h is not None and ph == "dwell":
            raise InputError(f"{f}.height", "a dwell takes no height")
        if h is not None and not 0 < h <= shown_lift * (1 + 1e-12):
            raise InputError(f"{f}.height", f"must be in (0, {shown_lift:g}] {unit} (the {lift_name}), got {h:g}")
        specs.append((ph, ang, law, h))
    if len(missing) > 1:
        raise InputError("motion", "only one dwell may omit its angle")
    total = sum(s[1] for s in specs if s[1] is not None)
    rest = 360.0 - total  # the angle of the dwell that omits it
    if missing:
        if rest < MIN_PHASE_ANGLE:
            raise InputError(f"motion[{missing[0]}].angle", f"the other phases take {total:g} degrees, nothing is left")
    elif abs(total - 360.0) > MIN_PHASE_ANGLE:
        raise InputError("motion", f"phase angles sum to {total:.10g} degrees, must sum to 360 (or leave one dwell's "
                         "angle out: it takes the rest)")
    # rises and returns must balance and reach the lift (checked here in the file's units)
    level = top = 0.0
    for i, (ph, _, _, h) in enumerate(specs):
        step = 0.0 if ph == "dwell" else (shown_lift if h is None else h)
        level += step if ph == "rise" else -step
        if level > shown_lift * (1 + 1e-9) or level < -1e-9 * shown_lift:
            raise InputError(f"motion[{i}]", f"takes the follower to {level:.6g} {unit}, outside [0, {shown_lift:g}] "
                             f"(the {lift_name}); give the phases heights that balance")
        top = max(top, level)
    if abs(level) > 1e-9 * shown_lift:
        raise InputError("motion", f"the follower ends the cycle {level:.6g} {unit} above where it started: the rises "
                         "and returns must balance (give heights, or add a return)")
    if abs(top - shown_lift) > 1e-9 * shown_lift:
        raise InputError("motion", f"the follower reaches only {top:.6g} {unit}, the {lift_name} is {shown_lift:g}")
    # a rocker's heights in radians; exact 2 pi: scale away rounding of the degree inputs
    heights = [float(np.radians(h)) if h is not None and kind == "rocker" else h for _, _, _, h in specs]
    angles = np.radians([rest if a is None else a for _, a, _, _ in specs])
    angles *= 2 * np.pi / angles.sum()
    return Program(tuple(Phase(ph, float(a), law, h)
                         for (ph, _, law, _), a, h in zip(specs, angles, heights, strict=True)), lift)


def _flat_design(d: dict, fo: dict, kind: str) -> FlatFaceDesign:
    """The design of a flat-faced follower (``face = "flat"``): see the module notes."""
    _refuse(fo, "follower", _NOT_FLAT)
    if kind == "rocker":
        for k in ("stroke", "offset"):
            if k in fo:
                raise InputError(f"follower.{k}", "applies to translating followers; a flat-faced rocker takes "
                                 "swing, centre_distance and face_offset")
        check_keys(fo, _KEYS["flat_rocker"], "follower")
        follower: FlatRocker | FlatTranslating
        swing = _num(fo, "swing", "follower.swing")
        if "centre_distance" not in fo:
            raise InputError("follower.centre_distance", "is required for a flat-faced rocker: the distance L from "
                             "the pivot to the cam centre (mm, > 0)")
        L = check_number("follower.centre_distance", _num(fo, "centre_distance", "follower.centre_distance"),
                         lo=0.0, strict=True)
        follower = FlatRocker(L, _num(fo, "face_offset", "follower.face_offset", default=0.0),
                              sense=sense_of("follower.rise_direction", fo.get("rise_direction", "cw")))
        lift = np.radians(swing)
        check_lift(lift, True)  # the model's rule, before the motion's heights are read against the swing
        default_min_radius = 0.1 * L * lift
    else:
        for k in ("swing", "rise_direction", "centre_distance", "face_offset"):
            if k in fo:
                raise InputError(f"follower.{k}", "applies to rocker followers; a flat-faced translating follower "
                                 "takes stroke and offset")
        check_keys(fo, _KEYS["flat_translating"], "follower")
        stroke = _num(fo, "stroke", "follower.stroke")
        check_lift(stroke, False)  # the model's rule, before the motion's heights are read against the stroke
        follower = FlatTranslating(_num(fo, "offset", "follower.offset", default=0.0), stroke_scale=stroke)
        lift = stroke
        default_min_radius = 0.1 * stroke

    cam = _table(d, "cam")
    check_keys(cam, _KEYS["flat_cam"], "cam")
    cam_sense = sense_of("cam.rotation", cam.get("rotation", "ccw"))
    program = _program(d, kind, lift)

    li = _table(d, "limits")
    _refuse(li, "limits", _NOT_FLAT)
    check_keys(li, _KEYS["flat_limits"], "limits")
    if li.get("closure", "force") != "force":
        check_option("limits.closure", li["closure"], ("force", "form"))
        raise InputError("limits.closure", "a flat-faced follower is force-closed (a spring keeps it on the cam): "
                         "only 'force'")
    pt = _table(d, "profile")
    _refuse(pt, "profile", _NOT_FLAT)
    check_keys(pt, _KEYS["flat_profile"], "profile")
    so = _table(d, "solve")
    for k in so:
        raise InputError(f"solve.{k}", "does not apply to a flat-faced follower: its base radius follows from "
                         "convexity directly; remove the [solve] table")
    dynamics = _dynamics(d, kind, flat=True)
    return FlatFaceDesign(
        follower=follower, program=program,
        min_radius=_num(li, "min_radius", "limits.min_radius", default=default_min_radius),
        cam_sense=cam_sense, rpm=_num(cam, "rpm", "cam.rpm", required=False), name=_name(d),
        min_base_radius=_num(li, "min_base_radius", "limits.min_base_radius", required=False),
        base_radius=_num(cam, "base_radius", "cam.base_radius", required=False),
        bore_radius=_num(cam, "bore_radius", "cam.bore_radius", required=False),
        hub_wall=_num(cam, "hub_wall", "cam.hub_wall", required=False),
        tolerance=_num(pt, "tolerance", "profile.tolerance", required=False),
        optimize=_optimize(d, {}), dynamics=dynamics,
        width=_num(cam, "width", "cam.width", required=False), contact=_contact(d), **_keyway(cam),
    )


def _contact(d: dict) -> ContactSpec | None:
    """The optional [contact] table (None without one), onto a :class:`cams.model.contact.ContactSpec` (the file's
    units; the material names are resolved by :mod:`cams.strength.materials` where the stress is computed)."""
    if "contact" not in d:
        return None
    table = d["contact"]
    if not isinstance(table, dict):
        raise InputError("contact", "must be a table")
    check_keys(table, CONTACT_KEYS, "contact")
    if "dynamics" not in d:
        raise InputError("contact", "the contact stress needs the contact force: add a [dynamics] table (and "
                         "cam.rpm)")
    if "width" not in (d.get("cam") or {}):
        raise InputError("cam.width", "the contact stress needs the cam's face width: give cam.width (mm, > 0)")
    return ContactSpec(**table)


def _dynamics(d: dict, kind: str, *, flat: bool = False) -> DynamicsSpec | None:
    """The optional [dynamics] table (None without one); ``kind``: the follower's; ``flat``: a flat face's."""
    if "dynamics" not in d:
        return None
    units = d.get("units", "mm")
    return dynamics_from_dict(d["dynamics"], units if isinstance(units, str) else "mm", follower=kind, flat=flat)


def dynamics_from_dict(table: dict, units: str = "mm", *, follower: str | None = None,
                       flat: bool | None = None) -> DynamicsSpec:
    """A design file's ``[dynamics]`` table, mapped onto a :class:`cams.model.dynamics.DynamicsSpec`.

    Keys (SI units except ``journal_radius``, in mm):
    ``mass`` (kg; kg m^2 for a rocker), ``load`` (N; N m), ``spring_rate``
    (N/m; N m/rad), ``preload`` (N; N m), ``friction``, ``face_friction``
    (flat face only; dimensionless), ``journal_radius`` (rocker only),
    ``margin`` (>= 1, default 1.2), ``max_spring_force`` (N; N m),
    ``min_installed_compression`` and ``max_installed_compression``
    (mm; translating only), ``min_installed_twist`` and
    ``max_installed_twist`` (degrees; rocker only: radians in the spec),
    ``train_stiffness`` (N/m; N m/rad) and ``damping_ratio`` (dimensionless):
    the elastic follower train (:mod:`cams.dynamics.vibration`).
    A spring is set when ``spring_rate`` and ``preload`` are both
    given; with only the rate, the preload is left to
    :func:`cams.dynamics.forces.spring_for_contact`.

    Parameters
    ----------
    table : dict
    units : str
        The file's length unit: ``"mm"`` only.
    follower : {"rocker", "translating"} or None
        The follower's kind; ``"translating"`` refuses the key
        ``journal_radius`` (a translating follower's friction is in its guide;
        the design refuses a journal radius other than 0 with the same
        message, :func:`cams.model.dynamics.check_dynamics_follower`) and
        the twist's bounds, ``"rocker"`` the compression's. None: not checked.
    flat : bool or None
        True for a flat-faced follower; False refuses the key
        ``face_friction`` (a roller turns freely). None: not checked.

    Returns
    -------
    DynamicsSpec

    Raises
    ------
    InputError
        Unknown keys, a missing mass, values that are not numbers, a unit
        other than mm, ``journal_radius`` for a translating follower; the
        values' ranges are checked by the model's classes.

    Examples
    --------
    >>> d = dynamics_from_dict({"mass": 0.4, "spring_rate": 3000, "preload": 20})
    >>> d.dynamics.spring, d.margin
    (Spring(rate=3000.0, preload=20.0), 1.2)
    """
    if not isinstance(table, dict):
        raise InputError("dynamics", "must be a table")
    check_keys(table, DYNAMICS_KEYS, "dynamics")  # listed in the table's documented order
    if units not in LENGTH_UNITS:
        raise InputError("units", f"{show_value(units)} is not supported: the files are in mm (the [dynamics] table's "
                         "journal_radius too; its other values are SI)")
    if follower == "translating" and "journal_radius" in table:
        raise journal_error()
    if flat is False and "face_friction" in table:
        raise face_friction_error()
    for key in table:
        if follower is not None and key.endswith(("_installed_twist", "_installed_compression")) and \
                key.endswith("twist") != (follower == "rocker"):
            raise installed_error(key, rocker=follower == "rocker")
    if "mass" not in table:
        raise InputError("dynamics.mass", "is required (kg, or kg m^2 about the pivot for a rocker)")
    v = {k: check_number(f"dynamics.{k}", table[k]) for k in table}
    if "preload" in v and "spring_rate" not in v:
        raise InputError("dynamics.spring_rate", "a preload needs its spring rate")
    both = "spring_rate" in v and "preload" in v
    spec = DynamicsSpec(
        FollowerDynamics(
            mass=v["mass"],
            load=v.get("load", 0.0),
            spring=Spring(v["spring_rate"], v["preload"]) if both else None,
            friction=v.get("friction", 0.0),
            journal_radius=v.get("journal_radius", 0.0),
            length_unit=LENGTH_UNITS[units],
            max_spring_force=v.get("max_spring_force"),
            face_friction=v.get("face_friction", 0.0),
            train_stiffness=v.get("train_stiffness"),
            damping_ratio=v.get("damping_ratio", 0.0),
        ),
        margin=v.get("margin", 1.2),
        rate=None if both else v.get("spring_rate"),
        min_installed_compression=v.get("min_installed_compression"),
        max_installed_compression=v.get("max_installed_compression"),
        min_installed_twist=_radians(v.get("min_installed_twist")),
        max_installed_twist=_radians(v.get("max_installed_twist")),
    )
    return spec


def _radians(deg: float | None) -> float | None:
    """A file's angle (degrees) in radians; None stays None."""
    return None if deg is None else float(np.radians(deg))


def load_design(path: str | Path) -> CamDesign | FlatFaceDesign:
    """Read a design file; raise :class:`InputError` for unreadable or invalid files.

    Parameters
    ----------
    path : str or Path
        A TOML design file (UTF-8).

    Returns
    -------
    CamDesign or FlatFaceDesign
        As :func:`design_from_dict`.
    """
    return design_from_dict(read_toml(path))


def designed_document(doc: dict, program: Program, free: tuple[int, ...], *, floor: float | None = None,
                      centre: tuple[float, float] | None = None) -> dict:
    """A design file's document with the free phases' laws replaced by ``program``'s, and no ``[optimize]``.

    Parameters
    ----------
    doc : dict
        The document read (:func:`cams.io.document.read_toml`); not changed.
    program : Program
        The designed program: the same phases, its free phases' laws
        :class:`laws.spline.SplineLaw` (written as law tables, exactly).
    free : tuple of int
        The phases whose law is replaced.
    floor : float or None
        ``limits.min_base_radius`` to write (length): the floor that made the designed cam pass its checks.
    centre : (float, float) or None
        ``[cam] centre`` to write (length, the follower's fixed frame): the cam the design holds (the least
        pressure angle's). It replaces the keys that would fix it otherwise (``[cam] base_radius``,
        ``follower.offset``, ``limits.centre_distance``).

    Returns
    -------
    dict
        For :func:`cams.io.tomlwrite.dumps`: read back, it is the designed
        design without the request (so it solves to the same cam). The
        request's objective goes with it where it sized the cam: ``[optimize]
        objective = "L"`` (a rocker's cams of fixed laws are then sized by
        their least L, :mod:`cams.motion_design`) becomes ``[solve]
        objective = "L"``; ``"R0"`` is the default, and the other objectives
        hold the cam's size (the chosen cam, or ``centre``).
    """
    import copy

    from cams.io.lawtable import law_to_table

    out = copy.deepcopy(doc)
    request = out.pop("optimize", None)
    if isinstance(request, dict) and request.get("objective") == "L":
        out.setdefault("solve", {})["objective"] = "L"
    for i in free:
        out["motion"][i]["law"] = law_to_table(program.law_of(i))
    if floor is not None:
        out.setdefault("limits", {})["min_base_radius"] = float(floor)
    if centre is not None:
        cam = out.setdefault("cam", {})
        cam.pop("base_radius", None)
        cam["centre"] = [float(centre[0]), float(centre[1])]
        out.get("follower", {}).pop("offset", None)
        out.get("limits", {}).pop("centre_distance", None)
    return out
