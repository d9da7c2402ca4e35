"""The closing spring one can buy (cams.dynamics.forces.spring_for_contact): rate, preload, installed compression.

What a chosen spring must be is checked against things that share no formula with the choice:

* the force contact needs, ``margin (-m q'' - P)``, from central finite differences of the lift ``s(phi)`` alone
  (the program's value, never its derivatives), on a grid ten times finer than the one the choice samples;
* the least largest force over (rate, installed compression) by a brute-force search on a grid of springs, and by
  scipy's LP solver (HiGHS) on the finite-difference constraints, with ``lo k <= F0 <= hi k`` for the bounds;
* the stiffest of the least largest force by a second LP;
* the hint of a spring too strong for ``max_spring_force`` by choosing again with the hinted bound.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from cams.dynamics.forces import chosen_spring, spring_for_contact
from cams.io.designfile import design_from_dict, load_design
from cams.model.dynamics import FollowerDynamics
from laws.errors import InputError
from laws.units import rpm_to_omega
from tests.conftest import EXAMPLES, rocker_dict

TRANS = load_design(EXAMPLES / "translating_force.toml")
ROCKER = design_from_dict(
    rocker_dict(
        motion=[
            {"phase": "rise", "law": "cycloidal", "angle": 100},
            {"phase": "dwell", "angle": 40},
            {"phase": "return", "law": "poly345", "angle": 140},
            {"phase": "dwell"},
        ]
    )
)
# a harmonic rise decelerates hardest at its very end, the far dwell: the largest need sits at the full lift, where
# the least largest force no longer fixes the installed compression (step 3 of the proof: the stiffest is taken)
HARMONIC = design_from_dict(
    rocker_dict(
        motion=[
            {"phase": "rise", "law": "harmonic", "angle": 120},
            {"phase": "dwell", "angle": 30},
            {"phase": "return", "law": "cycloidal", "angle": 150},
            {"phase": "dwell"},
        ]
    )
)
CASES = {
    "translating": (TRANS, FollowerDynamics(0.5, load=5.0), 1e-3),  # m per mm
    "rocker": (ROCKER, FollowerDynamics(0.004, load=0.5), 1.0),  # rad per rad
    "harmonic": (HARMONIC, FollowerDynamics(0.004, load=0.0), 1.0),
}


def fd_need(design, dyn, rpm, margin, si, n=36000):
    """q (m or rad) and the force contact needs, by central differences of the lift alone, on ``n`` angles.

    Angles within two steps of a phase joint (where the acceleration may jump) are left out: a difference across
    the joint is no one-sided value.
    """
    phi = np.linspace(0, 2 * np.pi, n, endpoint=False)
    dx = 1e-4
    starts = np.asarray(design.program.starts)
    near = np.min(np.abs(np.angle(np.exp(1j * (phi[:, None] - starts[None, :])))), axis=1) < 2 * dx
    phi = phi[~near]

    def s(x):
        return design.program.evaluate(np.mod(x, 2 * np.pi)).s * si

    q = s(phi)
    d2q = (s(phi + dx) - 2 * q + s(phi - dx)) / dx**2
    w = rpm_to_omega(rpm)
    return q, margin * (-dyn.mass * w**2 * d2q - dyn.load)


def stroke(design, si):
    return float(design.program.lift) * si


@pytest.mark.parametrize("name", sorted(CASES))
@pytest.mark.parametrize("rpm", [200.0, 600.0])
@pytest.mark.parametrize("bounds", [(None, None), (0.1, 0.5), (0.0, 2.0)])  # fractions of the stroke
def test_least_largest_force_against_lp_and_brute_force(name, rpm, bounds):
    from scipy.optimize import linprog

    design, dyn, si = CASES[name]
    h = stroke(design, si)
    lo, hi = (h / 4, h) if bounds == (None, None) else (bounds[0] * h, bounds[1] * h)
    # the API takes the bounds in mm (translating) or radians (rocker)
    given = {} if bounds == (None, None) else {"min_installed": lo / si, "max_installed": hi / si}
    sp = spring_for_contact(design, dyn, rpm=rpm, margin=1.25, **given)
    q, need = fd_need(design, dyn, rpm, 1.25, si)
    top = sp.preload + sp.rate * h
    assert sp.rate > 0 and sp.max_force == pytest.approx(top, rel=1e-12)
    assert lo * (1 - 1e-9) <= sp.installed <= hi * (1 + 1e-9)
    # it keeps contact with the margin at every angle (to the differences' round-off)
    assert np.min(sp.preload + sp.rate * q - need) >= -1e-7 * np.max(np.abs(need))
    # the LP over (F0, k): min F0 + k h, F0 + k q_i >= need_i, lo k <= F0 <= hi k
    A = np.vstack([-np.stack([np.ones_like(q), q], axis=1), [[-1.0, lo]], [[1.0, -hi]]])
    b = np.concatenate([-need, [0.0, 0.0]])
    lp = linprog([1.0, h], A_ub=A, b_ub=b, bounds=[(0, None), (0, None)], method="highs")
    assert lp.success
    assert top == pytest.approx(lp.fun, rel=1e-6)
    # the stiffest spring of that largest force (to the differences' 1e-7: where the largest need sits at the full
    # lift, the harmonic rise, springs of many rates come within 1e-9 of it and only the stiffest is asked for)
    stiff = linprog(
        [0.0, -1.0],
        A_ub=np.vstack([A, [[1.0, h]]]),
        b_ub=np.append(b, lp.fun * (1 + 1e-6)),
        bounds=[(0, None), (0, None)],
        method="highs",
    )
    assert stiff.success
    assert sp.rate == pytest.approx(stiff.x[1], rel=1e-3)
    # and a stiffer spring within the bounds needs a larger largest force (the definition, by brute force)
    k2 = 1.01 * sp.rate
    f0 = max(float(np.max(need - k2 * q)), lo * k2)
    assert f0 > hi * k2 or f0 + k2 * h > top * (1 + 1e-6)
    # brute force over a grid of springs (k, d0): none that holds does better, the best is near it
    d0s = np.linspace(lo, hi, 41)
    ks = np.linspace(0.0, 3.0 * sp.rate, 601)[1:]
    K, D = np.meshgrid(ks, d0s, indexing="ij")
    holds = np.ones(K.shape, dtype=bool)
    qb, nb = fd_need(design, dyn, rpm, 1.25, si, n=3600)
    for qi, ni in zip(qb[nb > 0], nb[nb > 0], strict=True):
        holds &= K * (D + qi) >= ni
    largest = np.where(holds, K * (D + h), np.inf)
    best = float(np.min(largest))
    assert np.isfinite(best)
    assert best >= top * (1 - 1e-6)
    assert best <= top * 1.02


def test_the_600_rpm_spring_of_the_issue_has_a_rate():
    """examples/translating_force.toml with mass 0.5 kg, load 5 N at 600 rpm: no longer rate 0 (a constant force)."""
    design, dyn, si = CASES["translating"]
    sp = spring_for_contact(design, dyn, rpm=600.0)
    assert sp.rate > 0 and sp.preload > 0
    # the default bounds: the installed compression is the stroke (the largest force falls as it grows)
    assert sp.installed == pytest.approx(30e-3, rel=1e-9)
    assert sp.preload / sp.max_force == pytest.approx(0.5, rel=1e-9)  # SEED's upper 50 % of preload


def test_given_rate_takes_the_least_preload_within_the_bounds():
    design, dyn, si = CASES["translating"]
    h = stroke(design, si)
    q, need = fd_need(design, dyn, 600.0, 1.2, si)
    for k in (2000.0, 5000.0, 20000.0):
        sp = spring_for_contact(design, dyn, rpm=600.0, rate=k)
        assert sp.rate == k and sp.note is None
        assert np.min(sp.preload + k * q - need) >= -1e-7 * np.max(np.abs(need))
        assert sp.installed >= h / 4 * (1 - 1e-12)
        # least: 0.1 % less preload breaks contact or the least installed compression
        less = 0.999 * sp.preload
        assert np.min(less + k * q - need) < 0 or less / k < h / 4


def test_a_soft_given_rate_is_noted_or_refused():
    """A rate whose least preload needs more than the stroke's compression: a note by default, an error when the
    file bounds it."""
    design, dyn, _ = CASES["translating"]
    sp = spring_for_contact(design, dyn, rpm=600.0, rate=100.0)
    assert sp.note is not None and "above the usual range" in sp.note and sp.installed > 30e-3
    m = re.search(r"at least ([\d.]+) mm", sp.note)
    assert float(m.group(1)) == pytest.approx(sp.installed * 1e3, rel=1e-5)
    with pytest.raises(InputError) as e:
        spring_for_contact(design, dyn, rpm=600.0, rate=100.0, max_installed=40.0)
    assert e.value.field == "dynamics.max_installed_compression" and "\n" not in str(e.value)
    # a rate of 0 stays allowed, without bounds
    sp0 = spring_for_contact(design, dyn, rpm=600.0, rate=0.0)
    assert sp0.rate == 0 and sp0.installed is None and sp0.preload > 0
    with pytest.raises(InputError, match="constant-force"):
        spring_for_contact(design, dyn, rpm=600.0, rate=0.0, max_installed=40.0)


def test_no_spring_needed_when_the_load_holds():
    design, _, _ = CASES["translating"]
    sp = spring_for_contact(design, FollowerDynamics(0.5, load=1000.0), rpm=600.0)
    assert sp.rate == 0 and sp.preload == 0 and "no spring is needed" in sp.note
    # the load alone holds it: need <= 0 everywhere, by the differences
    q, need = fd_need(design, FollowerDynamics(0.5, load=1000.0), 600.0, 1.2, 1e-3)
    assert np.max(need) < 0


def test_max_spring_force_hint_holds():
    """Too strong for max_spring_force: the error names the max_installed_compression that would do, and it does."""
    design, dyn, _ = CASES["translating"]
    sp = spring_for_contact(design, dyn, rpm=600.0)
    cap = 0.97 * sp.max_force  # within reach of a longer spring: the least largest force falls toward max(need)
    limited = FollowerDynamics(0.5, load=5.0, max_spring_force=cap)
    with pytest.raises(InputError) as e:
        spring_for_contact(design, limited, rpm=600.0)
    assert e.value.field == "dynamics.max_spring_force"
    d_req = float(re.search(r"max_installed_compression, ([\d.e+-]+) mm or more", str(e.value)).group(1))
    assert d_req > 30.0
    ok = spring_for_contact(design, limited, rpm=600.0, max_installed=d_req * 1.0001)
    assert ok.max_force <= cap
    with pytest.raises(InputError):
        spring_for_contact(design, limited, rpm=600.0, max_installed=d_req * 0.999)
    # below the largest need no spring can
    q, need = fd_need(design, dyn, 600.0, 1.2, 1e-3)
    with pytest.raises(InputError, match="no spring can"):
        spring_for_contact(design, FollowerDynamics(0.5, load=5.0, max_spring_force=0.99 * np.max(need)), rpm=600.0)


def test_rocker_spring_is_torsional_in_degrees():
    d = design_from_dict(
        rocker_dict(
            cam={"rpm": 300}, dynamics={"mass": 0.004, "load": 0.5, "min_installed_twist": 2, "max_installed_twist": 6}
        )
    )
    sp = chosen_spring(d.dynamics, d)
    assert sp.torsional and sp.rate > 0
    out = sp.to_dict()
    assert "installed_compression" not in out
    assert 2.0 - 1e-9 <= out["installed_twist"] <= 6.0 + 1e-9
    assert out["installed_twist"] == pytest.approx(np.degrees(sp.preload / sp.rate), rel=1e-12)
    assert out["max_force"] == pytest.approx(sp.preload + sp.rate * np.radians(15.0), rel=1e-9)


@pytest.mark.parametrize(
    "dynamics, field",
    [
        ({"min_installed_twist": 8, "max_installed_twist": 4}, "dynamics.max_installed_twist"),
        ({"min_installed_twist": -1}, "dynamics.min_installed_twist"),
        ({"max_installed_twist": "long"}, "dynamics.max_installed_twist"),
        ({"min_installed_compression": 5}, "dynamics.min_installed_compression"),  # a rocker's spring is torsional
        ({"spring_rate": 3.0, "preload": 1.0, "max_installed_twist": 5}, "dynamics.max_installed_twist"),
        ({"spring_rate": 0.0, "min_installed_twist": 5}, "dynamics.min_installed_twist"),
    ],
)
def test_bad_bounds_name_their_field(dynamics, field):
    with pytest.raises(InputError) as e:
        design_from_dict(rocker_dict(cam={"rpm": 300}, dynamics={"mass": 0.004, **dynamics}))
    assert e.value.field == field and "\n" not in str(e.value)
