"""The report's tables for each face: inputs, results, checks, forces and the motion design, as rows of text.

Each face's presenter (:mod:`cams.present.faces`) names its tables' function (:func:`roller_sections`,
:func:`flat_sections`); :func:`cams.present.report.report_sections` calls it. Lengths in mm, angles in degrees.
"""

from __future__ import annotations

import numpy as np

from cams.words import binding_text, bore_text, deg, force, length_format, spring_text
from cams.words import torque as torque_text

__all__ = ["roller_sections", "flat_sections"]


def _deg(x):
    """An angle given in radians, as every command prints angles (:func:`cams.words.deg`)."""
    return "—" if x is None else deg(x, radians=True)


def _cam_inputs(d) -> list[tuple[str, str]]:
    """The rows every face's inputs share: the cam's sense and speed (rpm), each phase (kind, law, degrees)."""
    rows = [("cam rotation", "ccw" if d.cam_sense > 0 else "cw")]
    if d.rpm:
        rows.append(("cam speed", f"{d.rpm:g} rpm"))
    for i, p in enumerate(d.program.phases):
        law = "" if p.law is None else f", {p.law.name}"
        rows.append((f"phase {i}", f"{p.kind}{law}, {np.degrees(p.angle):.6g} deg"))
    return rows


def flat_sections(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The report's tables for a flat-faced follower."""
    from cams.present.text import pressure_text

    d = cam.design
    f = d.follower
    inputs = [("name", d.name), ("follower", f"{f.kind}, flat face")]
    if f.kind == "rocker":
        inputs += [("swing ψmax", _deg(d.program.lift)), ("rocker on the rise", "ccw" if f.sense > 0 else "cw"),
                   ("centre distance L", f"{f.centre_distance:g} mm"),
                   ("face offset from the pivot", f"{f.face_offset:g} mm")]
    else:
        inputs += [("stroke h", f"{d.program.lift:g} mm"), ("offset", f"{f.offset:g} mm")]
    inputs += _cam_inputs(d)
    inputs.append(("smallest radius of curvature allowed", f"{d.min_radius:g} mm"))
    if d.min_base_radius is not None:
        inputs.append(("constructive floor on R0", f"{d.min_base_radius:g} mm"))
    if d.base_radius is not None:
        inputs.append(("chosen base radius", f"{d.base_radius:g} mm"))
    r = cam.solution.to_dict()
    results = [("sizing", f"convexity (R0 from {r['R0_source']})"), ("base radius R0", f"{r['R0']:.6f} mm"),
               *_part_rows(r, ".6f")]
    if r["R0_min"] is not None and r["R0_source"] != "convexity":
        results.append(("smallest convex enough R0", f"{r['R0_min']:.6f} mm"))
    fr = r["face_range"]
    where = "of the follower axis" if f.kind == "translating" else "along the face from the pivot's foot"
    results += [
        ("cam centre (x, y)", f"({r['centre']['x']:.6f}, {r['centre']['y']:.6f}) mm"),
        ("smallest radius of curvature", f"{r['min_rho']:.6f} mm at {deg(r['min_rho_at_deg'])}"),
        ("contact travel on the face", f"{fr['from']:.6f} to {fr['to']:.6f} mm {where}"),
        ("face width needed (no margins)", f"{r['face_width']:.6f} mm"),
    ]
    if r["face_width_centred"] is not None:
        results.append(("face centred on the axis", f"{r['face_width_centred']:.6f} mm"))
    results += [("pressure angle", pressure_text(r)),
                ("verified (radius of curvature >= limit)", "yes" if r["verified"] else "NO")]
    results += _assessment_rows(cam)
    results += [("note", n) for n in r["notes"]]
    return [("Inputs", inputs), ("Results", results), ("Checks", _check_rows(cam)), *_motion_section(cam)]


def _part_rows(r: dict, fl: str) -> list[tuple[str, str]]:
    """What governs the size, the pressure angle's own R0, the blank, the bore and the peaks at speed (the part's
    keys of a solve report, :meth:`cams.faces.result.SolveResult.to_dict`)."""
    from cams.present.text import GOVERNS_WORDS

    rows = [("governs", GOVERNS_WORDS.get(r["governs"], str(r["governs"])))]
    if r["pressure_angle_R0"] is not None and r["governs"] != "pressure_angle":
        rows.append(("R0 by the pressure angle alone", f"{r['pressure_angle_R0']:{fl}} mm"))
    rows.append(("the cam's largest radius (blank diameter)",
                 f"{r['largest_cam_radius']:{fl}} mm ({2 * r['largest_cam_radius']:{fl}} mm)"))
    if r["bore_radius"] is not None:
        rows.append(("bore radius, hub wall (at least)", f"{r['bore_radius']:{fl}} mm, {r['hub_wall']:{fl}} mm "
                     f"({r['hub_wall_required']:{fl}} mm)"))
    if r["rpm"] is not None:
        for k in ("velocity", "acceleration", "jerk"):
            p = r["peaks"][k]
            v = "unbounded (a jump)" if p["value"] is None else f"{p['value']:.6g} {p['unit']}"
            rows.append((f"peak {k} at {r['rpm']:g} rpm", f"{v} at {deg(p['at_deg'])}"))
    return rows


def _assessment_rows(cam) -> list[tuple[str, str]]:
    """Buildable beside verified, and what fails (:mod:`cams.assess`)."""
    a = cam.assessment
    rows = [("buildable (working profile, undercut, profile, bore, dynamics)", "yes" if a.buildable else "NO"),
            ("usable (verified and buildable)", "yes" if a.usable else "NO")]
    return rows + [("fails", f) for f in a.failures]


def _check_rows(cam) -> list[tuple[str, str]]:
    """One row per check, named in words (:data:`cams.words.CHECK_WORDS`), values as ``cams check`` prints them."""
    from cams.words import check_unit, check_words, deg, length_format
    from cams.words import check_value as _fmt

    if cam.face.no_profile(cam.design) is not None:
        return [("profile", "none: a knife edge cannot run in a groove (form closure needs a roller)")]

    f = length_format(cam.checks.profile.R0)
    checks = []
    for c in cam.checks.checks:
        cd = c.to_dict()
        at = "" if cd.get("at_deg") is None else f" at {deg(cd['at_deg'])}"
        unit = check_unit(cd["name"], cd.get("unit", ""))  # a count with what it counts
        lim_s = "" if cd.get("limit") is None else f" (limit {_fmt(cd['limit'], unit, f)})"
        worst = _fmt(cd.get('worst'), unit, f)
        checks.append((check_words(cd["name"]), f"{'pass' if cd['passed'] else 'FAIL'}: {worst}{at}{lim_s}"))
    given = any(c.name == "bore" for c in cam.checks.checks)
    checks.append(("bore", bore_text(cam.checks.bore_radius, not given)))
    return checks


def roller_sections(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The report's tables for a roller follower."""
    d = cam.design
    f = d.follower
    inputs = [("name", d.name), ("follower", f.kind), ("roller radius", f"{f.roller_radius:g} mm")]
    if f.kind == "rocker":
        inputs += [("arm l", f"{f.arm:g} mm"), ("swing ψmax", _deg(d.program.lift)),
                   ("rocker on the rise", "ccw" if f.sense > 0 else "cw")]
    else:
        inputs += [("stroke h", f"{d.program.lift:g} mm"),
                   ("offset", "free (solved)" if f.offset is None else f"{f.offset:g} mm")]
    inputs += _cam_inputs(d)
    lim = d.limits
    inputs += [("closure", lim.closure), ("allowable pressure angle, rise", _deg(lim.pressure_angle))]
    if lim.closure == "form":
        inputs.append(("allowable pressure angle, return", _deg(lim.return_limit)))
    inputs.append(("safety factor K_C", f"{lim.safety_factor:g}"))
    if lim.centre_distance is not None:
        inputs.append(("fixed centre distance L", f"{lim.centre_distance:g} mm"))
    if lim.min_base_radius is not None:
        inputs.append(("constructive floor on R0", f"{lim.min_base_radius:g} mm"))
    if d.base_radius is not None:
        inputs.append(("chosen base radius R0", f"{d.base_radius:g} mm"))
    if d.centre is not None:
        inputs.append(("chosen cam centre (x, y)", f"({d.centre[0]:g}, {d.centre[1]:g}) mm"))
    r = cam.solution.to_dict()
    method = "none: the chosen cam is checked, not sized" if r["mode"] == "chosen" else f"{r['method']} ({r['mode']})"
    fl = length_format(max(abs(r["R0"]), abs(r["L"] or 0.0), abs(r["offset"] or 0.0)))
    results = [("method", method),
               ("base radius R0 (pitch curve, to the roller centre)", f"{r['R0']:{fl}} mm"),
               ("the cam's own smallest radius (working profile)", f"{r['smallest_cam_radius']:{fl}} mm"),
               *_part_rows(r, fl)]
    if r["L"] is not None:
        results.append(("centre distance L", f"{r['L']:{fl}} mm"))
    if r["offset"] is not None:
        results.append(("offset e", f"{r['offset']:{fl}} mm"))
    results += [
        ("cam centre (x, y)", f"({r['centre']['x']:{fl}}, {r['centre']['y']:{fl}}) mm"),
        ("max pressure angle, rise", deg(r["max_pressure_angle"]["rise"])),
        ("max pressure angle, return", deg(r["max_pressure_angle"]["return"])),
        ("binding lines", ", ".join(binding_text(b) for b in r["binding"]) or "—"),
        ("error bound", "not stated by this method" if r["error_bound"] is None else f"{r['error_bound']:.3g} mm"),
        ("verified (independent pressure-angle check)", "yes" if r["verified"] else "NO"),
    ]
    results += _assessment_rows(cam)
    results += [("note", n) for n in r["notes"] if not any(n in f for f in cam.assessment.failures)]  # said once
    sections = [("Inputs", inputs), ("Results", results), ("Checks", _check_rows(cam))]
    sections += _motion_section(cam)
    df = cam.forces if d.dynamics is not None else None
    if df is not None:
        sections.append(("Forces at the cam", _force_rows(df, f.kind)))
    return sections


def _force_rows(df, df_kind: str = "translating") -> list[tuple[str, str]]:
    """The rows of the forces page (a :class:`cams.dynamics.forces.DesignForces`).

    At a rigid impact (a velocity jump, e.g. a linear law) a force is not a
    number: it is said to be unbounded there, as ``cams solve`` does, with
    the finite values between the impacts on their own row.
    """
    from cams.dynamics.forces import impact_note
    from cams.dynamics.jump import jump_text

    fo = df.to_dict()
    up = [i for i in fo["impacts"] if i["effect"] == "impulse"]
    down = [i for i in fo["impacts"] if i["effect"] == "separation"]

    def at_impact(imps, what=""):
        return f"unbounded{what} (rigid impact at {deg(imps[0]['cam_angle_deg'])})"

    largest = at_impact(up) if up else f"{force(fo['max_contact_force'])} at {deg(fo['max_contact_at_deg'])}"
    smallest = at_impact(down, " negative: contact lost") if down else force(fo['min_contact_force'])
    torque = at_impact(up) if up else f"{torque_text(fo['max_torque'])} at {deg(fo['max_torque_at_deg'])}"
    if fo["jump_at_impact"]:
        jump = f"any speed: the follower leaves the cam at its velocity drop (rigid impact at {deg(fo['jump_at_deg'])})"
    else:
        jump = jump_text(fo["jump_rpm"]) if fo["jump_at_deg"] is None or fo["jump_rpm"] is None or not np.isfinite(
            fo["jump_rpm"]) else f"{jump_text(fo['jump_rpm'])} (first at {deg(fo['jump_at_deg'])})"
    rows = [
        ("closing spring", spring_text(fo["spring"]["rate"], fo["spring"]["preload"], df_kind)),
        ("cam speed", f"{fo['rpm']:.6g} rpm"),
        ("largest contact force", largest),
        ("smallest contact force", smallest),
        ("largest camshaft torque", torque),
        ("jump speed", jump),
    ]
    bi = fo.get("between_impacts")
    if bi:
        rows.append(("between the rigid impacts",
                     f"contact force max {force(bi['max_contact_force'])} at {deg(bi['max_contact_at_deg'])}, min "
                     f"{force(bi['min_contact_force'])}; camshaft torque max {torque_text(bi['max_torque'])} at "
                     f"{deg(bi['max_torque_at_deg'])}; jump speed {jump_text(bi['jump_rpm'])}"))
    lost, jammed = ('yes' if fo[k] else 'no' for k in ('contact_lost', 'jammed'))
    rows.append(("contact lost / jammed", f"{lost} / {jammed}"))
    note = impact_note(df.forces)
    if note:
        rows.append(("note", note))
    return rows


def _motion_section(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The motion design's table (a design with ``[optimize]``), else nothing."""
    from cams.present.text import optimization_rows

    o = cam.solution.optimization
    return [] if o is None else [("Motion design", optimization_rows(o.to_dict(), cam.solution.R0))]
