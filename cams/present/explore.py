"""The explorer page of ``cams explore``: one self-contained HTML file (inline script and SVG, nothing fetched).

:func:`explore_data` gathers what the page computes from, through the cam's pipeline: the laws of every phase
(:func:`cams.present.explore_data.phase_samples`; with ``[optimize]``, the designed laws) and what the face lets the
user move (its presenter's :meth:`cams.present.faces.Presenter.explorer`); :func:`page` writes them into the
template (``explore_page.html``) with the page's mathematics (``explore_math.js``), which the tests also run.
"""

from __future__ import annotations

import json
from importlib import resources

__all__ = ["explore_data", "page", "math_source"]


def explore_data(cam, *, samples: int | None = None) -> dict:
    """The page's data of ``cam`` (a :class:`cams.cam.Cam`), JSON-ready; lengths in the design's unit, radians.

    The cam is sized first (with ``[optimize]``, the laws are designed first and theirs are embedded). Where no cam
    can be sized (:class:`laws.errors.InfeasibleError`: no feasible zone), the page still shows the file's laws
    and says why: ``diagnosis`` holds the error's line, as ``cams solve`` gives it. ``samples``: the steps per
    rise or return phase (default :data:`cams.present.explore_data.SAMPLES`).
    """
    from cams.present.explore_data import SAMPLES, phase_samples
    from cams.present.faces import presenter
    from laws.errors import InfeasibleError

    diagnosis = None
    try:
        solution = cam.solution
        design = cam.design
    except InfeasibleError as e:
        solution, design, diagnosis = None, cam.given, str(e)
    face = presenter(cam).explorer(design, solution)
    return {
        "name": design.name,
        "unit": "mm",
        "phases": phase_samples(design, SAMPLES if samples is None else samples),
        "face": face,
        "diagnosis": diagnosis,
        "designed": design is not cam.given,
        "notes": [] if solution is None else list(solution.notes),
    }


def math_source() -> str:
    """The page's mathematics, a plain script defining ``camsMath(data)`` (``explore_math.js``)."""
    return resources.files("cams.present").joinpath("explore_math.js").read_text(encoding="utf-8")


def _script_json(data: dict) -> str:
    """``data`` as JSON safe inside a ``<script>`` element (no ``</`` that would end it)."""
    return json.dumps(data, allow_nan=False, separators=(",", ":")).replace("</", "<\\/")


def page(data: dict) -> str:
    """The whole HTML page of :func:`explore_data`'s ``data``."""
    from html import escape

    template = resources.files("cams.present").joinpath("explore_page.html").read_text(encoding="utf-8")
    return (
        template.replace("{{TITLE}}", escape(data["name"]))
        .replace("{{MATH}}", math_source())
        .replace("{{DATA}}", _script_json(data))
    )
