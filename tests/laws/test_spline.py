"""Spline laws: piecewise polynomials in Bernstein form, checked against independent references."""

from __future__ import annotations

import math
from fractions import Fraction
from itertools import pairwise

import numpy as np
import pytest

from laws import SplineLaw
from laws.bernstein import subdivision
from laws.characteristics import characteristics
from laws.diagnostics import law_jumps
from laws.errors import InputError
from laws.standard import Parabolic, Poly345, Poly4567

U = np.linspace(0.0, 1.0, 1001)
#: Bernstein coefficients of the classical polynomials on [0, 1] (smoothstep: sum of the upper half of the basis)
B345 = (0, 0, 0, 1, 1, 1)
B4567 = (0, 0, 0, 0, 1, 1, 1, 1)


def split(b, breaks) -> list[list[float]]:
    """Exact Bernstein coefficients on each ``[breaks[j], breaks[j+1]]`` of the polynomial ``b`` on [0, 1].

    The blossom evaluated in rational arithmetic (de Casteljau with the span's ends as parameters), rounded once:
    a reference independent of :mod:`laws.bernstein`.
    """
    p = len(b) - 1
    out = []
    for a, c in pairwise(breaks):
        row = []
        for i in range(p + 1):
            pts = [Fraction(x) for x in b]
            for s in [Fraction(a)] * (p - i) + [Fraction(c)] * i:
                pts = [(1 - s) * pts[k] + s * pts[k + 1] for k in range(len(pts) - 1)]
            row.append(float(pts[0]))
        out.append(row)
    return out


def assert_same_law(law, ref, rel=1e-12):
    """``S .. S'''`` agree to ``rel`` times each derivative's peak (at least 1)."""
    got, want = law.evaluate(U), ref.evaluate(U)
    for k in range(4):
        scale = max(1.0, float(np.abs(want[k]).max()))
        np.testing.assert_allclose(got[k], want[k], rtol=0, atol=rel * scale, err_msg=f"derivative {k}")


# --------------------------------------------------------------------------- against the classical polynomials
@pytest.mark.parametrize("ref, b", [(Poly345(), B345), (Poly4567(), B4567)], ids=["345", "4567"])
def test_one_span_is_the_polynomial(ref, b):
    law = SplineLaw((0.0, 1.0), (b,))
    assert law.degree == len(b) - 1 and law.spans == 1 and law.breakpoints == ()
    assert_same_law(law, ref)


@pytest.mark.parametrize("breaks", [
    (0, Fraction(1, 2), 1),
    (0, Fraction(1, 4), Fraction(1, 2), Fraction(3, 4), 1),
    (0, Fraction(1, 8), Fraction(1, 2), Fraction(3, 4), 1),   # non-uniform
], ids=["2", "4", "non-uniform"])
@pytest.mark.parametrize("ref, b", [(Poly345(), B345), (Poly4567(), B4567)], ids=["345", "4567"])
def test_split_polynomial_is_the_polynomial(ref, b, breaks):
    law = SplineLaw(tuple(float(x) for x in breaks), split(b, breaks))
    assert law.spans == len(breaks) - 1
    assert law.breakpoints == tuple(float(x) for x in breaks[1:-1])
    assert_same_law(law, ref)
    assert law_jumps(law) == ()  # the pieces meet smoothly


@pytest.mark.parametrize("ref, b", [(Poly345(), B345), (Poly4567(), B4567)], ids=["345", "4567"])
def test_split_by_the_subdivision_matrix(ref, b):
    """laws.bernstein.subdivision's coefficients (rounded through a matrix product) give the same law."""
    p = len(b) - 1
    law = SplineLaw.uniform((subdivision(p, 2) @ np.array(b, float)).tolist())
    assert law.breaks == (0.0, 0.5, 1.0)
    assert_same_law(law, ref)


def test_parabolic_as_two_spans_of_degree_2():
    law = SplineLaw.uniform([[0, 0, 0.5], [0.5, 1, 1]], name="parabolic spline")
    assert law.degree == 2 and law.name == "parabolic spline"
    assert_same_law(law, Parabolic(), rel=1e-14)
    # on the break the later span's values: S'' = -4 at u = 0.5, like the closed form
    assert law.evaluate(0.5)[2] == -4.0


def test_derivatives_are_those_of_s(central_difference):
    """A C0 spline of degree 6 on uneven spans: S', S'', S''' against central differences (off the breaks)."""
    rng = np.random.default_rng(7)
    rows = rng.uniform(-1, 2, size=(3, 7))
    rows[0, 0], rows[-1, -1] = 0.0, 1.0
    rows[1, 0], rows[2, 0] = rows[0, -1], rows[1, -1]
    law = SplineLaw((0.0, 0.3, 0.55, 1.0), rows.tolist())
    u = np.concatenate([np.linspace(0.01, 0.29, 20), np.linspace(0.31, 0.54, 20), np.linspace(0.56, 0.99, 20)])
    d = law.evaluate(u)
    for k in range(3):
        fd = central_difference(lambda x, k=k: law.evaluate(x)[k], u)
        np.testing.assert_allclose(fd, d[k + 1], rtol=1e-6, atol=1e-6 * max(1.0, float(np.abs(d[k + 1]).max())))


def elevate(b, q: int) -> list[Fraction]:
    """Exact Bernstein coefficients at degree ``q`` of the polynomial ``b`` (``b'_i = sum_j C(p, j) C(q - p,
    i - j) / C(q, i) b_j``, rational)."""
    p = len(b) - 1
    return [sum((Fraction(math.comb(p, j) * math.comb(q - p, i - j), math.comb(q, i)) * Fraction(b[j])
                 for j in range(max(0, i - q + p), min(p, i) + 1)), Fraction(0)) for i in range(q + 1)]


@pytest.mark.parametrize(("degree", "spans"), [(11, 40), (7, 100), (11, 100)])
def test_many_short_spans_of_high_degree_keep_their_derivatives(degree, spans):
    """The 4-5-6-7 polynomial as a spline of degree 11 on 40 spans (and 7 or 11 on 100): its derivatives to the
    rounding of its coefficients, the second zero at the ends, Cj = 52.5 and finite. A k-th difference of the
    coefficients is exact to 2**k * 4 units of rounding, times p!/(p-k)! / h**k, and the sum over the basis
    (nonnegative, summing to 1) adds a few units per term of the derivative's size; the power form's Horner's
    rule gave the second derivative at u = 1 as 1.4e-7 on a designed law of degree 11 on 40 spans (its Cj
    infinite: a soft impact at the end)."""
    breaks = [Fraction(j, spans) for j in range(spans + 1)]
    law = SplineLaw.uniform(split(elevate(B4567, degree), breaks))
    u = np.concatenate([np.linspace(0.0, 1.0, 4001), [float(b) for b in breaks]])
    got, want = law.evaluate(u), Poly4567().evaluate(u)
    eps = np.finfo(float).eps
    for k in range(4):
        size = max(1.0, float(np.abs(want[k]).max()))
        tol = (2**k * 4 * math.perm(degree, k) * spans**k + 16 * (degree + 1) * size) * eps
        np.testing.assert_allclose(got[k], want[k], rtol=0, atol=tol, err_msg=f"derivative {k}")
    ends = law.evaluate(np.array([0.0, 1.0]))
    assert np.all(np.abs(ends[2]) <= 16 * eps * math.perm(degree, 2) * spans**2)
    c = characteristics(law)
    assert (c.cv, c.ca, c.cj) == pytest.approx((2.1875, 7.5131884, 52.5), rel=2e-8)


def test_evaluate_keeps_the_shape_and_clips():
    law = SplineLaw.uniform([[0, 0, 0.5], [0.5, 1, 1]])
    assert law.evaluate(0.25).shape == (4,)
    assert law.evaluate(np.full((2, 3), 0.75)).shape == (4, 2, 3)
    np.testing.assert_array_equal(law.evaluate([-1.0, 2.0])[0], [0.0, 1.0])


# --------------------------------------------------------------------------- diagnostics see the breaks
def test_characteristics_of_the_345_spline():
    c = characteristics(SplineLaw((0.0, 1.0), (B345,)))
    assert c.cv == pytest.approx(1.875, abs=1e-9)
    assert c.ca == pytest.approx(5.7735, abs=1e-4)
    assert c.cj == pytest.approx(60.0, abs=1e-9)


def test_characteristics_of_the_split_345_spline():
    breaks = (0, Fraction(1, 4), Fraction(1, 2), 1)
    c = characteristics(SplineLaw(tuple(float(x) for x in breaks), split(B345, breaks)))
    assert (c.cv, c.ca, c.cj) == pytest.approx((1.875, 5.7735027, 60.0), abs=1e-6)


def test_a_jump_of_s2_at_a_break_is_found():
    """Constant acceleration up to u = c, constant deceleration after: S'' jumps from 2/c to -2/(1-c)."""
    c = 0.3
    law = SplineLaw((0.0, c, 1.0), [[0, 0, c], [c, 1, 1]])
    (jump,) = law_jumps(law)
    assert jump.u == c and jump.kind == "soft"
    assert jump.size == pytest.approx(-2 / (1 - c) - 2 / c, rel=1e-6)
    assert math.isinf(characteristics(law).cj)


def test_a_jump_of_s1_at_a_break_is_found():
    law = SplineLaw.uniform([[0, 0.6], [0.6, 1]])
    assert [(j.u, j.kind) for j in law_jumps(law)] == [(0.5, "hard")]
    assert law_jumps(law)[0].size == pytest.approx(-0.4, rel=1e-6)


def test_breakpoints_are_the_instances_own():
    a = SplineLaw((0.0, 0.25, 1.0), [[0, 0, 0.25], [0.25, 1, 1]])
    b = SplineLaw.uniform([[0, 0, 0.5], [0.5, 1, 1]])
    assert (a.breakpoints, b.breakpoints, SplineLaw.breakpoints) == ((0.25,), (0.5,), ())


def test_equal_and_hashable():
    a = SplineLaw.uniform([[0, 0, 0.5], [0.5, 1, 1]])
    b = SplineLaw((0, 0.5, 1), ((0.0, 0.0, 0.5), (0.5, 1.0, 1.0)))
    assert a == b and hash(a) == hash(b)
    assert a.coefficients == ((0.0, 0.0, 0.5), (0.5, 1.0, 1.0)) and a.breaks == (0.0, 0.5, 1.0)


def test_ends_within_tolerance_are_accepted():
    law = SplineLaw((1e-13, 1 - 1e-13), ((1e-10, 0.5, 1 + 1e-10),))
    assert law.breaks == (0.0, 1.0)  # the ends are exact
    assert law.coefficients == ((1e-10, 0.5, 1 + 1e-10),)  # the coefficients as given


def test_degree_15_is_the_largest():
    law = SplineLaw((0.0, 1.0), (tuple(i / 15 for i in range(16)),))  # S = u at degree 15
    np.testing.assert_allclose(law.evaluate(U)[:2], [U, np.ones_like(U)], atol=1e-12)


# --------------------------------------------------------------------------- validation: one test each
def _raises(field, word, breaks, coefficients):
    with pytest.raises(InputError, match=word) as e:
        SplineLaw(breaks, coefficients)
    assert e.value.field == field


def test_coefficients_not_a_sequence():
    _raises("spline.coefficients", "sequence", (0, 1), 3.0)


def test_coefficients_empty():
    _raises("spline.coefficients", "non-empty", (0, 1), ())


def test_coefficients_a_string():
    _raises("spline.coefficients", "sequence", (0, 1), ("abc",))


def test_coefficients_not_numbers():
    _raises("spline.coefficients", "numbers", (0, 1), ((0, "x", 1),))


def test_coefficients_nested_too_deep():
    _raises("spline.coefficients", "flat", (0, 1), (((0, 1),),))


def test_coefficients_not_finite():
    _raises("spline.coefficients", "finite", (0, 1), ((0, math.nan, 1),))


def test_spans_of_different_lengths():
    _raises("spline.coefficients", "same number", (0, 0.5, 1), ((0, 0, 0.5), (0.5, 1)))


def test_degree_0_refused():
    _raises("spline.coefficients", "degree", (0, 1), ((1.0,),))


def test_degree_16_refused():
    _raises("spline.coefficients", "degree", (0, 1), (tuple(i / 16 for i in range(17)),))


def test_breaks_count():
    _raises("spline.breaks", "one more break", (0, 1), ((0, 0, 0.5), (0.5, 1, 1)))


def test_breaks_not_numbers():
    _raises("spline.breaks", "numbers", (0, "half", 1), ((0, 0, 0.5), (0.5, 1, 1)))


def test_breaks_not_finite():
    _raises("spline.breaks", "finite", (0, math.inf, 1), ((0, 0, 0.5), (0.5, 1, 1)))


def test_breaks_not_increasing():
    _raises("spline.breaks", "increasing", (0, 0.6, 0.4, 1), ((0, 0.2), (0.2, 0.5), (0.5, 1)))


def test_breaks_repeated():
    _raises("spline.breaks", "increasing", (0, 0.5, 0.5, 1), ((0, 0.2), (0.2, 0.5), (0.5, 1)))


def test_breaks_not_from_0():
    _raises("spline.breaks", "start at 0", (0.1, 1), ((0, 1),))


def test_breaks_not_to_1():
    _raises("spline.breaks", "end at 1", (0, 0.9), ((0, 1),))


def test_s_not_0_at_the_start():
    _raises("spline.coefficients", r"S\(0\) = 0", (0, 1), ((0.01, 1),))


def test_s_not_1_at_the_end():
    _raises("spline.coefficients", r"S\(1\) = 1", (0, 1), ((0, 0.99),))


def test_s_jumps_at_a_break():
    _raises("spline.coefficients", r"continuous.*u = 0\.25", (0, 0.25, 1), ((0, 0, 0.25), (0.3, 1, 1)))


def test_uniform_needs_spans():
    with pytest.raises(InputError, match="non-empty") as e:
        SplineLaw.uniform([])
    assert e.value.field == "spline.coefficients"


def test_bernstein_coefficient_bound_holds_for_random_polynomials():
    """laws.bernstein.coefficient_bound: no coefficient beyond K times the polynomial's largest |value| on [0, 1]
    (dense evaluation, 2001 points; the worst of 300 random polynomials a degree comes within 10 % of K)."""
    from laws.bernstein import basis, coefficient_bound

    rng = np.random.default_rng(1)
    t = np.linspace(0, 1, 2001)
    for p in range(1, 9):
        K = coefficient_bound(p)
        B = basis(p, t)
        ratios = []
        for _ in range(300):
            b = rng.standard_normal(p + 1) * rng.uniform(0.1, 10) * (rng.random(p + 1) < 0.8)
            top = np.max(np.abs(B @ b))
            if top > 0:
                ratios.append(np.max(np.abs(b)) / top)
        assert max(ratios) <= K
