"""The explorer's page (``cams explore``) in a real browser, against ``cams check`` at the same centre.

A headless Chromium (tests/present/browser.py: the system's, through Playwright) opens the page written by
``cams explore`` from ``file://`` with every other request aborted, and the tests say that none was attempted and
that the page raised no JavaScript error (a page that asks the network is caught: the harness's own test). For a
rocker roller (form closure with K_C; force closure, limited at the start position too), a translating roller
(force closure, the solver's offset) and a flat-faced rocker (its face through the pivot, and 15 mm from it for a
pressure angle that is not 0):

- the point is dragged with the mouse (press, move, release at the client coordinates ``window.cams.toScreen``
  gives) to five centres inside and outside the zone; a flat face, which has no centre, is given five sizes by
  ``window.cams.setSize(R0, L)``. At each, ``window.cams.state()`` is read and a copy of the design file with that
  centre (``[cam] centre``; a flat face: ``[cam] base_radius`` and ``[follower] centre_distance``) is run through
  ``cams check --json`` and ``cams solve --json``, as a user runs them: R0, L or the offset (to 1e-9) and the
  largest pressure angle of each phase (cams check's where it limits the phase, the chosen cam's of cams solve
  elsewhere; a flat face: the largest over the cycle, which cams solve gives) must agree within the page's stated
  ``error_bound`` (itself under 0.01 deg), and ``inside`` must be cams check's verdict on the file's limits (each
  phase's pressure angle, and the rocker's K_C through cams solve's ``safety_factor.ok``; a flat face's convexity);
- the smallest-cam button returns the point to the sized cam of ``cams solve --json``;
- the slider turns the cam: the drawings change, the numbers do not, and the slider back where it was gives the
  same drawings again;
- a design with no feasible zone: the page opens and says cams solve's diagnosis.

The targets are chosen clear of every limit (0.25 deg at the nearest, K_C 0.02 from its value, the radius of
curvature 5 mm; the test requires ten times the page's bound): the verdicts do not hang on the last digits. Screenshots
are kept in ``$CAMS_ARTEFACTS/explore`` when set, else in tests/artefacts/explore (ignored by git). The tests are
skipped, with the reason, only where no browser can be found or launched.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import re
from pathlib import Path

import pytest

from cams.cli import main
from tests.conftest import EXAMPLES, ROOT
from tests.present.browser import BrowserUnavailable, artefacts_dir, chromium, drag, open_offline

#: Each case: the example, and five targets: a roller's centres [x, y] in the follower's frame (mm), a flat face's
#: sizes (R0, L) (mm); each with the expected verdict (True: inside every limit), which the test also takes from
#: cams check, so a wrong expectation here fails loudly instead of testing less.
CASES = {
    # sized centre (128.285, 28.513); K_C = 1.1: (126, 28) meets every pressure-angle limit, not K_C
    "rocker_form": (
        "rocker_form.toml",
        [
            ((150.0, 60.0), True),
            ((140.0, 45.0), True),
            ((126.0, 28.0), False),
            ((130.0, 20.0), False),
            ((110.0, 40.0), False),
        ],
    ),
    # force closure, sized centre (134.363, 9.363): the rise limited on t-t and, at the start position, on t1-t1;
    # (150, 20) fails at cam angle 0 (t1-t1), (110, 30) in the rise (t-t)
    "rocker_force": (
        "rocker_force.toml",
        [
            ((140.0, 50.0), True),
            ((120.0, 40.0), True),
            ((145.0, 25.0), True),
            ((150.0, 20.0), False),
            ((110.0, 30.0), False),
        ],
    ),
    # sized centre (-8.791, -15.226): the rise is limited to 30 degrees
    "translating_force": (
        "translating_force.toml",
        [
            ((-10.0, -40.0), True),
            ((-20.0, -35.0), True),
            ((-12.0, -25.0), True),
            ((10.0, -30.0), False),
            ((5.0, -18.0), False),
        ],
    ),
    # sized R0 37.064 mm at L = 120 mm (convexity: radius of curvature >= 5 mm)
    "rocker_flat": (
        "rocker_flat.toml",
        [
            ((45.0, 120.0), True),
            ((60.0, 130.0), True),
            ((40.0, 110.0), True),
            ((25.0, 120.0), False),
            ((30.0, 125.0), False),
        ],
    ),
    # the same rocker with its face 15 mm from the pivot: a pressure angle of 5.8 to 9.4 deg that moves with R0, L
    "rocker_flat_offset": (
        "rocker_flat.toml",
        [
            ((45.0, 125.0), True),
            ((60.0, 110.0), True),
            ((50.0, 140.0), True),
            ((25.0, 120.0), False),
            ((30.0, 115.0), False),
        ],
    ),
}

#: Pages of a test of their own (not dragged): the example each edits.
OTHER_PAGES = {"translating_flat_offset": "translating_flat.toml"}

#: The cases that edit their example: (table, key) -> value, as written in the file.
EDITS = {"rocker_flat_offset": {("follower", "face_offset"): "15.0"},
         "translating_flat_offset": {("follower", "offset"): "12.0"}}

#: The cases of the button and slider tests: one of each face and follower.
BASIC = ["rocker_form", "translating_force", "rocker_flat"]

#: The loosest error bound (degrees) the page may state for the comparison to mean something.
BOUND_MAX = 0.01

#: How far, in screen pixels, the dragged point may land from its target (the mouse moves on the pixel grid).
PIXELS = 1.5


def _cli(argv: list[str]) -> tuple[int, dict]:
    """Run ``cams ARGV --json`` in this process, as the command line does; its exit code and JSON."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        code = main(argv)
    return code, json.loads(out.getvalue())


def _with(text: str, table: str, key: str, value: str) -> str:
    """The design file's text with ``key = value`` in ``[table]`` (replacing the key where it is set)."""
    line = re.compile(rf"^{key}\s*=.*$", re.M)
    head = re.search(rf"^\[{table}\]\s*$", text, re.M)
    assert head is not None, f"no [{table}] table"
    nxt = re.search(r"^\[", text[head.end() :], re.M)
    end = head.end() + (nxt.start() if nxt else len(text[head.end() :]))
    body = text[head.end() : end]
    body = line.sub(f"{key} = {value}", body) if line.search(body) else f"\n{key} = {value}" + body
    return text[: head.end()] + body + text[end:]


def _design_text(name: str) -> str:
    """The case's design file: its example with the case's edits."""
    text = (EXAMPLES / (CASES[name][0] if name in CASES else OTHER_PAGES[name])).read_text(encoding="utf-8")
    for (table, key), value in EDITS.get(name, {}).items():
        text = _with(text, table, key, value)
    return text


def _chosen(tmp: Path, name: str, state: dict, n: int) -> Path:
    """A copy of the case's design with the page's centre (a flat face: its R0 and L) as the chosen cam."""
    text = _design_text(name)
    if state["centre"] is None:
        text = _with(text, "cam", "base_radius", repr(float(state["R0"])))
        if state.get("L") is not None and "centre_distance" in text:
            text = _with(text, "follower", "centre_distance", repr(float(state["L"])))
    else:
        x, y = state["centre"]
        text = _with(text, "cam", "centre", f"[{float(x)!r}, {float(y)!r}]")
    path = tmp / f"{name}_{n}.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def browser():
    """One headless Chromium for the module; the tests skip with the reason when none can run here."""
    try:
        with chromium() as b:
            yield b
    except BrowserUnavailable as e:
        pytest.skip(f"no browser for the explorer's page: {e}")


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    """A case's design file and its explorer page, written by ``cams explore FILE --out PAGE.html`` when a test
    first asks (a worker of pytest-xdist writes only the cases it runs)."""
    out = tmp_path_factory.mktemp("explore")
    written: dict[str, tuple[Path, Path]] = {}

    def get(name: str) -> tuple[Path, Path]:
        if name not in written:
            design, page = out / f"{name}.toml", out / f"{name}.html"
            design.write_text(_design_text(name), encoding="utf-8")
            with contextlib.redirect_stdout(io.StringIO()):
                code = main(["explore", str(design), "--out", str(page)])
            assert code == 0 and page.is_file() and page.stat().st_size > 0, f"cams explore {name}: exit {code}"
            written[name] = (design, page)
        return written[name]

    return get


@pytest.fixture(scope="module")
def shots() -> Path:
    """Where the screenshots are kept (see the module's docstring)."""
    return artefacts_dir(ROOT / "tests" / "artefacts" / "explore")


@pytest.fixture(scope="module")
def sessions(browser, pages):
    """Each case's page, opened offline once for the module (opening runs the page's whole computation) and
    shared by the case's tests, each of which starts from wherever the point is; closed at the end."""
    opened: dict[str, tuple] = {}

    def get(name: str):
        if name not in opened:
            opened[name] = open_offline(browser, pages(name)[1])
        return opened[name]

    yield get
    for page, _, _ in opened.values():
        page.context.close()


@pytest.fixture
def opened(sessions, request):
    """The case's page; after the test: no request left the file, no JavaScript error, ever since it opened."""
    name = request.param
    page, blocked, errors = sessions(name)
    yield name, page
    assert blocked == [], f"the page asked the network for {blocked}"
    assert errors == [], f"the page's JavaScript failed: {errors}"


def _state(page) -> dict:
    return page.evaluate("() => window.cams.state()")


def _screen(page, x: float, y: float) -> tuple[float, float]:
    px, py = page.evaluate("([x, y]) => window.cams.toScreen(x, y)", [x, y])
    return float(px), float(py)


def _bound(state: dict) -> float:
    """The page's stated error bound on its pressure angles (degrees), checked to be a finite number >= 0."""
    eb = state["error_bound"]
    assert isinstance(eb, int | float) and math.isfinite(eb) and eb >= 0, f"error_bound {eb!r}"
    # a bound that makes the comparison worth something: well under the 0.1 deg the pages print
    assert eb < BOUND_MAX, f"error_bound {eb} deg: too loose to compare the pressure angle"
    return float(eb)


def _move_to(page, target: tuple[float, float]) -> dict:
    """Drag the point with the mouse from where it is to the model point ``target``; the state after the drag."""
    before = _state(page)["centre"]
    handle = page.locator("#centre-handle")
    assert handle.count() == 1, "no draggable #centre-handle"
    start = _screen(page, *before)
    box = handle.bounding_box()
    assert box is not None, "#centre-handle is not drawn"
    # the handle is drawn where toScreen puts the centre: the mouse grabs the handle itself
    assert box["x"] - 1 <= start[0] <= box["x"] + box["width"] + 1, (start, box)
    assert box["y"] - 1 <= start[1] <= box["y"] + box["height"] + 1, (start, box)
    end = _screen(page, *target)
    vw, vh = page.viewport_size["width"], page.viewport_size["height"]
    assert 0 <= end[0] <= vw and 0 <= end[1] <= vh, f"target {target} is off the page at {end}"
    drag(page, start, end)
    state = _state(page)
    # the point lands within a pixel or so of the target: measured on the screen, through toScreen
    got = _screen(page, *state["centre"])
    assert math.dist(got, end) <= PIXELS, f"dragged to {end}, the point is at {got} (model {state['centre']})"
    return state


def _expected_roller(path: Path) -> dict:
    """cams check and cams solve (chosen cam) at the file's centre: R0, L, offset, the largest pressure angle of
    each phase and the verdict on the limits."""
    _, chk = _cli(["check", str(path), "--json"])
    _, sol = _cli(["solve", str(path), "--json"])
    assert sol["mode"] == "chosen"
    jam = {c["name"].removeprefix("jamming_"): c for c in chk["checks"] if c["name"].startswith("jamming_")}
    assert "rise" in jam, chk["checks"]
    # the check's pressure angle where the check limits the phase; the chosen cam's (over the cycle) elsewhere
    pa = {p: (jam[p]["worst"] if p in jam else sol["max_pressure_angle"][p]) for p in ("rise", "return")}
    kc = sol.get("safety_factor")
    inside = all(c["passed"] for c in jam.values()) and (kc is None or kc["ok"])
    # how clear of its limits the cam is: degrees from each phase's limit; K_C met against K_C required
    margin = {"deg": min(abs(c["worst"] - c["limit"]) for c in jam.values())}
    if kc is not None:
        margin["K_C"] = abs(kc["met"] - kc["required"])
    return {
        "R0": chk["R0"],
        "L": sol["L"],
        "offset": sol["offset"],
        "pa": pa,
        "inside": inside,
        "margin": margin,
    }


def _expected_flat(path: Path) -> dict:
    """cams check and cams solve at the file's R0 and L: R0, L, the pressure angle, the verdict (convexity)."""
    _, chk = _cli(["check", str(path), "--json"])
    _, sol = _cli(["solve", str(path), "--json"])
    conv = next(c for c in chk["checks"] if c["name"] == "convexity")
    pa = max(abs(sol["pressure_angle"]["min"]), abs(sol["pressure_angle"]["max"]))
    return {
        "R0": chk["R0"],
        "L": sol["L"],
        "pa": pa,
        "inside": conv["passed"],
        "margin": {"mm": abs(conv["worst"] - conv["limit"])},  # the radius of curvature from min_radius
    }


@pytest.mark.parametrize("opened", list(CASES), indirect=True)
def test_dragged_centres_agree_with_cams_check(opened, tmp_path, shots):
    """Five centres (a flat face: five sizes) reached as a user would: the page's numbers are cams check's."""
    name, page = opened
    targets = CASES[name][1]
    flat = _state(page)["centre"] is None
    for n, (target, expect_inside) in enumerate(targets):
        if flat:
            page.evaluate("([r, l]) => window.cams.setSize(r, l)", list(target))
            state = _state(page)
            assert state["R0"] == pytest.approx(target[0], rel=1e-12)
            assert state["L"] == pytest.approx(target[1], rel=1e-12)
        else:
            state = _move_to(page, target)
        page.screenshot(path=str(shots / f"{name}_{n}.png"))
        eb = _bound(state)
        path = _chosen(tmp_path, name, state, n)
        at = f"{name} at {state['centre'] or (state['R0'], state['L'])}"
        if flat:
            want = _expected_flat(path)
            assert state["R0"] == pytest.approx(want["R0"], rel=1e-9, abs=1e-9), at
            assert state["L"] == pytest.approx(want["L"], rel=1e-9, abs=1e-9), at
            worst = max(abs(v) for v in state["max_pressure_angle"].values() if v is not None)
            assert abs(worst - want["pa"]) <= eb + 1e-9, (at, state, want)
        else:
            want = _expected_roller(path)
            assert state["R0"] == pytest.approx(want["R0"], rel=1e-9, abs=1e-9), at
            for key in ("L", "offset"):
                if want[key] is None:
                    assert state.get(key) is None, (at, key, state)
                else:
                    assert state[key] == pytest.approx(want[key], rel=1e-9, abs=1e-9), (at, key)
            for phase in ("rise", "return"):
                got = state["max_pressure_angle"][phase]
                assert abs(got - want["pa"][phase]) <= eb + 1e-9, (at, phase, got, want["pa"][phase], eb)
        # the verdict: the page's is cams check's; the target was chosen clear of every limit
        clear = {"deg": 10 * eb + 1e-6, "K_C": 1e-3, "mm": 1e-3}  # the page's bound on its angles, with room
        assert all(v > clear[k] for k, v in want["margin"].items()), (at, "too near a limit for a sure verdict", want)
        assert want["inside"] is expect_inside, (at, "the case's expectation is not cams check's", want)
        assert state["inside"] is want["inside"], (at, state, want)


@pytest.mark.parametrize("opened", BASIC, indirect=True)
def test_smallest_cam_button_returns_to_the_sized_cam(opened, pages, shots):
    """Away from the sized cam, the button brings the point back to cams solve's smallest cam."""
    name, page = opened
    targets = CASES[name][1]
    _, sol = _cli(["solve", str(pages(name)[0]), "--json"])
    flat = _state(page)["centre"] is None
    (far, _) = targets[0]
    if flat:
        page.evaluate("([r, l]) => window.cams.setSize(r, l)", list(far))
    else:
        _move_to(page, far)
    moved = _state(page)
    assert abs(moved["R0"] - sol["R0"]) > 1.0, "the point did not leave the sized cam"
    button = page.get_by_role("button", name=re.compile("smallest", re.I))
    assert button.count() == 1, "no 'smallest cam' button"
    button.click()
    state = _state(page)
    page.screenshot(path=str(shots / f"{name}_smallest.png"))
    assert state["R0"] == pytest.approx(sol["R0"], rel=1e-9), (name, state, sol["R0"])
    if flat:
        assert state["L"] == pytest.approx(sol["L"], rel=1e-9)
    else:
        assert state["centre"] == pytest.approx([sol["centre"]["x"], sol["centre"]["y"]], rel=1e-9, abs=1e-9)


#: The page's drawings: every SVG's markup, in document order.
DRAWINGS = "() => [...document.querySelectorAll('svg')].map((s) => s.outerHTML).join('\\n')"


@pytest.mark.parametrize("opened", ["rocker_form", "rocker_flat"], indirect=True)
def test_slider_turns_the_cam(opened, shots):
    """Moving the slider with the mouse turns the cam: the drawings change and the numbers do not; moved back, the
    drawings are the ones they were (compared as SVG markup: the pixels of text and borders may shift by a
    fraction when the page re-lays out)."""
    name, page = opened
    slider = page.get_by_label(re.compile("cam angle", re.I))
    assert slider.count() == 1, "no slider labelled 'cam angle'"
    slider.scroll_into_view_if_needed()
    box = slider.bounding_box()
    assert box is not None
    start_value = slider.input_value()
    before_state = _state(page)
    before = page.evaluate(DRAWINGS)
    page.mouse.click(box["x"] + 0.3 * box["width"], box["y"] + box["height"] / 2)
    assert slider.input_value() != start_value, "the slider did not move"
    page.screenshot(path=str(shots / f"{name}_turned.png"))
    assert page.evaluate(DRAWINGS) != before, "turning the cam changed no drawing"
    assert _state(page) == before_state, "turning the cam changed the design's numbers"
    slider.fill(start_value)  # back where it was
    assert slider.input_value() == start_value
    assert page.evaluate(DRAWINGS) == before, "the slider back at its start does not give the first drawings"


def test_the_blocker_sees_a_request_off_the_file(browser, tmp_path):
    """The harness's own check can fail: a page that asks for an image and a style sheet on the network has both
    requests aborted and recorded (so an explorer page that asked for anything would be caught)."""
    page_file = tmp_path / "asks.html"
    page_file.write_text(
        '<!doctype html><link rel="stylesheet" href="http://styles.invalid/a.css">'
        '<img src="https://images.invalid/b.png"><script>window.cams = {ready: true}</script>',
        encoding="utf-8",
    )
    page, blocked, errors = open_offline(browser, page_file)
    page.wait_for_load_state("load")
    assert sorted(blocked) == ["http://styles.invalid/a.css", "https://images.invalid/b.png"]
    assert errors, "the aborted loads are reported as the page's console errors"
    page.context.close()


def test_no_feasible_zone_the_page_opens_and_says_why(browser, tmp_path, shots):
    """Limits no centre meets (7 deg on both phases of the groove cam): the page still opens offline, shows the
    diagnosis cams solve gives, word for word, and the centres inside the example's own zone are outside this one."""
    design = tmp_path / "no_zone.toml"
    text = _with((EXAMPLES / "rocker_form.toml").read_text(encoding="utf-8"), "limits", "pressure_angle", "7.0")
    design.write_text(_with(text, "limits", "return_pressure_angle", "7.0"), encoding="utf-8")
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        assert main(["solve", str(design)]) == 2
    said = err.getvalue().strip()
    assert said.startswith("cams solve: error: "), said
    why = said.removeprefix("cams solve: error: ")
    page_file = tmp_path / "no_zone.html"
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        main(["explore", str(design), "--out", str(page_file)])
    page, blocked, errors = open_offline(browser, page_file)
    page.screenshot(path=str(shots / "no_zone.png"))
    shown = page.locator("body").inner_text()
    assert why in " ".join(shown.split()), f"the page does not say cams solve's {why!r}"
    assert _state(page)["inside"] is False
    for x, y in [c for c, inside in CASES["rocker_form"][1] if inside]:  # inside the zone of 45 and 50 deg
        page.evaluate("([x, y]) => window.cams.setCentre(x, y)", [x, y])
        assert _state(page)["centre"] == [x, y]
        assert _state(page)["inside"] is False, (x, y)
    assert blocked == [] and errors == [], (blocked, errors)
    page.context.close()


def test_a_translating_flat_faces_stem_is_on_its_axis(browser, pages, shots):
    """translating_flat with its axis 12 mm off the cam centre: the page draws the stem where cams plot's picture
    has it (cams.present.mechanism: the face's origin on the follower's axis), +12 mm from the cam centre."""
    from matplotlib.figure import Figure

    from cams.cam import Cam
    from cams.present.mechanism import draw_flat_mechanism

    design, html = pages("translating_flat_offset")
    cam = Cam.from_file(design)
    ax = Figure().add_subplot()
    draw_flat_mechanism(ax, cam, cam.profile, 0.0)  # the follower's frame
    body = [ln for ln in ax.lines if ln.get_label() == "follower (flat face and stem)"]  # the face, the stem
    (stem,) = [ln for ln in body if ln.get_xdata()[0] == ln.get_xdata()[-1]]  # the stem: upright
    expected = float(stem.get_xdata()[0] - cam.solution.centre[0])  # the stem's x from the cam centre, mm
    assert expected == pytest.approx(12.0)
    page, blocked, errors = open_offline(browser, html)
    try:
        x1, x2 = page.evaluate(
            "() => { const s = document.querySelector('[data-part=stem]');"
            " return [Number(s.getAttribute('x1')), Number(s.getAttribute('x2'))]; }"
        )
        page.screenshot(path=str(shots / "translating_flat_offset.png"))
    finally:
        page.close()
    assert x1 == x2 == pytest.approx(expected)
    assert blocked == [] and errors == []


def test_a_flat_faces_page_keeps_its_two_panes_side_by_side(browser, pages, shots):
    """rocker_flat's sizes (R0, L) under the drawing: each slider on a line of its own, so the left pane is no
    wider than its drawing and the numbers' pane stands beside it at 1400 px (it went below, out of view); the
    boxes show the sizes to 0.1 um, not a float's seventeen digits."""
    _, html = pages("rocker_flat")
    page, blocked, errors = open_offline(browser, html, width=1400, height=1000)
    try:
        left, right, drawing = (
            page.evaluate(f"() => {{ const r = document.getElementById('{i}').getBoundingClientRect();"
                          " return [r.left, r.top, r.right]; }")
            for i in ("left", "right", "zone")
        )
        boxes = page.evaluate("() => [document.getElementById('R0-input').value,"
                              " document.getElementById('L-input').value]")
        page.screenshot(path=str(shots / "rocker_flat_panes.png"))
    finally:
        page.context.close()
    assert right[1] == pytest.approx(left[1], abs=2) and right[0] >= left[2], (left, right)
    assert left[2] - drawing[2] <= 30, (left, drawing)  # the pane holds its drawing and a margin, no more
    for value in boxes:
        assert len(value.partition(".")[2]) <= 4, boxes
    assert blocked == [] and errors == []


@pytest.mark.parametrize("name", ["rocker_force", "rocker_flat"])
def test_the_charts_title_stands_above_its_curves(browser, pages, name):
    """The chart's title (its one text at the top) is drawn in a band of its own: every point of every curve lies
    below the title's box (a curve's peak ran through it)."""
    _, html = pages(name)
    page, blocked, errors = open_offline(browser, html)
    try:
        title_bottom, tops = page.evaluate(
            "() => { const c = document.getElementById('chart');"
            " const title = [...c.querySelectorAll('text')].find((t) => t.textContent.includes('over the cam angle'));"
            " const b = title.getBBox();"
            " const ys = [...c.querySelectorAll('polyline')].flatMap((p) => [...p.points].map((q) => q.y));"
            " return [b.y + b.height, Math.min(...ys)]; }"
        )
    finally:
        page.context.close()
    assert tops >= title_bottom, (tops, title_bottom)
    assert blocked == [] and errors == []
