"""Scale: every length x k (0.01 mm to 10 m) scales R0, L, the centre and the profile by k.

Similar mechanisms have the same angles, so the exact solution must scale to
round-off (relative 1e-9), the pressure angles and binding positions must not
change, and the profile built at the chord tolerance x k must have the same
points (scaled) and the same checks.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.cam import Cam
from cams.io.designfile import design_from_dict
from laws.errors import CamsError

from .helpers import assert_finite_report, check_outcome, design_dict, guarded, walk

BASE = {"rocker": 125.0, "translating": 30.0}       # arm / stroke of the reference design
ROLLER = {"rocker": 10.0, "translating": 8.0}
LENGTHS = [0.01, 1.0, 10_000.0]                     # characteristic length, mm (10 m at the top)


def _scaled(kind: str, closure: str, k: float) -> dict:
    key = "arm" if kind == "rocker" else "stroke"
    lim = {"closure": closure}
    if kind == "rocker" and closure == "form":
        lim["safety_factor"] = 1.1
    return design_dict(kind, follower={key: BASE[kind] * k, "roller_radius": ROLLER[kind] * k},
                       limits=lim, profile={"tolerance": 1e-3 * k})


_REF: dict = {}


def _reference(kind, closure):
    if (kind, closure) not in _REF:
        r = check_outcome(_scaled(kind, closure, 1.0))
        assert not isinstance(r, CamsError), r
        _REF[kind, closure] = r
    return _REF[kind, closure]


@pytest.mark.parametrize("kind", ["rocker", "translating"])
@pytest.mark.parametrize("closure", ["force", "form"])
@pytest.mark.parametrize("length", LENGTHS)
def test_solution_scales(kind, closure, length):
    k = length / BASE[kind]
    ref = _reference(kind, closure)
    r = check_outcome(_scaled(kind, closure, k))
    assert not isinstance(r, CamsError), r
    assert r.R0 / k == pytest.approx(ref.R0, rel=1e-9)
    np.testing.assert_allclose(r.centre / k, ref.centre, rtol=0, atol=1e-9 * ref.design.scale)
    if kind == "rocker":
        assert r.L / k == pytest.approx(ref.L, rel=1e-9)
    else:
        assert r.offset / k == pytest.approx(ref.offset, abs=1e-9 * ref.design.scale)
    assert r.pressure.rise == pytest.approx(ref.pressure.rise, abs=1e-9)
    assert r.pressure.ret == pytest.approx(ref.pressure.ret, abs=1e-9)
    assert r.error_bound <= 1e-9 * r.design.scale
    # the binding positions are angles: unchanged
    got = sorted((b.phase, b.side, round(b.phi, 6)) for b in r.binding)
    want = sorted((b.phase, b.side, round(b.phi, 6)) for b in ref.binding)
    assert got == want


@pytest.mark.parametrize("kind", ["rocker", "translating"])
@pytest.mark.parametrize("closure", ["force", "form"])
@pytest.mark.parametrize("length", [0.01, 10_000.0])
def test_profile_scales(kind, closure, length):
    """The profile at tolerance 1e-3 x k: same sample count, radii x k, finite, same verdicts."""
    k = length / BASE[kind]
    ref = guarded(lambda: _profile(_scaled(kind, closure, 1.0)))
    got = guarded(lambda: _profile(_scaled(kind, closure, k)))
    (pr, cr), (p, c) = ref, got
    assert len(p) == len(pr)
    for name in ("pitch", "work"):
        a = getattr(p, name)
        assert np.all(np.isfinite(a)), name
        np.testing.assert_allclose(a / k, getattr(pr, name), rtol=0, atol=1e-8 * BASE[kind])
    if closure == "form":
        assert np.all(np.isfinite(p.outer))
    assert p.min_work_radius / k == pytest.approx(pr.min_work_radius, rel=1e-7)
    assert c.passed == cr.passed
    rep, rep_ref = c.to_dict(), cr.to_dict()
    for (path, v), (_, _v0) in zip(walk(rep), walk(rep_ref), strict=True):
        if isinstance(v, float):
            assert np.isfinite(v), path
    assert [ch["passed"] for ch in rep["checks"]] == [ch["passed"] for ch in rep_ref["checks"]]


def _profile(d):
    cam = Cam(design_from_dict(d))
    assert_finite_report(cam.solution)
    return cam.profile, cam.checks
