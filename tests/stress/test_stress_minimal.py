"""Minimality of every exact answer over random designs at three unit scales (issue 12, item 1).

For random valid designs (rocker and translating, force and form closure,
every law, both senses, with and without dwells) at unit scales x1e-3, x1 and
x1e3, the exact minimum R0 must

* scale exactly with the lengths (relative 1e-9): the method has no tolerance
  tied to a length;
* be certified, with an error bound within 1e-9 of R0;
* be minimal: no admissible centre at ``R0 (1 - 1e-6)`` from the roller's start
  point, judged by the kinematic inversion of :mod:`cams.verify.pressure`, which shares
  no formula with the solver (:func:`tests.stress.helpers.assert_minimal`).
"""

from __future__ import annotations

import copy
import random

import pytest

from cams.io.designfile import design_from_dict
from laws.errors import CamsError

from .helpers import assert_minimal, check_outcome
from .test_stress_properties import random_design

SCALES = (1e-3, 1.0, 1e3)
LENGTH_KEYS = ("arm", "stroke", "roller_radius", "offset")


def _scaled(d: dict, k: float) -> dict:
    d = copy.deepcopy(d)
    for key in LENGTH_KEYS:
        if key in d["follower"]:
            d["follower"][key] *= k
    for m in d["motion"]:
        if "height" in m and d["follower"]["kind"] == "translating":
            m["height"] *= k
    return d


def _designs(per_kind: int) -> list[dict]:
    """``per_kind`` random designs of each follower kind and closure (senses, laws, shapes drawn at random)."""
    rng = random.Random(20261124)
    out: dict[tuple[str, str], list[dict]] = {}
    while sum(len(v) for v in out.values()) < 4 * per_kind:
        d = random_design(rng)
        key = (d["follower"]["kind"], d["limits"]["closure"])
        if len(out.setdefault(key, [])) == per_kind:
            continue
        d["follower"].pop("offset", None)  # the minimum R0 over the plane (a fixed offset is a line)
        # K_C > 1 narrows the zone beyond the pressure angle, which is all the independent check judges
        d["limits"].pop("safety_factor", None)
        out[key].append(d)
    return [d for v in out.values() for d in v]


@pytest.mark.parametrize("d", _designs(2), ids=lambda d: f"{d['follower']['kind']}-{d['limits']['closure']}")
def test_exact_answers_are_minimal_at_every_scale(d):
    ref = None
    for k in SCALES:
        r = check_outcome(design_from_dict(_scaled(d, k)))
        if isinstance(r, CamsError):
            assert ref is None, f"infeasible at scale {k} only: {r}"
            continue
        assert r.mode == "min_R0"
        assert r.certified is True and r.error_bound <= 1e-9 * r.R0
        assert_minimal(r)
        if ref is None:
            ref = (k, r.R0)
        else:
            assert r.R0 / k == pytest.approx(ref[1] / ref[0], rel=1e-9)
