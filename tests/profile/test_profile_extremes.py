"""cams.checks.profile: the vectorized search for the largest curvature and pressure angle.

(The search itself, :func:`cams.kinematics.extremum.maximize`, on known functions: tests/kinematics.)

The search (a grid per phase, then every bracket of a local maximum refined
together on the analytic derivative) is compared with a brute force of a
million positions per phase that uses the values only, and its array
evaluations are counted.
"""

from __future__ import annotations

import subprocess
import sys
import tomllib
from functools import cache
from pathlib import Path

import numpy as np
import pytest

import cams.checks.profile as checks
from cams.checks.profile import _phase_maxima, _phase_rates, check_profile
from cams.io.designfile import design_from_dict
from cams.kinematics.extremum import MAX_STEPS
from cams.kinematics.inversion import pitch_phase

DENSE = 1_000_000
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
NAMES = ("rocker_force", "rocker_form", "slotting_feed_cam", "translating_force", "translating_form_centric")


@cache
def _case(name: str, return_law: str | None = None):
    """``(design, centre)``: an example, its return law replaced if given, at the example's solved centre."""
    from cams.solve import solve

    d = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    centre = np.asarray(solve(design_from_dict(d)).centre, float)
    if return_law is not None:
        d["motion"][2]["law"] = return_law
    return design_from_dict(d), centre


def _brute_force(design, O, i):
    """Largest kappa, -kappa and pressure angle of phase ``i`` on DENSE + 1 even positions.

    Both sides of the law's breakpoints are added (one-sided limits). Values
    only, the pressure angle from the cam-frame normal turned back into the
    fixed frame (the definition), no derivative: independent of the search.
    """
    u = np.linspace(0.0, 1.0, DENSE + 1)
    bps = np.array([b for b in getattr(design.program.phases[i].law, "breakpoints", ()) if 0 < b < 1])
    if len(bps):
        u = np.unique(np.concatenate([u, bps, np.nextafter(bps, 0.0), np.nextafter(bps, 1.0)]))
    kappa, gamma = [], []
    for part in np.array_split(u, 8):
        k, g = _values(design, O, i, part)
        kappa.append(k)
        gamma.append(g)
    kappa, gamma = np.concatenate(kappa), np.concatenate(gamma)
    return {"convex": kappa, "concave": -kappa, "pressure": gamma}


def _values(design, O, i, u):
    g = pitch_phase(design, O, i, u)
    a = design.cam_sense * g.phi
    c, s = np.cos(a), np.sin(a)
    nx, ny = c * g.normal[:, 0] - s * g.normal[:, 1], s * g.normal[:, 0] + c * g.normal[:, 1]
    ex, ey = g.rise_dir[:, 0], g.rise_dir[:, 1]
    return g.kappa, np.arctan2(np.abs(nx * ey - ny * ex), nx * ex + ny * ey)


CASES = [(n, None) for n in NAMES] + [("rocker_form", "modified_trapezoid"), ("rocker_form", "parabolic")]


@pytest.mark.parametrize("case", CASES, ids=lambda c: c[0] + (f"-return-{c[1]}" if c[1] else ""))
def test_largest_values_match_a_million_point_brute_force(case):
    """Never below the brute force's best, and attained: the function at the reported angle is the value.

    So the value lies between the best of a million samples and the true
    supremum; on these designs the 2001-point grid alone falls short of the
    brute force by more than 1e-9 of the function's range somewhere, so the
    refinement is what makes the test pass.
    """
    design, O = _case(*case)
    prog = design.program
    grid_short = 0.0
    for i, p in enumerate(prog.phases):
        if p.kind == "dwell":
            continue
        dense = _brute_force(design, O, i)
        found = _phase_maxima(design, O, 2000, pressure={i})[i]
        ug = np.linspace(0.0, 1.0, 2001)
        kg, gg = _values(design, O, i, ug)
        grid = {"convex": kg.max(), "concave": (-kg).max(), "pressure": gg.max()}
        for w, f in dense.items():
            value, phi = found[w]
            scale = np.ptp(f)
            best = f.max()
            assert value >= best - 1e-13 * scale, (case, i, w)
            assert value - best <= 1e-9 * scale, (case, i, w)
            u = np.array([(phi - prog.starts[i]) / p.angle])
            k, g = _values(design, O, i, u)
            at = {"convex": k, "concave": -k, "pressure": g}[w][0]
            assert at == pytest.approx(value, rel=1e-13, abs=1e-13 * scale), (case, i, w)
            grid_short = max(grid_short, (best - grid[w]) / scale)
    assert grid_short > 1e-9


@pytest.mark.parametrize("name", ["rocker_form", "translating_force"])
@pytest.mark.parametrize("sense", [1, -1])
def test_analytic_slopes_match_finite_differences(name, sense):
    design, O = _case(name)
    design = design.with_(cam_sense=sense)
    h = 1e-6
    for i, p in enumerate(design.program.phases):
        u = np.linspace(0.03, 0.97, 60)
        what = ("convex", "concave", "pressure")
        v, dv = _phase_rates(design, O, i, u, what)
        vp, _ = _phase_rates(design, O, i, u + h, what)
        vm, _ = _phase_rates(design, O, i, u - h, what)
        num = (vp - vm) / (2 * h * p.angle)  # per radian of cam angle
        scale = np.abs(dv).max(axis=1, keepdims=True) + 1e-12
        assert np.allclose(dv, num, rtol=1e-5, atol=1e-6 * scale), (name, i)
        assert np.allclose(v[2], checks.pressure_from_profile(design, O, i, u), atol=1e-14)


@pytest.mark.parametrize("name", NAMES)
def test_checks_evaluate_a_bounded_number_of_arrays(monkeypatch, name):
    """One grid a phase (two positions for a dwell), then a few steps of one small array each."""
    design, O = _case(name)
    calls = []
    real = checks._phase_rates

    def counting(design_, centre, i, u, what):
        calls.append((i, len(u)))
        return real(design_, centre, i, u, what)

    monkeypatch.setattr(checks, "_phase_rates", counting)
    rep = check_profile(design, O)
    assert rep.passed
    phases = design.program.phases
    for i, p in enumerate(phases):
        mine = [n for j, n in calls if j == i]
        if p.kind == "dwell":
            assert mine == [2]
            continue
        assert mine[0] >= 2001  # the grid (with a breakpoint's sides)
        steps = mine[1:]
        assert len(steps) <= 10 < MAX_STEPS
        assert all(n <= 6 for n in steps)  # the open brackets only
    # (the former bounded scalar search evaluated 100 to 170 arrays a design, most of one position)
    assert len(calls) <= len(phases) + 10 * sum(p.kind != "dwell" for p in phases)


def test_checks_do_not_import_scipy():
    code = ("import sys\nfrom cams.cam import Cam\n"
            f"c = Cam.from_file({str(EXAMPLES / 'rocker_form.toml')!r})\n"
            "c.checks\nprint(' '.join(m for m in ('scipy.optimize', 'scipy') if m in sys.modules))")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert r.stdout.split() == []
