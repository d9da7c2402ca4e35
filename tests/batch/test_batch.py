"""The batch solver against the per-design path (:class:`cams.cam.Cam`): the same R0 to the two certificates'
bounds, the same largest pressure angles, the same verdicts; the rows it cannot vouch for sent back (None).

The per-design path is the reference for R0, the centre and the verdicts: a different solver (the exact method's
exchange on its own nearest-point method) and different buildability checks (the profile's, on the kernel's
extrema and the sampled polygon), so their agreement is not by construction. The largest pressure angles are not
checked independently by that comparison: the batch's come from the per-design check's own inversion, grid maxima
and zoom (:mod:`cams.verify.pressure`, on many designs at once), so they are also checked against the closed form
of an offset translating follower, written out below.
"""

from __future__ import annotations

import numpy as np
import pytest

from cams.batch import MARGIN, ROW_KEYS, size_batch
from cams.cam import Cam
from cams.io.designfile import design_from_dict
from cams.verify.pressure import check_pressure
from tests.conftest import rocker_dict

LAWS = ("cycloidal", "poly345", "poly4567", "modified_sine", "modified_trapezoid", "harmonic")


def _random_dict(rng: np.random.Generator, k: int) -> dict:
    """A random roller design: rocker (with or without K_C) or translating (its offset free or held), force or form
    closure, any senses, a few laws."""
    rise, ret = (str(x) for x in rng.choice(LAWS, 2))
    a_rise, a_dwell, a_ret = float(rng.uniform(80, 150)), float(rng.uniform(0, 60)), float(rng.uniform(80, 140))
    form = k % 4 == 3
    d = rocker_dict(
        name=f"random {k}",
        motion=[
            {"phase": "rise", "law": rise, "angle": a_rise},
            {"phase": "dwell", "angle": a_dwell},
            {"phase": "return", "law": ret, "angle": a_ret},
            {"phase": "dwell"},
        ],
        cam={"rotation": str(rng.choice(["cw", "ccw"]))},
        limits={"pressure_angle": float(rng.uniform(25, 45)), "closure": "form" if form else "force"},
    )
    if form:
        d["limits"]["return_pressure_angle"] = float(rng.uniform(30, 50))
    if k % 2:
        d["follower"] = {
            "kind": "translating",
            "stroke": float(rng.uniform(10, 40)),
            "roller_radius": float(rng.uniform(2, 8)),
        }
        if k % 3 == 0:  # the offset held: the centre on its line
            d["follower"]["offset"] = float(rng.uniform(-6, 6))
    else:
        d["follower"] = {
            "kind": "rocker",
            "arm": float(rng.uniform(70, 200)),
            "swing": float(rng.uniform(8, 25)),
            "roller_radius": float(rng.uniform(2, 10)),
            "rise_direction": str(rng.choice(["cw", "ccw"])),
        }
        if k % 4 == 2:  # a safety factor K_C (seed 3.26): the zone's lines moved
            d["limits"]["safety_factor"] = float(rng.uniform(1.02, 1.3))
    return d


@pytest.fixture(scope="module")
def compared():
    """32 random designs (seeded) and a few of the example's, through both paths."""
    rng = np.random.default_rng(29)
    dicts = [_random_dict(rng, k) for k in range(32)]
    dicts += [rocker_dict(limits={"pressure_angle": a}, follower={"arm": arm}) for a, arm in ((30, 90), (40, 160))]
    designs = [design_from_dict(d) for d in dicts]
    rows = size_batch(designs)
    cams = [Cam(d) for d in designs]
    return designs, rows, cams


def test_rows_agree_with_the_per_design_path(compared):
    designs, rows, cams = compared
    batched = 0
    for design, row, cam in zip(designs, rows, cams, strict=True):
        if row is None:
            continue
        batched += 1
        assert tuple(row) == ROW_KEYS
        s, a = cam.solution, cam.assessment
        assert a.usable and a.failures == () and s.governs == "pressure_angle", design.name
        assert (row["verified"], row["buildable"], row["failures"], row["error"]) == (True, True, None, None)
        bound = row["error_bound"] + s.error_bound
        assert 0 <= row["error_bound"] < 1e-9 * s.R0
        assert abs(row["R0"] - s.R0) <= bound, design.name
        # the nearest point of a convex zone is unique, but where one line binds it slides along the circle of
        # R0 as the square root of the bound: the centres agree to some 1e-7 of R0 only
        assert np.hypot(row["centre_x"] - s.centre[0], row["centre_y"] - s.centre[1]) <= 1e-5 * s.R0
        if s.L is not None:
            assert abs(row["L"] - s.L) <= 1e-5 * s.R0 and row["offset"] is None
        else:
            assert abs(row["offset"] - s.offset) <= 1e-5 * s.R0 and row["L"] is None
        # the largest pressure angles: the per-design check's at the batch's own centre to the last digits, and
        # the per-design path's (at its centre) to what that slide moves an unlimited phase's angle
        own = check_pressure(design, np.array([row["centre_x"], row["centre_y"]]))
        assert own.ok
        assert row["max_pressure_angle_rise"] == pytest.approx(np.degrees(own.rise), abs=1e-9)
        assert row["max_pressure_angle_return"] == pytest.approx(np.degrees(own.ret), abs=1e-9)
        rep = s.to_dict()["max_pressure_angle"]
        assert row["max_pressure_angle_rise"] == pytest.approx(rep["rise"], abs=1e-9)
        assert row["max_pressure_angle_return"] == pytest.approx(rep["return"], abs=1e-5)
    assert batched >= 20, f"only {batched} of {len(designs)} designs batched"


def test_the_rows_sent_back_are_the_per_design_path_s(compared):
    """A None is allowed anywhere, but the designs the per-design path raises to the part or fails must be None
    (the batch returns usable cams at the pressure angle's own minimum only)."""
    _, rows, cams = compared
    for row, cam in zip(rows, cams, strict=True):
        if not cam.assessment.usable or cam.solution.governs != "pressure_angle":
            assert row is None


@pytest.fixture(scope="module")
def at_the_undercut():
    """The example's pitch curve is the same for any roller (the zone does not depend on it): its smallest
    convex radius of curvature, by the per-design kernel, is the undercut's threshold."""
    from cams.checks.profile import curvature_extremes

    base = design_from_dict(rocker_dict(limits={"pressure_angle": 35}))
    rho = curvature_extremes(base, Cam(base).solution.centre).convex
    return base, rho


@pytest.mark.parametrize("factor", [1.0 - 0.1 * MARGIN, 1.0 + 0.1 * MARGIN])
def test_a_roller_at_the_undercut_goes_to_the_per_design_path(at_the_undercut, factor):
    from dataclasses import replace

    base, rho = at_the_undercut
    d = base.with_(follower=replace(base.follower, roller_radius=rho * factor))
    assert size_batch([d]) == [None]
    # and a roller well inside is batched, at the per-design R0
    far = base.with_(follower=replace(base.follower, roller_radius=0.5 * rho))
    (row,) = size_batch([far])
    assert row is not None and abs(row["R0"] - Cam(far).solution.R0) <= 2 * row["error_bound"] + 1e-12 * row["R0"]


def test_kinds_it_does_not_batch_are_sent_back(examples_dir):
    from cams.io.designfile import load_design

    rocker = design_from_dict(rocker_dict())
    others = [
        load_design(examples_dir / "translating_flat.toml"),  # a flat face
        load_design(examples_dir / "rocker_contact.toml"),  # [contact] (and [dynamics])
        design_from_dict(rocker_dict(cam={"centre": [130.0, 20.0]})),  # a chosen cam
        design_from_dict(rocker_dict(limits={"centre_distance": 130.0})),  # a fixed L
        design_from_dict(rocker_dict(limits={"min_base_radius": 30.0})),  # a floor
        design_from_dict(rocker_dict(cam={"bore_radius": 3.0, "hub_wall": 1.0})),  # a bore it does not clear
        design_from_dict(
            rocker_dict(
                motion=[
                    {"phase": "rise", "law": "linear", "angle": 120},
                    {"phase": "return", "law": "cycloidal", "angle": 120},
                    {"phase": "dwell"},
                ]
            )
        ),  # a velocity jump: a corner
    ]
    rows = size_batch([rocker, *others])
    assert rows[0] is not None and rows[1:] == [None] * len(others)
    assert size_batch([rocker], method="convex") == [None]
    assert size_batch([]) == []


def test_a_bore_it_clears_is_batched_at_the_per_design_size():
    """The example's cam at 45 deg has the working profile's smallest radius R0 - r = 3.24 mm (the roller at the
    near dwell): a bore of 2 mm with a 1 mm wall is cleared (the per-design path keeps the cam), one of 3 mm with
    the same wall is not (it raises the cam: sent back)."""
    clears = design_from_dict(rocker_dict(cam={"bore_radius": 2.0, "hub_wall": 1.0}))
    fails = design_from_dict(rocker_dict(cam={"bore_radius": 3.0, "hub_wall": 1.0}))
    row, back = size_batch([clears, fails])
    assert back is None
    cam = Cam(clears)
    s = cam.solution
    assert cam.assessment.usable and s.governs == "pressure_angle"
    assert row is not None and abs(row["R0"] - s.R0) <= row["error_bound"] + s.error_bound
    assert Cam(fails).solution.governs == "bore"


@pytest.mark.parametrize("rotation, eps, e", [("ccw", 1, 4.0), ("cw", -1, 4.0), ("ccw", 1, -3.0)])
def test_largest_pressure_angles_of_an_offset_translating_follower(rotation, eps, e):
    """The row's largest pressure angles against the closed form (tests/validation/test_reference.py derives it):
    the cam centre ``O = (-e, -d0)``, ``d0 = sqrt(R0^2 - e^2)``, the roller's velocity relative to the cam
    ``W = (eps (d0 + s), s' - eps e)``, so ``tan(gamma) = |s' - eps e| / (d0 + s)``; the cycloidal rise and return
    written out here, the maximum by a fine grid refined around its best point."""
    h, rise, ret = 20.0, np.radians(110.0), np.radians(130.0)
    d = rocker_dict(
        cam={"rotation": rotation},
        motion=[
            {"phase": "rise", "law": "cycloidal", "angle": 110},
            {"phase": "dwell", "angle": 40},
            {"phase": "return", "law": "cycloidal", "angle": 130},
            {"phase": "dwell"},
        ],
        limits={"pressure_angle": 30},
    )
    d["follower"] = {"kind": "translating", "stroke": h, "roller_radius": 5.0, "offset": e}
    (row,) = size_batch([design_from_dict(d)])
    assert row is not None and row["offset"] == pytest.approx(e, abs=1e-12)
    R0 = row["R0"]
    d0 = np.sqrt(R0**2 - e**2)
    assert (row["centre_x"], row["centre_y"]) == pytest.approx((-e, -d0), abs=1e-9 * R0)

    def largest(beta: float, up: bool) -> float:
        def gamma(u):
            c = u - np.sin(2 * np.pi * u) / (2 * np.pi)  # cycloidal: S(u), S'(u) = 1 - cos(2 pi u)
            s = h * c if up else h * (1.0 - c)
            ds = (1.0 if up else -1.0) * h / beta * (1.0 - np.cos(2 * np.pi * u))
            return np.arctan(np.abs(ds - eps * e) / (d0 + s))

        u = np.linspace(0.0, 1.0, 200_001)
        k = int(np.argmax(gamma(u)))
        fine = np.linspace(u[max(k - 1, 0)], u[min(k + 1, len(u) - 1)], 20_001)  # steps of 5e-10
        return float(np.degrees(gamma(fine).max()))

    assert row["max_pressure_angle_rise"] == pytest.approx(largest(rise, True), abs=1e-9)
    assert row["max_pressure_angle_return"] == pytest.approx(largest(ret, False), abs=1e-9)
