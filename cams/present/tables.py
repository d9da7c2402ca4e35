"""The report's tables for each face: inputs, results, checks, forces and the motion design, as rows of text.

Each face's presenter (:mod:`cams.present.faces`) names its tables' function (:func:`roller_sections`,
:func:`flat_sections`); :func:`cams.present.report.report_sections` calls it. Lengths in mm, angles in degrees.
"""

from __future__ import annotations

import numpy as np

from cams.words import binding_text, bore_text, deg, force, length_format, spring_text, spring_words, torque_words

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
    inputs += _dynamics_inputs(d, sliding_face=True)
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
    return [("Inputs", inputs), ("Results", results), _blank_section(r, ".6f"), *_lift_table_section(cam),
            ("Checks", _check_rows(cam)), *_motion_section(cam), *_forces_section(cam),
            *_contact_section(cam), *_vibration_section(cam)]


def _part_rows(r: dict, fl: str) -> list[tuple[str, str]]:
    """What governs the size, the pressure angle's own R0 and the peaks at speed (the part's keys of a solve
    report, :meth:`cams.faces.result.SolveResult.to_dict`; the blank and the bore are :func:`_blank_section`'s)."""
    from cams.present.text import GOVERNS_WORDS

    rows = [("governs", GOVERNS_WORDS.get(r["governs"], str(r["governs"])))]
    if r["pressure_angle_R0"] is not None and r["governs"] != "pressure_angle":
        rows.append(("R0 by the pressure angle alone", f"{r['pressure_angle_R0']:{fl}} mm"))
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
    inputs += _dynamics_inputs(d)
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
    return [("Inputs", inputs), ("Results", results), _blank_section(r, fl), *_lift_table_section(cam),
            ("Checks", _check_rows(cam)), *_motion_section(cam), *_forces_section(cam),
            *_contact_section(cam), *_vibration_section(cam)]


def _dynamics_inputs(d, *, sliding_face: bool = False) -> list[tuple[str, str]]:
    """The ``[dynamics]`` table's rows (SI units; a rocker's moments and inertia about its pivot), none without it;
    ``sliding_face`` adds the friction at a flat face."""
    from cams.words import spring_units

    spec = d.dynamics
    if spec is None:
        return []
    dyn = spec.dynamics
    kind = d.follower.kind
    rocker = kind == "rocker"
    _, pu = spring_units(kind)
    rows = [("[dynamics] " + ("moment of inertia about the pivot" if rocker else "reduced mass"),
             f"{dyn.mass:g} {'kg m²' if rocker else 'kg'}"),
            ("[dynamics] load opposing the rise", f"{dyn.load:g} {pu}")]
    if dyn.spring is not None:
        spring = spring_text(dyn.spring.rate, dyn.spring.preload, kind)
    elif spec.rate is not None:
        spring = f"rate {spec.rate:g} {spring_units(kind)[0]}, preload chosen for the contact margin"
    else:
        spring = "rate and preload chosen for the contact margin"
    rows += [("[dynamics] closing spring", spring), ("[dynamics] contact margin", f"{spec.margin:g}"),
             ("[dynamics] friction μ " + ("in the pivot" if rocker else "in the guide"), f"{dyn.friction:g}")]
    if sliding_face:
        rows.append(("[dynamics] friction μ at the face (sliding)", f"{dyn.face_friction:g}"))
    if rocker:
        rows.append(("[dynamics] pivot journal radius", f"{dyn.journal_radius:g} mm"))
    lo, hi = spec.installed_bounds
    if lo is not None or hi is not None:
        scale, unit, what = (180 / np.pi, "deg", "twist") if rocker else (1.0, "mm", "compression")
        shown = (f"{v * scale:g} {unit}" if v is not None else "default" for v in (lo, hi))
        rows.append((f"[dynamics] installed {what} (least, most)", ", ".join(shown)))
    if dyn.max_spring_force is not None:
        rows.append(("[dynamics] largest spring force allowed", f"{dyn.max_spring_force:g} {pu}"))
    return rows


def _blank_section(r: dict, fl: str) -> tuple[str, list[tuple[str, str]]]:
    """The blank the cam is cut from: its largest and smallest radius, the bore and the hub wall (the keys of a
    solve report, :meth:`cams.faces.result.SolveResult.to_dict`; lengths mm, angles from the timing datum)."""
    big, small = r["largest_cam_radius"], r["smallest_cam_radius"]
    rows = [("the cam's largest radius (blank diameter)",
             f"{big:{fl}} mm ({2 * big:{fl}} mm) at {deg(r['largest_cam_radius_at_deg'])}"),
            ("the cam's smallest radius", f"{small:{fl}} mm at {deg(r['smallest_cam_radius_at_deg'])}")]
    if r["bore_radius"] is not None:
        rows.append(("bore radius, hub wall (at least)", f"{r['bore_radius']:{fl}} mm, {r['hub_wall']:{fl}} mm "
                     f"({r['hub_wall_required']:{fl}} mm)"))
    else:
        rows.append(("bore", "none given ([cam] bore_radius)"))
    return ("Blank", rows)


#: Step of the lift table summarized in the report, degrees (``cams profile --table`` writes it at any step).
TABLE_STEP_DEG = 1.0


def _lift_table_section(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The lift table's summary (:mod:`cams.manufacture.table`, the face's columns at :data:`TABLE_STEP_DEG`): its
    rows, its columns and each quantity's range; none where no profile can be built."""
    if cam.face.no_profile(cam.design) is not None:
        return []
    phi_deg = np.arange(0.0, 360.0, TABLE_STEP_DEG)
    cols = cam.face.table(cam.design, cam.solution, np.radians(phi_deg))
    rows = [("rows", f"{phi_deg.size}, one every {TABLE_STEP_DEG:g} deg of cam angle from the timing datum "
                     "(cams profile FILE --table OUT.csv [--step DEG] writes it)"),
            ("columns", ", ".join(k for k, _ in cols))]
    units = {"_mm": "mm", "_deg": "deg"}
    for name, v in cols[1:]:
        if name.endswith(("_theta_deg", "_x_mm", "_y_mm")):
            continue  # the points' directions and coordinates: their radius is the row that says the size
        v = np.asarray(v, dtype=float)
        ok = np.isfinite(v)
        unit = next(u for suffix, u in units.items() if name.endswith(suffix))
        if name.startswith("rho_"):  # signed (negative: concave): the size that matters is the smallest |rho|
            k = int(np.argmin(np.where(ok, np.abs(v), np.inf)))
            rows.append((f"{name} smallest |ρ|", f"{abs(v[k]):.6g} {unit} at {deg(phi_deg[k])} "
                         f"({'concave' if v[k] < 0 else 'convex'} there)"))
            continue
        text = "no finite value" if not ok.any() else f"{v[ok].min():.6g} to {v[ok].max():.6g} {unit}"
        rows.append((f"{name} range", text))
    return [("Lift table", rows)]


def _forces_section(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The forces' table (a design with ``[dynamics]`` and forces), else nothing."""
    df = cam.forces if cam.design.dynamics is not None else None
    return [] if df is None else [("Forces at the cam", _force_rows(df, cam.design.follower.kind))]


def _vibration_section(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The follower train's table (``[dynamics] train_stiffness``), else nothing."""
    spec = cam.design.dynamics
    v = cam.vibration if spec is not None and spec.dynamics.train_stiffness is not None else None
    if v is None:
        return []
    from cams.dynamics.vibration import vibration_failure
    from cams.words import phase_words

    vi = v.to_dict()
    dyn = spec.dynamics
    rocker = cam.design.follower.kind == "rocker"
    rows = [("train stiffness", f"{dyn.train_stiffness:.6g} {'N m/rad' if rocker else 'N/m'}"),
            ("damping ratio", f"{dyn.damping_ratio:g} (against the train's and the spring's stiffness)"),
            ("natural frequency", f"{vi['natural_frequency_hz']:.6g} Hz at {v.rpm:.6g} rpm")]
    for p in vi["phases"]:
        steady = "none (undamped at resonance)" if p["residual"] is None else f"{p['residual']:.4g}"
        rows.append((phase_words(p["kind"], p["phase"]),
                     f"period ratio λ {p['period_ratio']:.4g}; residual vibration over the height "
                     f"{p['residual_from_rest']:.4g} from rest, {steady} in the steady state"))
    rows.append(("dynamic contact force", f"max {force(vi['dynamic_max_contact_force'])}, "
                 f"min {force(vi['dynamic_min_contact_force'])}"))
    rigid = cam.forces.jump.rpm if cam.forces is not None else None
    from cams.dynamics.jump import jump_text

    rows.append(("jump speed, elastic / rigid",
                 ("none found" if vi["dynamic_jump_rpm"] is None else f"{vi['dynamic_jump_rpm']:.6g} rpm")
                 + " / " + ("- (form closure)" if rigid is None else jump_text(rigid))))
    why = vibration_failure(v)
    rows.append(("contact lost", "no" if why is None else why.removeprefix("dynamics: ")))
    return [("Follower train: vibration", rows)]


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
    torque = "; ".join(torque_words(fo[f"max_{k}_torque"], fo[f"max_{k}_torque_at_deg"], k)
                       for k in ("driving", "braking"))
    if fo["jump_at_impact"]:
        jump = f"any speed: the follower leaves the cam at its velocity drop (rigid impact at {deg(fo['jump_at_deg'])})"
    else:
        jump = jump_text(fo["jump_rpm"]) if fo["jump_at_deg"] is None or fo["jump_rpm"] is None or not np.isfinite(
            fo["jump_rpm"]) else f"{jump_text(fo['jump_rpm'])} (first at {deg(fo['jump_at_deg'])})"
    rows = [
        ("closing spring", spring_words(fo["spring"], df_kind)),
        *([("spring note", fo["spring"]["note"])] if fo["spring"].get("note") else []),
        ("cam speed", f"{fo['rpm']:.6g} rpm"),
        ("largest contact force", largest),
        ("smallest contact force", smallest),
        ("camshaft torque", torque),
        ("jump speed", jump),
    ]
    bi = fo.get("between_impacts")
    if bi:
        rows.append(("between the rigid impacts",
                     f"contact force max {force(bi['max_contact_force'])} at {deg(bi['max_contact_at_deg'])}, min "
                     f"{force(bi['min_contact_force'])}; camshaft "
                     + "; ".join(torque_words(bi[f"max_{k}_torque"], bi[f"max_{k}_torque_at_deg"], k)
                                 for k in ("driving", "braking"))
                     + f"; jump speed {jump_text(bi['jump_rpm'])}"))
    if fo["jammed"] is None:  # a flat face: no pressure-angle jamming; sliding friction at the face
        rows.append(("contact lost", "yes" if fo["contact_lost"] else "no"))
        loss = fo["mean_sliding_loss"]
        rows.append(("sliding at the face", f"up to {fo['max_sliding_speed']:.6g} m/s"
                     + ("" if loss is None else f", mean friction loss {loss:.6g} W")))
    else:
        lost, jammed = ('yes' if fo[k] else 'no' for k in ('contact_lost', 'jammed'))
        rows.append(("contact lost / jammed", f"{lost} / {jammed}"))
    note = impact_note(df.forces)
    if note:
        rows.append(("note", note))
    return rows


def _contact_section(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The contact's table (a design with ``[contact]`` and its contact computed), else nothing: the largest Hertz
    pressure with its angle and radii, the subsurface stresses, the film, the life, the least width, the limit
    that binds, and the notes (edge loading first)."""
    co = cam.contact if cam.design.contact is not None else None
    if co is None:
        return []
    d = co.to_dict()
    am = d["at_max"]
    a = co.materials.allowable
    rc = "straight" if am["cam_curvature_radius"] is None else f"{am['cam_curvature_radius']:.6g} mm"
    rf = "a plane" if am["follower_radius"] is None else f"{am['follower_radius']:.6g} mm"
    p0 = "unbounded" if d["max_pressure"] is None else f"{d['max_pressure']:.6g} MPa"
    rows = [
        ("contact force", f"{d['force_model']} ([dynamics] at the cam speed)"),
        ("face width", f"{co.width:.6g} mm" + ("" if d["min_width"] is None else
                                                 f" (least for the allowable: {d['min_width']:.6g} mm)")),
        ("contact modulus E*", f"{co.materials.E_star:.6g} MPa (1/E* = sum (1 - nu^2)/E; the film's E' = 2 E*)"),
        ("largest Hertz pressure p0", f"{p0} at {deg(d['max_pressure_at_deg'])}"
         + ("" if a is None else f" (allowable {a:.6g} MPa)")),
        ("there", f"force {force(am['force'])}, cam's radius of curvature {rc}, follower's {rf}, half-width "
                  f"{am['half_width']:.4g} mm" if am["half_width"] is not None else "no line contact"),
        ("below the surface", f"largest shear {d['max_shear']:.6g} MPa at depth {d['max_shear_depth']:.4g} mm; "
                              f"largest von Mises stress {d['max_von_mises']:.6g} MPa"
         if d["max_shear"] is not None else "unbounded"),
    ]
    if d["min_film"] is not None:
        lam = "" if d["min_film_parameter"] is None else f", film parameter {d['min_film_parameter']:.3g} (least " \
            f"allowed {co.spec.min_film_parameter:g})"
        rows.append(("lubricant film", f"thinnest {d['min_film']:.4g} µm{lam} (Dowson-Higginson)"))
    if d["bearing_life_hours"] is not None:
        rows.append(("roller bearing life", f"L10 {d['bearing_life_hours']:.6g} h (ISO 281, mean load weighted by "
                                            "the roller's revolutions)"))
    if d["limit"] is not None:
        rows.append(("limit that binds", d["limit"].replace("_", " ")))
    rows.extend(("note", n) for n in co.notes())
    return [("Contact stress, film and life", rows)]


def _motion_section(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The motion design's table (a design with ``[optimize]``), else nothing."""
    from cams.present.text import optimization_rows

    o = cam.solution.optimization
    return [] if o is None else [("Motion design", optimization_rows(o.to_dict(), cam.solution.R0))]
