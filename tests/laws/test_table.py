"""Laws from a user's table of (u, S) points."""

from __future__ import annotations

import numpy as np
import pytest

from laws.errors import InputError
from laws.registry import get_law
from laws.table import TableLaw


def cycloid_table(n):
    u = np.linspace(0, 1, n)
    return u, u - np.sin(2 * np.pi * u) / (2 * np.pi)


def test_interpolates_the_points():
    u, s = cycloid_table(11)
    law = TableLaw(u, s)
    np.testing.assert_allclose(law.evaluate(u)[0], s, atol=1e-14)


def test_converges_to_the_tabulated_law():
    x = np.linspace(0, 1, 333)
    ref = get_law("cycloidal").evaluate(x)
    err = []
    for n in (21, 41):
        d = TableLaw(*cycloid_table(n)).evaluate(x)
        err.append(np.abs(d[1] - ref[1]).max())
    assert err[1] < err[0] / 8  # high-order convergence of the spline's derivative
    assert err[1] < 1e-4


def test_clamped_ends_meet_dwells():
    u = np.array([0, 0.2, 0.5, 0.8, 1.0])
    s = np.array([0, 0.1, 0.5, 0.9, 1.0])
    d = TableLaw(u, s, clamped=True).evaluate(np.array([0.0, 1.0]))
    np.testing.assert_allclose(d[0], [0, 1], atol=1e-14)
    np.testing.assert_allclose(d[1:3], 0.0, atol=1e-10)


def test_two_point_clamped_table_is_345():
    x = np.linspace(0, 1, 51)
    np.testing.assert_allclose(
        TableLaw([0, 1], [0, 1], clamped=True).evaluate(x), get_law("poly345").evaluate(x), atol=1e-10
    )


def test_derivatives_consistent(central_difference):
    law = TableLaw(*cycloid_table(13))
    u = np.linspace(0.01, 0.99, 60)
    for k in range(3):
        fd = central_difference(lambda x: law.evaluate(x)[k], u)
        np.testing.assert_allclose(fd, law.evaluate(u)[k + 1], atol=1e-5 * 10**k)


@pytest.mark.parametrize(
    "u, s, kw, field, match",
    [
        ([0, 0.5, 0.4, 1], [0, 0.3, 0.6, 1], dict(clamped=True), "table.u", "strictly increasing"),
        ([0, 0.5, 0.5, 1], [0, 0.3, 0.6, 1], dict(clamped=True), "table.u", "strictly increasing"),
        ([0.1, 0.5, 1], [0, 0.5, 1], dict(clamped=True), "table.u", "start at 0"),
        ([0, 0.5, 0.9], [0, 0.5, 1], dict(clamped=True), "table.u", "end at 1"),
        ([0, 0.5, 1], [0.1, 0.5, 1], dict(clamped=True), "table.s", "start at 0"),
        ([0, 0.5, 1], [0, 0.5, 2], dict(clamped=True), "table.s", "end at 1"),
        ([0, 0.5, 1], [0, 1], dict(clamped=True), "table.s", "match"),
        ([0, 0.5, 1], [0, 0.5, 1], dict(), "table.u", "at least 6 points"),
        ([0], [0], dict(clamped=True), "table.u", "at least 2 points"),
        ([0, "a", 1], [0, 0.5, 1], dict(clamped=True), "table.u", "numbers"),
        ([0, 0.5, 1], [0, float("nan"), 1], dict(clamped=True), "table.s", "finite"),
        ([[0, 1]], [[0, 1]], dict(clamped=True), "table.u", "one-dimensional"),
    ],
)
def test_bad_tables(u, s, kw, field, match):
    with pytest.raises(InputError, match=match) as e:
        TableLaw(u, s, **kw)
    assert e.value.field == field


def test_frozen_hashable_and_equal():
    a = TableLaw(*cycloid_table(8))
    b = TableLaw(*cycloid_table(8))
    assert a == b and hash(a) == hash(b)
    with pytest.raises(AttributeError):
        a.clamped = True
