"""The sampled profile as a CSV table of points: one row per cam angle, for a CNC program or a spreadsheet.

The frame, the units and the columns of a flat-faced follower's cam are those of
:mod:`cams.manufacture.drawing`; the file is not marked when the cam fails a check.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from cams.io.files import atomic_write
from cams.manufacture.drawing import length_decimals
from cams.profile.roller import Profile

__all__ = ["write_csv", "csv_header"]


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
    the coordinates with :data:`~cams.manufacture.drawing.SIGNIFICANT_DIGITS` significant digits of the
    cam's size (:func:`~cams.manufacture.drawing.length_decimals`), so a micrometre cam keeps them too.
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
