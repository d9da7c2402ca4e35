"""One report per design: inputs, results, checks and pictures, as HTML and PDF.

A flat-faced follower's report has the same sections; its pictures are the
motion diagrams, the pressure angle, the radius of curvature with the contact's
travel on the face, and the profile (no allowable-centre zone).

The HTML file is self-contained (pictures embedded as PNG data); the PDF is
written with matplotlib's PdfPages, one page per topic. Both are written to a
temporary file first and renamed, so a failed run leaves no partial report.
"""

from __future__ import annotations

import base64
import html
import io
from pathlib import Path

import numpy as np

__all__ = ["report_sections", "write_report"]


def _deg(x):
    return "—" if x is None else f"{np.degrees(x):.4f}°"


def _flat_sections(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The report's tables for a flat-faced follower."""
    from cams.commands.solve import pressure_text

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
        inputs.append((f"phase {i + 1}", f"{p.kind}{law}, {np.degrees(p.angle):.4g}°"))
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
        ("smallest radius of curvature", f"{r['min_rho']:.6f} mm at {r['min_rho_at_deg']:.3f}°"),
        ("contact travel on the face", f"{fr['from']:.6f} to {fr['to']:.6f} mm {where}"),
        ("face width needed (no margins)", f"{r['face_width']:.6f} mm"),
    ]
    if r["face_width_centred"] is not None:
        results.append(("face centred on the axis", f"{r['face_width_centred']:.6f} mm"))
    results += [("pressure angle", pressure_text(r)),
                ("verified (radius of curvature >= limit)", "yes" if r["verified"] else "NO")]
    results += _assessment_rows(cam)
    results += [("note", n) for n in r["notes"]]
    return [("Inputs", inputs), ("Results", results), ("Checks", _check_rows(cam))]


def _assessment_rows(cam) -> list[tuple[str, str]]:
    """Buildable beside verified, and what fails (:mod:`cams.assess`)."""
    a = cam.assessment
    rows = [("buildable (working profile, undercut, profile, bore, dynamics)", "yes" if a.buildable else "NO"),
            ("usable (verified and buildable)", "yes" if a.usable else "NO")]
    return rows + [("fails", f) for f in a.failures]


def _check_rows(cam) -> list[tuple[str, str]]:
    from cams.assess import knife_in_groove

    if knife_in_groove(cam.design):
        return [("profile", "none: a knife edge cannot run in a groove (form closure needs a roller)")]
    checks = []
    for c in cam.checks.checks:
        cd = c.to_dict()
        worst = cd.get("worst")
        at = cd.get("at_deg")
        val = "—" if worst is None else f"{worst:.6g} {cd.get('unit', '')}".strip()
        where = "" if at is None else f" at {at:.3f}°"
        lim_s = "" if cd.get("limit") is None else f" (limit {cd['limit']:.6g})"
        checks.append((cd["name"], f"{'pass' if cd['passed'] else 'FAIL'}: {val}{where}{lim_s}"))
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
        inputs.append((f"phase {i + 1}", f"{p.kind}{law}, {np.degrees(p.angle):.4g}°"))
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
    results = [("method", method), ("base radius R0", f"{r['R0']:.6f} mm")]
    if r["L"] is not None:
        results.append(("centre distance L", f"{r['L']:.6f} mm"))
    if r["offset"] is not None:
        results.append(("offset e", f"{r['offset']:.6f} mm"))
    results += [
        ("cam centre (x, y)", f"({r['centre']['x']:.6f}, {r['centre']['y']:.6f}) mm"),
        ("max pressure angle, rise", "—" if r["max_pressure_angle"]["rise"] is None else f"{r['max_pressure_angle']['rise']:.4f}°"),
        ("max pressure angle, return", "—" if r["max_pressure_angle"]["return"] is None else f"{r['max_pressure_angle']['return']:.4f}°"),
        ("binding positions", ", ".join(f"{b['line']} at {b['phi']:.3f}°" for b in r["binding"]) or "—"),
        ("error bound", "not stated by this method" if r["error_bound"] is None else f"{r['error_bound']:.3g} mm"),
        ("verified (independent pressure-angle check)", "yes" if r["verified"] else "NO"),
    ]
    results += _assessment_rows(cam)
    results += [("note", n) for n in r["notes"]]
    sections = [("Inputs", inputs), ("Results", results), ("Checks", _check_rows(cam))]
    df = cam.forces if "dynamics" in d.extra else None
    if df is not None:
        sections.append(("Forces at the cam", _force_rows(df)))
    return sections


def _force_rows(df) -> list[tuple[str, str]]:
    """The rows of the forces page (a :class:`cams.camforces.DesignForces`).

    At a rigid impact (a velocity jump, e.g. a linear law) a force is not a
    number: it is said to be unbounded there, as ``cams solve`` does, with
    the finite values between the impacts on their own row.
    """
    from cams.camforces import impact_note, jump_text

    fo = df.to_dict()
    up = [i for i in fo["impacts"] if i["effect"] == "impulse"]
    down = [i for i in fo["impacts"] if i["effect"] == "separation"]

    def at_impact(imps, what=""):
        return f"unbounded{what} (rigid impact at {imps[0]['cam_angle_deg']:.2f}°)"

    largest = at_impact(up) if up else f"{fo['max_contact_force']:.6g} N at {fo['max_contact_at_deg']:.2f}°"
    smallest = at_impact(down, " negative: contact lost") if down else f"{fo['min_contact_force']:.6g} N"
    torque = at_impact(up) if up else f"{fo['max_torque']:.6g} N m at {fo['max_torque_at_deg']:.2f}°"
    if fo["jump_at_impact"]:
        jump = f"any speed: the follower leaves the cam at its velocity drop (rigid impact at {fo['jump_at_deg']:.2f}°)"
    else:
        jump = jump_text(fo["jump_rpm"]) if fo["jump_at_deg"] is None or fo["jump_rpm"] is None or not np.isfinite(
            fo["jump_rpm"]) else f"{jump_text(fo['jump_rpm'])} (first at {fo['jump_at_deg']:.2f}°)"
    rows = [
        ("closing spring", f"rate {fo['spring']['rate']:.6g}, preload {fo['spring']['preload']:.6g} (SI)"),
        ("cam speed", f"{fo['rpm']:.6g} rpm"),
        ("largest contact force", largest),
        ("smallest contact force", smallest),
        ("largest camshaft torque", torque),
        ("jump speed", jump),
    ]
    bi = fo.get("between_impacts")
    if bi:
        rows.append(("between the rigid impacts",
                     f"contact force max {bi['max_contact_force']:.6g} N at {bi['max_contact_at_deg']:.2f}°, min "
                     f"{bi['min_contact_force']:.6g} N; camshaft torque max {bi['max_torque']:.6g} N m at "
                     f"{bi['max_torque_at_deg']:.2f}°; jump speed {bi['jump_rpm']:.6g} rpm"))
    rows.append(("contact lost / jammed", f"{'yes' if fo['contact_lost'] else 'no'} / {'yes' if fo['jammed'] else 'no'}"))
    note = impact_note(df.forces)
    if note:
        rows.append(("note", note))
    return rows


def _figures(cam):
    """The pictures, each titled as failing when the cam is not usable (:mod:`cams.assess`)."""
    from cams import plots
    from cams.assess import knife_in_groove

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
    title = cam.assessment.title()
    return [(name, plots.mark_failing(fig, title)) for name, fig in figs]


def write_report(cam, out: str | Path) -> tuple[Path, Path]:
    """Write ``report.html`` and ``report.pdf`` for ``cam`` into folder ``out``.

    Returns the two paths. Pictures are drawn once and used by both files.
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    from cams.files import atomic_write, ensure_folder

    out = ensure_folder(out, "--out")
    sections = report_sections(cam)
    figs = _figures(cam)

    def write_pdf(tmp):
        with PdfPages(tmp) as pdf:
            for title, rows in sections:
                page = Figure(figsize=(8.27, 11.69))
                page.text(0.08, 0.95, f"{cam.design.name}: {title}", fontsize=15, weight="bold")
                y = 0.91
                for label, value in rows:
                    page.text(0.08, y, label, fontsize=9, color="0.25")
                    page.text(0.45, y, value, fontsize=9, wrap=True)
                    y -= 0.024
                pdf.savefig(page)
            for _, fig in figs:
                pdf.savefig(fig)

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
