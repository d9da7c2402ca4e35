"""The sampled profile as an SVG drawing to scale (1 user unit = 1 mm), to print at 1:1 or to cut.

The groups, the frame and the marking of a failing cam are those of :mod:`cams.manufacture.drawing`.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from cams.io.files import atomic_write
from cams.manufacture.drawing import LAYERS, drawn_bore, length_decimals
from cams.profile.roller import Profile

__all__ = ["write_svg"]

_SVG_STYLE = {
    "PROFILE": 'stroke="#000000"',
    "OUTER": 'stroke="#000000"',
    "PITCH": 'stroke="#c00000" stroke-dasharray="{d} {d}"',
    "BASE": 'stroke="#008000" stroke-dasharray="{d} {d}"',
    "BORE": 'stroke="#0000c0"',
}


def _path_d(pts: np.ndarray, decimals: int) -> str:
    """SVG path data of a closed polyline, y turned downwards (SVG's convention)."""
    xy = [f"{x:.{decimals}f},{-y:.{decimals}f}" for x, y in pts]
    return "M" + " L".join(xy) + " Z"


def write_svg(profile: Profile, path: str | os.PathLike, *, bore_radius: float | None = None,
              field: str = "--svg", failing: str = "") -> Path:
    """Write the profile as an SVG drawing to scale (1 user unit = 1 mm).

    The ``viewBox`` is in millimetres and the ``width``/``height`` carry the
    ``mm`` unit, so the drawing prints at 1:1. SVG's y axis points down: the
    cam frame's y is negated. Groups with ``id`` ``PROFILE``, ``OUTER``,
    ``PITCH``, ``BASE``, ``BORE`` as in the DXF.

    Parameters
    ----------
    profile : Profile
    path : path-like
    bore_radius : float, optional
        Length unit; None (default): no bore drawn.
    field : str
        Name of the option for error messages.
    failing : str, optional
        Why the cam fails its checks; non-empty marks the drawing as failing
        (``<title>`` beginning with ``FAILED``, the reasons in ``<desc>``).
    """
    from xml.sax.saxutils import escape

    bore = drawn_bore(bore_radius)
    pts = [c for c in (profile.work, profile.pitch, profile.outer) if c is not None]
    allp = np.concatenate(pts)
    ext = max(float(np.max(np.abs(allp))), profile.R0)
    margin = 0.05 * ext
    lo = -ext - margin
    size = 2 * (ext + margin)
    k = length_decimals(ext)  # every number to the same resolution, whatever the cam's size
    sw = min(max(size / 1000.0, 0.05), size / 200.0)  # a visible line, thinner than the cam
    dash = f"{2 * sw:.{k}f}"
    body = {
        "PROFILE": f'<path d="{_path_d(profile.work, k)}"/>',
        "OUTER": f'<path d="{_path_d(profile.outer, k)}"/>' if profile.outer is not None else None,
        "PITCH": f'<path d="{_path_d(profile.pitch, k)}"/>' if profile.pitch is not None else None,
        "BASE": f'<circle cx="0" cy="0" r="{profile.R0:.{k}f}"/>',
        "BORE": None if bore is None else f'<circle cx="0" cy="0" r="{bore:.{k}f}"/>',
    }
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="{size:.{k}f}mm" height="{size:.{k}f}mm" '
        f'viewBox="{lo:.{k}f} {lo:.{k}f} {size:.{k}f} {size:.{k}f}">',
        f"<title>{'FAILED CHECKS, not for manufacture: ' if failing else ''}{escape(profile.name)}: cam profile, "
        "cam frame, mm</title>",
    ]
    if failing:
        lines.append(f"<desc>FAILED: {escape(failing)}</desc>")
    for name in LAYERS:
        if body[name] is None:
            continue
        style = _SVG_STYLE[name].format(d=dash)
        lines.append(f'<g id="{name}" fill="none" {style} stroke-width="{sw:.{k}f}">{body[name]}</g>')
    c = 0.03 * ext
    lines.append(f'<g id="CENTRE" stroke="#000000" stroke-width="{sw / 2:.{k}f}">'
                 f'<line x1="{-c:.{k}f}" y1="0" x2="{c:.{k}f}" y2="0"/><line x1="0" y1="{-c:.{k}f}" x2="0" '
                 f'y2="{c:.{k}f}"/></g>')
    lines.append("</svg>")
    text = "\n".join(lines) + "\n"

    def write(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(text)

    return atomic_write(path, field, write)
