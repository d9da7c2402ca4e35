"""When no cam centre is admissible: the binding limit and its nearest feasible value (issue 12, item 12).

Independent references:

* geometry: a rocker's wedges turn with it through the swing psi, so they share
  a direction to infinity only when the limit exceeds psi / 2; below it the
  zones of these designs are empty, above it they reach infinity, and the least
  R0 grows without bound as the limit falls to psi / 2 (an infimum, not
  attained);
* brute force: a grid of centres judged by the validation reference
  (``tests.validation.reference.ReferenceZone``: kinematic inversion, no zone
  formulas), each admissible one confirmed by :func:`cams.verify.pressure.check_pressure`:
  none is admissible just below the reported value, some are just above it.
"""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import design_from_dict
from cams.solve import solve
from cams.verify.pressure import check_pressure, check_pressure_many
from laws.errors import CamsError, InfeasibleError, SolverError
from optimize.diagnose import _attained, diagnosed, explain_infeasible, relaxations, zone_margin
from tests.conftest import EXAMPLES, rocker_dict
from tests.validation.reference import ReferenceZone

FORCE_7 = rocker_dict(limits={"pressure_angle": 7})  # swing 15 deg
FORM_RETURN_5 = rocker_dict(limits={"closure": "form", "pressure_angle": 45, "return_pressure_angle": 5,
                                    "safety_factor": 1.1})


def _error(dct) -> InfeasibleError:
    with pytest.raises(InfeasibleError) as info:
        solve(design_from_dict(dct))
    return info.value


def _value(msg: str, word: str) -> float:
    return float(re.search(word + r" is ([0-9.]+) deg", msg).group(1))


def _reference_admissible(design, P: np.ndarray) -> np.ndarray:
    """Which of the centres ``P`` the reference finds admissible at 200 steps a phase (those rejected at 8 of
    the same positions first: the same answer, less work)."""
    return ReferenceZone(design, 200).admissible(P, prefilter=ReferenceZone(design, 8))


def _grid_admissible(design, half: float = 3000.0, step: float = 15.0) -> np.ndarray:
    """Centres of a grid about the pivot that the reference finds admissible (200 steps a phase)."""
    x = np.arange(-half, half + step, step)
    X, Y = np.meshgrid(x, x)
    P = np.stack([X.ravel(), Y.ravel()], axis=1)
    return P[_reference_admissible(design, P)]


def _brute_force_brackets(dct, key: str, value_deg: float, **grid):
    """Nothing admissible 0.1 deg below the value; something 0.5 deg above, confirmed by check_pressure.

    The reference knows no safety factor: its zone holds the K_C zone, so nothing there below the value means
    nothing in the K_C zone either, and above it one of its centres (40 spread over them) must pass the check
    with K_C held, as the diagnosis says ("the other limits held").
    """
    d = design_from_dict(dct)
    below = d.with_(limits=replace(d.limits, **{key: np.radians(value_deg - 0.1)}))
    above = d.with_(limits=replace(d.limits, **{key: np.radians(value_deg + 0.5)}))
    assert len(_grid_admissible(below, **grid)) == 0
    found = _grid_admissible(above, **grid)
    assert len(found) > 0
    assert any(r.ok for r in check_pressure_many(above, found[::max(1, len(found) // 40)]))


def test_force_rocker_7_deg_names_the_rise_limit_and_its_infimum():
    """Before: "limits.pressure_angle: no cam centre satisfies the pressure-angle limits" (bare)."""
    e = _error(FORCE_7)
    msg = str(e)
    assert e.field == "limits.pressure_angle" and "\n" not in msg
    assert "7 deg on the rise" in msg and "other limits held" in msg
    inf = _value(msg, "infimum")
    assert inf == pytest.approx(15.0 / 2, abs=2e-4)  # psi / 2
    assert "not attained" in msg
    _brute_force_brackets(FORCE_7, "pressure_angle", inf)
    # the least R0 grows without bound towards the infimum
    d = design_from_dict(FORCE_7)
    r0 = [solve(d.with_(limits=replace(d.limits, pressure_angle=np.radians(inf + dg)))).R0 for dg in (1.0, 0.1)]
    assert r0[1] > 2 * r0[0]


#: Two rises (the second one linear) of a rocker: the zone is bounded near its least limit (a design of
#: the random campaign).
TWO_RISES = {
    "name": "two rises", "cam": {"rotation": "ccw"},
    "follower": {"kind": "rocker", "arm": 289.7011484176052, "swing": 42.148368567828854,
                 "roller_radius": 14.485057420880262, "rise_direction": "ccw"},
    "motion": [{"phase": "rise", "law": "cycloidal", "angle": 60.0, "height": 8.723812952238216},
               {"phase": "dwell", "angle": 20.0},
               {"phase": "rise", "law": "linear", "angle": 60.0, "height": 33.424555615590634},
               {"phase": "dwell", "angle": 20.0}, {"phase": "return", "law": "cycloidal", "angle": 100.0},
               {"phase": "dwell"}],
    "limits": {"pressure_angle": 10, "closure": "force"},
}


def test_attained_least_value_of_a_bounded_zone():
    """A bounded zone shrinking to a segment: "the least feasible is ..." (attained), bracketed by brute force."""
    e = _error(TWO_RISES)
    msg = str(e)
    assert e.field == "limits.pressure_angle" and "10 deg on the rise" in msg and "not attained" not in msg
    least = _value(msg, "least feasible")
    assert least == pytest.approx(16.7123, abs=2e-4)  # regression value of this module (bisection, 1e-6 deg)
    assert least < 42.148368567828854 / 2  # below psi / 2: a bounded zone, not one reaching infinity
    _brute_force_brackets(TWO_RISES, "pressure_angle", least, half=1000.0, step=4.0)
    # the printed value, rounded up, is itself feasible
    d = design_from_dict(TWO_RISES)
    assert solve(d.with_(limits=replace(d.limits, pressure_angle=np.radians(least)))).pressure.ok


def test_form_return_limit_is_reported_against_the_return_field():
    """Before: the return limit of 5 deg was reported against limits.pressure_angle."""
    e = _error(FORM_RETURN_5)
    assert e.field == "limits.return_pressure_angle"
    assert "5 deg on the return" in str(e)
    inf = _value(str(e), "infimum")
    assert inf == pytest.approx(7.5, abs=2e-4)
    _brute_force_brackets(FORM_RETURN_5, "return_pressure_angle", inf)


def test_both_limits_too_small_relaxed_together():
    dct = rocker_dict(limits={"closure": "form", "pressure_angle": 5, "return_pressure_angle": 6})
    e = _error(dct)
    assert e.field == "limits.pressure_angle"
    assert "no limit relaxed alone is enough" in str(e)
    assert _value(str(e), "infimum") == pytest.approx(7.5, abs=2e-4)


def test_safety_factor_is_not_offered_when_it_cannot_help():
    """Below psi / 2 the zone is empty at K_C = 1 too: K_C is not named as a fix, the rise limit is."""
    d = design_from_dict(rocker_dict(limits={"pressure_angle": 7, "safety_factor": 1.3}))
    found = relaxations(d)
    assert [r.field for r in found] == ["limits.pressure_angle"]


def test_fixed_L_with_an_empty_zone_names_the_limit(capsys, tmp_path):
    """A fixed L (whose range needs a non-empty zone) on the command line: one line, exit 2, the rise limit,
    its least value with L held (the zone alone would reach 7.5 deg only far from the pivot)."""
    text = (EXAMPLES / "rocker_force.toml").read_text()
    text = re.sub(r"pressure_angle = [0-9.]+", "pressure_angle = 7", text)
    text = text.replace("[limits]", "[limits]\ncentre_distance = 100")
    f = tmp_path / "d.toml"
    f.write_text(text)
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "limits.pressure_angle" in err and "L = 100 mm held" in err and "not attained" not in err
    assert _value(err, "least feasible") > 45.0  # L = 100 is below the least L at 45 deg (110.485 mm)


def _admissible_on_circle(design, L: float, n: int = 20000) -> np.ndarray:
    """Centres at distance L from the pivot (n evenly round) that the validation reference finds admissible."""
    a = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    P = design.follower.pivot + L * np.stack([np.cos(a), np.sin(a)], axis=1)
    return P[_reference_admissible(design, P)]


@pytest.mark.parametrize("L", [200.0, 400.0])
def test_fixed_L_least_limit_is_that_of_the_circle(L):
    """Issue 12, item 12, with limits.centre_distance: the least feasible limit holds L too.

    Before: "the infimum is 7.5000 deg, not attained: every larger value is feasible ... (other limits held)",
    false at a fixed L (10 deg is not feasible at L = 200 mm). Brute force on the circle of radius L about the
    pivot (the validation reference): no admissible centre 0.01 deg below the value, some 0.01 deg above,
    confirmed by check_pressure; the printed value itself is solved and verified.
    """
    dct = rocker_dict(limits={"pressure_angle": 7, "centre_distance": L})
    e = _error(dct)
    msg = str(e)
    assert e.field == "limits.pressure_angle" and f"L = {L:g} mm held" in msg and "not attained" not in msg
    least = _value(msg, "least feasible")
    d = design_from_dict(dct)
    assert least > 7.5
    below = d.with_(limits=replace(d.limits, pressure_angle=np.radians(least - 0.01)))
    above = d.with_(limits=replace(d.limits, pressure_angle=np.radians(least + 0.01)))
    assert len(_admissible_on_circle(below, L)) == 0
    found = _admissible_on_circle(above, L)
    assert len(found) > 0 and check_pressure(above, found[len(found) // 2]).ok
    r = solve(d.with_(limits=replace(d.limits, pressure_angle=np.radians(least))))
    assert r.L == pytest.approx(L, rel=1e-9) and r.pressure.ok


@pytest.mark.parametrize("method", ["convex", "exhaustive"])
def test_sampled_methods_give_the_same_diagnosis(method):
    dd = {**FORCE_7, "solve": {"method": method, "samples": 60}}
    e = _error(dd)
    assert e.field == "limits.pressure_angle" and _value(str(e), "infimum") == pytest.approx(7.5, abs=2e-4)


def test_feasible_design_is_not_diagnosed():
    assert explain_infeasible(design_from_dict(rocker_dict())) is None


def test_attained_or_not():
    """A least R0 converging to a finite value: attained; growing like a power of the distance: not."""
    assert _attained(lambda v: 100.0 + v, 7.5, 1.0)
    assert not _attained(lambda v: (v - 7.5) ** (-1 / 3), 7.5, 1.0)


@pytest.mark.parametrize("closure", ["force", "form"])
@pytest.mark.parametrize("offset", [-150.0, 150.0])
def test_translating_fixed_offset_never_empties_the_zone(closure, offset):
    """Why the diagnosis has no offset case: every wedge widens downwards, so any offset is admissible far enough down.

    Offsets of 5 strokes either side: the exact method sizes a cam on that line, verified independently.
    """
    from tests.stress.helpers import translating_dict

    d = design_from_dict(translating_dict(follower={"offset": offset}, limits={"closure": closure,
                                                                              "pressure_angle": 20}))
    r = solve(d)
    assert r.pressure.ok and r.offset == pytest.approx(offset)


def test_a_solver_that_fails_on_a_non_empty_zone_is_not_reported_as_infeasible_limits():
    """A solver refusing a feasible design: the error blames the solver and gives a centre checked independently.

    A SolverError, not an InfeasibleError (a CamsError, which the command line reports as bad input, exit 2).
    """

    @diagnosed
    def refuses(design, target, *, half_planes=None):
        raise InfeasibleError("limits.pressure_angle", "no cam centre satisfies the pressure-angle limits")

    d = design_from_dict(rocker_dict())
    with pytest.raises(SolverError) as info:
        refuses(d, d.follower.position(0.0))
    assert not isinstance(info.value, CamsError)
    assert "the zone is not empty" in str(info.value) and "try another method" in str(info.value)
    R0 = float(re.search(r"R0 = ([0-9.e+]+) mm", str(info.value)).group(1))
    assert R0 >= solve(d).R0 * (1 - 1e-9)  # no centre nearer than the least R0
    # the centre the message names (the zone's own proof, upper <= 0) is admissible by the independent check
    _, upper, O = zone_margin(d)
    assert upper <= 0 and check_pressure(d, O).ok
    assert R0 == pytest.approx(float(np.linalg.norm(O - d.follower.position(0.0))), rel=1e-5)


def test_attained_when_the_least_R0_converges_slowly():
    """R0* - c d^0.4 (steps shrink 2.5-fold a decade) is attained; c log(1/d) (equal steps) is not."""
    assert _attained(lambda v: 8400.0 - 3000.0 * (v - 15.0) ** 0.4, 15.0, 75.0)
    assert not _attained(lambda v: 500.0 * np.log(1.0 / (v - 15.0)), 15.0, 75.0)


def test_random_rockers_infimum_is_half_the_swing_or_attained_below():
    """Random rockers with small limits (both closures, any law, multi-rise programs, K_C, any scale).

    Geometry: the zone reaches infinity exactly when the limit exceeds psi / 2,
    so a bound that is not attained is psi / 2, and an attained one lies at or
    below it (a bounded zone). Every message is one line naming a limit.
    """
    import random

    from tests.stress.test_stress_properties import random_design

    rng = random.Random(11)
    seen = {"attained": 0, "not": 0}
    while sum(seen.values()) < 12:
        dd = random_design(rng)
        dd["limits"]["pressure_angle"] = rng.uniform(1, 25)
        if "return_pressure_angle" in dd["limits"]:
            dd["limits"]["return_pressure_angle"] = rng.uniform(1, 40)
        if dd["follower"]["kind"] != "rocker":
            continue
        try:
            solve(design_from_dict(dd))
            continue
        except InfeasibleError as e:
            msg, field = str(e), e.field
        assert "\n" not in msg and field in ("limits.pressure_angle", "limits.return_pressure_angle"), msg
        half = dd["follower"]["swing"] / 2
        if "not attained" in msg:
            assert _value(msg, "infimum") == pytest.approx(half, abs=1e-3), msg
            seen["not"] += 1
        else:
            assert _value(msg, "least feasible") <= half + 1e-3, msg
            seen["attained"] += 1
    assert seen["not"] >= 6  # the attained case: also test_attained_least_value_of_a_bounded_zone


def test_limit_at_half_the_swing_is_diagnosed_not_left_uncertified(capsys, tmp_path):
    """A form-closed rocker, swing 60 deg, limit 30 deg = psi / 2: the zone's infimum, not attained (the wedges
    share a direction to infinity only above psi / 2; the cam grows without bound as the limit falls to it).
    Before: exit 1, "not certified: ... R0 (1.05e7 mm) ... no feasible centre was found near it; try --method
    convex". Now the diagnosis, exit 2, one line; 0.5 deg above the infimum a cam is found and checked."""
    text = (EXAMPLES / "rocker_force.toml").read_text()
    text = re.sub(r"swing = [0-9.]+", "swing = 60", text)
    text = re.sub(r"pressure_angle = [0-9.]+", "pressure_angle = 30", text)
    text = re.sub(r'closure = "[a-z]+"', 'closure = "form"', text)
    f = tmp_path / "d.toml"
    f.write_text(text)
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "limits.pressure_angle" in err and "not attained" in err
    assert _value(err, "infimum") == pytest.approx(30.0, abs=2e-4)  # psi / 2
    f.write_text(text.replace("pressure_angle = 30", "pressure_angle = 30.5"))
    assert main(["solve", str(f)]) == 0


def test_zone_far_beyond_a_million_follower_sizes_is_not_empty():
    """A translating groove cam with a rise and a return of 1e-4 deg: its zone starts about 5.8e7 mm from A0,
    beyond the LP's first box (1e6 times the 30 mm stroke). Before: ``zone_empty`` said True (a false
    "no cam centre satisfies the limits" whenever a solver failed). Reference: a centre found by the exact
    method and confirmed admissible by ``check_pressure`` over every cam angle."""
    from optimize.diagnose import zone_empty
    from optimize.exact import nearest_exact

    d = design_from_dict({
        "name": "tiny phases", "follower": {"kind": "translating", "stroke": 30.0, "roller_radius": 8.0},
        "cam": {"rotation": "ccw"},
        "motion": [{"phase": "rise", "law": "cycloidal", "angle": 1e-4}, {"phase": "dwell", "angle": 179.9999},
                   {"phase": "return", "law": "poly345", "angle": 1e-4}, {"phase": "dwell"}],
        "limits": {"pressure_angle": 30, "closure": "form"}})
    sol = nearest_exact(d, d.follower.position(0.0))
    assert sol.objective > 1e6 * d.scale and check_pressure(d, sol.centre).ok
    assert not zone_empty(d)
    assert explain_infeasible(d, None) is None
