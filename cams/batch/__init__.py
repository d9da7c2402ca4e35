"""The batch solver: many roller-follower designs sized, verified and judged buildable in one vectorized pass.

:func:`size_batch` is the one entry point (the sweep's). It groups the designs it can size by motion program: a
roller follower's cam (rocker or translating, roller radius > 0) sized by the exact method to the least R0, nothing
else fixed but a translating follower's ``follower.offset`` (no ``[cam] base_radius`` or ``centre``, no
``limits.centre_distance`` or ``min_base_radius``; a rocker's safety factor K_C checked by the independent check's
moved lines), none of the tables that add checks or constraints
(``[optimize]``, ``[dynamics]``, ``[contact]``, ``[profile] min_curvature_radius``, a keyway, a ``[profile]
tolerance`` of its own, which a profile may not carry); a ``[cam] bore_radius`` and ``hub_wall`` are judged (the
pressure angle's cam whose working profile clears the bore by the wall with the margin is the part's). It sizes
each group at once (:mod:`cams.batch.sizing`: the exact method's problem, the law evaluated once per group),
checks every cam by kinematic inversion (:mod:`cams.batch.check`: no formula of the sizing) and returns a row only
for a cam whose every check passes with a margin: verified, buildable, no self-crossing of its working profile.
Every other design (another kind, a failing or borderline cam, an empty zone) is ``None``: the per-design path
(:class:`cams.cam.Cam`) gives its row, failures and errors included.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from laws.errors import CamsError

__all__ = ["size_batch", "ROW_KEYS", "SIZE_KEYS", "VERDICT_KEYS", "MARGIN", "PRESSURE_MARGIN"]

#: A sized cam's numbers, in a row's order (lengths in the design's unit, angles in degrees): the batch's rows and
#: the sweep's columns (:data:`cams.sweep.output.COLUMNS`) begin with them.
SIZE_KEYS = (
    "R0",
    "L",
    "offset",
    "centre_x",
    "centre_y",
    "blank_diameter",
    "max_pressure_angle_rise",
    "max_pressure_angle_return",
)
#: A row's verdict (the one rule, :mod:`cams.assess`) and its error bound (mm): the batch's rows and the sweep's
#: columns end with them.
VERDICT_KEYS = ("verified", "buildable", "error_bound", "failures", "error")
#: The keys of a row, in order.
ROW_KEYS = SIZE_KEYS + VERDICT_KEYS

#: The pressure angle's largest excess over its limit (radians) a row may have: a tenth of the per-design check's
#: tolerance (1e-7 rad), so that both judge it within the limit.
PRESSURE_MARGIN = 1e-8
#: The relative margin of the buildability tests: ``kappa r <= 1 - MARGIN`` on the pitch curve (convex; the
#: groove's concave too), the working profile at least ``MARGIN R0`` inside every tangent line from its kernel's
#: point and from the cam centre; closer goes to the per-design path.
MARGIN = 1e-3
#: Designs sized at once (checked in parts of :data:`cams.batch.check.CHUNK`, that module's own chunk).
CHUNK = 128


def _batchable(design, method: str | None) -> bool:
    """Whether the batch sizes ``design`` (see the module); else its row is the per-design path's."""
    from cams.model.follower import Rocker, Translating

    f = design.follower
    if not isinstance(f, (Rocker, Translating)):  # the roller followers (a flat face's are other types)
        return False
    lim = design.limits
    return (
        (method or design.method) == "exact"
        and design.objective == "R0"
        and not design.chosen
        and getattr(design, "centre", None) is None
        and lim.centre_distance is None
        and lim.min_base_radius is None
        and f.roller_radius > 0
        and design.optimize is None
        and design.dynamics is None
        and design.contact is None
        and (design.bore_radius is None or design.keyway_width is None)
        and design.tolerance is None
        and getattr(design, "min_curvature_radius", None) is None
        and bool(design.constrained_phases())
    )


def size_batch(designs: Sequence, method: str | None = None) -> list[dict | None]:
    """Size, verify and judge many designs at once; None for each design the per-design path must solve.

    Parameters
    ----------
    designs : sequence of cams.model.design.Design
    method : str, optional
        Overrides each design's ``[solve] method`` as ``cams.cam.Cam(design, method=method)`` does; the batch
        sizes by ``"exact"`` only.

    Returns
    -------
    list of dict or None
        Per design, in order: a row with :data:`ROW_KEYS` (``R0``, ``L`` (rocker, else None), ``offset``
        (translating, else None), ``centre_x``, ``centre_y`` in the design's length unit; the largest pressure
        angles over the rise and the return phases in degrees (None: no such phase); ``blank_diameter`` (twice the
        cam's largest radius, length); ``verified`` and
        ``buildable`` True, ``error_bound`` (length: R0 less the proven lower bound), ``failures`` and ``error``
        None), as the per-design path gives them to the last digits; or None.
    """
    out: list[dict | None] = [None] * len(designs)
    groups: dict[tuple, list[int]] = {}
    for k, d in enumerate(designs):
        if _batchable(d, method):
            fixed = getattr(d.follower, "offset", None) is not None  # a translating follower's offset held
            key = (d.program, tuple(i for i, _ in d.constrained_phases()), fixed)
            try:
                hash(key)
            except TypeError:  # a program that holds arrays (a law table): grouped by its object
                key = (_Same(d.program), *key[1:])
            groups.setdefault(key, []).append(k)
    for (prog, phases, _), idx in groups.items():
        program = prog.program if isinstance(prog, _Same) else prog
        with np.errstate(all="ignore"):
            for a in range(0, len(idx), CHUNK):  # arrays that stay in the processor's cache
                try:
                    _judge(designs, idx[a : a + CHUNK], list(phases), program, out)
                except (CamsError, ArithmeticError, ValueError, np.linalg.LinAlgError):
                    continue  # a chunk the batch cannot size: its rows stay None, the per-design path's to give
    return out


def _judge(designs, idx: list[int], phases: list[int], program, out: list) -> None:
    """Size and check the designs ``idx`` of one group; their rows into ``out`` where they pass with margin."""
    from cams.batch.check import JOINT, check_group
    from cams.batch.sizing import size_group

    group = [designs[k] for k in idx]
    sized = size_group(group, phases, program)
    chk = check_group(group, sized.centre, program)
    r = np.array([d.follower.roller_radius for d in group])
    good = (
        sized.ok
        & (chk.excess <= PRESSURE_MARGIN)
        & (chk.convex <= 1.0 - MARGIN)
        & (chk.kernel >= MARGIN * sized.R0)
        & (np.abs(np.abs(chk.turns) - 1.0) < 1e-9)
        & (chk.step < 0.5)
        & (chk.reach >= MARGIN * sized.R0)
        & (sized.R0 > r * (1.0 + MARGIN))
        & (chk.joint <= JOINT)
        & np.isfinite(chk.rise)
    )
    groove = np.array([d.limits.closure == "form" for d in group])
    good &= ~groove | (chk.concave <= 1.0 - MARGIN)
    # the bore: the working profile's smallest radius clears it by the hub wall, with the margin (the part's sizing
    # would raise the cam otherwise, and the grid's smallest radius is above the true one by far less)
    clear = np.array(
        [(d.bore_radius or 0.0) + (d.hub_wall or 0.0) if d.bore_radius is not None else -np.inf for d in group]
    )
    good &= chk.reach >= clear + MARGIN * sized.R0
    for q in np.flatnonzero(good):
        out[idx[q]] = _row(
            group[q], sized.centre[q], float(sized.R0[q]), float(sized.error_bound[q]), chk.rise[q], chk.ret[q],
            float(chk.largest[q]),
        )


class _Same:
    """A program grouped by its object (identity), where it cannot be hashed."""

    def __init__(self, program):
        self.program = program

    def __hash__(self) -> int:
        return id(self.program)

    def __eq__(self, other) -> bool:
        return isinstance(other, _Same) and other.program is self.program


def _row(design, centre, R0: float, bound: float, rise: float, ret: float, largest: float) -> dict:
    """One design's row (:data:`ROW_KEYS`)."""
    from cams.model.follower import Rocker, Translating
    from optimize.sizing import offset_x

    f = design.follower
    deg = lambda a: None if np.isnan(a) else float(np.degrees(a))  # noqa: E731
    return {
        "R0": R0,
        "L": float(np.hypot(*(centre - f.pivot))) if isinstance(f, Rocker) else None,
        "offset": offset_x(float(centre[0])) + 0.0 if isinstance(f, Translating) else None,
        "centre_x": float(centre[0]),
        "centre_y": float(centre[1]),
        "blank_diameter": 2.0 * largest,
        "max_pressure_angle_rise": deg(rise),
        "max_pressure_angle_return": deg(ret),
        "verified": True,
        "buildable": True,
        "error_bound": bound,
        "failures": None,
        "error": None,
    }
