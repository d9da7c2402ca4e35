"""The explorer page (``cams explore``): what it embeds, that it is self-contained, and that its numbers are
``cams check``'s.

The page computes in the browser; here (no browser: the browser tests drive the page itself) its data are checked
against closed forms and the laws' own evaluation, the interpolation bounds it embeds against the laws between
the samples, and its mathematics, run by ``node`` straight from the written page, against the independent
check of the pressure angle at cam centres given as ``[cam] centre`` (a flat face: ``[cam] base_radius``), within
the error bound the page states. A tiny Python port of the page's pressure angle (the cross product of the relative
velocity with the rise direction, not the page's normal) checks the formula where ``node`` is absent.
"""

from __future__ import annotations

import json
import math
import re
import shutil
import subprocess
from dataclasses import replace

import numpy as np
import pytest

from cams.cam import Cam
from cams.io.designfile import design_from_dict, load_design
from cams.kinematics.inversion import invert, pressure_angle
from cams.present.explore import explore_data, page
from tests.conftest import EXAMPLES, rocker_dict

NODE = shutil.which("node")


def _data_of(html: str) -> dict:
    """The data a written page embeds (the JSON after ``const CAMS_DATA =``)."""
    m = re.search(r"const CAMS_DATA = (.*);\n</script>", html)
    assert m is not None
    return json.loads(m.group(1))


def _math_of(html: str) -> str:
    """The page's own mathematics: the script that defines ``camsMath``."""
    for block in re.findall(r"<script>\n(.*?)</script>", html, flags=re.S):
        if "function camsMath(" in block:
            return block
    raise AssertionError("no camsMath in the page")


@pytest.fixture(scope="module")
def pages():
    """The page of each example the tests drive: (design file, cam, html, embedded data)."""
    out = {}
    for name in (
        "rocker_force",
        "translating_force",
        "rocker_form",
        "translating_form_centric",
        "rocker_flat",
        "translating_flat",
    ):
        cam = Cam(load_design(EXAMPLES / f"{name}.toml"))
        html = page(explore_data(cam))
        out[name] = (cam, html, _data_of(html))
    # a rise in two steps (two rise phases: the page's rise is the larger of their maxima, as the check's)
    two = rocker_dict(
        name="two rises",
        follower={"swing": 20.0},
        motion=[
            {"phase": "rise", "law": "cycloidal", "angle": 60, "height": 12},
            {"phase": "dwell", "angle": 30},
            {"phase": "rise", "law": "poly345", "angle": 60, "height": 8},
            {"phase": "dwell", "angle": 30},
            {"phase": "return", "law": "modified_sine", "angle": 120},
            {"phase": "dwell"},
        ],
    )
    cam = Cam(design_from_dict(two))
    html = page(explore_data(cam))
    out["two_rises"] = (cam, html, _data_of(html))
    # a flat rocker whose face misses the pivot: its pressure angle is not 0
    d = load_design(EXAMPLES / "rocker_flat.toml")
    cam = Cam(d.with_(follower=replace(d.follower, face_offset=15.0)))
    html = page(explore_data(cam))
    out["rocker_flat_offset"] = (cam, html, _data_of(html))
    return out


# -- what the page embeds ------------------------------------------------------------------------------------------


def test_cycloidal_samples_equal_the_closed_form(pages):
    """rocker_force: a cycloidal rise of 15 deg over 120 deg and a cycloidal return over 120 deg, by hand:
    s = H (u - sin(2 pi u) / (2 pi)), s' = H / b (1 - cos 2 pi u), s'' = 2 pi H / b**2 sin 2 pi u."""
    _, _, data = pages["rocker_force"]
    H, b = math.radians(15.0), math.radians(120.0)
    rise, ret = data["phases"][0], data["phases"][2]
    assert (rise["kind"], ret["kind"]) == ("rise", "return")
    for ph, sign, base in ((rise, 1.0, 0.0), (ret, -1.0, H)):
        u = np.linspace(0.0, 1.0, ph["n"] + 1)
        w = 2 * np.pi * u
        np.testing.assert_allclose(ph["s"], base + sign * H * (u - np.sin(w) / (2 * np.pi)), atol=1e-14)
        np.testing.assert_allclose(ph["ds"], sign * H / b * (1 - np.cos(w)), atol=1e-13)
        np.testing.assert_allclose(ph["d2s"], sign * 2 * np.pi * H / b**2 * np.sin(w), atol=1e-12)
        assert ph["start"] == pytest.approx(0.0 if sign > 0 else math.radians(150.0))
        assert ph["angle"] == pytest.approx(b)
    # the bound's constants: the cycloid's largest |s''| and |s'''| (2 pi H / b**2, 4 pi**2 H / b**3), raised 5 %
    assert rise["M2"] == pytest.approx(1.05 * 2 * np.pi * H / b**2, rel=1e-6)
    assert rise["M3"] == pytest.approx(1.05 * 4 * np.pi**2 * H / b**3, rel=1e-6)
    assert rise["jump"] == 0.0


def test_two_rises_are_named_and_each_is_sampled(pages):
    """A program with two rises embeds both (their heights by hand: 12 and 8 deg of a 20 deg swing)."""
    _, _, data = pages["two_rises"]
    rises = [p for p in data["phases"] if p["kind"] == "rise"]
    assert [p["index"] for p in rises] == [0, 2]
    assert rises[0]["s"][-1] == pytest.approx(math.radians(12.0), abs=1e-14)
    assert rises[1]["level"] == pytest.approx(math.radians(12.0), abs=1e-14)
    assert rises[1]["s"][-1] == pytest.approx(math.radians(20.0), abs=1e-14)


@pytest.mark.parametrize("law", ["cycloidal", "poly345", "modified_trapezoid", "parabolic", "harmonic"])
def test_interpolation_bounds_hold_between_the_samples(law):
    """Between the samples the laws (the periodic evaluation, another entry than the one sampled) stay within the
    embedded bounds of the linear interpolant, at every midpoint and at random points; a law whose acceleration
    jumps inside the phase (parabolic) has its jump in the bound."""
    d = design_from_dict(
        rocker_dict(
            motion=[
                {"phase": "rise", "law": law, "angle": 120},
                {"phase": "dwell", "angle": 30},
                {"phase": "return", "law": law, "angle": 120},
                {"phase": "dwell"},
            ]
        )
    )
    rng = np.random.default_rng(7)
    for ph in (p for p in explore_data(Cam(d))["phases"] if p["kind"] != "dwell"):
        n = ph["n"]
        nodes = np.linspace(0.0, 1.0, n + 1)
        u = np.concatenate([(np.arange(n) + 0.5) / n, rng.uniform(0.0, 1.0, 4000)])
        u = u[(u > 1e-9) & (u < 1 - 1e-9)]
        m = d.program.evaluate(ph["start"] + u * ph["angle"])
        for key, law_values in (("s", m.s), ("ds", m.ds), ("d2s", m.d2s)):
            err = np.abs(np.interp(u, nodes, ph[key]) - law_values)
            assert err.max() <= ph[f"err_{key}"], (law, ph["index"], key)
        assert (ph["jump"] > 0) == (law == "parabolic")
        # a useful bound: the pressure angle's sensitivity is of order 1 per unit of s' (rad per rad)
        assert ph["err_ds"] < (2e-4 if law == "parabolic" else 1e-6)


def test_designed_laws_are_embedded(tmp_path):
    """A design with [optimize]: the page embeds the designed laws (the solved design's program), not the file's."""
    d = load_design(EXAMPLES / "translating_designed_rise.toml")
    cam = Cam(d.with_(optimize=replace(d.optimize, spans=6, smoothing_slack=0.0)))  # a small space: quick
    data = explore_data(cam)
    assert data["designed"] is True
    rise = data["phases"][0]
    u = np.linspace(0.0, 1.0, rise["n"] + 1)
    designed = cam.design.program.evaluate_phase(0, u)
    given = cam.given.program.evaluate_phase(0, u)
    np.testing.assert_allclose(rise["s"], designed.s, atol=1e-12)
    np.testing.assert_allclose(rise["ds"], designed.ds, atol=1e-12)
    assert np.max(np.abs(designed.ds - given.ds)) > 1e-3  # the designed rise is another law
    assert data["face"]["start"]["R0"] == pytest.approx(cam.solution.R0)


def test_the_page_is_self_contained(pages):
    """No address, no external script, style, font or image; the embedded data are the pipeline's."""
    for name, (cam, html, data) in pages.items():
        low = html.lower()
        for word in ("http://", "https://", "src=", "<link", "@import", "url(", "fetch(", "xmlhttprequest", "//cdn"):
            assert word not in low, (name, word)
        assert html.count("<script>") == 3 and "<script src" not in low
        assert data == json.loads(json.dumps(explore_data(cam)))
        assert data["face"]["mode"] == ("size" if "flat" in name else "centre")


def test_a_name_cannot_end_the_script():
    """A design name with ``</script>`` is written into the data without ending its script element."""
    d = design_from_dict(rocker_dict(name="a </script><script>alert(1)</script> cam"))
    html = page(explore_data(Cam(d)))
    assert _data_of(html)["name"] == "a </script><script>alert(1)</script> cam"
    assert html.count("</script>") == 3
    assert "<title>a &lt;/script&gt;" in html


# -- the page's numbers against cams check ------------------------------------------------------------------------


def _chosen_design(cam, centre):
    """The design with ``[cam] centre = centre``: what a chosen centre fixes (L, the offset) and the floor are
    taken off the file, as they must be."""
    d = cam.design
    f = d.follower
    if getattr(f, "offset", None) is not None:
        f = replace(f, offset=None)
    lim = replace(d.limits, centre_distance=None, min_base_radius=None)
    return d.with_(follower=f, limits=lim, base_radius=None, objective="R0", centre=(float(centre[0]), float(centre[1])))


def _checked(cam, centre):
    """``cams check``'s numbers at ``[cam] centre = centre``: the chosen cam's solve report (as ``--json``)."""
    return Cam(_chosen_design(cam, centre)).solution.to_dict()


def _sized(cam, R0, L):
    """The flat cam of ``[cam] base_radius = R0`` (and ``follower.centre_distance = L``), its solve report."""
    d = cam.design
    if L is not None:
        d = d.with_(follower=replace(d.follower, centre_distance=float(L)))
    return Cam(d.with_(base_radius=float(R0))).solution.to_dict()


def _run_node(html: str, calls: list) -> list:
    """``camsMath`` of the page, run by node on the page's data: ``state(*args)`` (and ``evaluate``) per call."""
    script = _math_of(html) + (
        "\nconst inp = JSON.parse(require('fs').readFileSync(0, 'utf8'));\n"
        "const m = camsMath(inp.data);\n"
        "console.log(JSON.stringify(inp.calls.map((a) => { const e = m.evaluate(...a);"
        " return { state: m.state(...a), minRho: e.minRho === undefined ? null : e.minRho,"
        " rhoBound: e.rhoBound === undefined ? null : e.rhoBound,"
        " riseAt: e.riseAt === undefined ? null : e.riseAt, retAt: e.retAt === undefined ? null : e.retAt }; })));"
    )
    out = subprocess.run(
        [NODE, "-e", script],
        input=json.dumps({"data": _data_of(html), "calls": calls}),
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    return json.loads(out.stdout)


def _offsets(start):
    """Five centres: ``start`` and four moved from it (mm), in and out of the zone."""
    steps = np.array([(0.0, 0.0), (2.0, 1.0), (-3.0, 2.0), (1.0, -4.0), (10.0, 10.0)])
    return list(np.asarray(start, float) + steps)


@pytest.mark.skipif(NODE is None, reason="node is not installed: the page's script cannot run outside a browser")
@pytest.mark.parametrize(
    "name", ["rocker_force", "translating_force", "rocker_form", "translating_form_centric", "two_rises"]
)
def test_page_math_equals_cams_check_at_five_centres(pages, name):
    """The page's state at five centres (the sized one, four others in and out of the zone) equals the
    independent check's at ``[cam] centre`` within the bound the page states; inside equals verified."""
    cam, html, data = pages[name]
    centres = _offsets(data["face"]["start"]["centre"])
    got = _run_node(html, [list(map(float, c)) for c in centres])
    verdicts = set()
    for c, g in zip(centres, got, strict=True):
        st, ref = g["state"], _checked(cam, c)
        assert st["centre"] == pytest.approx(list(c), abs=0)
        assert st["R0"] == pytest.approx(ref["R0"], rel=1e-12)
        for key in ("L", "offset"):
            assert (st[key] is None) == (ref[key] is None)
            if ref[key] is not None:
                assert st[key] == pytest.approx(ref[key], rel=1e-12, abs=1e-12)
        bound = st["error_bound"]
        assert 0 < bound < 1e-3  # degrees: a bound that says something
        for kind in ("rise", "return"):
            assert abs(st["max_pressure_angle"][kind] - ref["max_pressure_angle"][kind]) <= bound + 1e-9, (c, kind)
        # where the page says each largest pressure angle lies (its table's "at ... deg"): the pressure angle there,
        # by the pipeline's own inversion, is the largest the check finds, within the page's bound (at a tie, as at
        # the sized centre's t-t and t1-t1, either place is right)
        d = _chosen_design(cam, c)
        for kind, at in (("rise", g["riseAt"]), ("return", g["retAt"])):
            if at is None or ref["max_pressure_angle"][kind] is None:
                continue
            phi = np.array([float(at)])
            there = np.degrees(pressure_angle(invert(d, np.asarray(c, float), phi, d.program.evaluate(phi))))[0]
            assert there >= ref["max_pressure_angle"][kind] - bound - 1e-9, (c, kind, np.degrees(at), there)
        # inside is every limit: compare where no maximum lies within the bound of its limit
        near = any(
            ref["limits"][k] is not None and abs(ref["max_pressure_angle"][k] - ref["limits"][k]) <= bound
            for k in ("rise", "return")
        )
        if not near:
            assert st["inside"] == ref["verified"], c
        verdicts.add(st["inside"])
    assert verdicts == {True, False}  # the five centres show both


@pytest.mark.skipif(NODE is None, reason="node is not installed: the page's script cannot run outside a browser")
@pytest.mark.parametrize("name", ["rocker_flat", "translating_flat", "rocker_flat_offset"])
def test_flat_page_math_equals_cams_check(pages, name):
    """A flat face: the smallest radius of curvature and the verdict at five sizes equal the chosen cam's
    (``[cam] base_radius``, a rocker's ``follower.centre_distance``) within the page's bound."""
    cam, html, data = pages[name]
    R0, L = data["face"]["start"]["R0"], data["face"]["start"]["L"]
    sizes = [
        (R0, L),
        (1.2 * R0, L),
        (0.8 * R0, L),
        (1.5 * R0, None if L is None else 1.1 * L),
        (R0, None if L is None else 0.9 * L),
    ]
    got = _run_node(html, [[r, ell] for r, ell in sizes])
    for (r, ell), g in zip(sizes, got, strict=True):
        st, ref = g["state"], _sized(cam, r, ell)
        assert st["centre"] is None
        assert st["R0"] == r and st["L"] == ell
        assert abs(g["minRho"] - ref["min_rho"]) <= g["rhoBound"] + 1e-9, (r, ell)
        assert g["rhoBound"] < 0.05 * ref["min_radius"]
        # the check's largest over the cycle: a dwell's equals its neighbours' ends (no velocity jump)
        page_max = max(st["max_pressure_angle"]["rise"], st["max_pressure_angle"]["return"])
        assert abs(page_max - ref["pressure_angle"]["max"]) <= st["error_bound"] + 1e-9, (r, ell)
        if name == "rocker_flat_offset":
            assert page_max > 1.0
        if abs(ref["min_rho"] - ref["min_radius"]) > g["rhoBound"]:
            assert st["inside"] == ref["verified"], (r, ell)


def _port_max_pressure(data, centre, kind):
    """The largest pressure angle (degrees) of the phases of ``kind``, from the embedded samples, in Python:
    cos(gamma) = eps (v x e) / |v| with v the roller centre's velocity relative to the cam (complex numbers)."""
    from scipy.optimize import minimize_scalar

    f = data["face"]["follower"]
    eps = data["face"]["cam_sense"]
    O = complex(*centre)

    def gamma(s, ds):
        if f["kind"] == "rocker":
            A = f["arm"] * np.exp(1j * f["sense"] * s)
            T = 1j * f["sense"] * A
        else:
            A, T = 1j * s, 1j + 0 * s
        v = T * ds - 1j * eps * (A - O)
        e = T / abs(T)
        cross = v.real * e.imag - v.imag * e.real
        return np.degrees(np.arccos(np.clip(eps * cross / np.abs(v), -1, 1)))

    best = -np.inf
    for ph in (p for p in data["phases"] if p["kind"] == kind):
        nodes = np.linspace(0.0, 1.0, ph["n"] + 1)
        g = gamma(np.array(ph["s"]), np.array(ph["ds"]))
        k = int(np.argmax(g))
        lo, hi = nodes[max(k - 1, 0)], nodes[min(k + 1, ph["n"])]
        r = minimize_scalar(
            lambda u: -gamma(np.interp(u, nodes, ph["s"]), np.interp(u, nodes, ph["ds"])),
            bounds=(lo, hi),
            method="bounded",
            options={"xatol": 1e-12},
        )
        best = max(best, g[k], -r.fun)
    return best


@pytest.mark.parametrize("name", ["rocker_force", "translating_force", "rocker_form", "two_rises"])
def test_python_port_of_the_page_formula_equals_cams_check(pages, name):
    """The page's pressure angle, ported to Python on the embedded samples, equals the check's at five centres."""
    cam, _, data = pages[name]
    for c in _offsets(data["face"]["start"]["centre"]):
        ref = _checked(cam, c)
        for kind in ("rise", "return"):
            assert _port_max_pressure(data, c, kind) == pytest.approx(ref["max_pressure_angle"][kind], abs=1e-4)


@pytest.mark.skipif(NODE is None, reason="node is not installed: the page's script cannot run outside a browser")
def test_the_stated_bound_holds_on_coarse_samples():
    """With 24 steps a phase the page's error is large enough to measure: it stays within the bound the page
    states, and the bound is not vacuous (within a factor 1000 of the error at some centre)."""
    cam = Cam(load_design(EXAMPLES / "rocker_form.toml"))
    data = explore_data(cam, samples=24)
    assert {p["n"] for p in data["phases"] if p["kind"] != "dwell"} == {24}
    html = page(data)
    centres = _offsets(data["face"]["start"]["centre"])
    got = _run_node(html, [list(map(float, c)) for c in centres])
    ratios = []
    for c, g in zip(centres, got, strict=True):
        st, ref = g["state"], _checked(cam, c)
        for kind in ("rise", "return"):
            err = abs(st["max_pressure_angle"][kind] - ref["max_pressure_angle"][kind])
            assert err <= st["error_bound"], (c, kind, err, st["error_bound"])
            ratios.append(err / st["error_bound"])
    assert max(ratios) > 1e-3
    assert 1e-3 < got[0]["state"]["error_bound"] < 1.0  # degrees, at 24 steps


@pytest.mark.skipif(NODE is None, reason="node is not installed: the page's script cannot run outside a browser")
def test_the_page_frame_is_the_design_files(tmp_path, capsys):
    """The page's numbers at (x, y) are ``cams check --json``'s for a file with ``[cam] centre = [x, y]``."""
    from cams.cli import main
    from cams.io.tomlwrite import dumps

    d = rocker_dict(follower={"rise_direction": "ccw"}, cam={"rotation": "cw"}, limits={"closure": "form"})
    html = page(explore_data(Cam(design_from_dict(d))))
    centre = [118.0, -22.0]
    (g,) = _run_node(html, [centre])
    f = tmp_path / "chosen.toml"
    f.write_text(dumps({**d, "cam": {"rotation": "cw", "centre": centre}}), encoding="utf-8")
    main(["check", str(f), "--json"])
    ref = json.loads(capsys.readouterr().out)
    worst = {c["name"]: c["worst"] for c in ref["checks"]}
    st = g["state"]
    assert st["centre"] == centre
    assert st["R0"] == pytest.approx(ref["R0"], rel=1e-12)
    for kind in ("rise", "return"):
        assert abs(st["max_pressure_angle"][kind] - worst[f"jamming_{kind}"]) <= st["error_bound"] + 1e-9
    assert st["inside"] is False and worst["jamming_rise"] > 45.0 + st["error_bound"]


def _three_point_radii(q: np.ndarray) -> np.ndarray:
    """The radius of the circle through each point of the closed polygon ``q`` and its two neighbours (mm), where
    the polygon turns the way it runs round (convex there); elsewhere infinity."""
    a, b, c = np.roll(q, 1, 0), q, np.roll(q, -1, 0)
    ab, bc, ca = (np.linalg.norm(u - v, axis=1) for u, v in ((b, a), (c, b), (a, c)))
    cross = (b - a)[:, 0] * (c - b)[:, 1] - (b - a)[:, 1] * (c - b)[:, 0]
    orient = np.sign(np.sum(q[:, 0] * np.roll(q[:, 1], -1) - np.roll(q[:, 0], -1) * q[:, 1]))
    return np.where(np.sign(cross) == orient, ab * bc * ca / (2.0 * np.abs(cross) + 1e-300), np.inf)


@pytest.mark.skipif(NODE is None, reason="node is not installed: the page's script cannot run outside a browser")
@pytest.mark.parametrize("name", ["rocker_force", "translating_force", "rocker_form", "translating_form_centric"])
def test_page_smallest_convex_radius_equals_the_pitch_polygons(pages, name):
    """The roller page's "smallest convex radius of curvature of the pitch curve" (its profile, as the page
    samples it) equals the smallest radius of the circles through three neighbouring points of the pipeline's own
    pitch curve (``cam.profile.pitch``), at the sized centre."""
    cam, html, data = pages[name]
    script = _math_of(html) + (
        "\nconst inp = JSON.parse(require('fs').readFileSync(0, 'utf8'));\n"
        "const m = camsMath(inp.data);\n"
        "console.log(JSON.stringify(m.profile(...inp.c).map((p) => p.rho)));"
    )
    run = subprocess.run(
        [NODE, "-e", script],
        input=json.dumps({"data": _data_of(html), "c": data["face"]["start"]["centre"]}),
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    rho = np.array(json.loads(run.stdout), float)
    page_min = float(np.min(rho[rho > 0]))
    ref = float(np.min(_three_point_radii(np.asarray(cam.profile.pitch, float))))
    assert page_min == pytest.approx(ref, rel=1e-4)


def _chosen(name: str, centre, roller: float):
    """The example ``name`` with its cam centre chosen (``[cam] centre``) and its roller radius ``roller`` (mm)."""
    d = load_design(EXAMPLES / f"{name}.toml")
    f = replace(d.follower, roller_radius=float(roller))
    if getattr(f, "offset", None) is not None:
        f = replace(f, offset=None)
    lim = replace(d.limits, centre_distance=None, min_base_radius=None)
    return Cam(d.with_(follower=f, limits=lim, base_radius=None, objective="R0", centre=tuple(map(float, centre))))


@pytest.mark.skipif(NODE is None, reason="node is not installed: the page's script cannot run outside a browser")
@pytest.mark.parametrize(
    ("name", "centre"),
    [("rocker_form", (128.28528875457778, 28.512954711665643)), ("translating_form_centric", (0.0, -50.0))],
)
def test_page_says_undercut_exactly_when_the_check_does(name, centre):
    """The page's undercut verdict (a red point where the roller's radius is above the pitch curve's convex radius
    of curvature) against the pipeline's ``undercut`` check of the same cam, with the roller 0.2 % below and above
    the pitch curve's smallest convex radius (on both designs it lies on a flank, not on the base circle: 27.17 mm
    on rocker_form's sized centre, 47.77 mm with translating_form_centric's centre 50 mm from the cam's)."""
    least = next(c for c in _chosen(name, centre, 1.0).checks.checks if c.name == "undercut").worst
    verdicts = []
    for roller in (least * 0.998, least * 1.002):
        cam = _chosen(name, centre, roller)
        check = next(c for c in cam.checks.checks if c.name == "undercut")
        assert check.limit == pytest.approx(roller) and check.worst == pytest.approx(least, rel=1e-12)
        html = page(explore_data(cam))
        script = _math_of(html) + (
            "\nconst inp = JSON.parse(require('fs').readFileSync(0, 'utf8'));\n"
            "const m = camsMath(inp.data);\n"
            "console.log(JSON.stringify(m.profile(...inp.c).map((p) => [p.undercut, p.rho])));"
        )
        run = subprocess.run([NODE, "-e", script], input=json.dumps({"data": _data_of(html), "c": list(centre)}),
                             capture_output=True, text=True, timeout=120, check=True)
        pts = json.loads(run.stdout)
        page_cuts = any(cut for cut, _ in pts)
        assert page_cuts == (not check.passed)
        # where the page marks an undercut, the radius there is below the roller's (and convex)
        assert all(0.0 < rho < roller for cut, rho in pts if cut)
        verdicts.append(page_cuts)
    assert verdicts == [False, True]  # the roller below the least radius does not undercut; above, it does
