"""What every export of a cam profile shares: the drawings' frame and layers, the bore drawn, the digits written.

The frame
---------
Everything is written in the cam frame of :mod:`cams.profile.roller` (origin at the cam centre, the axes those of
the follower's fixed frame with the cam at ``phi = 0``), in the design's length unit (mm): the frame of the lift
table (``cams profile --table``). The drawing is **not rotated** to put the timing datum on an axis; the layer
``DATUM`` draws the datum's direction instead: from the cam centre towards the roller centre at cam angle 0 (a
flat face: along the contact normal there), where the first ``[[motion]]`` row starts. Each file is written to a
temporary file in the target's folder and moved into place with :func:`os.replace`, so a failed export leaves no
partial file behind.

Layers (DXF, :mod:`cams.manufacture.dxf`) and groups (SVG, :mod:`cams.manufacture.svg`):

* ``PROFILE``: the working profile, as ``cams profile --curve`` chooses (:mod:`cams.manufacture.curves`):
  ``arcs`` a closed chain of tangent circular arcs (a DXF LWPOLYLINE with bulges, SVG ``A`` commands),
  ``spline`` a closed cubic B-spline (DXF SPLINE, SVG cubic Beziers ``C``), each certified within the
  tolerance of the exact curve; ``polyline`` the sampled points within the chord tolerance;
* ``OUTER``: the outer wall of a groove (form closure only), as ``PROFILE``;
* ``PITCH``: the pitch curve (roller-centre path), as ``PROFILE``;
* ``BASE``: the base circle of radius R0 (the pitch curve's, the project's R0);
* ``BORE``: the bore, only when a bore radius is given (``[cam] bore_radius``): the automatic bore is a
  suggestion, not a dimension. With a keyway the bore and its keyway are one closed outline here (the hole
  cut: one contour), a LWPOLYLINE of three lines and the bore's arc (:func:`cams.manufacture.keyway.bore_outline`);
* ``KEYWAY``: the keyway's centre line, from the bore's surface to the keyway's bottom
  (``[cam] keyway_width``, ``keyway_depth``, ``keyway_angle``);
* ``CENTRE``: a centre mark, two short lines crossing at the cam centre;
* ``DATUM``: the timing datum, a line from the cam centre along the datum's direction, past the cam.

A cam that fails a check (:mod:`cams.assess`) is exported only when asked for
(``cams profile --allow-failed``) and then marked: the DXF gets a layer
``FAILED`` holding a text with the reasons and a header property
``CAMS_STATUS`` (``FAILED: ...``), the SVG's ``<title>`` begins with
``FAILED`` and a ``<desc>`` gives the reasons. A CSV (:mod:`cams.manufacture.points`)
is not marked: its columns stay numbers only.

A flat-faced follower's cam (:class:`cams.profile.flat.FlatFaceProfile`) has no
pitch curve: its files hold the profile (``PROFILE``, the envelope of the face
lines, CSV columns ``phi_deg,work_x,work_y``), the base circle (R0, the
profile's distance from the centre at the near dwell) and the bore.
"""

from __future__ import annotations

import numpy as np

from laws.errors import InputError

__all__ = ["length_decimals", "drawn_bore", "datum_line", "centre_mark", "LAYERS", "SIGNIFICANT_DIGITS",
           "CURVE_LAYERS"]

#: Significant digits of the cam's size kept by every coordinate written as text (CSV, SVG).
SIGNIFICANT_DIGITS = 12

#: Layer names of the drawings, in drawing order.
LAYERS = ("PROFILE", "OUTER", "PITCH", "BASE", "BORE", "KEYWAY", "CENTRE", "DATUM")
#: The layers holding a curve of the cam (fitted as ``--curve`` chooses).
CURVE_LAYERS = ("PROFILE", "OUTER", "PITCH")
#: The datum line's length as a share of the drawing's extent (the largest radius drawn): past the cam.
DATUM_REACH = 1.1
#: The centre mark's half-length as a share of the drawing's extent.
CENTRE_MARK = 0.03


def datum_line(datum: np.ndarray, extent: float) -> np.ndarray:
    """The datum line's two ends (2, 2): the cam centre and :data:`DATUM_REACH` times ``extent`` (mm) along the
    unit vector ``datum`` (cam frame)."""
    return np.array([[0.0, 0.0], DATUM_REACH * extent * np.asarray(datum, float)])


def centre_mark(extent: float) -> np.ndarray:
    """The centre mark's two lines (2, 2, 2): along X and along Y, :data:`CENTRE_MARK` times ``extent`` each side
    of the cam centre."""
    c = CENTRE_MARK * extent
    return np.array([[[-c, 0.0], [c, 0.0]], [[0.0, -c], [0.0, c]]])


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


def drawn_bore(bore_radius: float | None) -> float | None:
    """The bore radius to draw: None when none is given (a suggested bore is not a dimension).

    Parameters
    ----------
    bore_radius : float or None
        Length unit; None: no bore.

    Raises
    ------
    InputError
        ``bore_radius`` not finite and positive.
    """
    if bore_radius is None:
        return None
    if not (np.isfinite(bore_radius) and bore_radius > 0):
        raise InputError("cam.bore_radius", f"must be > 0, got {bore_radius!r}")
    return float(bore_radius)
