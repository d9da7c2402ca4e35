"""The motion design's certificate says why it fails (issue 28, defect 7).

A result not certified lists every reason in its notes (the commands' FAIL line is built from them), so that
the output never falls back on a reason that is not the one ("no lower bound was proven" beside a proven
bound). The reasons are provoked by a solve of the fixed laws that reports its cam not verified or its size not
certified (the product's own solve, its verdict replaced).
"""

from __future__ import annotations

from dataclasses import replace

import pytest

import cams.faces.roller as roller
from cams.io.designfile import design_from_dict
from cams.io.document import read_toml
from cams.motion_design import design_motion

EXAMPLE = "examples/translating_force.toml"


def _design():
    d = read_toml(EXAMPLE)
    d["optimize"] = {"max_Ca": "poly4567", "max_Cj": "poly4567", "spans": 4}
    return design_from_dict(d)


def _spoiled(monkeypatch, **change):
    """The roller pipeline's sizing, its answers for the designed laws carrying ``change`` (the original's not)."""
    real = roller.size_roller

    def run(design, **kw):
        sol = real(design, **kw)
        if any(getattr(design.program.law_of(i), "name", "").startswith("designed") for i in (0, 2)):
            pressure = change.get("pressure")
            sol = replace(sol, **{k: v for k, v in change.items() if k != "pressure"})
            if pressure is not None:
                sol = replace(sol, detail=replace(sol.detail, pressure=replace(sol.detail.pressure, ok=False)))
        return sol

    monkeypatch.setattr(roller, "size_roller", run)


@pytest.mark.parametrize(("change", "reason"), [
    ({"pressure": False}, "the designed laws' cam is not verified: the independent check finds a limit exceeded"),
    ({"certified": False}, "the designed laws' cam's size is not proven: the exact method's bounds disagree"),
])
def test_every_reason_a_certificate_fails_is_said(change, reason, monkeypatch):
    _spoiled(monkeypatch, **change)
    res = design_motion(_design())
    o = res.optimization.to_dict()
    assert not o["certified"] and o["lower_bound"] is not None
    assert reason in o["notes"]


def test_a_certified_design_says_no_reason():
    o = design_motion(_design()).optimization.to_dict()
    # no reason; a note on the designed law's shape (its jerk ringing, issue 22) is not one
    assert o["certified"] and [n for n in o["notes"] if "jerk rings" not in n] == []


def test_an_infinite_peak_over_its_cap_is_said_in_words(monkeypatch):
    """A designed law whose Cj is infinite (its acceleration jumps) breaks its cap: the note says 'infinite',
    never 'None' (law_peaks' JSON value for it), and gives the cap with its digits."""
    import cams.motion_design as md

    real = md.law_peaks

    def peaks(law):
        out = real(law)
        return {**out, "Cj": None} if law.name.startswith("designed") else out

    monkeypatch.setattr(md, "law_peaks", peaks)
    o = design_motion(_design()).optimization.to_dict()
    assert not o["certified"]
    assert "free phase 0: Cj = infinite (the derivative below it jumps) exceeds its cap 52.5" in o["notes"]
    assert not any("None" in n for n in o["notes"])
