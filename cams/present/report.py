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

__all__ = ["report_sections", "report_pages", "write_report"]


def report_sections(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The report's tables as ``[(title, [(label, value), ...]), ...]`` (strings): the face's
    (:meth:`cams.present.faces.Presenter.report_sections`)."""
    from cams.present.faces import presenter

    return presenter(cam).report_sections(cam)


def _figures(cam):
    """The pictures, each titled as failing when the cam is not usable (:mod:`cams.assess`)."""
    from cams.present import plots
    from cams.present.faces import presenter

    figs = [(title, plots.picture(kind, cam)) for title, kind in presenter(cam).report_pictures
            if not (kind == "profile" and cam.face.no_profile(cam.design) is not None)]  # no profile to draw
    if cam.solution.optimization is not None:
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
