"""One report per design, to hand over: a title block, a PASS/FAIL banner, the tables and the pictures, as HTML
and PDF.

The PDF is typeset by Typst through its Python binding (the ``typst`` package: one self-contained wheel, the
compiler and its fonts inside, no system library). It was chosen over ReportLab (``reportlab``, a pure-Python
wheel) for three reasons:

* the pictures stay vector: Typst embeds matplotlib's SVG as it is, where ReportLab takes bitmaps (or needs
  ``svglib`` and ``lxml`` besides to convert an SVG into its own drawing);
* the layout is declared, not computed: tables that break across pages with their heading repeated, cells that
  wrap, a banner, a running header and footer and the page count are Typst's, where ReportLab's platypus needs
  each of them placed by code (frames, page templates, a second pass for the page count);
* the data go in as data: the tables, names and file paths are handed to one fixed template as JSON
  (``sys.inputs``) and shown as plain strings, so no text of the design (a ``#``, ``$`` or ``*`` in its name) is
  ever read as markup and nothing needs escaping.

Every page is A4 with the same margins. The first page begins with the banner (PASS, or FAIL with one line per
failing condition from :mod:`cams.assess`, the rule every command exits by), then the title block (design name,
file, date, version of ``cams``); then each of the face's tables (its presenter's :meth:`report_sections
<cams.present.faces.Presenter.report_sections>`: the inputs with the ``[dynamics]`` table, the results, the
blank, the lift table's summary, the checks, the forces) flows over the pages; then the face's pictures
(:attr:`report_pictures <cams.present.faces.Presenter.report_pictures>`, the forces when there are any), each
as SVG scaled to the text width (or, for a tall one, to :data:`PICTURE_MAX_H_MM`), shrunk to the room left on a
page when it keeps :data:`PICTURE_SHRINK` of that size there, and never split across pages. A failing cam's pages
carry FAIL in their header too.

The HTML file is self-contained (pictures embedded as PNG data). Both are written to a temporary file first and
renamed, so a failed run leaves no partial report. ``typst`` is imported only when the PDF is written.
"""

from __future__ import annotations

import base64
import datetime
import html
import io
import json
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import Any

__all__ = ["report_sections", "report_data", "render_pdf", "write_report", "PAGE_MM", "MARGIN_MM",
           "PICTURE_MAX_H_MM", "PICTURE_SHRINK"]

#: The page (A4 portrait) and its margins, mm.
PAGE_MM = (210.0, 297.0)
MARGIN_MM = 18.0
#: The height a picture may take (mm): the page's body (22 mm from the top, 20 mm from the bottom) less its title.
PICTURE_MAX_H_MM = 238.0
#: The least a picture is shrunk to (of its width) to fill the room left on a page rather than start the next one.
PICTURE_SHRINK = 0.6


def report_sections(cam) -> list[tuple[str, list[tuple[str, str]]]]:
    """The report's tables as ``[(title, [(label, value), ...]), ...]`` (strings): the face's
    (:meth:`cams.present.faces.Presenter.report_sections`)."""
    from cams.present.faces import presenter

    return presenter(cam).report_sections(cam)


def _drawings(cam):
    """The pictures as ``(title, kind, draw)``: ``kind`` the picture's (:data:`cams.present.plots.PICTURES`, or
    ``"optimized"``), ``draw()`` the matplotlib Figure, titled as failing when the cam is not usable
    (:mod:`cams.assess`): the face's, less the profile where none can be built and the forces where there are
    none."""
    from cams.present import plots
    from cams.present.faces import presenter

    def drawn(kind: str) -> bool:  # the pictures that need their data: the one table of plots.NEEDS
        if kind == "profile":
            return cam.face.no_profile(cam.design) is None
        return plots.missing(kind, cam) is None

    title = cam.assessment.title()

    def draw(kind: str):
        return plots.mark_failing(plots.picture(kind, cam), title)

    def draw_design():
        from cams.present.motion_plots import plot_motion_design

        return plots.mark_failing(plot_motion_design(cam), title)

    out: list[tuple[str, str, Callable[[], Any]]] = [(name, kind, partial(draw, kind)) for name, kind in
                                                    presenter(cam).report_pictures if drawn(kind)]
    if cam.solution.optimization is not None:
        out.append(("Motion design: the designed laws and cam beside the original", "optimized", draw_design))
    return out


def _figures(cam):
    """The pictures of :func:`_drawings`, drawn: ``(title, Figure)``."""
    return [(name, draw()) for name, _, draw in _drawings(cam)]


def _version() -> str:
    """The installed ``cams``'s version (its distribution's metadata, as ``pip show cams`` says it)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version("cams")
    except PackageNotFoundError:  # run from a source tree that was never installed
        return "unknown (not installed)"


def report_data(cam, *, source: str | Path | None = None, sections=None, today: datetime.date | None = None) -> dict:
    """What the PDF shows, as JSON-ready data (strings and numbers): the title block, the banner, the tables.

    Parameters
    ----------
    cam : cams.cam.Cam
    source : path, optional
        The design file, as given (shown in the title block; "—" without one).
    sections : optional
        :func:`report_sections`, when already made.
    today : datetime.date, optional
        The report's date (default today, UTC).
    """
    a = cam.assessment
    sections = report_sections(cam) if sections is None else sections
    today = datetime.datetime.now(datetime.UTC).date() if today is None else today
    return {
        "name": cam.design.name,
        "file": "—" if source is None else str(source),
        "date": today.isoformat(),
        "version": _version(),
        "pass": bool(a.usable),
        "failures": list(a.failures),
        "sections": [{"title": t, "rows": [[lab, val] for lab, val in rows]} for t, rows in sections],
    }


#: The Typst template: everything it shows comes from ``sys.inputs.data`` (JSON), shown as strings, never as markup.
TEMPLATE = r"""
#let d = json(bytes(sys.inputs.data))
#let failing = not d.pass
#let red = rgb("#b00020")
#let green = rgb("#1b6e2e")
#set document(title: d.name)
#set text(font: "DejaVu Sans", size: 8.5pt, lang: "en")
#set par(justify: false)
#set page(
  width: PAGE_W, height: PAGE_H, margin: (x: MARGIN, top: MARGIN + 4mm, bottom: MARGIN + 2mm),
  header: context [
    #set text(size: 7.5pt, fill: luma(90))
    #d.name #h(1fr) #if failing [#text(fill: red, weight: "bold")[FAIL]] else [PASS]
    #v(-2mm) #line(length: 100%, stroke: 0.4pt + luma(160))
  ],
  footer: context [
    #set text(size: 7.5pt, fill: luma(90))
    cams #d.version #h(1fr) page #counter(page).display() of #counter(page).final().first()
  ],
)
#show heading.where(level: 1): it => block(above: 5mm, below: 2.5mm, sticky: true,
  text(size: 12pt, weight: "bold", it.body))

// the banner: what the cam is, before anything else
#block(width: 100%, inset: 4mm, radius: 1.5mm, fill: if failing { rgb("#fde8ea") } else { rgb("#e6f4ea") },
  stroke: 1.2pt + if failing { red } else { green })[
  #if failing [
    #text(size: 15pt, weight: "bold", fill: red)[FAIL]
    #let n = d.failures.len()
    #h(3mm) #text(size: 10pt, weight: "bold")[this cam fails #n #if n == 1 [condition] else [conditions]:]
    #v(1mm)
    #for f in d.failures [- #f
    ]
  ] else [
    #text(size: 15pt, weight: "bold", fill: green)[PASS]
    #h(3mm) #text(size: 10pt)[verified and buildable: every check passes]
  ]
]

// the title block
#v(2mm)
#text(size: 17pt, weight: "bold", d.name)
#v(1mm)
#table(columns: (28mm, 1fr), stroke: none, inset: (x: 0mm, y: 1.2mm),
  text(fill: luma(90))[design file], d.file,
  text(fill: luma(90))[date], d.date,
  text(fill: luma(90))[cams version], d.version,
)

#for s in d.sections [
  #heading(level: 1, s.title)
  #table(
    columns: (42%, 1fr), stroke: (x, y) => (bottom: 0.3pt + luma(200)), inset: (x: 1.5mm, y: 1.3mm),
    fill: (x, y) => if y == 0 { luma(235) },
    table.header(text(weight: "bold")[quantity], text(weight: "bold")[value]),
    ..s.rows.map(r => (text(fill: luma(60), r.at(0)), r.at(1))).flatten(),
  )
]

// each picture as wide as the text (or as tall as the body allows); shrunk to the room left on the page when it
// keeps SHRINK of its size there, else on the next page
#for p in PICTURES [
  #context {
    let room = PAGE_H - MARGIN - 2mm - here().position().y - 16mm
    let w = p.width * 1mm
    let fit = room / p.aspect
    let w = if w * p.aspect <= room { w } else if fit >= SHRINK * w { fit } else { w }
    block(breakable: false, above: 6mm)[
      #heading(level: 1, p.title)
      #align(center, image(p.file, width: w))
    ]
  }
]
"""


def _svg(fig) -> tuple[bytes, float, float]:
    """``fig`` as SVG, its text drawn as paths (the picture looks the same wherever it is shown), and its width and
    height (pt).

    Saved to the bounding box of everything drawn, padded by 0.04 in (as ``bbox_inches="tight"``): a legend that
    reaches past the figure's edge is in the picture, not drawn over the page's margin (an SVG image is not
    clipped to its box).
    """
    import re

    from cams.present.plots import DPI, lay_out

    buf = io.BytesIO()
    lay_out(fig, DPI)  # the layout of the figure's PNG (cams plot), computed once and kept
    # the box measured on that layout: savefig's "tight" would draw the whole figure once more to measure it
    fig.savefig(buf, format="svg", bbox_inches=fig.get_tightbbox().padded(0.04))
    svg = buf.getvalue()
    head = svg[:svg.index(b"<svg") + 400].decode("utf-8", "replace")
    w, h = (float(re.search(rf'{k}="([0-9.]+)pt"', head).group(1)) for k in ("width", "height"))  # type: ignore[union-attr]
    return svg, w, h


def _drawn_svg(draw) -> tuple[bytes, float, float]:
    """:func:`_svg` of the Figure ``draw()`` makes."""
    return _svg(draw())


def render_pdf(data: dict, pictures: list[tuple[str, object]]) -> bytes:
    """Typeset the report: ``data`` (:func:`report_data`) and ``pictures`` (``(title, Figure)``) as PDF bytes.

    Each picture is embedded as SVG (vector), as wide as the text (174 mm on A4 with 18 mm margins), or less when
    that would make it taller than the page holds.
    """
    return _typeset(data, [(title, *_svg(fig)) for title, fig in pictures])


def _typeset(data: dict, svgs: list[tuple[str, bytes, float, float]]) -> bytes:
    """:func:`render_pdf` of pictures already drawn as SVG: ``(title, svg, width pt, height pt)``."""
    import tempfile

    import matplotlib
    import typst

    text_w = PAGE_MM[0] - 2 * MARGIN_MM
    with tempfile.TemporaryDirectory(prefix="cams-report-") as tmp:
        root = Path(tmp)
        pics = []
        for k, (title, svg, w_pt, h_pt) in enumerate(svgs):
            name = f"picture{k}.svg"
            (root / name).write_bytes(svg)
            width = min(text_w, PICTURE_MAX_H_MM * w_pt / h_pt)
            pics.append({"title": title, "file": name, "width": round(width, 3), "aspect": h_pt / w_pt})
        source = TEMPLATE
        for key, value in (("PAGE_W", f"{PAGE_MM[0]}mm"), ("PAGE_H", f"{PAGE_MM[1]}mm"), ("MARGIN", f"{MARGIN_MM}mm"),
                           ("SHRINK", f"{PICTURE_SHRINK:g}"), ("PICTURES", "json(bytes(sys.inputs.pictures))")):
            source = source.replace(key, value)
        (root / "report.typ").write_text(source, encoding="utf-8")
        fonts = Path(matplotlib.get_data_path()) / "fonts" / "ttf"  # DejaVu Sans, the pictures' own face
        pdf = typst.compile(str(root / "report.typ"), root=str(root), font_paths=[str(fonts)],
                            ignore_system_fonts=True,
                            sys_inputs={"data": json.dumps(data), "pictures": json.dumps(pics)})
    return bytes(pdf)


def write_report(cam, out: str | Path, *, source: str | Path | None = None, jobs: int | None = None,
                 note: Callable[[str], None] | None = None) -> tuple[Path, Path]:
    """Write ``report.html`` and ``report.pdf`` for ``cam`` into folder ``out``.

    ``source`` is the design file shown in the PDF's title block. Returns the two paths. Pictures are drawn once,
    as SVG (vector, their text as paths), and used by both files; up to ``jobs`` processes draw them side by side
    (None: one per core; :func:`cams.present.forked.forked_map`, which tells ``note`` in one line when a process
    ended abruptly and its pictures were drawn here instead).
    """
    from cams.io.files import atomic_write, ensure_folder
    from cams.present.forked import forked_map
    from cams.present.plots import EFFORT, prepare

    out = ensure_folder(out, "--out")
    sections = report_sections(cam)
    drawings = _drawings(cam)
    data = report_data(cam, source=source, sections=sections)
    prepare()
    drawn = forked_map([partial(_drawn_svg, draw) for _, _, draw in drawings], jobs=jobs,
                       effort=[EFFORT.get(kind, 10) for _, kind, _ in drawings], note=note)
    svgs = [(title, *svg) for (title, _, _), svg in zip(drawings, drawn, strict=True)]

    def write_pdf(tmp):
        Path(tmp).write_bytes(_typeset(data, svgs))

    def write_html(tmp):
        verdict = ("PASS: verified and buildable" if data["pass"]
                   else "FAIL: " + "; ".join(data["failures"]))
        parts = [
            "<!DOCTYPE html><html><head><meta charset='utf-8'>",
            f"<title>{html.escape(cam.design.name)}</title>",
            "<style>body{font-family:sans-serif;max-width:60em;margin:2em auto}"
            "table{border-collapse:collapse}td{border-bottom:1px solid #ddd;padding:.25em .8em}"
            ".pass{color:#1b6e2e}.fail{color:#b00020}"
            "section{page-break-after:always}img{max-width:100%}</style></head><body>",
            f"<p class='{'pass' if data['pass'] else 'fail'}'><strong>{html.escape(verdict)}</strong></p>",
            f"<h1>{html.escape(cam.design.name)}</h1>",
            f"<p>design file {html.escape(data['file'])}, {data['date']}, cams {html.escape(data['version'])}</p>",
        ]
        for title, rows in sections:
            parts.append(f"<section><h2>{html.escape(title)}</h2><table>")
            parts += [f"<tr><td>{html.escape(a)}</td><td>{html.escape(b)}</td></tr>" for a, b in rows]
            parts.append("</table></section>")
        for title, svg, _, _ in svgs:
            data64 = base64.b64encode(svg).decode("ascii")
            parts.append(f"<section><h2>{html.escape(title)}</h2>"
                         f"<img alt='{html.escape(title)}' src='data:image/svg+xml;base64,{data64}'></section>")
        parts.append("</body></html>")
        Path(tmp).write_text("\n".join(parts), encoding="utf-8")

    pdf = atomic_write(out / "report.pdf", "--out", write_pdf)
    page = atomic_write(out / "report.html", "--out", write_html)
    return page, pdf
