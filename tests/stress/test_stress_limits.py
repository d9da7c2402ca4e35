"""Pressure-angle limits near 0 and 90 degrees, tiny and huge swings and strokes, empty zones.

Contract of every case (:func:`check_outcome`): a clear InfeasibleError /
InputError naming its field, or a result with finite numbers that the
independent pressure check verifies (exact method). An "infeasible" answer is
judged by :func:`zone_witness`: no admissible centre may exist.
"""

from __future__ import annotations

import time

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from laws.errors import CamsError, InfeasibleError

from .helpers import check_outcome, design_dict, guarded, zone_witness

KINDS = ["rocker", "translating"]
CLOSURES = ["force", "form"]



def _judge_infeasible(err, d):
    assert isinstance(err, InfeasibleError)
    assert guarded(zone_witness, design_from_dict(d)) is None, "InfeasibleError, but an admissible centre exists"


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("closure", CLOSURES)
@pytest.mark.parametrize("limit", [0.1, 1.0])
def test_limit_near_zero(kind, closure, limit):
    """Rocker: the zone is empty (honestly); translating: a huge but verified cam."""
    d = design_dict(kind, limits={"pressure_angle": limit, "closure": closure})
    out = check_outcome(d)
    if isinstance(out, CamsError):
        assert out.field == "limits.pressure_angle"
        _judge_infeasible(out, d)
    else:
        # R0 of the order of stroke / tan(limit)
        assert out.R0 > 10 * out.design.scale
        assert out.pressure.rise == pytest.approx(np.radians(limit), abs=1e-7)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("closure", CLOSURES)
@pytest.mark.parametrize("limit", [
    85.0,
    89.0,
    89.5,
    89.85,   # before f69e9ce: pressure.ok False (peak inside the first scan cell)
    89.9,    # before f69e9ce: R0 = 0 and NaN pressure angles
    89.95,   # was a bug (R0 5.8e-8 mm failed its check): now an honest 'base radius vanishes' refusal (unverifiable size)
    89.99,   # R0 below 1e-10 x scale: an honest InfeasibleError naming limits.min_base_radius as the fix
])
def test_limit_near_ninety(kind, closure, limit):
    """A tiny but positive R0, verified, no NaN, the rise limit reached; or an honest refusal."""
    d = design_dict(kind, limits={"pressure_angle": limit, "closure": closure})
    r = check_outcome(d)
    if isinstance(r, CamsError):
        # a refusal must not claim an empty zone when there are admissible centres
        if "base radius" not in str(r):
            _judge_infeasible(r, d)
        return
    assert 0 < r.R0 < 0.01 * r.design.scale
    assert r.pressure.rise == pytest.approx(np.radians(limit), abs=1e-7)




@pytest.mark.parametrize("method", ["convex", "exhaustive"])
@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("limit", [1.0, 80.0])
def test_sampled_methods_near_limits(method, kind, limit):
    """Sampled methods (24 steps): clear error or finite report (they need not verify)."""
    d = design_dict(kind, limits={"pressure_angle": limit, "closure": "form"}, solve={"samples": 24})
    out = check_outcome(d, method=method)
    if isinstance(out, CamsError):
        _judge_infeasible(out, d)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("method", ["convex", "exhaustive"])
@pytest.mark.parametrize("limit", [89.0, 89.9])
def test_sampled_methods_near_ninety_have_no_nan(kind, method, limit):
    """Regression (fixed in f69e9ce): the sampled zone holds the roller's start point A0; the
    solvers returned centre = A0 (R0 = 0) and the pressure check NaN in to_dict()."""
    d = design_dict(kind, limits={"pressure_angle": limit, "closure": "force"}, solve={"samples": 24})
    out = check_outcome(d, method=method)
    if isinstance(out, CamsError):
        assert "base radius" in str(out) or guarded(zone_witness, design_from_dict(d)) is None


@pytest.mark.parametrize("closure", CLOSURES)
@pytest.mark.parametrize("swing", [0.01, 0.5, 60.0, 120.0, 170.0])
@pytest.mark.parametrize("limit", [45.0, 89.0])
def test_swing_extremes(swing, limit, closure):
    d = design_dict("rocker", follower={"swing": swing}, limits={"pressure_angle": limit, "closure": closure})
    out = check_outcome(d)
    if isinstance(out, CamsError):
        assert out.field == "limits.pressure_angle"
        _judge_infeasible(out, d)
    else:
        assert out.pressure.rise == pytest.approx(np.radians(limit), abs=1e-7)


@pytest.mark.parametrize("closure", CLOSURES)
@pytest.mark.parametrize("stroke", [1e-3, 1.0, 1e3, 1e4])
def test_stroke_extremes(stroke, closure):
    """Knife edge, stroke 1 um to 10 m: R0 proportional to the stroke."""
    d = design_dict("translating", follower={"stroke": stroke, "roller_radius": 0.0}, limits={"closure": closure})
    r = check_outcome(d)
    assert not isinstance(r, CamsError), r
    ref = check_outcome(design_dict("translating", follower={"stroke": 1.0, "roller_radius": 0.0},
                                    limits={"closure": closure}))
    assert r.R0 / stroke == pytest.approx(ref.R0, rel=1e-9)




@pytest.mark.parametrize("closure", CLOSURES)
@pytest.mark.parametrize("swing,limit", [
    (0.01, 80.0), (0.01, 89.0), (0.5, 89.0),
    (0.5, 89.9),  # was a bug: R0 = 1.7e-8 mm failed its check; now refused as vanishing
])
def test_nearly_parallel_lines(swing, limit, closure):
    """Tiny swing, large limit: the t-t lines are nearly parallel; the apex is still found and verified,
    or, where R0 is too small to verify, refused with the 'base radius vanishes' message."""
    d = design_dict("rocker", follower={"swing": swing}, limits={"pressure_angle": limit, "closure": closure})
    r = check_outcome(d)
    if isinstance(r, CamsError):
        assert "base radius vanishes" in str(r) and r.field == "limits.pressure_angle"
        return
    assert r.pressure.ok
    assert r.R0 > 0 and r.L == pytest.approx(125.0, rel=1e-3)


@pytest.mark.parametrize("method", ["exact", "convex", "exhaustive"])
@pytest.mark.parametrize("swing,limit", [(170.0, 10.0), (179.9, 45.0), (120.0, 45.0)])
def test_empty_zone_form_closure(method, swing, limit):
    """Huge swing, small limit, groove cam: InfeasibleError naming limits.pressure_angle, quickly."""
    d = design_dict("rocker", follower={"swing": swing}, limits={"pressure_angle": limit, "closure": "form"},
                    solve={"samples": 24})
    t0 = time.perf_counter()
    out = check_outcome(d, method=method)
    assert time.perf_counter() - t0 < 10
    assert isinstance(out, InfeasibleError), out
    assert out.field == "limits.pressure_angle"
    _judge_infeasible(out, d)




@pytest.mark.parametrize("swing", [
    83.0,
    83.7,
    83.8,  # was a bug: crossings of nearly parallel lines failed a fixed absolute feasibility tolerance
    83.9,
    84.2,
])
def test_edge_of_feasibility_far_zone(swing):
    """As the swing grows the zone recedes (R0 from 2 to 7+ arms) and then vanishes; every
    answer is a verified result or an honest InfeasibleError."""
    motion = [{"phase": "rise", "law": "cycloidal", "angle": 150}, {"phase": "return", "law": "cycloidal", "angle": 210}]
    d = design_dict("rocker", follower={"swing": swing, "roller_radius": 0.0}, motion=motion,
                    limits={"pressure_angle": 42.0, "closure": "force"})
    out = check_outcome(d)
    if isinstance(out, CamsError):
        _judge_infeasible(out, d)
    else:
        assert out.R0 > out.design.scale
        conv = check_outcome(d, method="convex")
        assert isinstance(conv, CamsError) or conv.R0 <= out.R0 + 1e-9 * out.design.scale
