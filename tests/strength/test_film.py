"""The lubricant film: the two EHL formulas against each other and their powers of speed, the film parameter, the
entrainment velocity of each face against finite differences of the contact's travel along both surfaces, and the
flat face's nose-radius trap."""

from __future__ import annotations

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.strength import film, hertz
from cams.strength.along import flat_geometry, roller_geometry

ES = hertz.contact_modulus(206e3, 0.3, 206e3, 0.3) * 1e6  # Pa
EP = 2 * ES  # the EHL literature's E'


@pytest.mark.parametrize("u, R, w", [(2.0, 7.5e-3, 2e5), (0.5, 20e-3, 5e4), (5.0, 5e-3, 4e5)])
def test_two_formulas_agree_within_their_spread(u, R, w):
    """Dowson-Higginson and Hamrock's form, two fits to the same numerical solutions, agree within 20 % over
    the practical range (an oil of 0.05 Pa s, 20/GPa)."""
    a = film.dowson_higginson(u, R, w, EP, 0.05, 20e-9)
    b = film.hamrock(u, R, w, EP, 0.05, 20e-9)
    assert 0.8 < float(b / a) < 1.2
    assert 0.05e-6 < float(a) < 5e-6  # a cam's film: a tenth of a micrometre to a few


def test_the_power_of_speed_and_the_groups():
    """h ~ u^0.7 (Dowson-Higginson), u^0.694 (Hamrock); h ~ w^-0.13; the groups use E' (half the film with E*
    in place of E' is not what they give)."""
    h1 = film.dowson_higginson(1.0, 0.01, 1e5, EP, 0.05, 20e-9)
    assert float(film.dowson_higginson(3.0, 0.01, 1e5, EP, 0.05, 20e-9) / h1) == pytest.approx(3**0.7, rel=1e-12)
    assert float(
        film.hamrock(3.0, 0.01, 1e5, EP, 0.05, 20e-9) / film.hamrock(1.0, 0.01, 1e5, EP, 0.05, 20e-9)
    ) == pytest.approx(3**0.694, rel=1e-12)
    assert float(film.dowson_higginson(1.0, 0.01, 2e5, EP, 0.05, 20e-9) / h1) == pytest.approx(2**-0.13, rel=1e-12)
    # by hand: h = 2.65 R U^0.7 G^0.54 W^-0.13
    U, G, W = 0.05 * 1.0 / (EP * 0.01), 20e-9 * EP, 1e5 / (EP * 0.01)
    assert float(h1) == pytest.approx(2.65 * 0.01 * U**0.7 * G**0.54 * W**-0.13, rel=1e-12)


def test_film_parameter_and_zero_crossings():
    assert float(film.film_parameter(0.5, 0.3, 0.4)) == pytest.approx(1.0)
    phi = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    z = film.zero_crossings(phi, np.cos(phi))
    assert z == pytest.approx([np.pi / 2, 3 * np.pi / 2], abs=1e-3)
    assert film.zero_crossings(phi, 2 + np.cos(phi)) == []


def _roller(kind: str) -> dict:
    fo = (
        {"kind": "rocker", "arm": 125.0, "swing": 15.0, "roller_radius": 10.0, "rise_direction": "cw"}
        if kind == "rocker"
        else {"kind": "translating", "stroke": 30.0, "roller_radius": 8.0}
    )
    return {
        "follower": fo,
        "cam": {"rotation": "ccw", "base_radius": 60.0},
        "motion": [
            {"phase": "rise", "law": "cycloidal", "angle": 120},
            {"phase": "dwell", "angle": 30},
            {"phase": "return", "law": "poly345", "angle": 120},
            {"phase": "dwell"},
        ],
        "limits": {
            "pressure_angle": 45,
            "closure": "force",
            **({"centre_distance": 150.0} if kind == "rocker" else {}),
        },
        **({} if kind == "rocker" else {"follower": {**fo, "offset": 5.0}}),
    }


@pytest.mark.parametrize("kind", ["translating", "rocker"])
def test_a_roller_s_entrainment_is_the_contact_s_travel_along_the_cam(kind):
    """A roller rolls: the entrainment velocity per unit cam speed is the speed of the working profile's point in
    the cam frame, here by central differences of the kernel's points offset by the roller."""
    from cams.faces import face_of
    from cams.kinematics.inversion import pitch_curve

    d = design_from_dict(_roller(kind))
    c = face_of(d).size(d).centre
    r = d.follower.roller_radius
    phi = np.linspace(0.1, 6.2, 50)
    g = roller_geometry(d, c, phi, length_unit=1.0)
    h = 1e-6

    def work(p):
        return pitch_curve(d, c, p).offset(-r)

    speed = np.linalg.norm(work(phi + h) - work(phi - h), axis=1) / (2 * h)
    assert g.entrainment == pytest.approx(speed, rel=1e-6, abs=1e-8)
    # the cam's radius of curvature at the contact: the working profile's, by the curve's three-point circle
    w0, w1, w2 = work(phi - 1e-4), work(phi), work(phi + 1e-4)
    a, b, cc = (np.linalg.norm(w1 - w0, axis=1), np.linalg.norm(w2 - w1, axis=1), np.linalg.norm(w2 - w0, axis=1))
    cross = (w1 - w0)[:, 0] * (w2 - w1)[:, 1] - (w1 - w0)[:, 1] * (w2 - w1)[:, 0]
    rho = a * b * cc / (2 * cross) * (-d.cam_sense)  # the profile runs against the cam's sense
    assert g.cam_radius == pytest.approx(rho, rel=1e-4)


def _flat(kind: str, R0: float) -> dict:
    fo = (
        {
            "kind": "rocker",
            "face": "flat",
            "swing": 15.0,
            "centre_distance": 120.0,
            "face_offset": 10.0,
            "rise_direction": "cw",
        }
        if kind == "rocker"
        else {"kind": "translating", "face": "flat", "stroke": 20.0, "offset": 3.0}
    )
    return {
        "follower": fo,
        "cam": {"rotation": "cw", "base_radius": R0},
        "motion": [
            {"phase": "rise", "law": "cycloidal", "angle": 120},
            {"phase": "dwell", "angle": 60},
            {"phase": "return", "law": "poly345", "angle": 120},
            {"phase": "dwell"},
        ],
        "limits": {"min_radius": 1.0},
    }


@pytest.mark.parametrize("kind, R0", [("translating", 40.0), ("rocker", 50.0)])
def test_a_flat_face_s_entrainment_from_the_travels_along_both_surfaces(kind, R0):
    """A flat face slides: each surface moves relative to the contact at minus the contact's travel along it; the
    travel along the face is d(position)/dphi, along the cam the cam-frame contact point's rate along the face's
    direction (both by central differences of the contact, :func:`cams.dynamics.flat_forces.flat_contact`)."""
    from cams.dynamics.flat_forces import flat_contact

    d = design_from_dict(_flat(kind, R0))
    eps = d.cam_sense
    phi = np.linspace(0.05, 6.2, 60)
    g = flat_geometry(d, R0, phi, length_unit=1.0)
    h = 1e-6

    def cam_frame(p):
        k = flat_contact(d, R0, p)
        t = -eps * p
        rot = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]]).transpose(2, 0, 1)
        return np.einsum("nij,nj->ni", rot, k.point - k.centre), np.einsum("nij,nj->ni", rot, k.along)

    (wp, _), (wm, _) = cam_frame(phi + h), cam_frame(phi - h)
    _, u_cam = cam_frame(phi)
    cam_travel = np.sum((wp - wm) / (2 * h) * u_cam, axis=1)
    face_travel = (flat_contact(d, R0, phi + h).position - flat_contact(d, R0, phi - h).position) / (2 * h)
    assert g.entrainment == pytest.approx(-(cam_travel + face_travel) / 2, rel=1e-5, abs=1e-6)
    if kind == "translating":  # by hand: -eps (R0 + s + 2 s'') / 2
        m = d.program.evaluate(phi)
        assert g.entrainment == pytest.approx(-eps * (R0 + m.s + 2 * m.d2s) / 2, rel=1e-12)


def test_the_nose_radius_trap():
    """A circular-arc cam's nose (radius r_n, its centre d from the cam's) under a translating flat face, lift h and
    base radius R0 fixed (d = h + R0 - r_n): at the nose tip s = h, s'' = -d, so the entrainment is
    omega (R0 + s + 2 s'')/2 = omega (2 r_n - h - R0)/2 in size. A larger nose lowers p0 (R = r_n grows) and brings
    the entrainment to zero at r_n = (h + R0)/2; there the film vanishes and it is flagged."""
    h, R0, load, width = 10.0, 25.0, 500.0, 10.0
    Es = hertz.contact_modulus(206e3, 0.3, 206e3, 0.3)
    noses = np.array([5.0, 8.0, 11.0, 14.0, 17.0, 17.5])
    p0 = hertz.max_pressure(load / width, hertz.effective_radius(noses, np.inf), Es)
    assert np.all(np.diff(p0) < 0)
    u_tip = np.abs(R0 + h + 2 * -(h + R0 - noses)) / 2
    assert np.all(np.diff(u_tip) < 0) and u_tip[-1] == 0.0
    hfilm = film.dowson_higginson(u_tip * 1e-3 * 100, noses * 1e-3, load / width * 1e3, 2 * Es * 1e6, 0.1, 20e-9)
    # the larger radius helps the film a little at first, then the falling entrainment wins, down to no film
    assert np.all(np.diff(hfilm[1:]) < 0) and hfilm[-1] == 0.0 and hfilm[1] > hfilm[0]
    # along a turn of such a nose the entrainment changes sign: the crossing is flagged
    phi = np.linspace(-0.5, 0.5, 201)
    d = h + R0 - 17.0
    u = 17.0 - d * np.cos(phi)  # R0 + s + 2 s'' on the nose: r_n + d cos - 2 d cos
    assert film.zero_crossings(phi + 0.5, u)
