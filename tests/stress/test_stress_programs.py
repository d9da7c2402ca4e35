"""Unusual motion programs: no dwell at all, several rises and returns with heights,
1-degree phases, laws with long stretches of (almost) zero velocity, table laws with flats.

For every program and both follower kinds and closures: the exact method gives
a verified, finite result; the cheap sampled methods (24-60 steps) a finite one
whose R0 (convex) does not exceed the exact R0 (the sampled zone contains the
continuous zone).
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.model.design import CamDesign, Limits
from cams.model.follower import Rocker, Translating
from laws.errors import CamsError
from laws.program import Phase, Program
from laws.registry import LAWS
from laws.table import TableLaw

from .helpers import check_outcome, design_dict

LIFT = {"rocker": 15.0, "translating": 30.0}   # swing (deg) / stroke (mm) of the base designs

PROGRAMS = {
    "rise180_return180": [
        {"phase": "rise", "law": "cycloidal", "angle": 180},
        {"phase": "return", "law": "cycloidal", "angle": 180},
    ],
    "rise100_return260_no_dwell": [
        {"phase": "rise", "law": "poly345", "angle": 100},
        {"phase": "return", "law": "poly4567", "angle": 260},
    ],
    "rise300_return60_no_dwell": [
        {"phase": "rise", "law": "modified_sine", "angle": 300},
        {"phase": "return", "law": "cycloidal", "angle": 60},
    ],
    "two_returns_with_heights": [
        {"phase": "rise", "law": "cycloidal", "angle": 60},
        {"phase": "dwell", "angle": 20},
        {"phase": "return", "law": "cycloidal", "angle": 60, "height": 0.4},
        {"phase": "dwell", "angle": 20},
        {"phase": "return", "law": "poly345", "angle": 60, "height": 0.6},
        {"phase": "dwell"},
    ],
    "rise_rise_return_return": [
        {"phase": "rise", "law": "cycloidal", "angle": 70, "height": 0.3},
        {"phase": "rise", "law": "poly345", "angle": 70, "height": 0.7},
        {"phase": "return", "law": "modified_trapezoid", "angle": 100, "height": 0.5},
        {"phase": "return", "law": "harmonic", "angle": 120, "height": 0.5},
    ],
    "all_phases_1deg": [
        {"phase": "rise", "law": "cycloidal", "angle": 1},
        {"phase": "dwell", "angle": 1},
        {"phase": "return", "law": "cycloidal", "angle": 1},
        {"phase": "dwell"},
    ],
    "rise_1deg_return_359": [
        {"phase": "rise", "law": "poly345", "angle": 1},
        {"phase": "return", "law": "cycloidal", "angle": 359},
    ],
    "dwells_1deg": [
        {"phase": "dwell", "angle": 1},
        {"phase": "rise", "law": "cycloidal", "angle": 179},
        {"phase": "dwell", "angle": 1},
        {"phase": "return", "law": "cycloidal", "angle": 179},
    ],
}


def _program(kind: str, name: str) -> list[dict]:
    out = []
    for ph in PROGRAMS[name]:
        ph = dict(ph)
        if "height" in ph:
            ph["height"] = ph["height"] * LIFT[kind]
        out.append(ph)
    return out


def _check_sampled_below_exact(d, exact):
    conv = check_outcome({**d, "solve": {**d["solve"], "samples": 60}}, method="convex")
    assert not isinstance(conv, CamsError), conv
    assert conv.R0 <= exact.R0 + 1e-9 * exact.design.scale
    exh = check_outcome({**d, "solve": {**d["solve"], "samples": 24}}, method="exhaustive")
    assert not isinstance(exh, CamsError), exh


@pytest.mark.parametrize("kind", ["rocker", "translating"])
@pytest.mark.parametrize("closure", ["force", "form"])
@pytest.mark.parametrize("name", list(PROGRAMS))
def test_program(kind, closure, name):
    d = design_dict(kind, motion=_program(kind, name), limits={"closure": closure})
    r = check_outcome(d)
    assert not isinstance(r, CamsError), r
    lim = np.radians(d["limits"]["pressure_angle"])
    if closure == "force":
        assert r.pressure.rise == pytest.approx(lim, abs=1e-7)
    else:
        # the limit is reached on the rise or on the return
        assert max(r.pressure.rise, r.pressure.ret) == pytest.approx(lim, abs=1e-7)
    if name in ("rise180_return180", "two_returns_with_heights", "all_phases_1deg"):
        _check_sampled_below_exact(d, r)


@pytest.mark.parametrize("kind", ["rocker", "translating"])
@pytest.mark.parametrize("closure", ["force", "form"])
@pytest.mark.parametrize("law", sorted(LAWS))
def test_long_slow_ends(kind, closure, law):
    """A 340-degree rise: near its ends the velocity stays almost zero over tens of degrees."""
    motion = [{"phase": "rise", "law": law, "angle": 340}, {"phase": "dwell", "angle": 1},
              {"phase": "return", "law": law, "angle": 19}]
    r = check_outcome(design_dict(kind, motion=motion, limits={"closure": closure}))
    assert not isinstance(r, CamsError), r


# Table laws: a clamped quintic spline with flat stretches (it overshoots a little
# around them, so the "rise" briefly moves backwards) and a smooth one.
TABLES = {
    "flats": TableLaw((0, .1, .2, .3, .5, .7, .8, .9, 1), (0, 0, 0, .1, .5, .9, 1, 1, 1), clamped=True),
    "smooth": TableLaw((0, .25, .5, .75, 1), (0, .1464, .5, .8536, 1), clamped=True),
    "two_point": TableLaw((0, 1), (0, 1), clamped=True),
}


def _table_design(law, kind, closure):
    r = np.radians
    ph = (Phase("rise", r(120), law), Phase("dwell", r(30)), Phase("return", r(120), "cycloidal"), Phase("dwell", r(90)))
    lim = Limits(r(45), closure=closure)
    if kind == "rocker":   # the solvers under stress: the pressure angle alone sizes the cam
        return CamDesign(Rocker(125.0, 10.0, -1), Program(ph, r(15)), lim, 1, samples=60, constraints="pressure_angle")
    return CamDesign(Translating(8.0, None, 30.0), Program(ph, 30.0), lim, 1, samples=60, constraints="pressure_angle")


@pytest.mark.parametrize("kind", ["rocker", "translating"])
@pytest.mark.parametrize("closure", ["force", "form"])
@pytest.mark.parametrize("table", list(TABLES))
def test_table_law(kind, closure, table):
    d = _table_design(TABLES[table], kind, closure)
    r = check_outcome(d)
    assert not isinstance(r, CamsError), r
    conv = check_outcome(d, method="convex")
    assert not isinstance(conv, CamsError), conv
    assert conv.R0 <= r.R0 + 1e-9 * d.scale
