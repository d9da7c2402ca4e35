"""Shared fixtures: the example designs and small design builders."""

from __future__ import annotations

import signal
from pathlib import Path

import pytest

# The Ctrl-C tests send SIGINT to the processes they start, as a terminal does. A test runner started with SIGINT
# ignored (a shell's background job, `cmd &`, is started so) would pass the ignoring on to every process it starts,
# and Python then installs no handler for it: Ctrl-C would do nothing there. Each process running the tests takes
# Python's usual handler back, so what it starts begins as a terminal's processes do (a handler is reset by exec).
if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    signal.signal(signal.SIGINT, signal.default_int_handler)

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"


def rocker_dict(**over) -> dict:
    """A rocker design as a design-file dict (seed 001's sense), with overrides per table."""
    d = {
        "name": "test rocker",
        "follower": {"kind": "rocker", "arm": 125.0, "swing": 15.0, "roller_radius": 10.0, "rise_direction": "cw"},
        "cam": {"rotation": "ccw"},
        "motion": [
            {"phase": "rise", "law": "cycloidal", "angle": 120},
            {"phase": "dwell", "angle": 30},
            {"phase": "return", "law": "cycloidal", "angle": 120},
            {"phase": "dwell"},
        ],
        "limits": {"pressure_angle": 45, "closure": "force"},
        "solve": {"method": "exact", "samples": 360},
    }
    for k, v in over.items():
        if isinstance(v, dict):
            d[k] = {**d.get(k, {}), **v}
        else:
            d[k] = v
    return d


@pytest.fixture
def examples_dir() -> Path:
    return EXAMPLES


@pytest.fixture
def linear_feed(tmp_path):
    """examples/slotting_feed_cam.toml with its parabolic rise made linear: velocity jumps (rigid impacts)."""
    text = (EXAMPLES / "slotting_feed_cam.toml").read_text(encoding="utf-8")
    assert 'law = "parabolic"' in text
    f = tmp_path / "linear_feed.toml"
    f.write_text(text.replace('law = "parabolic"', 'law = "linear"', 1), encoding="utf-8")
    return f
