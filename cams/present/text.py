"""The results in words for the terminal: a solve, a flat face's solve, the assessment, the checks.

Each function takes the JSON-ready report a result's ``to_dict`` gives (lengths
in the design's unit, angles in degrees) and prints it; numbers are formatted
with their units by :mod:`cams.words`.
"""

from __future__ import annotations

from cams.words import (
    binding_text,
    bore_text,
    check_unit,
    check_words,
    deg,
    duration,
    fault_words,
    length_format,
    off_by,
    phase_words,
)
from cams.words import check_value as _fmt

__all__ = ["print_summary", "print_flat_summary", "print_cam_forces", "print_contact", "print_assessment",
           "print_checks",
           "pressure_text", "optimization_rows", "print_optimization", "governs_line", "part_lines", "peaks_lines",
           "GOVERNS_WORDS", "verified_words", "NOT_VERIFIED", "no_working_profile"]

#: How the assessment's failure of the independent check starts (:func:`cams.assess.assess`).
NOT_VERIFIED = "not verified: "


def verified_words(rep: dict) -> str:
    """``verified: yes``, or what a cam that is not verified is: which limit it exceeds and by how much.

    ``rep`` holds ``verified`` and the assessment's ``failures`` (:meth:`cams.assess.Assessment.to_dict`); the
    failure of the independent check is said here, and :func:`print_assessment` leaves it out of its FAIL lines.

    >>> verified_words({"verified": False, "failures": ["not verified: rise pressure angle 46 deg exceeds the "
    ...                 "limit 45 deg by 1 deg"]})
    'verified: NO, the cam exceeds its limit: rise pressure angle 46 deg exceeds the limit 45 deg by 1 deg'
    """
    if rep["verified"]:
        return "verified: yes"
    why = [f.removeprefix(NOT_VERIFIED) for f in rep.get("failures", ()) if f.startswith(NOT_VERIFIED)]
    return "verified: NO, the cam exceeds its limit: " + ("; ".join(why) or "the independent check finds it so")


#: What ``governs`` names, in words.
GOVERNS_WORDS = {"pressure_angle": "the pressure angle", "convexity": "convexity (limits.min_radius)",
                 "min_base_radius": "the floor limits.min_base_radius", "bore": "the bore and its hub wall",
                 "undercut": "the roller (undercut)",
                 "curvature": "the least radius of curvature (profile.min_curvature_radius)",
                 "contact_stress": "the contact stress (contact.allowable_stress)", "chosen": "the chosen cam"}


def governs_line(rep: dict, f: str) -> str | None:
    """``governs: ...`` of a solve report: what set R0, and the pressure angle's own minimum beside it."""
    g = rep.get("governs")
    if g is None:
        return None
    text = f"  governs: {GOVERNS_WORDS.get(g, g)}"
    pa = rep.get("pressure_angle_R0")
    if pa is not None and g != "pressure_angle":
        text += f" (the pressure angle alone: R0 = {pa:{f}} mm)"
    return text


def part_lines(rep: dict, f: str) -> list[str]:
    """The blank and the bore of a solve report: the cam's largest radius, the bore and the hub wall achieved."""
    out = []
    large = rep.get("largest_cam_radius")
    if large is not None:
        out.append(f"  Rmax    = {large:{f}} mm  (the cam's largest radius: a blank of diameter "
                   f"{2 * large:{f}} mm at least)")
    if rep.get("bore_radius") is not None:
        need = rep.get("hub_wall_required") or 0.0
        out.append(f"  bore    = {rep['bore_radius']:{f}} mm, hub wall {rep['hub_wall']:{f}} mm (at least "
                   f"{need:{f}} mm)")
    return out


def peaks_lines(rep: dict, rpm: float | None) -> list[str]:
    """The follower's peaks at speed, one line each (only with a speed: ``rpm``), from a report's ``peaks``."""
    pk = rep.get("peaks")
    if not pk or rpm is None:
        return []
    out = []
    for i, k in enumerate(("velocity", "acceleration", "jerk")):
        p = pk[k]
        v = "unbounded (a jump)" if p["value"] is None else f"{p['value']:.6g} {p['unit']}"
        head = f"  peaks at {rpm:g} rpm: " if i == 0 else " " * len(f"  peaks at {rpm:g} rpm: ")
        out.append(f"{head}{k:<12} {v} at {deg(p['at_deg'])}")
    return out


def print_summary(rep: dict) -> None:
    """Short readable summary of a solve report (as from ``SolveResult.to_dict``)."""
    unit = "mm"
    f = length_format(max(abs(rep["R0"]), abs(rep["L"] or 0.0), abs(rep["offset"] or 0.0)))
    if rep["mode"] == "chosen":
        print(f"{rep['name']}: {rep['follower']} follower, the chosen cam (checked, not sized)")
    else:
        print(f"{rep['name']}: {rep['follower']} follower, method {rep['method']}, {rep['mode']}")
    print(f"  R0      = {rep['R0']:{f}} {unit}  (pitch curve's base radius: cam centre to roller centre)")
    gl = governs_line(rep, f)
    if gl:
        print(gl)
    cr = rep.get("smallest_cam_radius")
    if cr is not None and cr > 0:
        print(f"  Rmin    = {cr:{f}} {unit}  (the cam's own smallest radius, on the working profile)")
    elif cr is not None:  # the roller reaches the cam centre: there is no cam body to measure
        print(f"  Rmin    = none: the roller reaches past the cam centre (smallest pitch radius - roller radius "
              f"= {cr:{f}} {unit})")
    for line in part_lines(rep, f) if cr is not None and cr > 0 else ():
        print(line)
    if rep["L"] is not None:
        print(f"  L       = {rep['L']:{f}} {unit}")
    if rep["offset"] is not None:
        print(f"  offset  = {rep['offset']:{f}} {unit}")
    c = rep["centre"]
    print(f"  centre  = ({c['x']:{f}}, {c['y']:{f}}) {unit}")
    mp, lim = rep["max_pressure_angle"], rep["limits"]
    print(f"  max pressure angle: rise {deg(mp['rise'])} (limit {deg(lim['rise'])}), "
          f"return {deg(mp['return'])} (limit {deg(lim['return'])})")
    if rep["binding"]:
        print("  binding: " + ", ".join(binding_text(b) for b in rep["binding"]))
    eb = rep["error_bound"]
    bound = "" if rep["mode"] == "chosen" else \
        f"error bound: {'not stated by this method' if eb is None else f'{eb:.3g} {unit}'}; "
    print(f"  {bound}{verified_words(rep)}; {duration(rep['seconds'])}")
    for line in peaks_lines(rep, rep.get("rpm")):
        print(line)
    print_designed_and_at_speed(rep)
    failures = rep.get("failures", ())
    for n in rep["notes"]:
        said = any(n in f for f in failures) or (  # said once, on its FAIL line
            n.startswith("not buildable: R0") and any(f.startswith("no working profile") for f in failures))
        if not said:
            print(f"  note: {n}")


_OBJECTIVE_UNITS = {"R0": "mm", "L": "mm", "pressure_angle": "(ratio to the limit)", "Ca": "(normalized)",
                    "Cj": "(normalized)", "jerk_squared": "(normalized)", "snap_squared": "(normalized)"}


def _peak(v: float | None) -> str:
    return "inf" if v is None else f"{v:.4f}"


def objective_unit(o: dict) -> str:
    """The unit of the motion design's objective ``o["objective"]`` (``o``: the JSON's ``optimize``)."""
    return _OBJECTIVE_UNITS.get(o["objective"], "")


def bound_words(o: dict) -> str:
    """The proven lower bound and the relative gap, its unit beside, as ``cams solve`` prints them (``o``: the
    JSON's ``optimize``, with a ``lower_bound``)."""
    gap = "-" if o["gap"] is None else f"{o['gap']:.3g}"
    return f"{o['lower_bound']:.6g} {objective_unit(o)}, gap {gap} (relative)"


def optimization_rows(o: dict, R0: float | None = None) -> list[tuple[str, str]]:
    """The ``optimize`` part of a report (:mod:`cams.motion_design`) as ``(label, value)`` rows, units beside."""
    unit = objective_unit(o)
    rows = [("minimized", f"{o['objective']}: {o['value']:.6g} {unit}")]
    if o["lower_bound"] is None:
        rows += [("optimality", f"a local optimum (sequential convex programming, {o['iterations']} iterations); "
                                f"the linearized problem still predicts a decrease of {o['local_measure']:.2g} "
                                "(relative) within a radius of 1e-3"),
                 ("checked", "yes" if o["checked"] else "NO")]
    else:
        none = not o["bound_proven"]       # nothing above the trivial bound was proven
        said = ": none above 0 proven, how near the value is to the least is not known" if none else ""
        rows += [("proven lower bound", bound_words(o) + said),
                 ("certified", "yes" if o["certified"] else "the laws checked, no bound proven" if o["checked"]
                  else "NO")]
    rows.append(("space", f"degree {o['degree']}, {o['spans']} spans per free phase, C{o['continuity']} joints "
                          f"(the caps on Bernstein coefficients of {o['pieces']} pieces a span)"))
    sm = o.get("smoothing")
    if sm:
        rows.append((f"smoothing (slack {sm['slack']:g})", _smoothing_text(sm, o)))
    ref = o.get("reference")
    if ref and o["objective"] == "L" and ref.get("L") is not None:
        f = length_format(max(abs(ref["L"]), abs(o["value"])))
        rows.append(("the original laws' cam", f"L = {ref['L']:{f}} mm; this one: L = {o['value']:{f}} mm"))
    elif ref and R0 is not None:
        f = length_format(max(abs(ref["R0"]), abs(R0)))
        rows.append(("the original laws' cam", f"R0 = {ref['R0']:{f}} mm; this one: R0 = {R0:{f}} mm"))
    for p in o["phases"]:
        orig = p["original"]
        rows.append((phase_words(p["kind"], p["phase"]),
                     f"Cv {_peak(p['Cv'])}, Ca {_peak(p['Ca'])}, Cj {_peak(p['Cj'])}; was {orig['law']}: "
                     f"Cv {_peak(orig['Cv'])}, Ca {_peak(orig['Ca'])}, Cj {_peak(orig['Cj'])}"))
    return rows


def _smoothing_text(sm: dict, o: dict) -> str:
    """What the second stage's slack bought (:mod:`cams.motion_design`'s ``smoothing``), in words."""
    unit = objective_unit(o)
    if unit == "mm":
        f = length_format(max(abs(sm["value_before"]), abs(sm["value_after"])))
        value = f"{sm['value_before']:{f}} -> {sm['value_after']:{f}} mm"
    else:
        value = f"{sm['value_before']:.8g} -> {sm['value_after']:.8g} {unit}"
    d = "S" + "'" * sm["derivative"]
    tv = "-" if sm["jerk_variation_before"] is None else f"{sm['jerk_variation_before']:.1f}"
    tv2 = "-" if sm["jerk_variation_after"] is None else f"{sm['jerk_variation_after']:.1f}"
    orig = [p["original"].get("jerk_variation") for p in o["phases"]]
    was = "" if any(t is None for t in orig) else f" (the original laws': {sum(orig):.1f})"
    step = sm.get("step", 1.0)
    kept = ("" if step == 1.0 else "the second stage's laws not kept (see the note); " if step == 0.0
            else f"the laws {step:.4g} of the way to the second stage's (see the note); ")
    return (f"{kept}{o['objective']} {value}; integral of {d}^2 {sm['integral_before']:.4g} -> "
            f"{sm['integral_after']:.4g}, of S'''^2 {sm['jerk_squared_before']:.6g} -> {sm['jerk_squared_after']:.6g}; "
            f"total variation of S''' {tv} -> {tv2}{was}")


def print_optimization(o: dict, R0: float | None = None) -> None:
    """The ``optimize`` part of a report, in words (:func:`optimization_rows`)."""
    print("  motion design:")
    for label, value in optimization_rows(o, R0):
        print(f"    {label}: {value}")


def print_designed_and_at_speed(rep: dict) -> None:
    """The part of a solve's summary both faces share: the motion design's certificate (``[optimize]``), the
    forces (``[dynamics]``), the contact (``[contact]``) and the follower train's vibration, each when present."""
    if rep.get("optimize"):
        print_optimization(rep["optimize"], rep.get("R0"))
    fo = rep.get("forces")
    if fo:
        print_cam_forces(fo, follower=rep["follower"])
    if rep.get("contact"):
        print_contact(rep["contact"])
    print_vibration(rep)


def print_vibration(rep: dict, indent: str = "  ") -> None:
    """The ``vibration`` part of a report (the elastic follower train), when there is one."""
    vi = rep.get("vibration")
    if not vi:
        return
    from cams.dynamics.vibration import vibration_lines

    fo = rep.get("forces") or {}
    for line in vibration_lines(vi, rigid_jump_rpm=fo.get("jump_rpm"), indent=indent):
        print(line)


def print_cam_forces(fo: dict, indent: str = "  ", *, follower: str = "translating") -> None:
    """The [dynamics] part of a report (from ``DesignForces.to_dict``): spring, contact force, torque, jump speed.

    With rigid impacts the unbounded values are said so, the finite ones
    between the impacts follow, and the jump speed is "any speed". The
    spring's units follow the ``follower`` kind: N/m and N, or N m/rad and
    N m for a rocker's torsional spring, its installed compression in mm or
    its installed twist in deg (:func:`cams.words.spring_words`); the torques in words
    (:func:`cams.words.torque_words`).
    """
    from cams.dynamics.jump import jump_text
    from cams.words import force, spring_words, torque_words

    def torques(f: dict) -> str:
        return "; ".join(torque_words(f[f"max_{k}_torque"], f[f"max_{k}_torque_at_deg"], k)
                         for k in ("driving", "braking"))

    sp = fo["spring"]
    print(f"{indent}spring: {spring_words(sp, follower)}")
    if sp.get("note"):
        print(f"{indent}  note: {sp['note']}")
    print(f"{indent}contact force: max {force(fo['max_contact_force'])} at {deg(fo['max_contact_at_deg'])}, "
          f"min {force(fo['min_contact_force'])}")
    print(f"{indent}camshaft: {torques(fo)}")
    bi = fo.get("between_impacts")
    if bi:
        print(f"{indent}  between the rigid impacts: contact force max {force(bi['max_contact_force'])} at "
              f"{deg(bi['max_contact_at_deg'])}, min {force(bi['min_contact_force'])}; camshaft {torques(bi)}; "
              f"jump speed {jump_text(bi['jump_rpm'])}")
    if fo.get("jump_at_impact"):
        jump = f"follower leaves the cam at any speed (velocity drop at {deg(fo['jump_at_deg'])})"
    else:
        jump = f"follower jumps above {jump_text(fo['jump_rpm'])}"
    if fo["jammed"] is None:  # a flat face: no pressure-angle jamming; its friction slides at the face
        print(f"{indent}{jump}; contact lost: {'YES' if fo['contact_lost'] else 'no'}; jammed: cannot (a flat face)")
        loss = fo.get("mean_sliding_loss")
        print(f"{indent}sliding at the face: up to {fo['max_sliding_speed']:.6g} m/s"
              + ("" if loss is None else f", mean friction loss {loss:.6g} W"))
        return
    print(f"{indent}{jump}; contact lost: {'YES' if fo['contact_lost'] else 'no'}; "
          f"jammed: {'YES' if fo['jammed'] else 'no'} (jamming limit {deg(fo['jamming_limit_deg'])})")


def pressure_text(rep: dict) -> str:
    """The pressure angle of a flat face in words (from ``FlatFaceSolution.to_dict``)."""
    pa = rep["pressure_angle"]
    if pa["max"] == 0:
        why = "the face is perpendicular to the axis" if rep["follower"] == "translating" else \
            "the face passes through the pivot"
        return f"0 deg everywhere (fixed by the geometry: {why})"
    return (f"{pa['min']:.4f} to {pa['max']:.4f} deg, largest at {pa['max_at_deg']:.4f} deg "
            f"(fixed by the geometry: atan(|face_offset| / contact distance from the pivot's foot))")


def print_flat_summary(rep: dict) -> None:
    """Short readable summary of a flat-face solve report (as from ``FlatFaceSolution.to_dict``)."""
    unit = "mm"
    f = length_format(max(abs(rep["R0"]), abs(rep["L"] or 0.0), abs(rep["face_width"] or 0.0)))
    print(f"{rep['name']}: {rep['follower']} follower, flat face, sized by convexity")
    src = {"convexity": "the smallest with radius of curvature >= limits.min_radius",
           "limits.min_base_radius": "raised to limits.min_base_radius",
           "cam.base_radius": "given by cam.base_radius",
           "part": "the smallest that meets the part's constraints"}[rep["R0_source"]]
    print(f"  R0      = {rep['R0']:{f}} {unit}  ({src})")
    gl = governs_line(rep, f)
    if gl and rep.get("governs") not in ("convexity", "min_base_radius", "chosen"):     # else said by the R0 line
        print(gl)
    if rep.get("smallest_cam_radius") is not None:
        print(f"  Rmin    = {rep['smallest_cam_radius']:{f}} {unit}  (the cam's own smallest radius)")
    for line in part_lines(rep, f):
        print(line)
    if rep["R0_source"] != "convexity" and rep["R0_min"] is not None:
        print(f"  R0 min  = {rep['R0_min']:{f}} {unit}  (convexity, binding at {rep['binding_deg']:.4f} deg)")
    elif rep["binding_deg"] is not None and rep["R0_source"] == "convexity":
        print(f"  binding: smallest radius of curvature at {rep['binding_deg']:.4f} deg")
    print(f"  radius of curvature >= {rep['min_rho']:{f}} {unit} at {rep['min_rho_at_deg']:.4f} deg "
          f"(limit {rep['min_radius']:g} {unit})")
    if rep["L"] is not None:
        print(f"  L       = {rep['L']:{f}} {unit}, face offset {rep['face_offset']:g} {unit}")
    else:
        print(f"  offset  = {rep['offset']:{f}} {unit}")
    c = rep["centre"]
    print(f"  centre  = ({c['x']:{f}}, {c['y']:{f}}) {unit}")
    fr = rep["face_range"]
    where = "of the follower axis" if rep["follower"] == "translating" else "along the face from the pivot's foot"
    print(f"  face: contact from {fr['from']:{f}} to {fr['to']:{f}} {unit} {where} "
          f"(at {fr['from_at_deg']:.2f} and {fr['to_at_deg']:.2f} deg): width {rep['face_width']:{f}} {unit}")
    if rep["face_width_centred"] is not None:
        print(f"        a face centred on the axis needs {rep['face_width_centred']:{f}} {unit} (no margins)")
    print(f"  pressure angle: {pressure_text(rep)}")
    print(f"  {verified_words(rep)}; {duration(rep['seconds'])}")
    for line in peaks_lines(rep, rep.get("rpm")):
        print(line)
    print_designed_and_at_speed(rep)
    for n in rep["notes"]:
        print(f"  note: {n}")


_LIMIT_WORDS = {"contact_stress": "the contact stress", "film_parameter": "the lubricant film",
                "bearing_life": "the bearing's life"}


def print_contact(co: dict, indent: str = "  ") -> None:
    """The contact's lines of a solve report's ``contact`` (:meth:`cams.strength.along.ContactCycle.to_dict`):
    the largest Hertz pressure with its angle and radii, the subsurface stresses, the film, the life, the least
    face width and the contact limit that binds."""
    def num(v, unit: str, fmt: str = ".4g") -> str:
        return "unbounded" if v is None else f"{v:{fmt}} {unit}"

    am = co["at_max"]
    rf = "a plane (flat face)" if am["follower_radius"] is None else num(am["follower_radius"], "mm")
    rc = "straight" if am["cam_curvature_radius"] is None else num(am["cam_curvature_radius"], "mm")
    print(f"{indent}contact ({co['force_model']} force): largest Hertz pressure p0 {num(co['max_pressure'], 'MPa')} "
          f"at {co['max_pressure_at_deg']:.2f} deg (force {num(am['force'], 'N')}, cam's radius of curvature {rc}, "
          f"follower's {rf}, half-width {num(am['half_width'], 'mm')})")
    print(f"{indent}  below the surface: largest shear {num(co['max_shear'], 'MPa')} at depth "
          f"{num(co['max_shear_depth'], 'mm')}, largest von Mises stress {num(co['max_von_mises'], 'MPa')}")
    if co["min_film"] is not None:
        lam = "" if co["min_film_parameter"] is None else f", film parameter {co['min_film_parameter']:.3g}"
        print(f"{indent}  lubricant film: thinnest {co['min_film']:.4g} µm{lam} (Dowson-Higginson)")
    z = co["zero_entrainment_at_deg"]
    if z:
        print(f"{indent}  entrainment velocity zero at " + ", ".join(f"{a:.2f} deg" for a in z))
    if co["bearing_life_hours"] is not None:
        print(f"{indent}  roller bearing: L10 life {co['bearing_life_hours']:.4g} h at the cam's speed (ISO 281)")
    if co["min_width"] is not None:
        print(f"{indent}  least face width for the allowable stress: {co['min_width']:.4g} mm")
    if co["limit"] is not None:
        print(f"{indent}  contact limit that binds: {_LIMIT_WORDS.get(co['limit'], co['limit'])}")


def print_assessment(a: dict, indent: str = "  ", file=None) -> None:
    """The buildable line beside verified (from ``Assessment.to_dict``), with what fails.

    The verified line (:func:`verified_words`), printed before it by every command, says why a cam is not
    verified; the FAIL lines say the rest.

    ``usable`` is :attr:`cams.assess.Assessment.usable`, the exit code's rule: certified (a ``certified`` key is
    present only when false), verified and buildable.
    """
    usable = a.get("certified", True) is not False and a["verified"] and a["buildable"]
    print(f"{indent}buildable: {'yes' if a['buildable'] else 'NO'}; usable: {'yes' if usable else 'NO'}", file=file)
    for f in a["failures"]:
        if not f.startswith(NOT_VERIFIED):  # said on the verified line (verified_words)
            print(f"{indent}FAIL: {f}", file=file)


def no_working_profile(rep: dict) -> str | None:
    """Why a roller cam has no working profile to measure or bore, in words (None: it has one).

    From a check or profile report (``smallest_cam_radius``, the checks): the roller reaches past the cam centre
    (the smallest pitch radius less the roller radius is not positive), or the profile undercuts or crosses
    itself. Its "smallest radius" then measures no cam, and no bore is suggested for it.
    """
    cam_r = rep.get("smallest_cam_radius")
    if cam_r is not None and not cam_r > 0:
        f = length_format(max(abs(cam_r), 1e-9))
        return (f"no working profile: the roller reaches past the cam centre (smallest pitch radius - roller "
                f"radius = {cam_r:{f}} mm)")
    cuts = ("undercut", "undercut_outer", "profile_polygon", "outer_polygon")
    failed = {c["name"] for c in rep.get("checks", ()) if not c["passed"]}
    said = rep.get("failures", ())  # the assessment's lines (cams profile's report has no checks)
    if failed & set(cuts) or any(f.startswith(fault_words(n) + ":") for f in said for n in cuts):
        return "no working profile: the roller undercuts it (the profile crosses itself)"
    return None


def _by(c: dict) -> str:
    """How far a failed check's worst value is on the wrong side of its limit (:func:`cams.words.off_by`)."""
    return "" if c["passed"] else off_by(c["worst"], c["limit"], c["unit"])


def print_checks(rep: dict) -> None:
    """Readable table of a check report (as from ``CheckReport.to_dict``), the checks named in words."""
    f = length_format(rep["R0"])
    cam_r = rep.get("smallest_cam_radius")
    head = f"R0 = {rep['R0']:{f}} mm (pitch curve)" if cam_r is not None else f"R0 = {rep['R0']:{f}} mm"
    broken = no_working_profile(rep)
    if cam_r is not None:
        head += ", " + (broken or f"cam's smallest radius {cam_r:{f}} mm")
    print(f"{rep['name']}: {rep['points']} points at tolerance {rep['tolerance']:g} mm, {head}")
    for c in rep["checks"]:
        at = "" if c["at_deg"] is None else f" at {deg(c['at_deg'])}"
        c = {**c, "unit": check_unit(c["name"], c["unit"])}  # a count with what it counts
        lim = "" if c["limit"] is None else f" (limit {_fmt(c['limit'], c['unit'], f)})"
        worst = _fmt(c['worst'], c['unit'], f)
        print(f"  {'pass' if c['passed'] else 'FAIL'}  {check_words(c['name'])}: {worst}{at}{lim}{_by(c)}")
    lr = rep.get("largest_roller_radius")
    if lr is not None:
        print(f"  roller radius {rep['roller_radius']:{f}} mm; largest without undercut {lr:{f}} mm, "
              f"recommended <= {rep['recommended_roller_radius']:{f}} mm")
    given = any(c["name"] == "bore" for c in rep["checks"])
    bore = bore_text(rep["bore_radius"], not given) if given or broken is None else \
        "no bore suggested: the cam has no working profile to hold one"
    print(f"  {bore}; {'all checks pass' if rep['passed'] else 'a check FAILS'}")
