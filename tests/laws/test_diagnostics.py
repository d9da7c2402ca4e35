"""Hard and soft impacts of laws and cycle programs."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pytest

from laws.base import Law
from laws.diagnostics import Impact, LawJump, find_impacts, law_jumps
from laws.errors import InputError
from laws.program import Phase, Program
from laws.registry import LAWS, get_law

Q = math.pi / 2


def four_phases(rise, ret, lift=2.0):
    return Program(
        (Phase("rise", Q, get_law(rise)), Phase("dwell", Q), Phase("return", Q, get_law(ret)), Phase("dwell", Q)),
        lift=lift,
    )


def test_parabolic_has_one_internal_soft_jump():
    assert law_jumps(get_law("parabolic")) == (LawJump(0.5, "soft", -8.0),)


@pytest.mark.parametrize("name", [n for n in LAWS if n != "parabolic"])
def test_other_named_laws_smooth_inside(name):
    assert law_jumps(get_law(name)) == ()


def test_undeclared_jump_found_by_scan():
    @dataclass(frozen=True)
    class Kinked(Law):
        """Constant acceleration split at 0.3 instead of 0.5, with no breakpoints declared."""

        name: str = "kinked"

        def _evaluate(self, u):
            a, b = 1 / 0.3, 1 / 0.7  # accelerations 2a, -2b; S'(0.3) = 2a * 0.3 = 2
            first = u < 0.3
            w = 1 - u
            s = np.where(first, a * u * u, 1 - b * w * w)
            return s, np.where(first, 2 * a * u, 2 * b * w), np.where(first, 2 * a, -2 * b), np.zeros_like(u)

    (j,) = law_jumps(Kinked())
    assert j.kind == "soft"
    assert j.u == pytest.approx(0.3, abs=1e-8)
    assert j.size == pytest.approx(-2 / 0.7 - 2 / 0.3, rel=1e-6)


def test_cycloidal_program_is_smooth():
    assert find_impacts(four_phases("cycloidal", "modified_sine")) == []


def test_linear_gives_hard_impacts_at_every_joint_with_a_dwell():
    imp = find_impacts(four_phases("linear", "linear", lift=2.0))
    assert [(round(math.degrees(i.phi)), i.kind) for i in imp] == [(0, "hard"), (90, "hard"), (180, "hard"), (270, "hard")]
    v = 2.0 / Q  # lift / phase angle, per radian
    assert [i.size for i in imp] == pytest.approx([v, -v, -v, v])
    assert not any(i.inside for i in imp)


def test_harmonic_soft_impacts_with_sizes():
    imp = find_impacts(four_phases("harmonic", "cycloidal", lift=2.0))
    a = 2.0 * math.pi**2 / 2 / Q**2  # h * S''(0) / beta^2
    assert [(round(math.degrees(i.phi)), i.kind) for i in imp] == [(0, "soft"), (90, "soft")]
    assert [i.size for i in imp] == pytest.approx([a, a])  # 0 -> +a at the start; -a -> 0 at the end


def test_parabolic_internal_jump_in_program_units():
    imp = find_impacts(four_phases("cycloidal", "parabolic", lift=2.0))
    inside = [i for i in imp if i.inside]
    assert len(inside) == 1
    (m,) = inside
    assert m.phi == pytest.approx(Q * 2.5)
    assert m.phase == 2 and m.kind == "soft"
    assert m.size == pytest.approx(-1 * 2.0 * -8.0 / Q**2)  # a return flips the sign


def test_wrap_joint_at_zero():
    # cycloidal rise then harmonic return, no dwells: the return ends with
    # d2s = -h S''(1) / beta^2 = +1/2 and the rise starts with 0, a jump at the
    # wrap 360 -> 0 deg, reported at phi = 0 against phase 0
    p = Program((Phase("rise", math.pi, get_law("cycloidal")), Phase("return", math.pi, get_law("harmonic"))), lift=1.0)
    imp = find_impacts(p)
    assert [(i.phi, i.kind, i.phase) for i in imp] == [(0.0, "soft", 0), (pytest.approx(math.pi), "soft", 1)]
    assert [i.size for i in imp] == pytest.approx([-0.5, -0.5])


def test_eccentric_cam_has_no_impacts():
    # harmonic rise and return over 180 deg each: the eccentric circle, smooth everywhere
    p = Program((Phase("rise", math.pi, get_law("harmonic")), Phase("return", math.pi, get_law("harmonic"))), lift=1.0)
    assert find_impacts(p) == []


def test_tolerance_filters_round_off():
    p = four_phases("poly345", "poly4567")
    assert all(abs(i.size) < 1e-9 for i in find_impacts(p, rtol=0.0))
    assert find_impacts(p) == []
    with pytest.raises(InputError) as e:
        find_impacts(p, rtol=-1)
    assert e.value.field == "rtol"


def test_impact_is_frozen():
    i = Impact(0.0, "hard", 1.0, 0)
    with pytest.raises(AttributeError):
        i.size = 2.0
