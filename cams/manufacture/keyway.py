"""The bore with its keyway, the datum and the centre mark of the drawings: what times the cam on its shaft.

Geometry, cam frame of :mod:`cams.manufacture.drawing` (mm, radians inside):

* The **datum** is the unit direction from the cam centre to the roller centre at cam angle 0 (a flat face: the
  contact normal there), where the first ``[[motion]]`` row starts (:class:`cams.profile.exact.ExactCam`).
* The **keyway**'s centre line leaves the cam centre at the angle ``alpha = atan2(datum) + eps keyway_angle``:
  ``keyway_angle`` from the datum in the cam's sense of rotation ``eps`` (+1 counter-clockwise). The keyway is a
  slot of ``keyway_width`` about that line, its flat bottom at ``bore_radius + keyway_depth`` from the centre
  (the depth measured radially from the bore's surface, on the centre line); its sides meet the bore at
  ``sqrt(bore^2 - (width / 2)^2)``.
* The **hub wall at the keyway** is the least distance from the working profile to the slot (the rectangle
  from the bore to the keyway's bottom, ``width`` wide): the material the keyway leaves. It must be at least
  ``[cam] hub_wall`` (0 when not given: the slot must not reach the profile). It is computed on the exact
  working profile, sampled and refined where the minimum may lie, as a certified lower bound
  (:func:`_refined`, :func:`_lower`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.profile.exact import ExactCam
from laws.errors import InputError
from laws.search import bisect_boundary

__all__ = ["Keyway", "keyway_of", "bore_outline", "keyway_wall", "check_keyway_wall", "WALL_SAMPLES"]

#: Samples of each piece of the exact working profile in the keyway's wall, at first and at most.
WALL_SAMPLES, MAX_WALL_SAMPLES = 4096, 200_000


@dataclass(frozen=True)
class Keyway:
    """A keyway in the bore: ``width``, ``depth`` (mm, from the bore's surface) and ``alpha``, the direction of its
    centre line in the cam frame (radians, counter-clockwise from +X)."""

    width: float
    depth: float
    alpha: float

    @property
    def direction(self) -> np.ndarray:
        """Unit vector of the keyway's centre line, cam frame."""
        return np.array([np.cos(self.alpha), np.sin(self.alpha)])


def keyway_of(design, datum: np.ndarray) -> Keyway | None:
    """The design's keyway (``[cam] keyway_width``, ``keyway_depth``, ``keyway_angle``), placed from the datum in
    the cam's sense of rotation; None without one."""
    if design.keyway_width is None:
        return None
    angle = 0.0 if design.keyway_angle is None else float(design.keyway_angle)
    alpha = float(np.arctan2(datum[1], datum[0]) + design.cam_sense * angle)
    return Keyway(float(design.keyway_width), float(design.keyway_depth), alpha)


def bore_outline(bore: float, keyway: Keyway) -> tuple[np.ndarray, np.ndarray]:
    """The bore with its keyway as one closed outline: vertices (4, 2) and bulges (4,) of a closed LWPOLYLINE.

    From the bore's surface out along the keyway's right side (seen looking out along its centre line), across
    its bottom, back along its left side to the bore, then round the bore counter-clockwise, the long way, to the
    start: three lines (bulge 0) and one arc of sweep ``2 pi - 2 asin(width / (2 bore))`` (bulge its
    ``tan(sweep / 4)``).
    """
    e = keyway.direction
    p = np.array([-e[1], e[0]])
    h = keyway.width / 2.0
    x0 = np.sqrt(bore * bore - h * h)
    xb = bore + keyway.depth
    pts = np.array([x0 * e - h * p, xb * e - h * p, xb * e + h * p, x0 * e + h * p])
    sweep = 2.0 * np.pi - 2.0 * np.arcsin(h / bore)
    return pts, np.array([0.0, 0.0, 0.0, np.tan(sweep / 4.0)])


def _slot_distance(X: np.ndarray, bore: float, keyway: Keyway) -> np.ndarray:
    """Distance of points ``X`` (n, 2) to the keyway's slot (the rectangle from the centre line's foot at the
    bore out to its bottom, ``width`` wide), 0 inside."""
    e = keyway.direction
    a = X @ e  # along the centre line
    b = X @ np.array([-e[1], e[0]])  # across it
    h = keyway.width / 2.0
    x0 = np.sqrt(bore * bore - h * h)
    da = np.maximum(np.maximum(x0 - a, a - (bore + keyway.depth)), 0.0)
    db = np.maximum(np.abs(b) - h, 0.0)
    return np.hypot(da, db)


def _refined(exact: ExactCam, bore: float, keyway: Keyway) -> list[np.ndarray]:
    """Points of each piece of the exact working profile, in order along it: :data:`WALL_SAMPLES` steps, then
    every interval whose bound (:func:`_lower`) is below the least sampled distance to the slot cut in 16, until
    the bounds are within 1e-9 of the cam's size of that distance (or :data:`MAX_WALL_SAMPLES` are reached, or the
    slot reaches the profile)."""
    out = []
    for piece in exact.curves["PROFILE"].pieces:
        u = np.linspace(0.0, 1.0, WALL_SAMPLES + 1)
        pts = piece.evaluate(u)[0]
        scale = float(np.max(np.hypot(pts[:, 0], pts[:, 1])))
        for _ in range(12):
            d = _slot_distance(pts, bore, keyway)
            if np.min(d) <= 0:  # the slot reaches the profile: no wall, nothing to refine
                break
            low = _intervals(pts, d)
            open_ = np.nonzero(low < np.min(d) - 1e-9 * scale)[0]
            if len(open_) == 0 or len(u) + 15 * len(open_) > MAX_WALL_SAMPLES:
                break
            k = np.linspace(0.0, 1.0, 17)[1:-1]
            new = (u[open_, None] + (u[open_ + 1] - u[open_])[:, None] * k[None]).ravel()
            u = np.sort(np.concatenate([u, new]))
            pts = piece.evaluate(u)[0]
        out.append(pts)
    return out


def _intervals(pts: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Per interval between neighbouring samples, the least the distance can be: ``(d_a + d_b - L) / 2``."""
    return 0.5 * (d[:-1] + d[1:] - 1.01 * np.hypot(*np.diff(pts, axis=0).T))


def _lower(samples: list[np.ndarray], bore: float, keyway: Keyway) -> float:
    """The certified lower bound of the distance from the profile through ``samples`` to the slot (mm).

    The distance to a fixed set moves no faster than its point, so between two samples ``a``, ``b`` of the
    curve, an arc of length ``L``, it is at least ``(d_a + d_b - L) / 2``; ``L`` is taken as 1.01 times the chord
    (an arc exceeds its chord by ``(kappa L)^2 / 24`` of it, and the steps are far below the radius).
    """
    return float(min(np.min(_intervals(p, _slot_distance(p, bore, keyway))) for p in samples))


def keyway_wall(exact: ExactCam, bore: float, keyway: Keyway) -> float:
    """The hub wall the keyway leaves (mm): the least distance from the exact working profile to its slot, a
    certified lower bound (the module's notes)."""
    return _lower(_refined(exact, bore, keyway), bore, keyway)


def check_keyway_wall(exact: ExactCam, bore: float, keyway: Keyway, hub_wall: float | None) -> float:
    """The keyway's wall (:func:`keyway_wall`), or :class:`InputError` on ``cam.keyway_depth`` when it is less than
    ``hub_wall`` (mm; None: 0), with the deepest keyway that leaves it (found by bisection on the depth of the
    certified lower bound, so the depth named does leave the wall; the samples refined again at each pass's
    answer)."""
    need = 0.0 if hub_wall is None else float(hub_wall)
    samples = _refined(exact, bore, keyway)  # refined where this keyway's wall is least: a lower bound for any

    def wall(depth: float) -> float:
        return _lower(samples, bore, Keyway(keyway.width, depth, keyway.alpha))

    got = wall(keyway.depth)
    if got >= need:
        return got
    lo = 0.0
    if wall(lo) < need:
        corner = float(np.hypot(bore, keyway.width / 2.0))
        raise InputError(
            "cam.keyway_depth",
            f"even 0 mm deep a keyway {keyway.width:g} mm wide (its bottom corners "
            f"{corner:.4g} mm from the centre) leaves {wall(lo):.4g} mm to the working profile, less "
            f"than the hub wall {need:g} mm: choose another cam.keyway_angle or a narrower keyway",
        )
    for _ in range(3):  # each pass refined where the last one's deepest keyway leaves the least wall
        lo = bisect_boundary(lambda depth: wall(depth) >= need, lo, keyway.depth, max_steps=40)
        samples = _refined(exact, bore, Keyway(keyway.width, lo, keyway.alpha))
    raise InputError(
        "cam.keyway_depth",
        f"{keyway.depth:g} mm leaves {got:.4g} mm of material between the keyway "
        f"and the working profile, less than the hub wall {need:g} mm (cam.hub_wall); at most "
        f"{lo:.4g} mm deep",
    )
