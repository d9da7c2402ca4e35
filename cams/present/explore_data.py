"""What the explorer page (``cams explore``) embeds: the laws sampled with their interpolation bounds, the zone.

The page computes in the browser; these functions gather, from the cam's own pipeline, what it computes from.
Each ``[[motion]]`` phase is embedded as its displacement ``s``, ``ds/dphi`` and ``d2s/dphi2`` at ``n + 1`` evenly
spaced positions (the program's own evaluation, :meth:`laws.program.Program.evaluate_phase`); the page interpolates
``s``, ``ds/dphi`` and ``d2s/dphi2`` linearly between them, and the bounds of that interpolation are embedded with
them:

* ``s``: the error of a linear interpolant of a function with ``|s''| <= M2`` on a step ``h`` (radians of cam
  angle) is at most ``h**2 / 8 * M2``;
* ``ds/dphi``: at most ``h**2 / 8 * M3`` with ``|s'''| <= M3`` where the acceleration is continuous; a step ``J``
  of the acceleration inside a phase (a law with a jump of ``s''``, the constant acceleration's) adds at most
  ``h / 4 * J`` (the linear interpolant of a function whose slope varies by ``J`` errs by at most ``h J / 4``);
* ``d2s/dphi2`` (a flat face's radius of curvature): the interpolant's error measured on the dense grid, plus half a
  dense step times the largest slope the error can have between its points (``M3`` plus the interpolant's own
  slope), plus ``J``.

``M2``, ``M3`` and ``J`` are read off the law's own ``d2s`` and ``d3s`` on a grid :data:`DENSE` times finer (each
raised by :data:`RAISE` for the peaks between those samples). Lengths in the design's unit, angles in radians.
"""

from __future__ import annotations

import numpy as np

__all__ = ["SAMPLES", "DENSE", "RAISE", "phase_samples", "roller_zone"]

#: Steps per rise or return phase embedded in the page.
SAMPLES = 2048
#: The bounds' grid: this many times finer than the embedded one.
DENSE = 64
#: The bounds read off the dense grid are raised by this factor (peaks between its samples).
RAISE = 1.05


def _r(a) -> list[float]:
    """A float array as a JSON list (full precision: the page's numbers are compared with ``cams check``)."""
    return [float(x) for x in np.asarray(a, float).ravel()]


def phase_samples(design, n: int = SAMPLES) -> list[dict]:
    """Every phase of ``design``'s program as the page embeds it.

    Returns
    -------
    list of dict
        One per ``[[motion]]`` phase, in order: ``index`` (from 0), ``kind`` (``"rise"``, ``"return"``,
        ``"dwell"``), ``start`` and ``angle`` (rad), ``level`` (the displacement at its start: rad for a rocker,
        length for a translating follower). A rise or return has ``n`` (steps), ``s``, ``ds``, ``d2s`` (``n + 1``
        values each: displacement, per rad, per rad squared), the bounds of their linear interpolation ``err_s``,
        ``err_ds`` and ``err_d2s`` (the displacement's unit, per rad, per rad squared), and ``M2``, ``M3`` and
        ``jump`` (the largest ``|s''|``, ``|s'''|`` and step of ``s''`` inside the phase) they are made of.
    """
    prog = design.program
    out = []
    for i, p in enumerate(prog.phases):
        entry: dict = {
            "index": i,
            "kind": p.kind,
            "start": float(prog.starts[i]),
            "angle": float(p.angle),
            "level": float(prog.levels[i]),
        }
        if p.kind != "dwell":
            m = prog.evaluate_phase(i, np.linspace(0.0, 1.0, n + 1))
            fine = prog.evaluate_phase(i, np.linspace(0.0, 1.0, n * DENSE + 1))
            h, hd = p.angle / n, p.angle / (n * DENSE)
            M2 = RAISE * float(np.max(np.abs(fine.d2s)))
            M3 = RAISE * float(np.max(np.abs(fine.d3s)))
            # a step of s'' the jerk does not explain: an acceleration jump inside the phase
            step = np.abs(np.diff(fine.d2s)) - M3 * hd
            jump = float(np.max(step)) if np.max(step) > 1e-9 * max(M2, 1e-300) else 0.0
            # s'': the interpolant's error measured on the dense grid, and between its points at most half a dense
            # step times the error's slope (|s'''| plus the interpolant's own), plus a step of s'' inside
            ud = np.linspace(0.0, 1.0, n * DENSE + 1)
            measured = float(np.max(np.abs(fine.d2s - np.interp(ud, np.linspace(0.0, 1.0, n + 1), m.d2s))))
            slope = float(np.max(np.abs(np.diff(m.d2s)))) / h
            entry.update(
                n=n,
                s=_r(m.s),
                ds=_r(m.ds),
                d2s=_r(m.d2s),
                M2=M2,
                M3=M3,
                jump=jump,
                err_s=h * h / 8.0 * M2,
                err_ds=h * h / 8.0 * M3 + h / 4.0 * jump,
                err_d2s=measured + hd / 2.0 * (M3 + slope) + jump,
            )
        out.append(entry)
    return out


def roller_zone(design, centre, binding, *, extra=()) -> dict:
    """The zone picture's data of a roller ``design`` (:func:`optimize.drawing.zone_drawing`), JSON-ready.

    ``centre``: the sized cam's centre (fixed frame, length) or None; ``binding``: the solver's binding lines
    (:class:`optimize.result.Binding`); ``extra``: further points the view holds. The view is widened by half its
    span each way so that the point can be dragged out of the zone.
    """
    from optimize.drawing import zone_drawing

    f = design.follower
    c = np.asarray(f.position(0.0) if centre is None else centre, float)
    pts = tuple(np.atleast_2d(np.asarray(e, float)) for e in extra)
    x0, y0, x1, y1 = zone_drawing(design, c, samples=8, n_lines=2, extra_points=pts, margin=0.5).box
    # a square view (the page's picture is square): the zone and its lines are cut at its edges, not inside it
    half = max(x1 - x0, y1 - y0) / 2
    mid = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    corners = np.array([mid - half, mid + half])
    zd = zone_drawing(
        design,
        c,
        binding=tuple((b.phi, b.side) for b in binding),
        samples=360,
        n_lines=8,
        extra_points=(*pts, corners),
        margin=0.0,
    )
    return {
        "box": [float(v) for v in zd.box],
        "polygon": [_r(p) for p in zd.polygon] if len(zd.polygon) else [],
        "polygon_k1": None if zd.polygon_k1 is None else [_r(p) for p in zd.polygon_k1],
        "lines": [
            {"phi": float(phi), "line": "t-t" if side == 0 else "t1-t1", "p0": _r(p0), "p1": _r(p1), "binding": bool(b)}
            for phi, side, p0, p1, b in zd.lines
        ],
        "curves": [
            {"phase": c.phase, "kind": c.kind, "A": [_r(a) for a in c.A], "D": [_r(d) for d in c.D]} for c in zd.curves
        ],
        "binding": [
            {"phi": float(b.phi), "phase": int(b.phase), "line": "t-t" if b.side == 0 else "t1-t1"} for b in binding
        ],
    }
