"""What every export of a sampled cam profile shares: the drawings' layers, the bore drawn, the digits written.

Everything is written in the cam frame of :mod:`cams.profile.roller` (origin at the
cam centre, cam at ``phi = 0``), in the design's length unit (mm). Each file
is written to a temporary file in the target's folder and moved into place
with :func:`os.replace`, so a failed export leaves no partial file behind.

Layers (DXF, :mod:`cams.manufacture.dxf`) and groups (SVG, :mod:`cams.manufacture.svg`):

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

__all__ = ["length_decimals", "drawn_bore", "LAYERS", "SIGNIFICANT_DIGITS"]

#: Significant digits of the cam's size kept by every coordinate written as text (CSV, SVG).
SIGNIFICANT_DIGITS = 12

#: Layer names of the drawings, in drawing order.
LAYERS = ("PROFILE", "OUTER", "PITCH", "BASE", "BORE")


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
