"""Read an exported profile back: a drawing's working profile as the elements of :mod:`cams.kinematics.exported`.

The round trip design -> export -> read back -> motion: the curve a DXF's layer ``PROFILE`` (or an SVG's group
``PROFILE``) holds, turned into :class:`~cams.kinematics.exported.Line`, :class:`~cams.kinematics.exported.Arc` and
:class:`~cams.kinematics.exported.SplinePiece` elements in the cam frame, chained into one closed curve.

* DXF (read with ezdxf): ``LINE``, ``ARC``, ``CIRCLE``, ``LWPOLYLINE`` and 2D ``POLYLINE`` (straight or bulged
  segments: a bulge ``b`` is ``tan`` of a quarter of the arc's signed sweep, positive counter-clockwise) and
  ``SPLINE`` (its B-spline, rational or not, cut at its knots into polynomial pieces; a spline given by fit points
  only is ezdxf's interpolation of them). An arc drawn with its extrusion along -Z is mirrored into the XY plane.
* SVG: the ``<path>`` of the group ``id="PROFILE"``: commands ``M L H V A C Q Z`` (and their relative forms),
  circle arcs (``rx = ry``) and Bezier curves; SVG's y axis points down and is turned back up.

Lengths in the drawing's unit (mm), angles radians.
"""

from __future__ import annotations

import os
import re

import numpy as np

from cams.kinematics.exported import Arc, Element, Line, SplinePiece, check_closed
from laws.errors import InputError

__all__ = ["read_dxf_profile", "read_svg_profile", "read_profile", "spline_pieces", "bulge_arc", "chain"]


def bulge_arc(p0: np.ndarray, p1: np.ndarray, bulge: float) -> Element:
    """The element from ``p0`` to ``p1`` of a polyline vertex's bulge (``tan(sweep / 4)``, positive ccw)."""
    p0, p1 = np.asarray(p0, float), np.asarray(p1, float)
    if bulge == 0:
        return Line(tuple(p0), tuple(p1))
    sweep = 4.0 * np.arctan(bulge)
    chord = float(np.hypot(*(p1 - p0)))
    R = chord / (2.0 * abs(np.sin(sweep / 2)))
    mid = 0.5 * (p0 + p1)
    d = (p1 - p0) / chord
    left = np.array([-d[1], d[0]])
    # the centre lies left of the chord for a ccw sweep under pi, at the distance R cos(sweep / 2)
    c = mid + left * (R * np.cos(sweep / 2)) * np.sign(sweep)
    a0 = float(np.arctan2(p0[1] - c[1], p0[0] - c[0]))
    return Arc((float(c[0]), float(c[1])), float(R), a0, a0 + sweep, 1 if sweep > 0 else -1)


def spline_pieces(
    control: np.ndarray, knots: np.ndarray, degree: int, weights: np.ndarray | None = None
) -> list[SplinePiece]:
    """A B-spline cut at its knots into polynomial pieces (homogeneous coordinates, power basis on ``[0, 1]``).

    Parameters
    ----------
    control : ndarray, shape (n, 2)
        Control points.
    knots : ndarray, shape (n + degree + 1,)
    degree : int
    weights : ndarray, shape (n,), optional
        A rational spline's weights; None: all 1.
    """
    from scipy.interpolate import BSpline, PPoly

    control = np.asarray(control, float)[:, :2]
    w = np.ones(len(control)) if weights is None or len(weights) == 0 else np.asarray(weights, float)
    hom = np.column_stack([control * w[:, None], w])
    knots = np.asarray(knots, float)
    pieces = []
    cols = [PPoly.from_spline(BSpline(knots, hom[:, j], degree)) for j in range(3)]  # type: ignore[arg-type]
    x = cols[0].x
    lo, hi = knots[degree], knots[len(knots) - degree - 1]
    for j in range(len(x) - 1):
        a, b = x[j], x[j + 1]
        if b - a <= 0 or a < lo or b > hi:
            continue
        h = b - a
        powers = h ** np.arange(degree, -1, -1)
        coeffs = np.column_stack([cols[k].c[:, j] * powers for k in range(3)])
        pieces.append(SplinePiece(coeffs))
    return pieces


def _reverse(e: Element) -> Element:
    if isinstance(e, Line):
        return Line(e.end, e.start)
    if isinstance(e, Arc):
        return Arc(e.centre, e.radius, e.start + e.sense * e.span, e.start, -e.sense)
    flip = np.poly1d([-1.0, 1.0])
    cols = [np.poly1d(e.coeffs[:, j])(flip).coeffs for j in range(3)]
    deg = len(e.coeffs) - 1
    return SplinePiece(np.column_stack([np.concatenate([np.zeros(deg + 1 - len(c)), c]) for c in cols]))


def chain(elements: list[Element], field: str) -> list[Element]:
    """The elements put in order into one closed chain (each reversed where needed), or :class:`InputError`."""
    if not elements:
        raise InputError(field, "holds no curve on its PROFILE: the working profile as lines, arcs or splines")
    ends = [e.ends for e in elements]
    size = max(float(np.max(np.abs(np.concatenate(x)))) for x in ends)
    tol = 1e-7 * max(size, 1.0)
    left = list(range(1, len(elements)))
    out = [elements[0]]
    cur = ends[0][1]
    start = ends[0][0]
    while left:
        for k, j in enumerate(left):
            a, b = ends[j]
            if np.hypot(*(a - cur)) <= tol:
                out.append(elements[j])
                cur = b
            elif np.hypot(*(b - cur)) <= tol:
                out.append(_reverse(elements[j]))
                cur = a
            else:
                continue
            del left[k]
            break
        else:
            if np.hypot(*(cur - start)) <= tol:
                raise InputError(
                    field,
                    f"its PROFILE holds more than one closed curve ({len(left)} elements left "
                    "over): the working profile is one closed curve",
                )
            raise InputError(
                field, f"its PROFILE is not a closed curve: nothing starts at ({cur[0]:.6g}, {cur[1]:.6g}) mm"
            )
    check_closed(out, field)
    return out


def _dxf_entities(entity, field: str) -> list[Element]:
    kind = entity.dxftype()
    if kind == "LINE":
        s, e = entity.dxf.start, entity.dxf.end
        return [Line((s.x, s.y), (e.x, e.y))]
    if kind in ("ARC", "CIRCLE"):
        c = entity.dxf.center
        mirror = entity.dxf.extrusion.z < 0
        cx = -c.x if mirror else c.x
        if kind == "CIRCLE":
            return [Arc((cx, c.y), float(entity.dxf.radius), 0.0, 2 * np.pi, 1)]
        a0, a1 = np.radians(entity.dxf.start_angle), np.radians(entity.dxf.end_angle)
        if mirror:  # the OCS's x is -X: angles mirrored, the arc turns clockwise in the XY plane
            return [Arc((cx, c.y), float(entity.dxf.radius), np.pi - a0, np.pi - a1, -1)]
        return [Arc((cx, c.y), float(entity.dxf.radius), a0, a1, 1)]
    if kind in ("LWPOLYLINE", "POLYLINE"):
        if kind == "LWPOLYLINE":
            pts = [(p[0], p[1], p[4]) for p in entity.get_points("xyseb")]
            closed = entity.closed
            mirror = entity.dxf.extrusion.z < 0
        else:
            if entity.is_3d_polyline or entity.is_poly_face_mesh or entity.is_polygon_mesh:
                raise InputError(field, "its PROFILE holds a 3D polyline or mesh: the profile is a 2D curve")
            pts = [(v.dxf.location.x, v.dxf.location.y, v.dxf.bulge) for v in entity.vertices]
            closed = entity.is_closed
            mirror = entity.dxf.extrusion.z < 0
        xy = np.array([(-x if mirror else x, y) for x, y, _ in pts])
        bulges = [(-b if mirror else b) for _, _, b in pts]
        n = len(xy) if closed else len(xy) - 1
        out = []
        for i in range(n):
            p0, p1 = xy[i], xy[(i + 1) % len(xy)]
            if np.array_equal(p0, p1):
                continue
            out.append(bulge_arc(p0, p1, float(bulges[i])))
        return out
    if kind == "SPLINE":
        bs = entity.construction_tool()
        ctrl = np.array([(p.x, p.y) for p in bs.control_points])
        w = np.asarray(bs.weights(), float) if bs.is_rational else None
        return list(spline_pieces(ctrl, np.asarray(bs.knots(), float), bs.degree, w))
    raise InputError(field, f"its PROFILE holds a {kind}: read are LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE and SPLINE")


def read_dxf_profile(path: str | os.PathLike, field: str = "FILE") -> list[Element]:
    """The closed curve on a DXF's layer ``PROFILE``, as elements in order (cam frame, the drawing's unit).

    Raises
    ------
    InputError
        Naming ``field``: not a readable DXF, no layer ``PROFILE`` or nothing on it, an entity of another kind,
        a curve that is not one closed chain.
    """
    import ezdxf

    try:
        doc = ezdxf.readfile(os.fspath(path))
    except (OSError, ezdxf.DXFStructureError) as exc:
        raise InputError(field, f"cannot be read as a DXF: {exc}") from None
    if "PROFILE" not in doc.layers:
        raise InputError(field, "has no layer PROFILE: the working profile is read from that layer")
    elements: list[Element] = []
    for e in doc.modelspace().query('*[layer=="PROFILE"]'):
        elements.extend(_dxf_entities(e, field))
    return chain(elements, field)


_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def _svg_arc(p0: np.ndarray, p1: np.ndarray, rx: float, ry: float, large: bool, sweep: bool, field: str) -> Element:
    """An SVG arc command (SVG's own y-down coordinates) as a cam-frame element (y turned up)."""
    if abs(rx - ry) > 1e-9 * max(rx, ry):
        raise InputError(field, "its PROFILE holds an elliptic arc: only circle arcs (rx = ry) are read")
    q0, q1 = p0 * [1, -1], p1 * [1, -1]  # the cam frame: a sweep-flag 1 (y-down positive) turns clockwise here
    R = float(rx)
    d = 0.5 * float(np.hypot(*(q1 - q0)))
    if d == 0:
        return Line(tuple(q0), tuple(q1))
    R = max(R, d)
    h = np.sqrt(max(R * R - d * d, 0.0))
    u = (q1 - q0) / (2 * d)
    left = np.array([-u[1], u[0]])
    sense = -1 if sweep else 1
    # going ccw (sense +1) the short way round, the centre lies left of the chord; the long way, right
    side = sense * (-1 if large else 1)
    c = 0.5 * (q0 + q1) + side * h * left
    a0 = float(np.arctan2(q0[1] - c[1], q0[0] - c[0]))
    a1 = float(np.arctan2(q1[1] - c[1], q1[0] - c[0]))
    return Arc((float(c[0]), float(c[1])), R, a0, a1, sense)


def _bezier(points: list[np.ndarray]) -> SplinePiece:
    """A Bezier curve (control points, cam frame) as a polynomial piece."""
    from math import comb

    n = len(points) - 1
    coeffs = np.zeros((n + 1, 3))
    for i, p in enumerate(points):  # Bernstein polynomial C(n, i) t^i (1 - t)^(n - i), expanded
        for k in range(n - i + 1):
            c = comb(n, i) * comb(n - i, k) * (-1) ** k
            coeffs[n - (i + k), :2] += c * p
    coeffs[n, 2] = 1.0
    return SplinePiece(coeffs)


def read_svg_profile(path: str | os.PathLike, field: str = "FILE") -> list[Element]:
    """The closed curve of an SVG's group ``id="PROFILE"`` (its ``<path>`` elements), in the cam frame (y up)."""
    import xml.etree.ElementTree as ET

    try:
        root = ET.parse(os.fspath(path)).getroot()
    except (OSError, ET.ParseError) as exc:
        raise InputError(field, f"cannot be read as an SVG: {exc}") from None
    group = next((g for g in root.iter() if g.get("id") == "PROFILE"), None)
    if group is None:
        raise InputError(field, 'has no group PROFILE: the working profile is read from the group id="PROFILE"')
    elements: list[Element] = []
    for node in group.iter():
        if node.tag.rsplit("}", 1)[-1] == "path":
            elements.extend(_svg_path(node.get("d", ""), field))
    return chain(elements, field)


def _svg_path(d: str, field: str) -> list[Element]:
    tokens = re.findall(rf"[MmLlHhVvAaCcQqZz]|{_NUMBER}", d)
    out: list[Element] = []
    cur = start = np.zeros(2)
    cmd = ""
    i = 0

    def take(k: int) -> list[float]:
        nonlocal i
        vals = tokens[i : i + k]
        if len(vals) < k or any(v.isalpha() for v in vals):
            raise InputError(field, f"its PROFILE path is malformed near {' '.join(tokens[i - 1 : i + k])!r}")
        i += k
        return [float(v) for v in vals]

    def pt(xy: list[float], rel: bool) -> np.ndarray:
        return cur + np.array(xy) if rel else np.array(xy)

    while i < len(tokens):
        if tokens[i].isalpha():
            cmd = tokens[i]
            i += 1
        elif not cmd:
            raise InputError(field, f"its PROFILE path has a number {tokens[i]!r} where a command is expected")
        rel = cmd.islower()
        c = cmd.upper()
        if c == "Z":
            if not np.array_equal(cur, start):
                out.append(Line(tuple(cur * [1, -1]), tuple(start * [1, -1])))
            cur = start
            cmd = ""
            continue
        if c == "M":
            cur = start = pt(take(2), rel)
            cmd = "l" if rel else "L"
            continue
        if c in "LHV":
            if c == "L":
                nxt = pt(take(2), rel)
            elif c == "H":
                (x,) = take(1)
                nxt = np.array([cur[0] + x if rel else x, cur[1]])
            else:
                (y,) = take(1)
                nxt = np.array([cur[0], cur[1] + y if rel else y])
            if not np.array_equal(cur, nxt):
                out.append(Line(tuple(cur * [1, -1]), tuple(nxt * [1, -1])))
        elif c == "A":
            rx, ry, _, large, sweep, x, y = take(7)
            nxt = pt([x, y], rel)
            out.append(_svg_arc(cur, nxt, rx, ry, bool(large), bool(sweep), field))
        elif c in "CQ":
            k = 3 if c == "C" else 2
            ctrl = [cur] + [pt(take(2), rel) for _ in range(k)]
            nxt = ctrl[-1]
            out.append(_bezier([p * [1, -1] for p in ctrl]))
        else:
            raise InputError(field, f"its PROFILE path has the command {cmd!r}: read are M L H V A C Q Z")
        cur = nxt
    return out


def read_profile(path: str | os.PathLike, field: str = "FILE") -> list[Element]:
    """:func:`read_dxf_profile` or :func:`read_svg_profile` by the file's suffix (``.svg``: SVG, else DXF)."""
    if os.fspath(path).lower().endswith(".svg"):
        return read_svg_profile(path, field)
    return read_dxf_profile(path, field)
