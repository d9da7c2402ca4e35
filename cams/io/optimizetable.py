"""A design file's ``[optimize]`` table: the motion design's request.

Mapped onto :class:`cams.model.motiondesign.MotionDesignSpec`.

Keys (see docs/files.md)::

    [optimize]
    free = ["rise"]          # "rise" (every rise), "return", or phase indices [0, 2]
    objective = "R0"         # "R0" | "L" (rocker) | "pressure_angle" | "Ca" | "Cj" | "jerk_squared" | "snap_squared"
    max_Ca = "poly4567"      # per free phase, normalized: a law's name (its peak), a number, or a list of them
    max_Cv, max_Cj           # likewise
    continuity = 3           # derivatives continuous at the joints: 1, 2 or 3
    degree = 7               # polynomial degree of each span (> continuity)
    spans = 20               # knot spans per free phase
    smoothing_slack = 0      # the share of the objective given up for smoothness, in [0, 1)

The loader checks the table's shape (known keys, lists); the model checks the values.
"""

from __future__ import annotations

from cams.io.document import check_keys
from cams.model.motiondesign import CAP_KEYS, DEFAULT_CONTINUITY, DEFAULT_DEGREE, DEFAULT_SPANS, MotionDesignSpec
from laws.errors import InputError, show_value

__all__ = ["OPTIMIZE_KEYS", "optimize_from_table"]

#: The keys of ``[optimize]``, in their documented order.
OPTIMIZE_KEYS = ("free", "objective", "max_Cv", "max_Ca", "max_Cj", "continuity", "degree", "spans",
                 "smoothing_slack")


def _listed(table: dict, key: str, default: tuple) -> tuple:
    v = table.get(key)
    if v is None:
        return default
    if isinstance(v, list):
        if not v and key != "free":
            raise InputError(f"optimize.{key}", "is an empty list: give at least one value")
        return tuple(v)
    return (v,)


def optimize_from_table(table: object) -> MotionDesignSpec:
    """The ``[optimize]`` table as a :class:`MotionDesignSpec`.

    Raises
    ------
    InputError
        Not a table, an unknown key, or a value the model refuses (named ``optimize.KEY``).
    """
    if not isinstance(table, dict):
        raise InputError("optimize", f"must be a table ([optimize]), got {show_value(table)}")
    check_keys(table, set(OPTIMIZE_KEYS), "optimize")
    caps = {k: _listed(table, k, (None,)) for k in CAP_KEYS}
    return MotionDesignSpec(
        free=_listed(table, "free", ("rise",)),
        objective=table.get("objective", "R0"),
        max_Cv=caps["max_Cv"], max_Ca=caps["max_Ca"], max_Cj=caps["max_Cj"],
        continuity=table.get("continuity", DEFAULT_CONTINUITY),
        degree=table.get("degree", DEFAULT_DEGREE),
        spans=table.get("spans", DEFAULT_SPANS),
        smoothing_slack=table.get("smoothing_slack", 0.0),
    )
