"""The motion an exported curve gives (cams.kinematics.exported), against closed forms and brute force.

* An eccentric circle cam (radius Rc, centre e from the cam's) drives a translating roller follower whose axis
  passes through the cam centre: the roller centre's distance from the cam centre is
  ``e cos x + sqrt((Rc + r)^2 - e^2 sin^2 x)`` (x the angle from the circle's centre to the follower's axis, seen
  from the cam) -- derived by the law of cosines in the triangle cam centre, circle centre, roller centre. A rocker
  against the same circle: the roller centre on the arm's circle at ``Rc + r`` from the circle's centre (law of
  cosines at the pivot). A flat face: the support ``C . m + Rc``.
* A vertex is the circle of radius 0: the roller rounds it on the closed form above with ``Rc = 0``.
* A spline piece against the test's own search: the largest ``s`` at which the roller (dense points of the curve,
  refined) comes within ``r`` of the curve, by bisection.
* The derivatives against central differences of the positions, inside one element's contact.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from cams.kinematics.exported import (
    Arc,
    Line,
    SplinePiece,
    check_closed,
    corners,
    export_motion,
    flat_contact,
    roller_contact,
)
from cams.model.design import CamDesign, FlatFaceDesign, Limits
from cams.model.follower import FlatRocker, FlatTranslating, Rocker, Translating
from laws.errors import InputError
from laws.program import Phase, Program
from laws.registry import get_law

RC, E, R = 30.0, 5.0, 8.0  # the eccentric circle and the roller, mm


def _program(lift: float) -> Program:
    return Program(
        (
            Phase("rise", np.radians(120), get_law("cycloidal")),
            Phase("dwell", np.radians(60)),
            Phase("return", np.radians(120), get_law("cycloidal")),
            Phase("dwell", np.radians(60)),
        ),
        lift,
    )


def _translating(cam_sense: int, r: float = R) -> tuple[CamDesign, np.ndarray, float]:
    """A translating roller follower on the axis x = 0 of the fixed frame, the cam centre d0 below the roller
    centre at s = 0."""
    d0 = RC + r - E
    return (
        CamDesign(Translating(r, offset=0.0), _program(2 * E), Limits(np.radians(30)), cam_sense=cam_sense),
        np.array([0.0, -d0]),
        d0,
    )


def _eccentric(
    phi: np.ndarray, cam_sense: int, centre_angle: float, rc: float = RC, e: float = E, r: float = R
) -> np.ndarray:
    """Roller-centre distance from the cam centre, the circle's centre at polar (e, centre_angle) on the cam.

    The follower's axis points along +Y of the fixed frame; seen from the cam it points at the cam-frame angle
    ``pi/2 - eps phi``; x is the angle between it and the circle's centre."""
    x = np.pi / 2 - cam_sense * phi - centre_angle
    return e * np.cos(x) + np.sqrt((rc + r) ** 2 - e**2 * np.sin(x) ** 2)


PHI = np.linspace(0.0, 2 * np.pi, 721)


@pytest.mark.parametrize("cam_sense", [1, -1])
@pytest.mark.parametrize("pieces", [1, 3])
def test_eccentric_circle_as_arcs_is_exact(cam_sense, pieces):
    d, centre, d0 = _translating(cam_sense)
    ang = 0.7
    cx, cy = E * np.cos(ang), E * np.sin(ang)
    cuts = np.linspace(0.2, 0.2 + 2 * np.pi, pieces + 1)
    if pieces == 1:
        arcs = [Arc((cx, cy), RC, cuts[0], cuts[1], 1)]
    else:  # drawn clockwise, the chain the other way round
        arcs = [Arc((cx, cy), RC, b, a, -1) for a, b in itertools.pairwise(cuts)][::-1]
    c = roller_contact(d, centre, arcs, PHI)
    exact = _eccentric(PHI, cam_sense, ang) - d0
    assert np.max(np.abs(c.s - exact)) < 1e-12
    # derivatives of the closed form by central differences (h small, 4th order)
    h = 1e-3
    f = [_eccentric(PHI + k * h, cam_sense, ang) for k in (-2, -1, 1, 2)]
    d1 = (f[0] - 8 * f[1] + 8 * f[2] - f[3]) / (12 * h)
    d2 = (-f[0] + 16 * f[1] - 30 * (exact + d0) + 16 * f[2] - f[3]) / (12 * h * h)
    assert np.max(np.abs(c.ds - d1)) < 1e-8
    assert np.max(np.abs(c.d2s - d2)) < 1e-5


def test_arc_contains_and_span():
    a = Arc((0.0, 0.0), 1.0, np.radians(350), np.radians(10), 1)
    assert a.span == pytest.approx(np.radians(20))
    assert a.contains(0.0) and not a.contains(np.pi)
    b = Arc((0.0, 0.0), 1.0, np.radians(10), np.radians(350), -1)
    assert b.span == pytest.approx(np.radians(20)) and b.contains(0.0)


def _polygon(n: int, rc: float = RC, offset: float = 0.0) -> tuple[list[Line], np.ndarray]:
    ang = offset + 2 * np.pi * np.arange(n) / n
    v = rc * np.column_stack([np.cos(ang), np.sin(ang)])
    return [Line(tuple(v[i]), tuple(v[(i + 1) % n])) for i in range(n)], v


def test_polygon_vertex_rounding_closed_form():
    """A regular polygon about the cam centre: where the follower's axis points at a vertex, the roller sits on
    the circle of radius r about it (the closed form with Rc = 0, e = the vertex's radius) and its acceleration is
    that circle's, -rv - rv^2 / r; where it points along a side's normal, the side's: s'' = d + r."""
    n = 36
    lines, v = _polygon(n)
    d, centre, d0 = _translating(1)
    rv = RC
    # axis angle pi/2 - phi = vertex angle 2 pi k / n  -> phi = pi/2 - 2 pi k / n
    phi_v = np.pi / 2 - 2 * np.pi * np.arange(n) / n
    c = roller_contact(d, centre, lines, phi_v)
    assert np.max(np.abs(c.s + d0 - (rv + R))) < 1e-12
    assert np.max(np.abs(c.d2s - (-rv - rv**2 / R))) < 1e-8
    # near a vertex, the closed form of the circle of radius 0 about it
    x = np.linspace(-0.004, 0.004, 9)
    c = roller_contact(d, centre, lines, np.pi / 2 - x)
    assert np.max(np.abs(c.s + d0 - _eccentric(np.pi / 2 - x, 1, 0.0, rc=0.0, e=rv))) < 1e-12
    # along a side's normal: the side's distance d = rv cos(pi / n) plus r, curvature 0 (s'' = (d + r) sec'' = d + r)
    dist = rv * np.cos(np.pi / n)
    c = roller_contact(d, centre, lines, np.pi / 2 - np.pi / n - 2 * np.pi * np.arange(n) / n)
    assert np.max(np.abs(c.s + d0 - (dist + R))) < 1e-12
    assert np.max(np.abs(c.d2s - (dist + R))) < 1e-8
    assert np.max(np.abs(c.ds)) < 1e-9


def _brute_s(points: np.ndarray, q0: np.ndarray, u: np.ndarray, r: float, lo: float, hi: float) -> float:
    """The largest s in [lo, hi] with a point of ``points`` within r of q0 + s u: bisection on the nearest distance
    (the test's own search, no closed form)."""
    w = points - q0
    band = points[np.abs(w[:, 0] * u[1] - w[:, 1] * u[0]) <= r + 1e-3]  # the points the roller can reach

    def touches(s):
        return len(band) > 0 and np.min(np.hypot(*(band - (q0 + s * u)).T)) <= r

    assert not touches(hi)
    lo = hi
    while not touches(lo):  # down from outside in steps under the roller's radius: the first touch
        lo -= 0.25 * r
    hi = lo + 0.25 * r
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if touches(mid) else (lo, mid)
    return lo


def _bezier_circle(rc: float, cx: float, cy: float) -> list[SplinePiece]:
    """Four cubic Bezier quarter arcs near a circle (not on it: the spline's own curve is what is followed)."""
    k = 0.5523
    pieces = []
    for q in range(4):
        a = q * np.pi / 2
        p0 = np.array([np.cos(a), np.sin(a)])
        p3 = np.array([np.cos(a + np.pi / 2), np.sin(a + np.pi / 2)])
        t0 = np.array([-p0[1], p0[0]])
        t3 = np.array([-p3[1], p3[0]])
        ctrl = [p0, p0 + k * t0, p3 - k * t3, p3]
        ctrl = [rc * np.array([1.0, 0.8]) * p + (cx, cy) for p in ctrl]  # an ellipse-like curve
        c = np.zeros((4, 3))
        c[0, :2] = -ctrl[0] + 3 * ctrl[1] - 3 * ctrl[2] + ctrl[3]
        c[1, :2] = 3 * ctrl[0] - 6 * ctrl[1] + 3 * ctrl[2]
        c[2, :2] = -3 * ctrl[0] + 3 * ctrl[1]
        c[3, :2] = ctrl[0]
        c[3, 2] = 1.0
        pieces.append(SplinePiece(c))
    return pieces


def test_spline_contact_against_brute_force():
    pieces = _bezier_circle(RC, 2.0, -3.0)
    d, centre, d0 = _translating(1)
    t = np.linspace(0, 1, 200_001)
    pts = np.concatenate([[p.derivatives(x)[0] for x in t[::50]] for p in pieces])
    fine = []
    for p in pieces:  # dense points: the Bernstein form evaluated directly (not the piece's power basis)
        cp = _controls(p)
        b = (
            ((1 - t) ** 3)[:, None] * cp[0]
            + (3 * (1 - t) ** 2 * t)[:, None] * cp[1]
            + (3 * (1 - t) * t**2)[:, None] * cp[2]
            + (t**3)[:, None] * cp[3]
        )
        fine.append(b)
    pts = np.concatenate(fine)
    phis = np.linspace(0.0, 2 * np.pi, 13)[:-1] + 0.05
    c = roller_contact(d, centre, pieces, phis)
    for ph, s in zip(phis, c.s, strict=True):
        q0 = _turn(-centre, -ph)
        u = _turn(np.array([0.0, 1.0]), -ph)
        sb = _brute_s(pts, q0, u, R, 0.0, 80.0)
        # the dense points' spacing (<= 2e-4 mm) bounds the brute force's own error by spacing^2 / (8 r)
        assert abs(s - sb) < 1e-8, (np.degrees(ph), s, sb)


def _controls(p: SplinePiece) -> np.ndarray:
    """The Bezier control points of a cubic piece from its power basis (inverse of the Bernstein expansion)."""
    a, b, c, d = p.coeffs[:, :2]
    p0 = d
    p1 = d + c / 3
    p2 = d + 2 * c / 3 + b / 3
    p3 = a + b + c + d
    return np.array([p0, p1, p2, p3])


def _turn(v: np.ndarray, a: float) -> np.ndarray:
    return np.array([np.cos(a) * v[0] - np.sin(a) * v[1], np.sin(a) * v[0] + np.cos(a) * v[1]])


@pytest.mark.parametrize("curve", ["polygon", "spline", "arcs"])
@pytest.mark.parametrize("kind", ["translating", "rocker"])
def test_derivatives_against_differences(curve, kind):
    """s' and s'' against central differences of the positions, where the element in contact is the same at the
    three angles."""
    if curve == "polygon":
        els = _polygon(24, offset=0.1)[0]
    elif curve == "spline":
        els = _bezier_circle(RC, 2.0, -3.0)
    else:
        els = [Arc((E, 0.0), RC, 0.0, np.pi, 1), Arc((E, 0.0), RC, np.pi, 2 * np.pi, 1)]
    if kind == "translating":
        d, centre, _ = _translating(-1)
    else:
        d = CamDesign(Rocker(90.0, R, sense=1), _program(np.radians(5)), Limits(np.radians(40)), cam_sense=1)
        centre = np.array([70.0, -50.0])
    phi = np.linspace(0.0, 2 * np.pi, 400, endpoint=False) + 0.013
    h = 1e-4
    c0, cm, cp = (roller_contact(d, centre, els, phi + k) for k in (0.0, -h, h))
    same = (c0.element == cm.element) & (c0.element == cp.element)
    assert same.sum() > 300
    d1 = (cp.s - cm.s) / (2 * h)
    d2 = (cp.s - 2 * c0.s + cm.s) / h**2
    scale = np.max(np.abs(c0.d2s[same]))
    assert np.max(np.abs(d1 - c0.ds)[same]) < 1e-6 * max(1.0, np.max(np.abs(c0.ds)))
    assert np.max(np.abs(d2 - c0.d2s)[same]) < 2e-4 * scale


@pytest.mark.parametrize("sigma", [1, -1])
def test_rocker_eccentric_circle_closed_form(sigma):
    """The arm's circle meets the circle of radius Rc + r about the cam circle's centre (law of cosines)."""
    arm = 90.0
    centre = np.array([70.0, -50.0 * sigma])
    eps = -1
    d = CamDesign(Rocker(arm, R, sense=sigma), _program(np.radians(5)), Limits(np.radians(40)), cam_sense=eps)
    cc = np.array([E, 1.0])
    c = roller_contact(d, centre, [Arc(tuple(cc), RC, 0.0, 2 * np.pi, 1)], PHI)
    cf = centre + np.array([_turn(cc, eps * p) for p in PHI])  # the circle's centre, fixed frame
    D = np.hypot(cf[:, 0], cf[:, 1])
    beta = np.arctan2(cf[:, 1], cf[:, 0])
    gam = np.arccos((arm**2 + D**2 - (RC + R) ** 2) / (2 * arm * D))
    psi = np.array([max(sigma * (b + gam), sigma * (b - gam)) for b, gam in zip(beta, gam, strict=True)])
    # the answer within pi of the design's swing: the same branch of the angle
    psi = psi + 2 * np.pi * np.round((c.s - psi) / (2 * np.pi))
    assert np.max(np.abs(c.s - psi)) < 1e-12


def test_flat_translating_support_of_a_circle():
    """The face's distance is the circle's support C . m + Rc: s = C . m + Rc - R0, s' and s'' its derivatives."""
    prog = _program(2 * E)
    d = FlatFaceDesign(FlatTranslating(offset=3.0, stroke_scale=2 * E), prog, 1.0, cam_sense=-1)
    cc = np.array([1.0, E])
    R0 = RC - E
    c = flat_contact(d, R0, [Arc(tuple(cc), RC, 0.0, 2 * np.pi, 1)], PHI)
    th = np.pi / 2 + PHI  # the face normal, cam frame: pi/2 - eps phi
    assert np.max(np.abs(c.s - (cc[0] * np.cos(th) + cc[1] * np.sin(th) + RC - R0))) < 1e-12
    assert np.max(np.abs(c.ds - (-cc[0] * np.sin(th) + cc[1] * np.cos(th)))) < 1e-12
    assert np.max(np.abs(c.d2s - (-cc[0] * np.cos(th) - cc[1] * np.sin(th)))) < 1e-12


def test_flat_rocker_against_residual_and_differences():
    prog = _program(np.radians(8))
    d = FlatFaceDesign(FlatRocker(centre_distance=80.0, face_offset=5.0, sense=1), prog, 1.0, cam_sense=1)
    cc = np.array([2.0, 1.0])
    els = [Arc(tuple(cc), RC, 0.0, 2 * np.pi, 1)]
    from cams.kinematics.flat import oscillating_setup

    a0 = oscillating_setup(prog, 80.0, RC - 3.0, 5.0, 1)
    phi = np.linspace(0, 2 * np.pi, 50)
    c = flat_contact(d, RC - 3.0, els, phi)
    a = a0 + c.s
    th = a - phi
    # the face line f - L cos a from the cam centre touches the circle: its support C . m + Rc
    assert np.max(np.abs(5.0 - 80.0 * np.cos(a) - (cc[0] * np.cos(th) + cc[1] * np.sin(th) + RC))) < 1e-11
    h = 1e-4
    cp, cm = flat_contact(d, RC - 3.0, els, phi + h), flat_contact(d, RC - 3.0, els, phi - h)
    assert np.max(np.abs((cp.s - cm.s) / (2 * h) - c.ds)) < 1e-7
    assert np.max(np.abs((cp.s - 2 * c.s + cm.s) / h**2 - c.d2s)) < 1e-5


def test_export_motion_errors_and_shares():
    """The eccentric circle is the design when the law is its own motion: the errors of one ARC are the
    difference between the law and the closed form, here of a design whose law is not the circle's."""
    d, centre, d0 = _translating(1)
    em = export_motion(d, [Arc((0.0, E), RC, 0.0, 2 * np.pi, 1)], centre=centre)
    m = d.program.evaluate(em.contact.phi)
    exact = _eccentric(em.contact.phi, 1, np.pi / 2) - d0
    assert em.max_ds == pytest.approx(np.max(np.abs(exact - m.s)), abs=1e-12)
    assert em.to_dict()["max_da_ratio"] == pytest.approx(em.max_da / em.peak_acceleration)
    # the cycloidal rise's peak acceleration, 2 pi h / beta^2
    assert em.peak_acceleration == pytest.approx(2 * np.pi * 2 * E / np.radians(120) ** 2, rel=1e-9)


def test_not_closed_and_no_touch():
    lines, _ = _polygon(12)
    with pytest.raises(InputError, match="not a closed curve"):
        check_closed(lines[:-1])
    with pytest.raises(InputError, match="holds no curve"):
        check_closed([])
    d, centre, _ = _translating(1)
    far = [Arc((500.0, 500.0), 1.0, 0.0, 2 * np.pi, 1)]
    with pytest.raises(InputError, match="does not touch"):
        roller_contact(d, centre, far, np.array([0.0]))


def test_knife_edge():
    """A knife edge (r = 0) on the eccentric circle follows the closed form with r = 0; on a polygon's corner its
    velocity jumps, so its acceleration there is unbounded: infinite here, null in the JSON entry."""
    d, centre, d0 = _translating(1, r=0.0)
    arc = Arc((0.0, E), RC, 0.0, 2 * np.pi, 1)
    c = roller_contact(d, centre, [arc], PHI)
    exact = _eccentric(PHI, 1, np.pi / 2, r=0.0)
    assert np.max(np.abs(c.s + d0 - exact)) < 1e-12
    h = 1e-4
    fd = (_eccentric(PHI + h, 1, np.pi / 2, r=0.0) - _eccentric(PHI - h, 1, np.pi / 2, r=0.0)) / (2 * h)
    assert np.max(np.abs(c.ds - fd)) < 1e-6
    lines, v = _polygon(8)
    c = roller_contact(d, centre, lines, np.array([np.pi / 2]))  # the axis points at the vertex at angle 0
    assert c.s[0] + d0 == pytest.approx(RC, abs=1e-12)
    assert corners(lines) == 8 and corners([arc]) == 0
    em = export_motion(d, lines, centre=centre, phi=np.array([0.3, 0.4]))  # between the corners, yet unbounded
    assert em.to_dict()["max_da"] is None and em.to_dict()["max_da_ratio"] is None
    assert em.to_dict()["max_ds"] is not None


def test_a_joint_takes_the_nearer_side_of_the_law():
    """A harmonic rise's acceleration jumps at its ends: at a joint the contact's one-sided value (either side)
    is no error, a value off both sides is."""
    from cams.kinematics.exported import Contact, _law_errors

    prog = Program(
        (
            Phase("rise", np.radians(120), get_law("harmonic")),
            Phase("dwell", np.radians(60)),
            Phase("return", np.radians(180), get_law("harmonic")),
        ),
        10.0,
    )
    d = CamDesign(Translating(R, offset=0.0), prog, Limits(np.radians(30)), cam_sense=1)
    joint = np.array([np.radians(120)])
    peak = np.pi**2 / 2 * 10.0 / np.radians(120) ** 2  # the harmonic rise's acceleration at its ends, by hand
    for d2s in (-peak, 0.0):  # the rise's end, the dwell's start
        c = Contact(joint, np.array([10.0]), np.array([0.0]), np.array([d2s]), np.array([0]))
        assert np.max(_law_errors(d, c)) < 1e-9
    c = Contact(joint, np.array([10.0]), np.array([0.0]), np.array([1.0]), np.array([0]))
    assert _law_errors(d, c)[2, 0] == pytest.approx(1.0)


def test_a_pieces_derivatives_at_one_number_are_its_derivatives_bit_for_bit():
    """SplinePiece._derivatives_at (Python floats, for the root searches) promises the same IEEE results as
    SplinePiece.derivatives (numpy): compared exactly, at the ends and inside, on rational pieces (w != 1)."""
    rng = np.random.default_rng(7)
    pieces = _bezier_circle(RC, 2.0, -3.0)
    c = np.array(pieces[0].coeffs, float)
    c[:, 2] += np.array([0.1, -0.2, 0.3, 0.0])  # a rational piece: its weight varies along it
    pieces.append(SplinePiece(c))
    for p in pieces:
        for t in [0.0, 1.0, 0.5, *rng.uniform(0.0, 1.0, 20)]:
            fast, ref = p._derivatives_at(float(t)), p.derivatives(float(t))
            for a, b in zip(fast, ref, strict=True):
                assert np.array_equal(a, b), (t, a, b)
