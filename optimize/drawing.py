"""Data for the pictures of the allowable-centre zone (no plotting here).

The pictures in :mod:`cams.present.plots` take these objects and only draw them.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from cams.model.design import CamDesign
from optimize.planar import clip_polygon
from optimize.zone import phase_wedges, sample_wedges

__all__ = ["AnalogueCurve", "ZoneDrawing", "analogue_diagram", "zone_drawing"]


@dataclass(frozen=True)
class AnalogueCurve:
    """The analogue-velocity diagram of one rise or return phase.

    ``A`` (n, 2): roller centre positions; ``D`` (n, 2): the instant points
    (seed 001: the end of the vector psi' l laid along the rocker, or ds/dphi
    laid across a translating follower's axis); ``phi`` (n,) cam angles, rad.
    """

    phase: int
    kind: str
    phi: np.ndarray
    A: np.ndarray
    D: np.ndarray


@dataclass(frozen=True)
class ZoneDrawing:
    """What a zone picture shows.

    Attributes
    ----------
    box : (xmin, ymin, xmax, ymax)
        The view, fixed frame, length unit.
    polygon : ndarray (k, 2)
        The admissible zone (sampled, with K_C) clipped to the view.
    polygon_k1 : ndarray (k, 2) or None
        The zone without the safety factor, when K_C > 1.
    curves : list of AnalogueCurve
    lines : list of (phi, side, p0, p1, binding)
        Constraint lines drawn: segment ends p0, p1 inside the view.
    """

    box: tuple[float, float, float, float]
    polygon: np.ndarray
    polygon_k1: np.ndarray | None
    curves: list[AnalogueCurve]
    lines: list[tuple[float, int, np.ndarray, np.ndarray, bool]]


def analogue_diagram(design: CamDesign, n: int = 121) -> list[AnalogueCurve]:
    """Instant points D of every rise and return phase (safety factor not applied).

    Parameters
    ----------
    design : CamDesign
    n : int, optional
        Evenly spaced positions per phase, both ends included.

    Returns
    -------
    list of AnalogueCurve
        One per rise or return phase, in program order: roller centres ``A``
        and instant points ``D`` in the follower's fixed frame
        (:mod:`cams.model.follower`), length unit; ``phi`` cam angles, radians from
        the start of the cycle.
    """
    base = design
    if design.limits.safety_factor != 1:
        base = design.with_(limits=replace(design.limits, safety_factor=1.0))
    out = []
    u = np.linspace(0.0, 1.0, n)
    for i, p in enumerate(base.program.phases):
        if p.kind == "dwell":
            continue
        w = phase_wedges(base, i, base.limits.pressure_angle, u)
        m = base.program.evaluate_phase(i, u)
        out.append(AnalogueCurve(i, p.kind, w.phi, base.follower.position(m.s), w.apex[:, 0]))
    return out


def _segment_in_box(n, c, box):
    """The part of the line n.x = c inside the box, or None."""
    x0, y0, x1, y1 = box
    d = np.array([-n[1], n[0]])
    p = n * c
    ts = []
    for k, (lo, hi) in enumerate(((x0, x1), (y0, y1))):
        if abs(d[k]) > 1e-15:
            ts += [(lo - p[k]) / d[k], (hi - p[k]) / d[k]]
    pts = [p + t * d for t in ts]
    pts = [q for q in pts if x0 - 1e-9 <= q[0] <= x1 + 1e-9 and y0 - 1e-9 <= q[1] <= y1 + 1e-9]
    if len(pts) < 2:
        return None
    pts.sort(key=lambda q: q @ d)
    return pts[0], pts[-1]


def zone_drawing(
    design: CamDesign,
    centre: np.ndarray,
    *,
    binding: tuple[tuple[float, int], ...] = (),
    samples: int = 180,
    n_lines: int = 6,
    extra_points: tuple[np.ndarray, ...] = (),
    margin: float = 0.06,
) -> ZoneDrawing:
    """Everything a zone picture needs, for a solved centre.

    Parameters
    ----------
    design : CamDesign
    centre : ndarray (2,)
        The chosen cam centre, fixed frame, length unit.
    binding : tuple of (phi, side)
        Cam angles (rad) and sides (0 t-t, 1 t1-t1) of the binding lines: drawn and flagged.
    samples : int
        Steps per phase of the zone polygon.
    n_lines : int
        Evenly spaced positions per constrained phase whose lines are drawn.
    extra_points : tuple of ndarray
        Further points the view must hold (e.g. a trade-off curve's ends).
    margin : float
        The view's margin on each side, a fraction of the points' span that way (at least a quarter of
        the larger span, so that a flat drawing keeps some room).

    Returns
    -------
    ZoneDrawing
        In the follower's fixed frame (:mod:`cams.model.follower`), length unit: the
        view box holds ``centre``, the frame's origin (the rocker pivot, or
        A0 of a translating follower), the analogue curves and
        ``extra_points`` with ``margin``; ``lines`` holds,
        per constrained phase, the side nearer to binding at ``n_lines``
        positions and each ``binding`` line of the phase (flagged True).
    """
    curves = analogue_diagram(design)
    f = design.follower
    pts = [np.asarray(centre, float)[None], f.pivot[None], *[c.A for c in curves], *[c.D for c in curves],
           *[np.atleast_2d(p) for p in extra_points]]
    P = np.concatenate(pts)
    lo, hi = P.min(axis=0), P.max(axis=0)
    span = max(hi - lo) or design.scale
    pad = margin * np.maximum(hi - lo, 0.25 * span)
    box = (lo[0] - pad[0], lo[1] - pad[1], hi[0] + pad[0], hi[1] + pad[1])
    N, c = sample_wedges(design, samples).lines()
    poly = clip_polygon(N, c, box)
    poly_k1 = None
    if design.limits.safety_factor != 1.0:
        d1 = design.with_(limits=replace(design.limits, safety_factor=1.0))
        poly_k1 = clip_polygon(*sample_wedges(d1, samples).lines(), box)
    lines = []
    for i, lim in design.constrained_phases():
        u = np.linspace(0.0, 1.0, n_lines)
        start, ang = design.program.starts[i], design.program.phases[i].angle
        mine = [(phi, k) for phi, k in binding if start - 1e-12 <= phi <= start + ang + 1e-12]
        uu = np.concatenate([u, [(phi - start) / ang for phi, _ in mine]])
        w = phase_wedges(design, i, lim, uu)
        h = w.violation(np.asarray(centre, float))
        for j in range(len(uu)):
            if j < len(u):
                # the side nearer to binding at the chosen centre: the readable subset
                k = int(np.argmax(h[j]))
                is_b = False
            else:
                k = mine[j - len(u)][1]
                is_b = True
            seg = _segment_in_box(w.normals[j, k], w.offsets[j, k], box)
            if seg is not None:
                lines.append((float(w.phi[j]), k, seg[0], seg[1], is_b))
    return ZoneDrawing(box=box, polygon=poly, polygon_k1=poly_k1, curves=curves, lines=lines)
