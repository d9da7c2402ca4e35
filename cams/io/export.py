"""Exports of a sampled cam profile for manufacturing: CSV, DXF, SVG.

Everything is written in the cam frame of :mod:`cams.profile.roller` (origin at the
cam centre, cam at ``phi = 0``), in the design's length unit (mm). Each file
is written to a temporary file in the target's folder and moved into place
with :func:`os.replace`, so a failed export leaves no partial file behind.

Layers (DXF) and groups (SVG):

* ``PROFILE``: the working profile, a closed polyline within the chord
  tolerance of the true envelope;
* ``OUTER``: the outer wall of a groove (form closure only);
* ``PITCH``: the pitch curve (roller-centre path);
* ``BASE``: the base circle of radius R0 (the pitch curve's, the project's R0);
* ``BORE``: the bore circle, only when a bore radius is given (``[cam]
  bore_radius``): the automatic bore is a suggestion, not a dimension.

A cam that fails a check (:mod:`cams.assess`) is exported only when asked for
(``cams profile --allow-failed``) and then marked: the DXF gets a layer
``FAILED`` holding a text with the reasons and a header property
``CAMS_STATUS`` (``FAILED: ...``), the SVG's ``<title>`` begins with
``FAILED`` and a ``<desc>`` gives the reasons. A CSV is not marked: its
columns stay numbers only.

A flat-faced follower's cam (:class:`cams.profile.flat.FlatFaceProfile`) has no
pitch curve: its files hold the profile (``PROFILE``, the envelope of the face
lines, CSV columns ``phi_deg,work_x,work_y``), the base circle (R0, the
profile's distance from the centre at the near dwell) and the bore.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from cams.io.files import atomic_write
from cams.profile.roller import Profile
from laws.errors import InputError

__all__ = ["write_csv", "write_dxf", "write_svg", "csv_header", "length_decimals", "LAYERS", "SIGNIFICANT_DIGITS"]

#: Significant digits of the cam's size kept by every coordinate written as text (CSV, SVG).
SIGNIFICANT_DIGITS = 12

#: Layer names of the drawings, in drawing order.
LAYERS = ("PROFILE", "OUTER", "PITCH", "BASE", "BORE")
_COLOURS = {"PROFILE": 7, "OUTER": 7, "PITCH": 1, "BASE": 3, "BORE": 5}  # AutoCAD colour index
_SVG_STYLE = {
    "PROFILE": 'stroke="#000000"',
    "OUTER": 'stroke="#000000"',
    "PITCH": 'stroke="#c00000" stroke-dasharray="{d} {d}"',
    "BASE": 'stroke="#008000" stroke-dasharray="{d} {d}"',
    "BORE": 'stroke="#0000c0"',
}


def length_decimals(size: float, digits: int = SIGNIFICANT_DIGITS) -> int:
    """Decimals that keep ``digits`` significant digits of a length of magnitude ``size`` (fixed-point).

    A cam 20 mm across gets 10 decimals, one of 2e-6 mm 17, one of 1e7 mm 4:
    every coordinate is written to the same absolute resolution, ``digits``
    significant digits of the cam's size. At least 0, at most 30.

    >>> length_decimals(20.0), length_decimals(2e-6), length_decimals(1e7)
    (10, 17, 4)
    """
    import math

    if not (size > 0 and math.isfinite(size)):
        return 9
    return min(30, max(0, digits - 1 - math.floor(math.log10(size))))


def _size(profile: Profile) -> float:
    """The cam's size: the largest coordinate of its curves (length)."""
    return max(float(np.max(np.abs(c))) for c in (profile.work, profile.pitch, profile.outer) if c is not None)


def csv_header(profile: Profile) -> str:
    """The CSV header line (without newline)."""
    if profile.pitch is None:
        return "phi_deg,work_x,work_y"
    cols = ["phi_deg", "pitch_x", "pitch_y", "work_x", "work_y"]
    if profile.outer is not None:
        cols += ["outer_x", "outer_y"]
    return ",".join(cols)


def write_csv(profile: Profile, path: str | os.PathLike, *, field: str = "--csv") -> Path:
    """Write the profile as CSV: one header line, then one row per sample.

    Columns ``phi_deg,pitch_x,pitch_y,work_x,work_y`` (plus ``outer_x,outer_y``
    for a groove; ``phi_deg,work_x,work_y`` for a flat-faced follower's cam):
    cam angle in degrees, coordinates in the cam frame, length unit; rows in
    cam-angle order, the first at ``phi = 0``. The curves are closed: the last
    row joins the first. Numbers are fixed-point: the angle with 9 decimals,
    the coordinates with :data:`SIGNIFICANT_DIGITS` significant digits of the
    cam's size (:func:`length_decimals`), so a micrometre cam keeps them too.
    The file holds the header and the numbers only (no comment line).

    Parameters
    ----------
    profile : Profile
    path : path-like
    field : str
        Name of the option for error messages.

    Raises
    ------
    InputError
        The file cannot be written (no partial file is left).
    """
    if profile.pitch is None:
        cols = [np.degrees(profile.phi), profile.work[:, 0], profile.work[:, 1]]
    else:
        cols = [np.degrees(profile.phi), profile.pitch[:, 0], profile.pitch[:, 1], profile.work[:, 0],
                profile.work[:, 1]]
    if profile.outer is not None:
        cols += [profile.outer[:, 0], profile.outer[:, 1]]
    data = np.column_stack(cols)
    fmt = ["%.9f"] + [f"%.{length_decimals(_size(profile))}f"] * (data.shape[1] - 1)

    def write(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(csv_header(profile) + "\n")
            np.savetxt(fh, data, fmt=fmt, delimiter=",")

    return atomic_write(path, field, write)


def _bore(profile: Profile, bore_radius: float | None) -> float | None:
    """The bore radius to draw: None when none is given (a suggested bore is not a dimension)."""
    if bore_radius is None:
        return None
    if not (np.isfinite(bore_radius) and bore_radius > 0):
        raise InputError("cam.bore_radius", f"must be > 0, got {bore_radius!r}")
    return float(bore_radius)


def write_dxf(profile: Profile, path: str | os.PathLike, *, bore_radius: float | None = None,
              field: str = "--dxf", failing: str = "") -> Path:
    """Write the profile as a DXF drawing (R2010, millimetres).

    The working profile (layer ``PROFILE``), the groove's outer wall
    (``OUTER``) and the pitch curve (``PITCH``) are closed LWPOLYLINEs through
    the profile's samples (within its chord tolerance); the base circle of
    radius R0 (``BASE``) and the bore (``BORE``) are circles about the origin,
    the cam centre.

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
        (layer ``FAILED`` with this text, header property ``CAMS_STATUS``).
    """
    import ezdxf
    from ezdxf import units

    bore = _bore(profile, bore_radius)
    doc = ezdxf.new("R2010")
    doc.units = units.MM
    doc.header["$MEASUREMENT"] = 1
    for name in LAYERS:
        if (name == "OUTER" and profile.outer is None) or (name == "PITCH" and profile.pitch is None) or (
                name == "BORE" and bore is None):
            continue
        doc.layers.add(name, color=_COLOURS[name])
    msp = doc.modelspace()
    msp.add_lwpolyline(profile.work.tolist(), format="xy", close=True, dxfattribs={"layer": "PROFILE"})
    if profile.outer is not None:
        msp.add_lwpolyline(profile.outer.tolist(), format="xy", close=True, dxfattribs={"layer": "OUTER"})
    if profile.pitch is not None:
        msp.add_lwpolyline(profile.pitch.tolist(), format="xy", close=True, dxfattribs={"layer": "PITCH"})
    msp.add_circle((0.0, 0.0), profile.R0, dxfattribs={"layer": "BASE"})
    if bore is not None:
        msp.add_circle((0.0, 0.0), bore, dxfattribs={"layer": "BORE"})
    if failing:
        doc.header.custom_vars.append("CAMS_STATUS", f"FAILED: {failing}")
        doc.layers.add("FAILED", color=1)
        ext = max(float(np.max(np.abs(profile.work))), profile.R0)
        msp.add_text(f"FAILED CHECKS - NOT FOR MANUFACTURE: {failing}", height=0.05 * ext,
                     dxfattribs={"layer": "FAILED"}).set_placement((-ext, 1.15 * ext))

    def write(tmp: str) -> None:
        doc.saveas(tmp)

    return atomic_write(path, field, write)


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

    bore = _bore(profile, bore_radius)
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


