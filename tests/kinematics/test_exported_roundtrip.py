"""Round trips design -> export -> read back -> motion (cams.manufacture.readback, cams.kinematics.exported).

* Today's exporters (a polyline): the DXF's and the SVG's curve read back is the profile's points; the motion it
  gives is within the chord tolerance's reach of the design's (a chord of a convex curve lies inside it by at most
  the tolerance, a concave one outside, so the roller sits at most ``tol / cos(pressure angle)`` off along its axis).
* Drawings built here with ezdxf and by hand (ARC, CIRCLE, bulged LWPOLYLINE, an exact rational SPLINE circle, SVG
  arcs and Beziers): the eccentric circle's closed form ``e cos x + sqrt((Rc + r)^2 - e^2 sin^2 x)``.
* Bad drawings: one line naming the file and what is wrong.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.kinematics.exported import Arc, Line, SplinePiece, export_motion, roller_contact
from cams.manufacture.readback import bulge_arc, read_dxf_profile, read_profile, read_svg_profile
from cams.model.design import CamDesign, Limits
from cams.model.follower import Translating
from laws.errors import InputError
from laws.program import Phase, Program
from laws.registry import get_law
from tests.conftest import EXAMPLES

RC, E, R = 30.0, 5.0, 8.0


def _design() -> tuple[CamDesign, np.ndarray, float]:
    prog = Program(
        (
            Phase("rise", np.radians(120), get_law("cycloidal")),
            Phase("return", np.radians(120), get_law("cycloidal")),
            Phase("dwell", np.radians(120)),
        ),
        2 * E,
    )
    d0 = RC + R - E
    return CamDesign(Translating(R, offset=0.0), prog, Limits(np.radians(30)), cam_sense=1), np.array([0.0, -d0]), d0


def _closed_form(phi: np.ndarray, cx: float, cy: float) -> np.ndarray:
    """The roller centre's distance from the cam centre (law of cosines), the circle's centre at (cx, cy)."""
    e, ang = np.hypot(cx, cy), np.arctan2(cy, cx)
    x = np.pi / 2 - phi - ang
    return e * np.cos(x) + np.sqrt((RC + R) ** 2 - e**2 * np.sin(x) ** 2)


PHI = np.linspace(0.0, 2 * np.pi, 181)
CX, CY = 1.5, -E


def _check_circle(elements):
    d, centre, d0 = _design()
    c = roller_contact(d, centre, elements, PHI)
    assert np.max(np.abs(c.s + d0 - _closed_form(PHI, CX, CY))) < 1e-9


def _new_dxf():
    import ezdxf

    doc = ezdxf.new("R2010")
    doc.layers.add("PROFILE")
    return doc, doc.modelspace()


def test_dxf_arcs_circle_bulges_and_exact_spline(tmp_path):
    at = {"layer": "PROFILE"}
    # two ARCs (counter-clockwise, as DXF draws them), one listed before the other the wrong way round
    doc, msp = _new_dxf()
    msp.add_arc((CX, CY), RC, 200.0, 20.0, dxfattribs=at)
    msp.add_arc((CX, CY), RC, 20.0, 200.0, dxfattribs=at)
    doc.saveas(tmp_path / "arcs.dxf")
    els = read_dxf_profile(tmp_path / "arcs.dxf")
    assert [type(e) for e in els] == [Arc, Arc]
    _check_circle(els)
    # the same two arcs drawn with the extrusion along -Z (the OCS's x is -X: the centre given at x = -CX)
    doc, msp = _new_dxf()
    mirrored = {**at, "extrusion": (0.0, 0.0, -1.0)}
    msp.add_arc((-CX, CY), RC, 20.0, 200.0, dxfattribs=mirrored)
    msp.add_arc((-CX, CY), RC, 200.0, 20.0, dxfattribs=mirrored)
    doc.saveas(tmp_path / "mirrored.dxf")
    els = read_dxf_profile(tmp_path / "mirrored.dxf")
    assert [e.sense for e in els] == [-1, -1]
    _check_circle(els)
    # one CIRCLE
    doc, msp = _new_dxf()
    msp.add_circle((CX, CY), RC, dxfattribs=at)
    doc.saveas(tmp_path / "circle.dxf")
    _check_circle(read_dxf_profile(tmp_path / "circle.dxf"))
    # an LWPOLYLINE of two half circles: bulge 1 (tan of a quarter of 180 degrees), and -1 drawn clockwise
    for b in (1.0, -1.0):
        doc, msp = _new_dxf()
        msp.add_lwpolyline([(CX + RC, CY, 0, 0, b), (CX - RC, CY, 0, 0, b)], format="xyseb", close=True, dxfattribs=at)
        doc.saveas(tmp_path / "bulge.dxf")
        _check_circle(read_dxf_profile(tmp_path / "bulge.dxf"))
    # the exact rational quadratic B-spline of a circle (nine control points, weights 1 and sqrt(2)/2)
    doc, msp = _new_dxf()
    sq = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)]
    ctrl = [(CX + RC * x, CY + RC * y, 0.0) for x, y in sq]
    w = [1.0, np.sqrt(0.5)] * 4 + [1.0]
    knots = [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1]
    msp.add_rational_spline(ctrl, w, degree=2, knots=knots, dxfattribs=at)
    doc.saveas(tmp_path / "spline.dxf")
    els = read_dxf_profile(tmp_path / "spline.dxf")
    assert len(els) == 4 and all(isinstance(e, SplinePiece) for e in els)
    _check_circle(els)
    # its derivatives too: the closed form's by central differences
    d, centre, d0 = _design()
    c = roller_contact(d, centre, els, PHI)
    h = 1e-4
    f = [_closed_form(PHI + k * h, CX, CY) for k in (-1, 0, 1)]
    assert np.max(np.abs(c.ds - (f[2] - f[0]) / (2 * h))) < 1e-6
    assert np.max(np.abs(c.d2s - (f[2] - 2 * f[1] + f[0]) / h**2)) < 1e-3


def test_bulge_arc_geometry():
    """A bulge's arc: the chord's ends on it, its sweep 4 atan(b), its sagitta b chord / 2 (by definition)."""
    p0, p1 = np.array([1.0, 2.0]), np.array([4.0, 6.0])
    for b in (0.3, -0.3, 2.0, -2.0):
        a = bulge_arc(p0, p1, b)
        s, e = a.ends
        assert np.allclose(s, p0) and np.allclose(e, p1)
        assert a.span == pytest.approx(4 * np.arctan(abs(b)))
        mid = a.point(a.start + a.sense * a.span / 2)
        # the arc's middle lies b * chord / 2 off the chord's midpoint, to the right for b > 0 (travelling p0 -> p1)
        chord = p1 - p0
        right = np.array([chord[1], -chord[0]]) / np.hypot(*chord)
        assert np.dot(mid - (p0 + p1) / 2, right) == pytest.approx(b * np.hypot(*chord) / 2)
    assert isinstance(bulge_arc(p0, p1, 0.0), Line)


def _svg(tmp_path, d: str, name="p.svg"):
    p = tmp_path / name
    p.write_text(f'<svg xmlns="http://www.w3.org/2000/svg"><g id="PROFILE"><path d="{d}"/></g></svg>')
    return p


def test_svg_arcs_and_beziers(tmp_path):
    # SVG's y points down: the circle's centre at (CX, -CY); two half arcs, sweep flag 1 and 0, absolute/relative
    x0, x1, y = CX + RC, CX - RC, -CY
    for sweep in (0, 1):
        p = _svg(tmp_path, f"M{x0},{y} A{RC},{RC} 0 0 {sweep} {x1},{y} a{RC} {RC} 0 1 {sweep} {2 * RC} 0 Z")
        els = read_svg_profile(p)
        assert len(els) == 2 and all(isinstance(e, Arc) for e in els)
        _check_circle(els)
    # a large arc flag: three quarters (clockwise on the screen: right, bottom, left, top) then a quarter
    p = _svg(tmp_path, f"M{x0},{y} A{RC},{RC} 0 1 1 {CX},{y - RC} A{RC},{RC} 0 0 1 {x0},{y}Z")
    _check_circle(read_svg_profile(p))
    # cubic Beziers: a closed curve of four, followed like the same pieces given directly
    k = 0.5523 * RC
    d = (
        f"M{x0},{y} C{x0},{y - k} {CX + k},{y - RC} {CX},{y - RC} C{CX - k},{y - RC} {x1},{y - k} {x1},{y} "
        f"C{x1},{y + k} {CX - k},{y + RC} {CX},{y + RC} C{CX + k},{y + RC} {x0},{y + k} {x0},{y} Z"
    )
    els = read_svg_profile(_svg(tmp_path, d))
    assert len(els) == 4 and all(isinstance(e, SplinePiece) for e in els)
    # the Bezier's points on the circle's quarter marks, its midpoint at the classic 0.5523 radius
    b = els[0].derivatives(0.5)[0]
    assert np.hypot(b[0] - CX, b[1] - CY) == pytest.approx(RC * np.sqrt(0.5) * (1 + 0.75 * 0.5523))


@pytest.fixture(scope="module")
def translating_cam():
    from cams.cam import Cam

    cam = Cam.from_file(EXAMPLES / "translating_force.toml")
    return cam, cam.profile


def test_todays_polyline_round_trip(translating_cam, tmp_path):
    from cams.kinematics.inversion import invert_at, pressure_angle
    from cams.manufacture.dxf import write_dxf
    from cams.manufacture.svg import write_svg

    cam, prof = translating_cam
    write_dxf(prof, tmp_path / "p.dxf")
    write_svg(prof, tmp_path / "p.svg")
    dxf, svg = read_profile(tmp_path / "p.dxf"), read_profile(tmp_path / "p.svg")
    assert len(dxf) == len(svg) == len(prof.work)
    pts = np.array([e.start for e in dxf])
    assert np.array_equal(pts, prof.work)  # the DXF keeps the doubles
    assert np.max(np.abs(np.array([e.start for e in svg]) - prof.work)) < 1e-9 * np.max(np.abs(prof.work))
    em = export_motion(cam.design, dxf, centre=cam.solution.centre)
    # within the tolerance of the curve (inside it where convex, outside where concave), the roller sits at most
    # tol / cos(gamma) off along its axis
    gamma = np.max(pressure_angle(invert_at(cam.design, cam.solution.centre, em.contact.phi)))
    assert em.max_ds <= 1.001 * prof.tolerance / np.cos(gamma)
    # the polyline's acceleration: the roller rounds each vertex, far from the law's (the measure)
    assert em.da_ratio > 1.0
    em_svg = export_motion(cam.design, svg, centre=cam.solution.centre)
    assert em_svg.max_ds == pytest.approx(em.max_ds, abs=1e-8)


def test_bad_drawings(tmp_path):
    import ezdxf

    doc = ezdxf.new("R2010")
    doc.modelspace().add_circle((0, 0), 10.0)
    doc.saveas(tmp_path / "nolayer.dxf")
    with pytest.raises(InputError, match="no layer PROFILE"):
        read_dxf_profile(tmp_path / "nolayer.dxf", "--dxf")
    doc, msp = _new_dxf()
    msp.add_lwpolyline([(0, 0), (10, 0), (10, 10)], close=False, dxfattribs={"layer": "PROFILE"})
    doc.saveas(tmp_path / "open.dxf")
    with pytest.raises(InputError, match="not a closed curve"):
        read_dxf_profile(tmp_path / "open.dxf")
    doc, msp = _new_dxf()
    msp.add_circle((0, 0), 10.0, dxfattribs={"layer": "PROFILE"})
    msp.add_circle((0, 0), 20.0, dxfattribs={"layer": "PROFILE"})
    doc.saveas(tmp_path / "two.dxf")
    with pytest.raises(InputError, match="more than one closed curve"):
        read_dxf_profile(tmp_path / "two.dxf")
    doc, msp = _new_dxf()
    msp.add_ellipse((0, 0), (10, 0), 0.5, dxfattribs={"layer": "PROFILE"})
    doc.saveas(tmp_path / "ellipse.dxf")
    with pytest.raises(InputError, match="ELLIPSE"):
        read_dxf_profile(tmp_path / "ellipse.dxf")
    doc, _ = _new_dxf()
    doc.saveas(tmp_path / "empty.dxf")
    with pytest.raises(InputError, match="holds no curve"):
        read_dxf_profile(tmp_path / "empty.dxf")
    (tmp_path / "junk.dxf").write_text("not a drawing\n")
    with pytest.raises(InputError, match="cannot be read as a DXF"):
        read_dxf_profile(tmp_path / "junk.dxf")
    (tmp_path / "g.svg").write_text('<svg xmlns="http://www.w3.org/2000/svg"><g id="PITCH"/></svg>')
    with pytest.raises(InputError, match="no group PROFILE"):
        read_svg_profile(tmp_path / "g.svg")
    with pytest.raises(InputError, match="not a closed curve"):
        read_svg_profile(_svg(tmp_path, "M0,0 L10,0 L10,10"))
    with pytest.raises(InputError, match="elliptic arc"):
        read_svg_profile(_svg(tmp_path, "M0,0 A10,5 0 0 1 10,0 Z"))


def _arc_from(p: np.ndarray, t: np.ndarray, q: np.ndarray):
    """The circle arc from p, tangent to the unit vector t there, to q (a Line when straight): its centre on the
    normal at p, equidistant from p and q."""
    n = np.array([-t[1], t[0]])
    w = q - p
    h = n @ w
    if abs(h) < 1e-12 * (w @ w):
        return Line(tuple(p), tuple(q))
    rho = (w @ w) / (2 * h)
    c = p + rho * n
    return Arc(
        tuple(c), abs(rho), float(np.arctan2(*(p - c)[::-1])), float(np.arctan2(*(q - c)[::-1])), 1 if rho > 0 else -1
    )


def _biarcs(P: np.ndarray, T: np.ndarray) -> list:
    """The test's own biarc fit through the closed points P with unit tangents T: two arcs a span, tangent at both
    ends and at their joint, the two tangent lengths equal."""
    els = []
    for i in range(len(P)):
        p0, p1, t0, t1 = P[i], P[(i + 1) % len(P)], T[i], T[(i + 1) % len(P)]
        v, ts, den = p1 - p0, t0 + t1, 2 * (1 - t0 @ t1)
        d = (v @ v) / (4 * (v @ t1)) if den < 1e-12 else (-(v @ ts) + np.sqrt((v @ ts) ** 2 + den * (v @ v))) / den
        m = 0.5 * ((p0 + d * t0) + (p1 - d * t1))
        back = _arc_from(p1, -t1, m)  # the second arc built from its far end, then turned round
        second = (
            Line(tuple(m), tuple(p1))
            if isinstance(back, Line)
            else Arc(back.centre, back.radius, back.end, back.start, -back.sense)
        )
        els += [_arc_from(p0, t0, m), second]
    return els


def test_biarc_export_keeps_the_motion(translating_cam, tmp_path):
    """A biarc of the working profile's points (tangents from the profile's normals), drawn as DXF ARCs and read
    back: the same motion as the arcs themselves, its acceleration error a few percent of the law's peak where the
    polyline through the same points is several times it."""
    cam, prof = translating_cam
    W, N = prof.work, prof.normal
    T = np.column_stack([-N[:, 1], N[:, 0]])
    T *= np.sign(np.sum(T * (np.roll(W, -1, axis=0) - W), axis=1))[:, None]
    arcs = _biarcs(W, T)
    doc, msp = _new_dxf()
    for a in arcs:
        if isinstance(a, Line):
            msp.add_line(a.start, a.end, dxfattribs={"layer": "PROFILE"})
        else:  # DXF arcs turn counter-clockwise: a clockwise one is drawn from its end
            a0, a1 = (a.start, a.end) if a.sense > 0 else (a.end, a.start)
            msp.add_arc(a.centre, a.radius, np.degrees(a0), np.degrees(a1), dxfattribs={"layer": "PROFILE"})
    doc.saveas(tmp_path / "biarc.dxf")
    read = read_dxf_profile(tmp_path / "biarc.dxf")
    assert len(read) == len(arcs)
    centre = cam.solution.centre
    em, em_read = export_motion(cam.design, arcs, centre=centre), export_motion(cam.design, read, centre=centre)
    assert em_read.max_ds == pytest.approx(em.max_ds, abs=1e-10)
    assert em_read.max_da == pytest.approx(em.max_da, rel=1e-6)
    lines = [Line(tuple(W[i]), tuple(W[(i + 1) % len(W)])) for i in range(len(W))]
    poly = export_motion(cam.design, lines, centre=centre)
    assert em.da_ratio < 0.05 < 1.0 < poly.da_ratio
    assert em.max_ds < 0.1 * poly.max_ds
