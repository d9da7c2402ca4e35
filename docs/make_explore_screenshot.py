"""The README's screenshot of the explorer's page: ``python docs/make_explore_screenshot.py`` writes docs/explore.png.

It runs ``cams explore examples/rocker_form.toml`` into a temporary directory, opens the page offline in the
system's headless Chromium (the browser tests' launcher, tests/present/browser.py: Debian's ``chromium`` and
Playwright for Python, ``pip install -e '.[test]'``), drags the point with the mouse from the smallest cam to a
centre just outside the K_C zone, turns the cam a little with the slider and saves the page, 1440 x 960 pixels.
The PNG is reduced to a 64-colour palette (Pillow, which matplotlib installs) when that keeps it under 200 kB.

Usage: ``python docs/make_explore_screenshot.py [--out PNG] [--design TOML] [--centre X Y]``.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import re
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from cams.cli import main as cams_main  # noqa: E402
from tests.present.browser import BrowserUnavailable, chromium, drag, open_offline  # noqa: E402

#: The README's view: the groove cam of seed 001 (K_C = 1.1), the point just outside the K_C zone's t-t line.
DESIGN = ROOT / "examples" / "rocker_form.toml"
CENTRE = (126.0, 28.0)
SIZE = (1440, 960)
LIMIT = 200_000  # bytes


def _shrink(png: Path) -> None:
    """Re-save ``png`` with a 64-colour palette when that is smaller (the page's flat colours survive it)."""
    from PIL import Image

    with Image.open(png) as im:
        small = im.convert("RGB").quantize(colors=64, method=Image.Quantize.MEDIANCUT)
    buf = io.BytesIO()
    small.save(buf, format="PNG", optimize=True)
    if buf.tell() < png.stat().st_size:
        png.write_bytes(buf.getvalue())


def make(out: Path, design: Path = DESIGN, centre: tuple[float, float] = CENTRE) -> Path:
    """Write the screenshot of ``design``'s page with the point dragged to ``centre`` (mm) to ``out``; its path."""
    with tempfile.TemporaryDirectory() as tmp:
        page_file = Path(tmp) / "explore.html"
        with contextlib.redirect_stdout(io.StringIO()):
            code = cams_main(["explore", str(design), "--out", str(page_file)])
        if code != 0:
            raise SystemExit(f"cams explore {design} exited {code}")
        with chromium() as browser:
            page, blocked, errors = open_offline(browser, page_file, width=SIZE[0], height=SIZE[1])
            state = page.evaluate("() => window.cams.state()")
            if state["centre"] is not None:
                start = page.evaluate("([x, y]) => window.cams.toScreen(x, y)", state["centre"])
                end = page.evaluate("([x, y]) => window.cams.toScreen(x, y)", list(centre))
                drag(page, tuple(start), tuple(end))
            slider = page.get_by_label(re.compile("cam angle", re.I))
            if slider.count() == 1:
                box = slider.bounding_box()
                if box is not None:
                    page.mouse.click(box["x"] + 0.2 * box["width"], box["y"] + box["height"] / 2)
            out.parent.mkdir(parents=True, exist_ok=True)
            page.screenshot(path=str(out))
            if blocked or errors:
                raise SystemExit(f"the page asked the network for {blocked} or failed: {errors}")
    if out.stat().st_size > LIMIT:
        _shrink(out)
    return out


def _cli() -> int:
    p = argparse.ArgumentParser(description="Write the README's screenshot of the explorer's page.")
    p.add_argument("--out", type=Path, default=ROOT / "docs" / "explore.png", help="the PNG (default docs/explore.png)")
    p.add_argument("--design", type=Path, default=DESIGN, help="the design file (default examples/rocker_form.toml)")
    p.add_argument(
        "--centre",
        type=float,
        nargs=2,
        default=CENTRE,
        metavar=("X", "Y"),
        help="where the point is dragged, mm in the follower's frame (roller faces)",
    )
    a = p.parse_args()
    try:
        out = make(a.out, a.design, tuple(a.centre))
    except BrowserUnavailable as e:
        print(f"make_explore_screenshot: {e}", file=sys.stderr)
        return 2
    print(f"wrote {out} ({out.stat().st_size / 1000:.0f} kB)")
    return 0


if __name__ == "__main__":
    raise SystemExit(_cli())
