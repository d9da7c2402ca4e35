"""The sampled profile as a DXF drawing (R2010, millimetres), for CAD and CAM.

The layers, the frame and the marking of a failing cam are those of :mod:`cams.manufacture.drawing`.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from cams.io.files import atomic_write
from cams.manufacture.drawing import LAYERS, drawn_bore
from cams.profile.roller import Profile

__all__ = ["write_dxf"]

_COLOURS = {"PROFILE": 7, "OUTER": 7, "PITCH": 1, "BASE": 3, "BORE": 5}  # AutoCAD colour index


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

    bore = drawn_bore(bore_radius)
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
