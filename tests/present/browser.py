"""A headless Chromium for the explorer's page (``cams explore``): launch, open offline, drag, screenshot.

Shared by the real-browser tests (tests/present/test_explore_browser.py) and the README's screenshot
(docs/make_explore_screenshot.py). The browser is the system's Chromium (Debian's ``chromium`` package, which
``.ci/run`` installs as root, best effort), driven by Playwright for Python through ``executable_path``:
Playwright's own browser download cannot work on the closed network, and pytest-playwright's fixtures would try
it. The flags run it as root (``--no-sandbox``) without a display or a GPU, and keep it from opening any connection
of its own (QUIC, component updates, sync, background networking), which the closed network would refuse.
Playwright gives each launch a fresh, temporary user-data directory (its ``launch``; not a persistent context).

Every page is opened from ``file://`` with every other request aborted and recorded, so a test can say that the
page asked for nothing outside its own file.
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

__all__ = [
    "CHROMIUM_ARGS",
    "BrowserUnavailable",
    "artefacts_dir",
    "chromium",
    "drag",
    "find_chromium",
    "open_offline",
]

#: Chromium's command-line flags: headless, as root, no GPU, and no connection of its own.
CHROMIUM_ARGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)

#: Where a system Chromium is looked for: the names on PATH, then Debian's path.
_NAMES = ("chromium", "chromium-browser")
_PATHS = ("/usr/bin/chromium",)


class BrowserUnavailable(RuntimeError):
    """No browser can run here: Playwright is not installed, no Chromium is found, or it does not start."""


def find_chromium() -> str | None:
    """The system Chromium's executable (``$CAMS_CHROMIUM`` first, then PATH, then /usr/bin/chromium), or None."""
    given = os.environ.get("CAMS_CHROMIUM")
    if given:
        return given if Path(given).is_file() else None
    for name in _NAMES:
        found = shutil.which(name)
        if found:
            return found
    return next((p for p in _PATHS if Path(p).is_file()), None)


@contextmanager
def chromium() -> Iterator[Any]:
    """A launched headless Chromium (a Playwright ``Browser``), closed on exit.

    Raises
    ------
    BrowserUnavailable
        With the reason: Playwright missing, no Chromium found, or its launch failing (the message says which).
    """
    try:
        from playwright.sync_api import Error, sync_playwright
    except ImportError as e:
        raise BrowserUnavailable(f"Playwright for Python is not installed ({e}); pip install -e '.[test]'") from e
    exe = find_chromium()
    if exe is None:
        raise BrowserUnavailable(
            "no Chromium found (chromium on PATH, /usr/bin/chromium or $CAMS_CHROMIUM); "
            "as root: apt-get install chromium (.ci/run does it)"
        )
    with sync_playwright() as pw:
        try:
            browser = pw.chromium.launch(executable_path=exe, headless=True, args=list(CHROMIUM_ARGS))
        except Error as e:
            first = str(e).strip().splitlines()[0] if str(e).strip() else type(e).__name__
            raise BrowserUnavailable(f"Chromium at {exe} does not start: {first}") from e
        try:
            yield browser
        finally:
            browser.close()


def open_offline(browser: Any, page_file: Path, *, width: int = 1440, height: int = 960, ready_ms: float = 10000):
    """Open ``page_file`` from ``file://`` with every non-file request aborted; wait for ``window.cams.ready``.

    Returns
    -------
    page : playwright Page
    blocked : list of str
        The URLs of the requests that were aborted (the page must ask for none); filled as the page runs.
    errors : list of str
        The page's uncaught JavaScript errors and console errors, filled as the page runs.
    """
    from playwright.sync_api import TimeoutError

    context = browser.new_context(viewport={"width": width, "height": height}, device_scale_factor=1)
    blocked: list[str] = []
    errors: list[str] = []

    def route(r) -> None:
        url = r.request.url
        if url.startswith("file:"):
            r.continue_()
        else:
            blocked.append(url)
            r.abort()

    context.route("**/*", route)
    page = context.new_page()
    page.on("pageerror", lambda e: errors.append(f"uncaught: {e}"))
    page.on("console", lambda m: errors.append(f"console.error: {m.text}") if m.type == "error" else None)
    page.goto(Path(page_file).resolve().as_uri())
    waited = 0.0
    while True:  # in short waits, so that a page whose script failed is reported at once
        try:
            page.wait_for_function("() => window.cams !== undefined && window.cams.ready === true", timeout=250)
            return page, blocked, errors
        except TimeoutError as e:
            waited += 250
            if errors or waited >= ready_ms:
                raise AssertionError(
                    f"window.cams.ready is not true after {waited / 1000:g} s; the page's errors: {errors}"
                ) from e


def drag(page: Any, start: tuple[float, float], end: tuple[float, float], steps: int = 8) -> None:
    """Drag with the mouse from client point ``start`` to client point ``end`` (px): press, move in steps, release."""
    page.mouse.move(*start)
    page.mouse.down()
    page.mouse.move(*end, steps=steps)
    page.mouse.up()


def artefacts_dir(default: Path) -> Path:
    """The directory the screenshots are kept in: ``$CAMS_ARTEFACTS/explore`` when set, else ``default``, made."""
    root = os.environ.get("CAMS_ARTEFACTS")
    out = Path(root) / "explore" if root else default
    out.mkdir(parents=True, exist_ok=True)
    return out
