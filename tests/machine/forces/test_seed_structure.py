"""The seeds' structural analysis, recomputed from the kinetostatic model (cams.machine.kinetostatics).

* seed 000, "Структурный анализ механизма": W = 3 n - 2 p1 - p2 = 3 * 5 - 2 * 7 - 0 = 1 with
  the pairs 0-1, 1-2, 2-3, 3-0, 1-4, 4-5, 5-0; the input link 1 and two groups of class II
  (links 2, 3 and 4, 5).
* seed 004, section 1.3: n = 5, p5 = 7, p4 = 0, W = 1; structural formula
  I(0;1), II(2;3), II(4;5); section 2.6 lists the revolute pairs O1, A, O2, C3 and the
  prismatic pairs A3, C5, E.

The model's links are numbered as the seeds' (:data:`cams.machine.kinetostatics.LINKS`, 1..5; ground 0).
A statically determinate model has 3 n equations for 2 p reaction components and the
balancing moment: 3 n = 2 p + 1 is W = 1 read the other way.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.machine.kinetostatics import ForceSpec, build_model
from cams.machine.linkage.machines import OpposedTwin, SlottedLeverPump


def _structure(machine):
    mod = build_model(machine, ForceSpec(), phi=np.radians([60.0]))
    pairs = {j.name: (j.kind, frozenset((j.a + 1, j.b + 1))) for j in mod.joints}  # seed numbers, ground 0
    return len(mod.bodies), pairs


def _assur_groups_ok(groups, pairs):
    """Each group of two links: three pairs, one inside, two to links added before; W of the group = 0."""
    known = {0, 1}
    for g in groups:
        inner = [p for _, p in pairs.values() if p <= g]
        outer = [p for _, p in pairs.values() if len(p & g) == 1 and (p - g) <= known]
        assert len(inner) == 1 and len(outer) == 2
        assert 3 * len(g) - 2 * (len(inner) + len(outer)) == 0
        known |= g
    assert known == {0, 1, 2, 3, 4, 5}


@pytest.mark.parametrize(
    "machine",
    [
        OpposedTwin(crank=48.0, rod=192.0, rod_cg=64.0, rpm=200 * 60 / (2 * np.pi)),
        SlottedLeverPump.from_course(2.0, 250.0, 525.0, rpm=77),
    ],
    ids=["seed000", "seed004"],
)
def test_seed_mobility_is_one(machine):
    n, pairs = _structure(machine)
    p1 = len(pairs)  # every pair of the model is a lower pair (one-degree-of-freedom)
    assert all(kind in ("revolute", "prismatic") for kind, _ in pairs.values())
    assert (n, p1) == (5, 7)
    assert 3 * n - 2 * p1 - 0 == 1
    _assur_groups_ok([frozenset({2, 3}), frozenset({4, 5})], pairs)


def test_seed_000_pairs():
    _, pairs = _structure(OpposedTwin(crank=48.0, rod=192.0, rod_cg=64.0, rpm=100.0))
    seed = {frozenset(p) for p in ((0, 1), (1, 2), (2, 3), (3, 0), (1, 4), (4, 5), (5, 0))}
    assert {p for _, p in pairs.values()} == seed


def test_seed_004_pair_kinds():
    """Seed 004, 2.6: revolute O1, A, O2, C3; prismatic A3 (block in the lever), C5 (pin block in the piston), E (piston)."""
    _, pairs = _structure(SlottedLeverPump.from_course(2.0, 250.0, 525.0, rpm=77))
    kinds = {name: kind for name, (kind, _) in pairs.items()}
    assert kinds == {
        "O1": "revolute", "A": "revolute", "O2": "revolute", "C": "revolute",
        "A_slot": "prismatic", "C_slot": "prismatic", "E": "prismatic",
    }
