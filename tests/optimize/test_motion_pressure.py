"""The least pressure angle (``objective = "pressure_angle"``) against an independent evaluation.

The answer's two ends are checked without the product's programs: the returned laws' pressure angle by the
independent check (:func:`cams.verify.pressure.pressure_angle`, kinematic inversion) at dense angles, and the
lower bound by an independent linear program (the space rebuilt as a B-spline basis with scipy, the textbook
pressure-angle condition at samples, the size held outer-approximated by a polygon, solved by HiGHS): it must
have no law at the lower bound (every law of the space has a larger ratio) and one at the value (the returned
law's own).
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.io.document import read_toml
from cams.solve import solve

EXAMPLE = "examples/translating_force.toml"
SPANS, DEGREE, CONTINUITY = 6, 7, 3


@pytest.fixture(scope="module")
def solved():
    d = read_toml(EXAMPLE)
    d["optimize"] = {
        "objective": "pressure_angle",
        "max_Ca": "poly4567",
        "max_Cj": "poly4567",
        "spans": SPANS,
        "degree": DEGREE,
        "continuity": CONTINUITY,
    }
    return solve(design_from_dict(d))


def _least_slack(
    ratio: float,
    *,
    held: float,
    caps: tuple[float, float] | None,
    limit: float,
    stroke: float,
    beta: float,
    spans: int = SPANS,
) -> float:
    """The least slack ``t`` (length over ``held``) of the pressure rows ``|s' + x| - T (d + s) <= t``,
    ``T = tan(ratio limit)``, over the laws of the space (degree 7 on ``spans`` equal spans, C3 at the knots, at
    rest at both ends: the neighbours are dwells) and the cam centres within ``held`` of the roller's, at 64
    samples a span (they nest the product's relaxation's 17), with ``|S''|``, ``|S'''|`` within the caps (None:
    no caps, the coefficients unbounded) and S within [0, 1] there: above 0 when no law of the space meets the
    ratio. ``tan gamma = (s' + x) / (d + s)`` is the
    textbook form (the offset ``-x``; the disk of centres is symmetric in ``x``, so the cam's sense does not
    matter)."""
    from scipy.interpolate import BSpline
    from scipy.optimize import linprog

    p, m = DEGREE, DEGREE - CONTINUITY
    t = np.concatenate([np.zeros(p + 1), np.repeat(np.arange(1, spans) / spans, m), np.ones(p + 1)])
    nb = t.size - p - 1
    basis = BSpline(t, np.eye(nb), p)
    u = np.linspace(0.0, 1.0, 64 * spans + 1)
    B = [basis.derivative(k)(u) if k else basis(u) for k in range(4)]
    n = nb + 3  # coefficients, the centre (x, d) over held, the slack t
    T = np.tan(ratio * limit)
    rows, rhs = [], []

    def le(a, b):
        rows.append(a)
        rhs.append(b)

    s0, s1 = stroke / held * B[0], stroke / held / beta * B[1]
    for sign in (1.0, -1.0):  # sign (s' + x) - T (d + s) - t <= 0
        a = np.zeros((u.size, n))
        a[:, :nb] = sign * s1 - T * s0
        a[:, nb], a[:, nb + 1], a[:, nb + 2] = sign, -T, -1.0
        le(a, np.zeros(u.size))
        for k, cap in () if caps is None else ((2, caps[0]), (3, caps[1])):
            a = np.zeros((u.size, n))
            a[:, :nb] = sign * B[k]
            le(a, np.full(u.size, cap))
    a = np.zeros((u.size, n))
    a[:, :nb] = B[0]
    le(a, np.full(u.size, 1 + 1e-6))
    le(-a, np.full(u.size, 1e-6))
    th = np.linspace(0.0, 2 * np.pi, 720, endpoint=False)  # the disk of radius held inside the polygon
    a = np.zeros((th.size, n))
    a[:, nb], a[:, nb + 1] = np.cos(th), np.sin(th)
    le(a, np.ones(th.size))
    ends = [(k, x) for k in range(4) for x in (0.0, 1.0)]
    A = np.zeros((len(ends), n))
    b = np.zeros(len(ends))
    for j, (k, x) in enumerate(ends):
        A[j, :nb] = (basis.derivative(k) if k else basis)(np.array([x]))[0]
        b[j] = 1.0 if (k == 0 and x == 1.0) else 0.0
    bounds = [(None, None)] * nb + [(-1.0, 1.0), (0.0, 1.0), (-1.0, 1.0)]
    cost = np.zeros(n)
    cost[-1] = 1.0
    G, h = np.vstack(rows), np.concatenate(rhs)
    norm = np.linalg.norm(G, axis=1)
    res = linprog(cost, A_ub=G / norm[:, None], b_ub=h / norm, A_eq=A, b_eq=b, bounds=bounds, method="highs")
    assert res.status == 0, res.message
    return float(res.fun)


def test_value_is_the_returned_laws_pressure_angle(solved):
    """The value is the returned laws' largest ratio of pressure angle to limit, by the independent check at
    200,001 angles; the lower bound below it, the gap as printed."""
    from cams.verify.pressure import pressure_angle

    o = solved.optimization.to_dict()
    design = solved.design
    g = np.abs(pressure_angle(design, solved.centre, 0, np.linspace(0.0, 1.0, 200_001)))
    assert o["value"] == pytest.approx(g.max() / design.limits.pressure_angle, rel=1e-7)
    assert o["lower_bound"] <= o["value"] < 1.0
    assert o["gap"] == pytest.approx((o["value"] - o["lower_bound"]) / o["value"], rel=1e-12)
    assert solved.verified and o["certified"]


def test_no_law_below_the_lower_bound_and_one_at_the_value(solved):
    """The independent linear program has no law at the proven lower bound and one at the value: the two ends
    bracket the space's least ratio, whatever the product's programs."""
    from laws.characteristics import characteristics
    from laws.standard import Poly4567

    o = solved.optimization.to_dict()
    design = solved.design
    ch = characteristics(Poly4567())
    kw = {
        "held": o["held_R0"],
        "caps": (ch.ca, ch.cj),
        "limit": design.limits.pressure_angle,
        "stroke": float(design.program.lift),
        "beta": float(design.program.phases[0].angle),
    }
    assert _least_slack(o["lower_bound"], **kw) > 1e-6
    assert _least_slack(o["value"] * (1 + 1e-6), **kw) <= 1e-9
