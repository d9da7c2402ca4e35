"""The safety factor K_C at a given cam centre (seed 001, formula 3.26), from the contact normal.

Part of the independent check (:mod:`cams.verify`): it is derived here from the
seed's definition and the contact normal of the kinematic inversion
(:mod:`cams.verify.pressure`), and shares no formula with the zone's wedges
(:mod:`optimize.zone`).

The definition
--------------
At one position of a rocker (pivot O1, arm l, unit vector ``lam`` from O1 to
the roller centre A, ``e`` the unit direction in which A moves on the rise),
the cam centres O that give the pressure angle exactly [γ] lie on two lines
through the point D where the contact normal crosses the rocker line
(seed 3.19-3.20: ``O1 D = l (1 + psi')``; D does not depend on O, every normal
of that position passes through it). The seed's formula 3.26 moves both lines
parallel into the zone: the line of ``l (1 + psi')`` to ``l (K_C + psi')`` and
the other to ``l (1/K_C + psi')``, K_C >= 1, "shifting the lines t-t and t1-t1
inside the zone". A line through O1's rocker line moved outwards narrows the
zone when the zone lies on its outer side: that is the line whose normal leans
away from the pivot (the normal from O towards D makes the angle [γ] with
``e`` on the side of ``+lam``); the other line, whose normal leans towards the
pivot, narrows the zone moved inwards. So, with ``rho`` the distance from O1
along ``lam`` at which a line crosses the rocker line:

* ``rho_D``: where the contact normal through O crosses it (the inversion's
  normal, crossed with the rocker line);
* ``rho_out``, ``rho_in``: where the lines through O at the limit's directions
  ``cos[γ] e + sin[γ] lam`` (leaning outwards) and ``cos[γ] e - sin[γ] lam``
  (inwards) cross it;

and O meets the safety factor K at this position when

    rho_out - rho_D >= (K - 1) l   and   rho_D - rho_in >= (1 - 1/K) l

(K = 1: the pressure angle within [γ] on the side of the cam that pushes).
The distance of O outside a moved line is ``cos[γ]`` times its shortfall along
the rocker line (the lines meet the rocker line at ``90 deg - [γ]``), and the
largest K a position admits follows from each inequality solved for K.
"""

from __future__ import annotations

import numpy as np

__all__ = ["safety_terms"]


def _crossing(px, py, dx, dy, lx, ly) -> np.ndarray:
    """Where the line through ``(px, py)`` (relative to the pivot) along ``(dx, dy)`` crosses the rocker line.

    The distance from the pivot along the unit vector ``(lx, ly)``: ``p + t d = rho lam`` crossed with ``d``.
    NaN where the line is parallel to the rocker line.
    """
    den = lx * dy - ly * dx
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(den != 0.0, (px * dy - py * dx) / np.where(den != 0.0, den, 1.0), np.nan)


def safety_terms(px, py, nx, ny, ex, ey, lx, ly, *, arm: float, factor: float, limit: float):
    """The safety factor's two moved lines at one or many positions and centres (components broadcast).

    Parameters
    ----------
    px, py : array_like
        Cam centre O relative to the rocker pivot O1, length unit (mm).
    nx, ny : array_like
        Unit contact normal at O's pitch curve (:func:`cams.verify.pressure.contact_normal`; any sign).
    ex, ey : array_like
        Unit direction of the roller centre's motion on the rise.
    lx, ly : array_like
        Unit vector from the pivot to the roller centre (the rocker line).
    arm : float
        Pivot to roller centre l, length unit.
    factor : float
        The safety factor K_C >= 1 (seed 3.26).
    limit : float
        The allowable pressure angle [γ] of the phase, radians, in (0, pi/2).

    Returns
    -------
    outside : ndarray, shape (..., 2)
        Signed distance of O outside the moved line leaning outwards (``[..., 0]``) and inwards (``[..., 1]``),
        length unit (<= 0: inside, by that much).
    reach : ndarray, shape (..., 2)
        Distance from O to each moved line's crossing with the rocker line (its moved pole), length unit:
        ``outside / reach`` is the sine of the angle by which the direction from O to the moved pole exceeds
        [γ] (the pressure angle's excess at K_C = 1).
    admits : ndarray, shape (..., 2)
        The largest safety factor each line admits at O (``inf`` where the inward line admits any).
    """
    px, py, nx, ny, ex, ey, lx, ly = np.broadcast_arrays(*(np.asarray(a, dtype=float)
                                                         for a in (px, py, nx, ny, ex, ey, lx, ly)))
    c, sn = np.cos(limit), np.sin(limit)
    rho_d = _crossing(px, py, nx, ny, lx, ly)
    rho_out = _crossing(px, py, c * ex + sn * lx, c * ey + sn * ly, lx, ly)
    rho_in = _crossing(px, py, c * ex - sn * lx, c * ey - sn * ly, lx, ly)
    move_out = (factor - 1.0) * arm           # l (K_C + psi') - l (1 + psi')
    move_in = (1.0 - 1.0 / factor) * arm      # l (1 + psi') - l (1/K_C + psi')
    pole_out, pole_in = rho_d + move_out, rho_d - move_in
    outside = np.stack([c * (pole_out - rho_out), c * (rho_in - pole_in)], axis=-1)
    reach = np.stack([np.hypot(px - pole_out * lx, py - pole_out * ly),
                      np.hypot(px - pole_in * lx, py - pole_in * ly)], axis=-1)
    gap_in = (rho_d - rho_in) / arm
    with np.errstate(divide="ignore", invalid="ignore"):
        k_in = np.where(gap_in < 1.0, 1.0 / np.where(gap_in < 1.0, 1.0 - gap_in, 1.0), np.inf)
    k_in = np.where(np.isnan(gap_in), np.nan, k_in)
    admits = np.stack([1.0 + (rho_out - rho_d) / arm, k_in], axis=-1)
    return outside, reach, admits
