"""The translating roller's pressure rows against the kernel's inversion.

The rows' coefficients are made once (:func:`optimize.motion.translating.pressure_sides`) and combined three
ways: the program's rows at a ratio (:func:`build`), the rows with the ratio as a parameter
(:func:`pressure_rows`) and their two sides at a point (:func:`pressure_terms`). Each is checked here against
the cam the point describes, inverted by the kernel (:func:`cams.kinematics.inversion.invert_at`, which knows
nothing of the programs): at every sample of the relaxed rows, and at the ends of every piece of the
conservative ones (where a piece's first and last Bernstein coefficients are its values), ``|s' + eps x|`` over
``d + s`` is ``|tan|`` of the kernel's pressure angle and ``d + s`` the roller centre's distance from the cam
centre along the follower's axis. The design has partial heights (the programs' scale is not the phases'), a
fixed constrained phase between two free ones, and both senses of rotation.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.kinematics.inversion import invert_at, pressure_angle
from optimize.motion.lawrows import fit
from optimize.motion.space import Space
from optimize.motion.translating import (
    FIXED_SAMPLES,
    SAMPLES_PER_SPAN,
    Request,
    build,
    form_ratio,
    pressure_rows,
    pressure_terms,
)

SPANS, DEGREE, PIECES = 3, 7, 4
X, D = 4.2, 41.0  # the cam centre (x, -d) in the follower's frame, mm
RATIO = 0.8


def _design(sense: int):
    return design_from_dict(
        {
            "name": "two rises",
            "follower": {"kind": "translating", "stroke": 30.0, "roller_radius": 8.0},
            "cam": {"rotation": "ccw" if sense > 0 else "cw"},
            "motion": [
                {"phase": "rise", "law": "poly345", "angle": 80, "height": 17.3},
                {"phase": "dwell", "angle": 30},
                {"phase": "rise", "law": "poly4567", "angle": 70, "height": 12.7},
                {"phase": "return", "law": "poly4567", "angle": 120},
                {"phase": "dwell"},
            ],
            "limits": {"pressure_angle": 30, "return_pressure_angle": 35, "closure": "form"},
        }
    )


@pytest.fixture(scope="module", params=[1, -1], ids=["ccw", "cw"])
def case(request):
    """A request (phases 0 and 3 free, 2 fixed and limited), a point of its space away from the original laws
    (a random change projected on the joints) with the cam centre (X, -D), and the cam it describes."""
    design = _design(request.param)
    space = Space(design.program, (0, 3), DEGREE, SPANS, 3)
    assert space.pieces == PIECES
    rng = np.random.default_rng(7)
    near = fit(space, {})
    laws = space.project(near + 0.05 * np.max(np.abs(near)) * rng.standard_normal(space.size))
    ell = design.scale
    v = np.concatenate([laws, [X / ell, D / ell, 0.0]])
    req = Request(
        space=space,
        follower="roller",
        cam_sense=design.cam_sense,
        limits=dict(design.constrained_phases()),
        caps={},
        objective="feasibility",
        bound=1e4,
        ratio=RATIO,
        length=ell,
    )
    cam = design.with_(program=space.programme(laws, "test"))
    return req, v, cam


def _kernel(cam, phase: int, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``(|tan gamma|, d + s)`` of the cam's roller at positions ``u`` of ``phase`` (the kernel's inversion)."""
    p = cam.program
    phi = p.starts[phase] + u * p.phases[phase].angle
    inv = invert_at(cam, np.array([X, -D]), phi)
    return np.abs(np.tan(pressure_angle(inv))), inv.r[:, 1]


def _points(req: Request, form: str, phase: int) -> tuple[np.ndarray, np.ndarray]:
    """The rows' positions u in the phase that are values, and their row indices within the phase's block."""
    if phase not in req.space.free:
        u = np.linspace(0.0, 1.0, FIXED_SAMPLES)
        return u, np.arange(u.size)
    if form == "relaxed":
        u = np.linspace(0.0, 1.0, (SAMPLES_PER_SPAN - 1) * SPANS + 1)
        return u, np.arange(u.size)
    # the Bernstein coefficients, DEGREE + 1 a piece, pieces in order: the first and the last are the values at
    # the piece's ends
    k = np.arange(SPANS * PIECES)
    u = np.concatenate([k, k + 1]) / (SPANS * PIECES)
    at = np.concatenate([k * (DEGREE + 1), k * (DEGREE + 1) + DEGREE])
    return u, at


def _blocks(req: Request, form: str) -> list[int]:
    """Each limited phase's number of points (the rows of one sign)."""
    sp = req.space
    if form == "relaxed":
        free = (SAMPLES_PER_SPAN - 1) * SPANS + 1
    else:
        free = SPANS * PIECES * (DEGREE + 1)
    return [free if i in sp.free else FIXED_SAMPLES for i in req.limits]


@pytest.mark.parametrize("form", ["relaxed", "conservative"])
def test_the_rows_are_the_kernels_pressure_angle(case, form):
    """Per limited phase, sign +1 rows then sign -1 rows: from the program built at RATIO the two rows of a point
    give ``s' + eps x = (g+ - g-) / 2`` and ``d + s = -(g+ + g-) / (2 tan(RATIO limit))`` (``g = G v - h``);
    from the rows with the ratio as a parameter ``U v + u0`` (its sign) and ``W v + c``; from the terms at the
    point the two sides themselves. Each, times the scale, is the kernel's."""
    req, v, cam = case
    ell = req.length
    prog = build(req, form)
    rows = pressure_rows(req, form)
    terms = pressure_terms(req, v, form)
    g = prog.G @ v - prog.h
    top_p, bottom_p = rows.U @ v + rows.u0, rows.W @ v + rows.c
    at = 0
    assert len(terms) == len(req.limits) == 3
    for (i, limit), m, (top_t, bottom_t, lim_t) in zip(req.limits.items(), _blocks(req, form), terms, strict=True):
        u, idx = _points(req, form, i)
        tan_k, centre_k = _kernel(cam, i, u)
        assert np.all(centre_k > 0) and np.max(tan_k) > 0.2  # the roller on its side of the cam; angles not 0
        T = np.tan(RATIO * limit)
        plus, minus = g[at : at + m][idx], g[at + m : at + 2 * m][idx]
        sides = {
            "build": ((plus - minus) / 2, -(plus + minus) / (2 * T)),
            "pressure_rows": (top_p[at : at + m][idx], bottom_p[at : at + m][idx]),
            "pressure_terms": (top_t[idx], bottom_t[idx]),
        }
        for name, (top, bottom) in sides.items():
            assert bottom * ell == pytest.approx(centre_k, rel=1e-10), name
            assert np.abs(top) / bottom == pytest.approx(tan_k, rel=1e-9, abs=1e-12), name
        # the -1 rows are the +1 rows' other sign
        assert top_p[at + m : at + 2 * m] == pytest.approx(-top_p[at : at + m], rel=0, abs=0)
        assert bottom_p[at + m : at + 2 * m] == pytest.approx(bottom_p[at : at + m], rel=0, abs=0)
        assert lim_t == limit and np.all(rows.limit[at : at + 2 * m] == limit)
        assert np.all(prog.G[at : at + 2 * m, -1] == -1.0)  # the slack column: these are the pressure rows
        at += 2 * m
    assert rows.m == at


def test_the_conservative_ratio_bounds_the_kernels(case):
    """The conservative rows hold at every cam angle (a piece within its Bernstein coefficients' hull): the
    ratio of the point in them is at least the kernel's largest ratio of pressure angle to limit at 2,001
    angles a phase, and near it (the hull's excess, small at 4 pieces a span); the relaxed ratio, at the
    samples alone, is at most it."""
    req, v, cam = case
    u = np.linspace(0.0, 1.0, 2001)
    dense = max(float(np.max(np.arctan(_kernel(cam, i, u)[0]))) / lim for i, lim in req.limits.items())
    assert dense * (1 - 1e-12) <= form_ratio(req, v, "conservative") <= dense * 1.05
    assert form_ratio(req, v, "relaxed") <= dense * (1 + 1e-12)
