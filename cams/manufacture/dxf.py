"""The cam's profile as a DXF drawing (R2010, millimetres), for CAD and CAM.

The layers, the frame and the marking of a failing cam are those of :mod:`cams.manufacture.drawing`.

The arcs of ``--curve arcs`` are written as one closed LWPOLYLINE with bulges per curve rather than as ARC
entities: each curve stays one closed contour for the CAM program (no chain to join), neighbouring elements share
their vertex exactly (an ARC stores its centre, radius and angles, so separate ARCs meet only to rounding), and
a straight element is a bulge of 0 in the same entity. The spline of ``--curve spline`` is a SPLINE entity
(degree 3, its knots and control points; clamped, its ends meeting where the curve starts, at cam angle 0).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from cams.io.files import atomic_write
from cams.manufacture.curves import ArcChain, CubicSpline, FittedCurves
from cams.manufacture.drawing import CURVE_LAYERS, LAYERS, centre_mark, datum_line, drawn_bore
from cams.manufacture.keyway import Keyway, bore_outline
from cams.profile.roller import Profile

__all__ = ["write_dxf"]

_COLOURS = {"PROFILE": 7, "OUTER": 7, "PITCH": 1, "BASE": 3, "BORE": 5, "KEYWAY": 5, "CENTRE": 8,
            "DATUM": 6}  # AutoCAD colour index


def _extent(profile: Profile) -> float:
    """The drawing's extent: the largest radius of its curves and base circle (mm)."""
    curves = [c for c in (profile.work, profile.pitch, profile.outer) if c is not None]
    return max(max(float(np.max(np.hypot(c[:, 0], c[:, 1]))) for c in curves), float(profile.R0))


def write_dxf(profile: Profile, path: str | os.PathLike, *, bore_radius: float | None = None,
              field: str = "--dxf", failing: str = "", curves: FittedCurves | None = None,
              datum: np.ndarray | None = None, keyway: Keyway | None = None) -> Path:
    """Write the profile as a DXF drawing (R2010, millimetres).

    The working profile (layer ``PROFILE``), the groove's outer wall (``OUTER``) and the pitch curve
    (``PITCH``) are the fitted ``curves`` (a closed LWPOLYLINE with bulges per curve for arcs, a SPLINE for a
    spline) or, without them, closed LWPOLYLINEs through the profile's samples (within its chord tolerance); the
    base circle of radius R0 (``BASE``) is a circle about the origin, the cam centre; the bore (``BORE``) a
    circle, or with a ``keyway`` one closed LWPOLYLINE of the bore and its keyway, whose centre line is on
    ``KEYWAY``; a centre mark (``CENTRE``) and, given the ``datum``, its line (``DATUM``).

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
    curves : FittedCurves, optional
        The fitted curves by layer (:func:`cams.manufacture.curves.fit_curves`); None: the polylines.
    datum : array_like, shape (2,), optional
        The timing datum's unit direction, cam frame (:class:`cams.profile.exact.ExactCam`).
    keyway : Keyway, optional
        The bore's keyway (needs ``bore_radius``).
    """
    import ezdxf
    from ezdxf import units
    from ezdxf.math import BSpline

    bore = drawn_bore(bore_radius)
    doc = ezdxf.new("R2010")
    doc.units = units.MM
    doc.header["$MEASUREMENT"] = 1
    drawn = {"PROFILE": True, "OUTER": profile.outer is not None, "PITCH": profile.pitch is not None,
             "BASE": True, "BORE": bore is not None, "KEYWAY": bore is not None and keyway is not None,
             "CENTRE": True, "DATUM": datum is not None}
    for name in LAYERS:
        if drawn[name]:
            doc.layers.add(name, color=_COLOURS[name])
    msp = doc.modelspace()
    points = {"PROFILE": profile.work, "OUTER": profile.outer, "PITCH": profile.pitch}
    for name in CURVE_LAYERS:
        if not drawn[name]:
            continue
        attribs = {"layer": name}
        fitted = None if curves is None else curves.curves.get(name)
        if isinstance(fitted, ArcChain):
            rows = np.column_stack([fitted.start, fitted.bulge])
            msp.add_lwpolyline(rows.tolist(), format="xyb", close=True, dxfattribs=attribs)
        elif isinstance(fitted, CubicSpline):
            spline = msp.add_spline(dxfattribs=attribs)
            spline.apply_construction_tool(BSpline(fitted.control.tolist(), order=4, knots=fitted.knots.tolist()))
        else:
            pts = points[name]
            assert pts is not None  # drawn: the profile has this curve
            msp.add_lwpolyline(pts.tolist(), format="xy", close=True, dxfattribs=attribs)
    msp.add_circle((0.0, 0.0), profile.R0, dxfattribs={"layer": "BASE"})
    ext = _extent(profile)
    if bore is not None and keyway is None:
        msp.add_circle((0.0, 0.0), bore, dxfattribs={"layer": "BORE"})
    elif bore is not None and keyway is not None:
        pts, bulges = bore_outline(bore, keyway)
        msp.add_lwpolyline(np.column_stack([pts, bulges]).tolist(), format="xyb", close=True,
                           dxfattribs={"layer": "BORE"})
        e = keyway.direction
        msp.add_line(tuple(bore * e), tuple((bore + keyway.depth) * e), dxfattribs={"layer": "KEYWAY"})
    for a, b in centre_mark(ext):
        msp.add_line(tuple(a), tuple(b), dxfattribs={"layer": "CENTRE"})
    if datum is not None:
        a, b = datum_line(datum, ext)
        msp.add_line(tuple(a), tuple(b), dxfattribs={"layer": "DATUM"})
    if failing:
        doc.header.custom_vars.append("CAMS_STATUS", f"FAILED: {failing}")
        doc.layers.add("FAILED", color=1)
        ext = max(float(np.max(np.abs(profile.work))), profile.R0)
        msp.add_text(f"FAILED CHECKS - NOT FOR MANUFACTURE: {failing}", height=0.05 * ext,
                     dxfattribs={"layer": "FAILED"}).set_placement((-ext, 1.15 * ext))

    def write(tmp: str) -> None:
        doc.saveas(tmp)

    return atomic_write(path, field, write)
