"""The lift table: the cam at every step of cam angle, as a shop's table (``cams profile --table``).

For each cam angle ``phi`` from 0 (the start of the first ``[[motion]]`` row, the timing datum): the follower's
lift (mm, or degrees for a rocker), the profile's points in the cam frame of the exports
(:mod:`cams.manufacture.drawing`) in polar coordinates (the point's radius and its own polar angle, counter-clockwise
from +X) and Cartesian ones, the pressure angle and the working profile's radius of curvature (positive convex,
``inf`` where straight). A roller's table has the pitch curve's points too (and a groove's outer wall); at a phase
joint the later phase's values are given. Lengths in the design's unit, angles in degrees; each column's name
carries its unit.
"""

from __future__ import annotations

import numpy as np

from cams.kinematics.inversion import curvature, invert_at, outward_normal, pressure_angle
from laws.units import turn_degrees

__all__ = ["roller_table", "flat_table", "lift_column", "polar_columns"]


def lift_column(design, phi: np.ndarray) -> tuple[str, np.ndarray]:
    """The follower's lift at ``phi``: ``lift_deg`` (a rocker's swing, degrees) or ``lift_mm`` (a stroke)."""
    s = design.program.evaluate(phi).s
    if design.follower.kind == "rocker":
        return "lift_deg", np.degrees(s)
    return "lift_mm", s


def polar_columns(name: str, pts: np.ndarray) -> list[tuple[str, np.ndarray]]:
    """``name_r_mm``, ``name_theta_deg`` (in [0, 360)), ``name_x_mm``, ``name_y_mm`` of the points ``pts``."""
    r = np.hypot(pts[:, 0], pts[:, 1])
    theta = turn_degrees(np.arctan2(pts[:, 1], pts[:, 0]))
    return [(f"{name}_r_mm", r), (f"{name}_theta_deg", theta), (f"{name}_x_mm", pts[:, 0]),
            (f"{name}_y_mm", pts[:, 1])]


def _radius(kappa: np.ndarray) -> np.ndarray:
    """``1 / kappa`` (length, positive convex), ``inf`` where the curvature is 0."""
    with np.errstate(divide="ignore"):
        return np.where(kappa == 0, np.inf, 1.0 / np.where(kappa == 0, 1.0, kappa))


def roller_table(design, centre: np.ndarray, phi: np.ndarray) -> list[tuple[str, np.ndarray]]:
    """A roller (or knife-edge) follower's lift table at cam angles ``phi`` (radians).

    The pitch point ``P`` and its outward normal ``n`` are the kernel's (:mod:`cams.kinematics.inversion`); the
    working profile is ``P - r n`` (radius of curvature ``rho - r``), a groove's outer wall ``P + r n``
    (``rho + r``); the pressure angle is the kernel's, between the contact normal and the roller centre's rise.
    """
    inv = invert_at(design, centre, phi)
    P, n, kappa = inv.point, outward_normal(inv), curvature(inv)
    r = float(design.follower.roller_radius)
    rho = _radius(kappa)
    cols = [("phi_deg", np.degrees(phi)), lift_column(design, phi), *polar_columns("pitch", P),
            *polar_columns("work", P - r * n)]
    groove = design.limits.closure == "form"
    if groove:
        cols += polar_columns("outer", P + r * n)
    cols += [("pressure_angle_deg", np.degrees(pressure_angle(inv))), ("rho_work_mm", rho - r)]
    if groove:
        cols.append(("rho_outer_mm", rho + r))
    return cols


def flat_table(design, R0: float, phi: np.ndarray) -> list[tuple[str, np.ndarray]]:
    """A flat-faced follower's lift table at cam angles ``phi`` (radians): the envelope's points, the pressure
    angle and the radius of curvature (:func:`cams.profile.flat.flat_face_cam` at those angles; no pitch curve)."""
    from cams.profile.flat import flat_face_cam

    cam = flat_face_cam(design, R0, phi=phi)
    return [("phi_deg", np.degrees(phi)), lift_column(design, phi), *polar_columns("work", cam.point),
            ("pressure_angle_deg", np.degrees(cam.pressure_angle)), ("rho_work_mm", cam.rho)]
