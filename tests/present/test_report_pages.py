"""The PDF report's pages, read back with a PDF reader (pdfplumber): every page A4, no text box over another, none
cut by the page's edge or past the margins, no page but the last under a stated fill, the pictures as wide as the
text, and the report of a failing cam beginning with its FAIL banner that names what fails.

The reports are rendered by ``cams report`` as a user runs it, for a rocker roller with ``[dynamics]``, a
translating roller without, a translating and a rocker flat face, and a failing translating roller with
``[dynamics]``; the measures are the reader's (the boxes of the characters and drawings in the file), not the
template's.
"""

from __future__ import annotations

import datetime
import re

import numpy as np
import pdfplumber  # the test extra installs it
import pytest

from cams.cam import Cam
from cams.cli import main
from tests.conftest import EXAMPLES

MM = 72 / 25.4
A4 = (210 * MM, 297 * MM)
#: The stated layout: 18 mm margins left and right; the body between 22 mm from the top and 20 mm from the bottom.
MARGIN = 18 * MM
BODY = (22 * MM, A4[1] - 20 * MM)
#: The tallest a picture may be (a tall one is narrower than the text).
PICTURE_H = 238 * MM
#: Every page but the last is filled over at least this share of the body's height.
FILL = 0.30

FAIL_EDIT = ('rotation = "ccw"', 'rotation = "ccw"\nbase_radius = 20.0\nrpm = 600')


def _design(tmp, name: str):
    """(path, expected picture headings, has [dynamics], fails) of the report's cases."""
    if name == "failing":  # a chosen cam too small for its pressure-angle limit, with [dynamics]
        text = (EXAMPLES / "translating_force.toml").read_text(encoding="utf-8")
        text = text.replace(*FAIL_EDIT).replace("[follower]", "[follower]\noffset = 0.0", 1)
        text += "\n[dynamics]\nmass = 0.5\nload = 5.0\n"
        path = tmp / "failing_cam.toml"
        path.write_text(text, encoding="utf-8")
        return path, ["Allowable-centre zone", "Motion diagrams", "Pressure angle", "Cam profile",
                      "Forces at the cam"], True, True
    roller = ["Allowable-centre zone", "Motion diagrams", "Pressure angle", "Cam profile"]
    flat = ["Motion diagrams", "Pressure angle", "Radius of curvature and contact on the face", "Cam profile"]
    return {"slotting_feed_cam": (EXAMPLES / "slotting_feed_cam.toml", [*roller, "Forces at the cam"], True, False),
            "translating_force": (EXAMPLES / "translating_force.toml", roller, False, False),
            # the flat examples carry [dynamics] (issue 22): their forces are drawn too
            "translating_flat": (EXAMPLES / "translating_flat.toml", [*flat, "Forces at the cam"], True, False),
            "rocker_flat": (EXAMPLES / "rocker_flat.toml", [*flat, "Forces at the cam"], True, False)}[name]


CASES = ["slotting_feed_cam", "translating_force", "translating_flat", "rocker_flat", "failing"]


@pytest.fixture(scope="module", params=CASES)
def report(request, tmp_path_factory):
    """The case's design path, its rendered pages (pdfplumber) and what the report should show."""
    tmp = tmp_path_factory.mktemp(request.param)
    path, pictures, dynamics, fails = _design(tmp, request.param)
    rc = main(["report", str(path), "--out", str(tmp / "out")])
    assert rc == (1 if fails else 0)
    pdf = pdfplumber.open(tmp / "out" / "report.pdf")
    yield {"path": path, "pdf": pdf, "pages": pdf.pages, "pictures": pictures, "dynamics": dynamics,
           "fails": fails, "cam": Cam.from_file(path)}
    pdf.close()


def _words(page):
    return page.extract_words(keep_blank_chars=False, use_text_flow=False)


def _text(page) -> str:
    return " ".join(w["text"] for w in sorted(_words(page), key=lambda w: (round(w["top"]), w["x0"])))


def _overlaps(boxes) -> list[tuple[int, int]]:
    """Pairs of boxes (x0, top, x1, bottom) that overlap by more than half a point each way."""
    b = np.asarray(boxes, float).reshape(-1, 4)
    w = np.minimum(b[:, None, 2], b[None, :, 2]) - np.maximum(b[:, None, 0], b[None, :, 0])
    h = np.minimum(b[:, None, 3], b[None, :, 3]) - np.maximum(b[:, None, 1], b[None, :, 1])
    i, j = np.nonzero(np.triu((w > 0.5) & (h > 0.5), k=1))
    return list(zip(i.tolist(), j.tolist(), strict=True))


def _graphics(page):
    return page.rects + page.curves + page.lines


def _picture_frames(page):
    """The pictures' frames: white-filled rectangles wider than 60 % of the text, not inside another such one
    (matplotlib's figure background; its axes' backgrounds lie inside it)."""
    white = [r for r in page.rects if r.get("fill") and r.get("non_stroking_color") in (1, 1.0, (1,), [1], (1.0,),
                                                                                          [1.0], (1, 1, 1), [1, 1, 1])
             and r["x1"] - r["x0"] > 0.6 * (A4[0] - 2 * MARGIN)]

    def inside(a, b):
        return a is not b and a["x0"] >= b["x0"] - 0.1 and a["x1"] <= b["x1"] + 0.1 and a["top"] >= b["top"] - 0.1 \
            and a["bottom"] <= b["bottom"] + 0.1

    return [r for r in white if not any(inside(r, o) for o in white)]


def test_every_page_is_a4(report):
    for page in report["pages"]:
        assert page.width == pytest.approx(A4[0], abs=0.05) and page.height == pytest.approx(A4[1], abs=0.05)


def test_no_text_box_overlaps_another(report):
    for n, page in enumerate(report["pages"], 1):
        words = _words(page)
        pairs = _overlaps([(w["x0"], w["top"], w["x1"], w["bottom"]) for w in words])
        assert not pairs, f"page {n}: " + "; ".join(f"{words[i]['text']!r} over {words[j]['text']!r}"
                                                    for i, j in pairs[:5])


def test_nothing_is_cut_by_the_page_edge_or_runs_past_the_margins(report):
    for n, page in enumerate(report["pages"], 1):
        for c in page.chars:
            assert c["x0"] >= MARGIN - 0.5 and c["x1"] <= A4[0] - MARGIN + 0.5, (n, c["text"], c["x0"], c["x1"])
            assert c["top"] >= 0 and c["bottom"] <= A4[1], (n, c["text"])
        for g in _graphics(page):
            assert g["x0"] >= MARGIN - 1 and g["x1"] <= A4[0] - MARGIN + 1, (n, g["object_type"], g["x0"], g["x1"])
            assert g["top"] >= 0 and g["bottom"] <= A4[1], (n, g["object_type"])


def test_no_page_but_the_last_is_under_the_fill(report):
    pages = report["pages"]
    assert len(pages) >= 2
    for n, page in enumerate(pages[:-1], 1):
        body = [o for o in [*page.chars, *_graphics(page)] if o["top"] >= BODY[0] - 1 and o["bottom"] <= BODY[1] + 1]
        assert body, f"page {n} is empty"
        filled = (max(o["bottom"] for o in body) - min(o["top"] for o in body)) / (BODY[1] - BODY[0])
        assert filled >= FILL, f"page {n} filled {filled:.0%}"


def test_the_pictures_are_as_wide_as_the_text_and_each_one_is_there(report):
    frames = [f for page in report["pages"] for f in _picture_frames(page)]
    assert len(frames) == len(report["pictures"])
    sized = 0
    for f in frames:
        # as wide as the text (174 mm), or, for a tall one, as tall as the stated 238 mm of the body; or shrunk,
        # to no less than the stated 60 %, to fill the room left on a page
        w, h = f["x1"] - f["x0"], f["bottom"] - f["top"]
        full = w == pytest.approx(A4[0] - 2 * MARGIN, abs=0.5) or (h == pytest.approx(PICTURE_H, abs=0.5) and
                                                                   w < A4[0] - 2 * MARGIN)
        shrunk = 0.6 * (A4[0] - 2 * MARGIN) - 0.5 <= w < A4[0] - 2 * MARGIN and h < PICTURE_H
        assert full or shrunk, (w, h)
        sized += full
        assert BODY[0] - 1 <= f["top"] and f["bottom"] <= BODY[1] + 1
    assert sized >= 1
    text = " ".join(_text(p) for p in report["pages"])
    for title in report["pictures"]:
        assert title in text
    assert text.count("Forces at the cam") == (2 if report["dynamics"] else 0)  # its table and its picture


def test_first_page_starts_with_the_banner_then_the_title_block(report):
    page = report["pages"][0]
    body = sorted((w for w in _words(page) if w["top"] >= BODY[0]), key=lambda w: (round(w["top"]), w["x0"]))
    first = body[0]["text"]
    text = re.sub(r"\s+", " ", " ".join(w["text"] for w in body))  # the page below its running header
    cam = report["cam"]
    if report["fails"]:
        assert first == "FAIL"
        assert cam.assessment.failures
        for line in cam.assessment.failures:  # each failing condition named, as cams.assess words it
            assert re.sub(r"\s+", " ", line) in text
        for p in report["pages"]:  # and every page's header says it
            assert "FAIL" in [w["text"] for w in _words(p) if w["bottom"] <= BODY[0]]
        assert text.index("FAIL") < text.index(cam.design.name)
    else:
        assert first == "PASS" and "FAIL" not in text
    import tomllib

    from tests.conftest import ROOT

    version = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]["version"]
    today = datetime.datetime.now(datetime.UTC).date().isoformat()
    for item in (cam.design.name, str(report["path"]), today, f"cams version {version}"):
        assert item in text, item
    assert text.index(first) == 0 and text.index(cam.design.name) < text.index("Inputs")


def test_inputs_blank_and_lift_table_are_there(report):
    text = " ".join(_text(p) for p in report["pages"])
    for title in ("Inputs", "Results", "Blank", "Lift table", "Checks"):
        assert re.search(rf"\b{title}\b", text), title
    assert ("[dynamics] load opposing the rise" in text) == report["dynamics"]
    r = report["cam"].solution.to_dict()
    assert f"{r['largest_cam_radius']:.6f} mm ({2 * r['largest_cam_radius']:.6f} mm)" in text.replace("\n", " ")
