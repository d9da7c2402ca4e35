"""Cv, Ca, Cj against published values.

Literature values: Norton, R. L., *Cam Design and Manufacturing Handbook*
(Industrial Press), ch. 3, and VDI 2143 Blatt 1, "Bewegungsgesetze fuer
Kurvengetriebe", as commonly quoted; the books themselves were not at hand.
Checked to 4 significant digits. Values dimensionless (rise 1 over u in
[0, 1]).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from laws.characteristics import characteristics, law_table
from laws.polynomial import PolynomialLaw
from laws.registry import LAWS, get_law
from laws.table import TableLaw

INF = math.inf

# name, Cv, Ca, Cj -- literature (Norton ch. 3; VDI 2143), 4 significant digits
PUBLISHED = [
    ("cycloidal", 2.0, 2 * math.pi, 4 * math.pi**2),
    ("poly345", 1.875, 5.7735, 60.0),
    ("poly4567", 2.1875, 7.5132, 52.5),
    ("modified_trapezoid", 2.0, 4.888, 61.43),  # Norton lists Cj 61.4
    ("modified_sine", 1.760, 5.528, 69.47),  # Norton lists Cj 69.5
    ("harmonic", math.pi / 2, math.pi**2 / 2, INF),  # soft impacts at the dwells
    ("parabolic", 2.0, 4.0, INF),  # constant acceleration: soft impacts
    ("linear", 1.0, INF, INF),  # constant velocity: hard impacts
]

# Derived here, NOT literature: closed forms of the law as implemented in
# laws.modified.ModifiedCycloid (cycloid split by a constant-velocity middle).
# The published Wildt form (Rothbart) could not be consulted; see its docstring.
DERIVED = [("modified_cycloid", 4 / 3, 8 * math.pi / 3, 32 * math.pi**2 / 3)]


def _close(x, ref, sig=4):
    if math.isinf(ref):
        return math.isinf(x)
    return x == pytest.approx(ref, rel=0.5 * 10 ** (1 - sig))


@pytest.mark.parametrize("name, cv, ca, cj", PUBLISHED, ids=[p[0] for p in PUBLISHED])
def test_published_values(name, cv, ca, cj):
    c = characteristics(get_law(name))
    assert _close(c.cv, cv) and _close(c.ca, ca) and _close(c.cj, cj), c


@pytest.mark.parametrize("name, cv, ca, cj", DERIVED, ids=[p[0] for p in DERIVED])
def test_derived_values(name, cv, ca, cj):
    c = characteristics(get_law(name))
    assert c.cv == pytest.approx(cv, rel=1e-9)
    assert c.ca == pytest.approx(ca, rel=1e-9)
    assert c.cj == pytest.approx(cj, rel=1e-9)


def test_closed_forms_of_the_modified_laws_to_full_precision():
    # derived in laws.modified from S(1/2) = 1/2
    pi = math.pi
    mt = characteristics(get_law("modified_trapezoid"))
    assert (mt.cv, mt.ca, mt.cj) == pytest.approx((2.0, 8 * pi / (pi + 2), 32 * pi**2 / (pi + 2)), rel=1e-10)
    ms = characteristics(get_law("modified_sine"))
    assert (ms.cv, ms.ca, ms.cj) == pytest.approx((4 * pi / (pi + 4), 4 * pi**2 / (pi + 4), 16 * pi**3 / (pi + 4)), rel=1e-10)


def test_refinement_finds_interior_peaks():
    # 3-4-5: peak acceleration at u = 1/2 - sqrt(3)/6, between samples; exact 10 sqrt(3)/3
    assert characteristics(get_law("poly345")).ca == pytest.approx(10 * math.sqrt(3) / 3, rel=1e-12)


def test_infinite_for_user_laws_with_end_jumps():
    # velocity 1 at the start: a hard impact against a dwell
    c = characteristics(PolynomialLaw.from_boundary(start=(1.0,), end=(0.0,)))
    assert math.isinf(c.ca) and math.isinf(c.cj) and math.isfinite(c.cv)
    # zero velocity, non-zero acceleration at the end: soft impact only
    c = characteristics(PolynomialLaw.from_boundary(start=(0, 0), end=(0, 2.0)))
    assert math.isfinite(c.ca) and math.isinf(c.cj)


def test_clamped_table_is_finite():
    u = np.linspace(0, 1, 9)
    c = characteristics(TableLaw(u, u - np.sin(2 * np.pi * u) / (2 * np.pi), clamped=True))
    assert all(math.isfinite(x) for x in (c.cv, c.ca, c.cj))


def test_law_table_rows():
    rows = law_table()
    assert [r["name"] for r in rows] == list(LAWS)
    for r in rows:
        assert set(r) == {"name", "Cv", "Ca", "Cj"}
        assert isinstance(r["Cv"], float)
        assert all(r[k] is None or (isinstance(r[k], float) and math.isfinite(r[k])) for k in ("Ca", "Cj"))
    lin = rows[0]
    assert lin == {"name": "linear", "Cv": 1.0, "Ca": None, "Cj": None}


def test_cached():
    law = get_law("cycloidal")
    assert characteristics(law) is characteristics(law)


def test_rejects_non_laws():
    from laws.errors import InputError

    with pytest.raises(InputError) as e:
        characteristics("cycloidal")
    assert e.value.field == "law"
