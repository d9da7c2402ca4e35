"""One report per design: inputs, results, checks and pictures, as HTML and PDF.

A flat-faced follower's report has the same sections; its pictures are the
motion diagrams, the pressure angle, the radius of curvature with the contact's
travel on the face, and the profile (no allowable-centre zone).

The HTML file is self-contained (pictures embedded as PNG data); the PDF is
written with matplotlib's PdfPages: the tables flow over A4 pages (a new page
only when one is full), then one page per picture. Both are written to a
temporary file first and renamed, so a failed run leaves no partial report.
"""

from __future__ import annotations

import base64
import html
import io
from pathlib import Path

import numpy as np

from cams.words import binding_text, bore_text, deg, force, length_format, spring_text
from cams.words import torque as torque_text

__all__ = ["report_sections", "report_pages", "write_report"]


def _deg(x):
    """An angle given in radians, as every command prints angles (:func:`cams.words.deg`)."""
    return "—" if x is None else deg(x, radians=True)


def _flat_sections(cam) -> list[tuple[str, list[tuple[str, str]]]]:
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
    inputs += [("cam rotation", "ccw" if d.cam_sense > 0 else "cw")]
    if d.rpm:
        inputs.append(("cam speed", f"{d.rpm:g} rpm"))
    for i, p in enumerate(d.program.phases):
        law = "" if p.law is None else f", {p.law.name}"
        inputs.append((f"phase {i + 1}", f"{p.kind}{law}, {np.degrees(p.angle):.6g} deg"))
    inputs.append(("smallest radius of curvature allowed", f"{d.min_radius:g} mm"))
    if d.min_base_radius is not None:
        inputs.append(("constructive floor on R0", f"{d.min_base_radius:g} mm"))
    if d.base_radius is not None:
        inputs.append(("chosen base radius", f"{d.base_radius:g} mm"))
    r = cam.solution.to_dict()
    results = [("sizing", f"convexity (R0 from {r['R0_source']})"), ("base radius R0", f"{r['R0']:.6f} mm")]
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


def _assessment_rows(cam) -> list[tuple[str, str]]:
    """Buildable beside verified, and what fails (:mod:`cams.assess`)."""
    a = cam.assessment
    rows = [("buildable (working profile, undercut, profile, bore, dynamics)", "yes" if a.buildable else "NO"),
            ("usable (verified and buildable)", "yes" if a.usable else "NO")]
    return rows + [("fails", f) for f in a.failures]


def _check_rows(cam) -> list[tuple[str, str]]:
    """One row per check, named in words (:data:`cams.words.CHECK_WORDS`), values as ``cams check`` prints them."""
    from cams.assess import knife_in_groove
    from cams.words import check_value as _fmt
    from cams.words import check_words, deg, length_format

    if knife_in_groove(cam.design):
        return [("profile", "none: a knife edge cannot run in a groove (form closure needs a roller)")]

    f = length_format(cam.checks.profile.R0)
    checks = []
    for c in cam.checks.checks:
        cd = c.to_dict()
        at = "" if cd.get("at_deg") is None else f" at {deg(cd['at_deg'])}"
        lim_s = "" if cd.get("limit") is None else f" (limit {_fmt(cd['limit'], cd.get('unit', ''), f)})"
        worst = _fmt(cd.get('worst'), cd.get('unit', ''), f)
        checks.append((check_words(cd["name"]), f"{'pass' if cd['passed'] else 'FAIL'}: {worst}{at}{lim_s}"))
    given = any(c.name == "bore" for c in cam.checks.checks)
    checks.append(("bore", bore_text(cam.checks.bore_radius, not given)))
    return checks


def report_sections(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The report's tables as ``[(title, [(label, value), ...]), ...]`` (strings)."""
    if getattr(cam, "flat", False):
        return _flat_sections(cam)
    d = cam.design
    f = d.follower
    inputs = [("name", d.name), ("follower", f.kind), ("roller radius", f"{f.roller_radius:g} mm")]
    if f.kind == "rocker":
        inputs += [("arm l", f"{f.arm:g} mm"), ("swing ψmax", _deg(d.program.lift)),
                   ("rocker on the rise", "ccw" if f.sense > 0 else "cw")]
    else:
        inputs += [("stroke h", f"{d.program.lift:g} mm"),
                   ("offset", "free (solved)" if f.offset is None else f"{f.offset:g} mm")]
    inputs += [("cam rotation", "ccw" if d.cam_sense > 0 else "cw")]
    if d.rpm:
        inputs.append(("cam speed", f"{d.rpm:g} rpm"))
    for i, p in enumerate(d.program.phases):
        law = "" if p.law is None else f", {p.law.name}"
        inputs.append((f"phase {i + 1}", f"{p.kind}{law}, {np.degrees(p.angle):.6g} deg"))
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
               ("the cam's own smallest radius (working profile)", f"{r['smallest_cam_radius']:{fl}} mm")]
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

    o = getattr(cam.solution, "optimization", None)
    return [] if o is None else [("Motion design", optimization_rows(o, cam.solution.R0))]


def _figures(cam):
    """The pictures, each titled as failing when the cam is not usable (:mod:`cams.assess`)."""
    from cams.assess import knife_in_groove
    from cams.present import plots

    if getattr(cam, "flat", False):
        figs = [("Motion diagrams", plots.plot_motion(cam.design)),
                ("Pressure angle", plots.plot_flat_pressure(cam.solution)),
                ("Radius of curvature and contact on the face", plots.plot_curvature(cam.solution)),
                ("Cam profile", plots.plot_profile(cam))]
    else:
        figs = [("Allowable-centre zone", plots.plot_zone(cam.solution, tradeoff=cam.tradeoff)),
                ("Motion diagrams", plots.plot_motion(cam.design)),
                ("Pressure angle", plots.plot_pressure(cam.solution))]
        if not knife_in_groove(cam.design):  # a knife edge in a groove has no profile to draw
            figs.append(("Cam profile", plots.plot_profile(cam)))
    if getattr(cam.solution, "optimization", None) is not None:
        from cams.present.motion_plots import plot_motion_design

        figs.append(("Motion design: the designed laws and cam beside the original", plot_motion_design(cam)))
    title = cam.assessment.title()
    return [(name, plots.mark_failing(fig, title)) for name, fig in figs]


#: A4 portrait, inches.
A4_IN = (8.27, 11.69)
#: Page layout of the text pages, as fractions of the page: margins, columns, one line of 9 pt text.
_TOP, _BOTTOM, _LEFT, _VALUE_X, _LINE = 0.95, 0.05, 0.08, 0.45, 0.0145
#: Characters per line of the label and value columns at 9 pt (their widths over an average glyph).
_LABEL_CHARS, _VALUE_CHARS = 40, 58


def _text_pages(title: str, sections) -> list:
    """The report's tables on A4 pages, the sections one after the other (a new page only when one is full).

    Labels and values are wrapped to their column's width and each row
    takes as many lines as its longer cell, so a wrapped value never runs
    into the next row.
    """
    import textwrap

    from matplotlib.figure import Figure

    pages: list = []
    y = 0.0

    def new_page(heading: str | None = None):
        nonlocal y
        page = Figure(figsize=A4_IN)
        pages.append(page)
        head = "\n".join(textwrap.wrap(title, 60))
        page.text(_LEFT, _TOP, head, fontsize=15, weight="bold", va="top")
        y = _TOP - 0.03 * (head.count("\n") + 1) - 0.01
        if heading:
            page.text(_LEFT, y, heading, fontsize=12, weight="bold", va="top")
            y -= 0.028

    def lines(text: str, width: int) -> list[str]:
        return textwrap.wrap(text, width) or [""]

    new_page()
    for heading, rows in sections:
        first = max(len(lines(rows[0][0], _LABEL_CHARS)), len(lines(rows[0][1], _VALUE_CHARS))) if rows else 1
        if y - 0.028 - first * _LINE < _BOTTOM:
            new_page()
        pages[-1].text(_LEFT, y, heading, fontsize=12, weight="bold", va="top")
        y -= 0.028
        for label, value in rows:
            lab, val = lines(label, _LABEL_CHARS), lines(value, _VALUE_CHARS)
            n = max(len(lab), len(val))
            if y - n * _LINE < _BOTTOM:
                new_page(f"{heading} (continued)")
            page = pages[-1]
            page.text(_LEFT, y, "\n".join(lab), fontsize=9, color="0.25", va="top", linespacing=1.2)
            page.text(_VALUE_X, y, "\n".join(val), fontsize=9, va="top", linespacing=1.2)
            y -= n * _LINE + 0.005
        y -= 0.02
    return pages


def report_pages(cam, sections=None, figs=None) -> list:
    """The PDF's pages as matplotlib Figures: the tables flowed onto A4 pages, then one page per picture.

    Parameters
    ----------
    cam : cams.cam.Cam
    sections, figs : optional
        :func:`report_sections` and the pictures, when already made.
    """
    sections = report_sections(cam) if sections is None else sections
    figs = _figures(cam) if figs is None else figs
    return _text_pages(cam.design.name, sections) + [fig for _, fig in figs]


def write_report(cam, out: str | Path) -> tuple[Path, Path]:
    """Write ``report.html`` and ``report.pdf`` for ``cam`` into folder ``out``.

    Returns the two paths. Pictures are drawn once and used by both files.
    """
    from matplotlib.backends.backend_pdf import PdfPages

    from cams.io.files import atomic_write, ensure_folder

    out = ensure_folder(out, "--out")
    sections = report_sections(cam)
    figs = _figures(cam)

    def write_pdf(tmp):
        with PdfPages(tmp) as pdf:
            for page in report_pages(cam, sections, figs):
                pdf.savefig(page)

    def write_html(tmp):
        parts = [
            "<!DOCTYPE html><html><head><meta charset='utf-8'>",
            f"<title>{html.escape(cam.design.name)}</title>",
            "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}"
            "table{border-collapse:collapse}td{border-bottom:1px solid #ddd;padding:.25em .8em}"
            "section{page-break-after:always}img{max-width:100%}</style></head><body>",
            f"<h1>{html.escape(cam.design.name)}</h1>",
        ]
        for title, rows in sections:
            parts.append(f"<section><h2>{html.escape(title)}</h2><table>")
            parts += [f"<tr><td>{html.escape(a)}</td><td>{html.escape(b)}</td></tr>" for a, b in rows]
            parts.append("</table></section>")
        for title, fig in figs:
            buf = io.BytesIO()
            fig.savefig(buf, format="png", dpi=120)
            data = base64.b64encode(buf.getvalue()).decode("ascii")
            parts.append(f"<section><h2>{html.escape(title)}</h2>"
                         f"<img alt='{html.escape(title)}' src='data:image/png;base64,{data}'></section>")
        parts.append("</body></html>")
        Path(tmp).write_text("\n".join(parts), encoding="utf-8")

    pdf = atomic_write(out / "report.pdf", "--out", write_pdf)
    page = atomic_write(out / "report.html", "--out", write_html)
    return page, pdf
