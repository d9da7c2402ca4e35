"""The flat face where the motion law puts it, against the cam's profile and against what the mechanism's
drawing (the profile picture and the animation, ``draw_mechanism`` and its ``move``) shows.

The face is placed here from the design's own numbers, independently of the package's frames: the timing datum
is the direction from the cam centre to the contact at cam angle 0 (a dwell at the base circle, so the contact is
the foot of the perpendicular, at distance R0 along the face's normal); the cam turns by ``eps phi`` ([cam]
rotation); a translating face moves along that normal by the lift; a rocker's face turns with the rocker about its
pivot by ``sigma s(phi)`` (rise_direction), the pivot at ``f`` from the face on the cam's side (face_offset) and
at L from the cam centre, on the side where a turn in the rise's sense moves the face away from the cam. Then at
every cam angle no profile point lies beyond the face, and the face touches the profile.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.cam import Cam
from cams.io.designfile import design_from_dict, load_design
from tests.conftest import EXAMPLES

_MOTION = [
    {"phase": "rise", "law": "cycloidal", "angle": 120},
    {"phase": "dwell", "angle": 40},
    {"phase": "return", "law": "poly345", "angle": 120},
    {"phase": "dwell"},
]


def _rocker(rotation: str, rise: str, face_offset: float) -> dict:
    return {
        "name": f"rocker {rotation} {rise} f={face_offset}",
        "motion": _MOTION,
        "limits": {"min_radius": 5.0},
        "cam": {"rotation": rotation},
        "follower": {
            "kind": "rocker",
            "face": "flat",
            "swing": 15.0,
            "centre_distance": 120.0,
            "face_offset": face_offset,
            "rise_direction": rise,
        },
    }


def _translating(rotation: str, offset: float) -> dict:
    return {
        "name": f"translating {rotation} e={offset}",
        "motion": _MOTION,
        "limits": {"min_radius": 5.0},
        "cam": {"rotation": rotation},
        "follower": {"kind": "translating", "face": "flat", "stroke": 20.0, "offset": offset},
    }


DESIGNS = {
    "rocker_flat.toml": None,
    "translating_flat.toml": None,
    "rocker cw/cw f=10": _rocker("cw", "cw", 10.0),
    "rocker ccw/ccw f=-8": _rocker("ccw", "ccw", -8.0),
    "translating cw e=3": _translating("cw", 3.0),
}


@pytest.fixture(scope="module", params=list(DESIGNS))
def case(request):
    """The cam, its design file's values as read here, and the face's placement (see :func:`_face`)."""
    raw = DESIGNS[request.param]
    if raw is None:
        import tomllib

        raw = tomllib.loads((EXAMPLES / request.param).read_text(encoding="utf-8"))
        cam = Cam(load_design(EXAMPLES / request.param))
    else:
        cam = Cam(design_from_dict(raw))
    return cam, raw


def _rot(v: np.ndarray, ang) -> np.ndarray:
    c, s = np.cos(ang), np.sin(ang)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def _face(cam, raw: dict, phi: float):
    """The face at cam angle ``phi`` (radians) with the cam centre at the origin and the cam frame's axes:
    ``(n, p, pivot)``, the face the line ``n . X = p`` (``n`` its unit normal away from the cam), a rocker's
    pivot (None for a translating face)."""
    prof = cam.profile
    X0 = prof.work[np.argmin(np.abs((prof.phi + np.pi) % (2 * np.pi) - np.pi))]  # the contact at cam angle 0
    R0 = float(np.hypot(*X0))
    D0 = X0 / R0
    T0 = np.array([-D0[1], D0[0]])
    fo = raw["follower"]
    s = float(cam.design.program.evaluate(np.array([phi])).s[0])  # the motion law: mm, or radians of swing
    if fo["kind"] == "translating":
        return D0, R0 + s, None
    sigma = 1 if fo.get("rise_direction", "cw") == "ccw" else -1
    f, L = float(fo.get("face_offset", 0.0)), float(fo["centre_distance"])
    # the face n . X = n . P + f turns about P; d(n . X)/d(turn) at the near dwell is T0 . P: > 0 for sigma > 0
    P = (R0 - f) * D0 + sigma * np.sqrt(L**2 - (R0 - f) ** 2) * T0
    n = _rot(D0, sigma * s)
    return n, float(n @ P) + f, P


def _eps(raw: dict) -> int:
    return 1 if raw.get("cam", {}).get("rotation", "ccw") == "ccw" else -1


def test_the_profile_stays_behind_the_face_and_touches_it(case):
    cam, raw = case
    prof = cam.profile
    size = float(np.max(np.hypot(prof.work[:, 0], prof.work[:, 1])))
    X0 = prof.work[np.argmin(np.abs((prof.phi + np.pi) % (2 * np.pi) - np.pi))]
    assert np.hypot(*X0) == pytest.approx(cam.solution.R0, rel=1e-9)  # cam angle 0: the base circle's dwell
    # the cam frame is the documented one (FlatFaceProfile.point): a translating face's fixed frame (Y along the
    # rise: the face's normal at cam angle 0 is +Y), a rocker's line-of-centres frame (the pivot on -X, at L)
    n0, _, P = _face(cam, raw, 0.0)
    if P is None:
        np.testing.assert_allclose(n0, [0.0, 1.0], rtol=0, atol=1e-12)
    else:
        np.testing.assert_allclose(P, [-raw["follower"]["centre_distance"], 0.0], rtol=0, atol=1e-9 * size)
    gaps = []
    for phi in np.radians(np.arange(0.0, 360.0, 0.5)):
        n, p, _ = _face(cam, raw, phi)
        gaps.append(float(np.min(p - _rot(prof.work, _eps(raw) * phi) @ n)))  # >= 0: on the cam's side
    least = np.array(gaps)
    assert least.min() >= -1e-9 * size  # nothing beyond the face
    assert least.max() <= 2 * prof.tolerance  # touching (the samples lie within the chord tolerance of the curve)


PHIS = np.radians([0.0, 37.0, 95.0, 100.0, 105.0, 119.5, 140.0, 197.0, 250.0, 300.0])


def _centre_and_pivot(ax):
    lines = {a.get_marker(): a for a in ax.lines if a.get_linestyle() in ("None", "")}
    centre = np.asarray(lines["+"].get_xydata(), float)[0]
    pivots = [np.asarray(a.get_xydata(), float)[0] for a in ax.lines if a.get_marker() == "o" and a.get_color() == "k"]
    return centre, pivots


@pytest.mark.parametrize("fresh", [False, True], ids=["moved", "fresh"])
def test_the_drawing_puts_the_face_where_the_motion_law_does(case, fresh):
    from matplotlib.figure import Figure

    from cams.present.faces import presenter

    cam, raw = case
    draw = presenter(cam).draw_mechanism
    tol = 1e-9 * cam.design.scale
    if not fresh:
        ax = Figure(dpi=100).add_subplot()
        move = draw(ax, cam, cam.profile, 1.0)
    for phi in PHIS:
        if fresh:
            ax = Figure(dpi=100).add_subplot()
            patch, face, contact, stem = draw(ax, cam, cam.profile, phi)(phi)
        else:
            patch, face, contact, stem = move(phi)
        O, pivots = _centre_and_pivot(ax)
        n, p, P = _face(cam, raw, phi)
        ends = np.asarray(face.get_xydata(), float) - O
        np.testing.assert_allclose(ends @ n, p, rtol=0, atol=tol)  # the drawn face is the face's line
        cam_pts = np.asarray(patch.get_xy(), float) - O
        gap = p - cam_pts @ n
        assert gap.min() >= -tol and gap.min() <= 2 * cam.profile.tolerance  # the drawn cam touches, uncut
        c = np.asarray(contact.get_xydata(), float)[0] - O
        assert c @ n == pytest.approx(p, abs=tol)  # the contact point on the face...
        assert np.min(np.hypot(*(cam_pts - c).T)) <= 2 * np.sqrt(
            2 * cam.profile.tolerance * np.max(np.abs(cam.profile.rho))
        )  # ... and on the cam (within a chord's length of a vertex)
        along = (c - ends[0]) @ (ends[1] - ends[0]) / np.sum((ends[1] - ends[0]) ** 2)
        assert 0.0 < along < 1.0  # inside the drawn face
        if P is not None:
            assert len(pivots) == 1
            np.testing.assert_allclose(pivots[0] - O, P, rtol=0, atol=tol)  # the rocker's pivot
            np.testing.assert_allclose(np.asarray(stem.get_xydata(), float)[0] - O, P, rtol=0, atol=tol)
        # the face's and the stem's strokes lie beside the line, away from the cam: their edge on the cam's
        # side is the face line (a shift of half the stroke along n, in points)
        for a in (face, stem):
            xy = np.asarray(a.get_xydata(), float)
            shift = a.get_transform().transform(xy) - ax.transData.transform(xy)
            points = shift * 72.0 / ax.figure.dpi
            np.testing.assert_allclose(
                points, np.broadcast_to(0.5 * a.get_linewidth() * n, points.shape), rtol=0, atol=1e-9
            )
