"""A Cam computes only what is asked for, once (counting calls, not timing)."""

import numpy as np

import cams.profile.roller
import cams.solve
from cams.cam import Cam
from tests.conftest import EXAMPLES


def test_motion_does_not_solve_and_results_are_reused(monkeypatch):
    calls = {"solve": 0, "profile": 0}
    real_solve = cams.solve.solve

    def counting_solve(*a, **k):
        calls["solve"] += 1
        return real_solve(*a, **k)

    real_build = cams.profile.roller.build_profile

    def counting_build(*a, **k):
        calls["profile"] += 1
        return real_build(*a, **k)

    monkeypatch.setattr(cams.solve, "solve", counting_solve)
    monkeypatch.setattr(cams.profile.roller, "build_profile", counting_build)
    cam = Cam.from_file(EXAMPLES / "rocker_force.toml")
    cam.motion(np.linspace(0, 6, 7))
    from cams.present.plots import plot_motion

    plot_motion(cam.design)
    assert calls == {"solve": 0, "profile": 0}
    r1 = cam.solution
    r2 = cam.solution
    assert r1 is r2 and calls == {"solve": 1, "profile": 0}
    cam.checks
    cam.profile
    assert calls == {"solve": 1, "profile": 1}
