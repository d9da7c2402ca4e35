"""The lift table as CSV: one row per step of cam angle, for a shop's inspection or a CNC program by the degree.

The columns are those of the face's pipeline (:meth:`cams.faces.base.Face.table`, :mod:`cams.profile.table`): the
cam angle from the timing datum (the start of the first ``[[motion]]`` row), the follower's lift, the profile's
points in polar and Cartesian coordinates in the cam frame of :mod:`cams.manufacture.drawing`, the pressure angle
and the radius of curvature; each name carries its unit (``_deg``, ``_mm``). Like the profile's CSV the file is
plain numbers under one header line, not marked when the cam fails a check.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from cams.io.files import atomic_write
from cams.manufacture.drawing import length_decimals
from laws.errors import InputError

__all__ = ["table_angles", "write_table", "MAX_ROWS"]

#: The most rows of a lift table (a step of 0.001 degrees).
MAX_ROWS = 360_000


def table_angles(step: float, field: str = "--step") -> np.ndarray:
    """The table's cam angles in degrees, ``0, step, 2 step, ...`` below 360.

    Raises
    ------
    InputError
        Naming ``field``: a step that is not a number > 0, that does not divide 360 (to 1e-9 of the count), or
        that gives more than :data:`MAX_ROWS` rows.
    """
    if isinstance(step, bool) or not isinstance(step, (int, float)) or not (np.isfinite(step) and step > 0):
        raise InputError(field, f"must be a number of degrees > 0 that divides 360, got {step!r}")
    count = 360.0 / step
    n = round(count)
    if n < 1 or abs(count - n) > 1e-9 * count:
        raise InputError(field, f"{step:g} degrees does not divide 360 (360 / {step:g} = {count:.10g}); "
                         "e.g. 1, 0.5, 2, 5 or 10")
    if n > MAX_ROWS:
        raise InputError(field, f"{step:g} degrees gives {n} rows, more than {MAX_ROWS}; the smallest step is "
                         f"{360 / MAX_ROWS:g} degrees")
    return np.arange(n) * (360.0 / n)


def write_table(columns: list[tuple[str, np.ndarray]], path: str | os.PathLike, *, field: str = "--table") -> Path:
    """Write the lift table ``columns`` (``(name with unit, values)``) as CSV: a header, then one row per angle.

    Angles (``_deg``) with 9 decimals; lengths (``_mm``) fixed-point with
    :data:`~cams.manufacture.drawing.SIGNIFICANT_DIGITS` significant digits of the cam's size, its points'
    largest radius (a micrometre cam keeps them too); a radius of curvature of a straight piece is ``inf``.

    Raises
    ------
    InputError
        The file cannot be written (no partial file is left).
    """
    # the cam's size: its points' radii and the lift (a radius of curvature near an inflection is no size)
    lengths = [np.abs(v[np.isfinite(v)]) for k, v in columns if k.endswith("_r_mm") or k == "lift_mm"]
    size = max((float(v.max()) for v in lengths if v.size), default=1.0)
    dec = length_decimals(size)
    fmt = ["%.9f" if k.endswith("_deg") else f"%.{dec}f" for k, _ in columns]
    data = np.column_stack([v for _, v in columns])

    def write(tmp: str) -> None:
        with open(tmp, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(",".join(k for k, _ in columns) + "\n")
            np.savetxt(fh, data, fmt=fmt, delimiter=",")

    return atomic_write(path, field, write)
