"""The cam's profile as an SVG drawing to scale (1 user unit = 1 mm), to print at 1:1 or to cut.

The groups, the frame and the marking of a failing cam are those of :mod:`cams.manufacture.drawing`. Arcs are
path ``A`` commands (radius, large-arc and sweep flags; SVG's y axis points down, so a counter-clockwise arc of
the cam frame has sweep flag 0), a spline's spans cubic Beziers (``C``), a straight element ``L``.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from cams.io.files import atomic_write
from cams.manufacture.curves import ArcChain, CubicSpline, FittedCurves
from cams.manufacture.drawing import LAYERS, centre_mark, datum_line, drawn_bore, length_decimals
from cams.manufacture.keyway import Keyway, bore_outline
from cams.profile.roller import Profile

__all__ = ["write_svg"]

_SVG_STYLE = {
    "PROFILE": 'stroke="#000000"',
    "OUTER": 'stroke="#000000"',
    "PITCH": 'stroke="#c00000" stroke-dasharray="{d} {d}"',
    "BASE": 'stroke="#008000" stroke-dasharray="{d} {d}"',
    "BORE": 'stroke="#0000c0"',
    "KEYWAY": 'stroke="#0000c0" stroke-dasharray="{d} {d}"',
    "CENTRE": 'stroke="#000000"',
    "DATUM": 'stroke="#c000c0" stroke-dasharray="{d} {d}"',
}


def _xy(p, k: int) -> str:
    """A point of the cam frame in SVG's coordinates (y turned downwards)."""
    return f"{p[0]:.{k}f},{-p[1]:.{k}f}"


def _path_d(pts: np.ndarray, decimals: int) -> str:
    """SVG path data of a closed polyline, y turned downwards (SVG's convention)."""
    return "M" + " L".join(_xy(p, decimals) for p in pts) + " Z"


def _bulge_path(start: np.ndarray, bulge: np.ndarray, k: int) -> str:
    """SVG path data of a closed chain of elements from ``start[i]`` to ``start[i + 1]`` of bulge ``bulge[i]``
    (a line where 0, else an arc of sweep ``4 atan(bulge)``, counter-clockwise positive in the cam frame)."""
    end = np.roll(start, -1, axis=0)
    out = ["M" + _xy(start[0], k)]
    for a, b, bu in zip(start, end, bulge, strict=True):
        if bu == 0.0:
            out.append("L" + _xy(b, k))
            continue
        sweep = 4.0 * np.arctan(bu)
        chord = float(np.hypot(*(b - a)))
        r = chord / (2.0 * abs(np.sin(sweep / 2.0)))
        large = 1 if abs(sweep) > np.pi else 0
        flag = 0 if sweep > 0 else 1  # y down: the cam frame's counter-clockwise is SVG's negative angle
        out.append(f"A{r:.{k}f},{r:.{k}f} 0 {large} {flag} {_xy(b, k)}")
    return " ".join(out) + " Z"


def _spline_path(spline: CubicSpline, k: int) -> str:
    """SVG path data of a closed spline: its spans as cubic Beziers."""
    bz = spline.bezier()
    out = ["M" + _xy(bz[0, 0], k)]
    out += [f"C{_xy(b[1], k)} {_xy(b[2], k)} {_xy(b[3], k)}" for b in bz]
    return " ".join(out) + " Z"


def write_svg(profile: Profile, path: str | os.PathLike, *, bore_radius: float | None = None,
              field: str = "--svg", failing: str = "", curves: FittedCurves | None = None,
              datum: np.ndarray | None = None, keyway: Keyway | None = None) -> Path:
    """Write the profile as an SVG drawing to scale (1 user unit = 1 mm).

    The ``viewBox`` is in millimetres and the ``width``/``height`` carry the
    ``mm`` unit, so the drawing prints at 1:1. SVG's y axis points down: the
    cam frame's y is negated. Groups with ``id`` ``PROFILE``, ``OUTER``,
    ``PITCH``, ``BASE``, ``BORE``, ``KEYWAY``, ``CENTRE``, ``DATUM`` as in the DXF
    (:func:`cams.manufacture.dxf.write_dxf`, whose parameters these are).
    """
    from xml.sax.saxutils import escape

    bore = drawn_bore(bore_radius)
    pts = [c for c in (profile.work, profile.pitch, profile.outer) if c is not None]
    allp = np.concatenate(pts)
    ext = max(float(np.max(np.hypot(allp[:, 0], allp[:, 1]))), profile.R0)
    reach = ext * (1.1 if datum is not None else 1.0)
    margin = 0.05 * reach
    lo = -reach - margin
    size = 2 * (reach + margin)
    k = length_decimals(ext)  # every number to the same resolution, whatever the cam's size
    sw = min(max(size / 1000.0, 0.05), size / 200.0)  # a visible line, thinner than the cam
    dash = f"{2 * sw:.{k}f}"

    def curve(name: str, polyline: np.ndarray | None) -> str | None:
        if polyline is None:
            return None
        fitted = None if curves is None else curves.curves.get(name)
        if isinstance(fitted, ArcChain):
            return f'<path d="{_bulge_path(fitted.start, fitted.bulge, k)}"/>'
        if isinstance(fitted, CubicSpline):
            return f'<path d="{_spline_path(fitted, k)}"/>'
        return f'<path d="{_path_d(polyline, k)}"/>'

    def line(a, b) -> str:
        return (f'<line x1="{a[0]:.{k}f}" y1="{-a[1]:.{k}f}" x2="{b[0]:.{k}f}" y2="{-b[1]:.{k}f}"/>')

    bore_body = None
    keyway_body = None
    if bore is not None and keyway is None:
        bore_body = f'<circle cx="0" cy="0" r="{bore:.{k}f}"/>'
    elif bore is not None and keyway is not None:
        opts, bulges = bore_outline(bore, keyway)
        bore_body = f'<path d="{_bulge_path(opts, bulges, k)}"/>'
        keyway_body = line(bore * keyway.direction, (bore + keyway.depth) * keyway.direction)
    body = {
        "PROFILE": curve("PROFILE", profile.work),
        "OUTER": curve("OUTER", profile.outer),
        "PITCH": curve("PITCH", profile.pitch),
        "BASE": f'<circle cx="0" cy="0" r="{profile.R0:.{k}f}"/>',
        "BORE": bore_body,
        "KEYWAY": keyway_body,
        "CENTRE": "".join(line(a, b) for a, b in centre_mark(ext)),
        "DATUM": None if datum is None else line(*datum_line(datum, ext)),
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
        width = sw / 2 if name == "CENTRE" else sw
        lines.append(f'<g id="{name}" fill="none" {style} stroke-width="{width:.{k}f}">{body[name]}</g>')
    lines.append("</svg>")
    text = "\n".join(lines) + "\n"

    def write(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8") as fh:
            fh.write(text)

    return atomic_write(path, field, write)
