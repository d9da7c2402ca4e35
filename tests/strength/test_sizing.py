"""Sizing to the contact: the R0 that keeps p0 within the allowable (the part's search, certified) against a scan
of the floor family, and the roller radius range against p0 computed for rollers of a grid of radii on the same
cam."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from cams.cam import Cam
from cams.io.designfile import design_from_dict
from tests.conftest import EXAMPLES


def _translating(**contact) -> dict:
    d = tomllib.loads((EXAMPLES / "translating_contact.toml").read_text(encoding="utf-8"))
    d["limits"].pop("min_base_radius")
    d["contact"].update({"min_film_parameter": 0.5, **contact})  # the film not at stake here
    return d


def test_r0_sized_by_the_contact_stress():
    """Allowable 400 MPa: the pressure angle's cam (17.58 mm) exceeds it; the answer meets it, the cams of the floor
    family below it (sized by the pressure angle alone at each floor) all exceed it, and governs says so."""
    doc = _translating(allowable_stress=400.0)
    d = design_from_dict(doc)
    cam = Cam(d)
    s = cam.solution
    assert s.governs == "contact_stress" and s.R0 > s.pressure_angle_R0
    assert cam.contact.max_pressure <= 400.0
    assert cam.contact.max_pressure == pytest.approx(400.0, rel=1e-6)
    alone = d.with_(constraints="pressure_angle")
    for F in np.linspace(s.pressure_angle_R0, s.R0 * (1 - 1e-5), 12):
        below = Cam(alone.with_floor(float(F)))
        assert below.contact.max_pressure > 400.0
    assert cam.assessment.usable


def test_the_governing_contact_stress_is_said(capsys):
    import tempfile
    from pathlib import Path

    from cams.cli import main
    from tests.commands.test_bad_input import to_toml

    with tempfile.TemporaryDirectory() as t:
        f = Path(t) / "d.toml"
        f.write_text(to_toml(_translating(allowable_stress=400.0)), encoding="utf-8")
        capsys.readouterr()
        assert main(["solve", str(f)]) == 0
    out = capsys.readouterr().out
    assert "governs: the contact stress (contact.allowable_stress) (the pressure angle alone: R0 = 17.581358 mm)" in out


def test_the_roller_radius_range_against_rollers_of_a_grid():
    """p0 is not monotone in the roller radius: on the same cam (its centre chosen) rollers inside the range keep
    p0 within the allowable, rollers outside it do not; at the range's least radius p0 is the allowable."""
    doc = _translating(allowable_stress=450.0)
    base = Cam(design_from_dict(doc))
    lo, hi = base.contact.roller_radius_range()
    centre = [float(c) for c in base.solution.centre]
    doc["cam"]["centre"] = centre

    def p0(x: float) -> float:
        doc["follower"]["roller_radius"] = float(x)
        return Cam(design_from_dict(doc)).contact.max_pressure

    for x in np.linspace(0.5, 0.98 * hi, 25):
        if abs(x - lo) > 1e-3 * lo:
            assert (p0(x) <= 450.0) == (lo <= x <= hi), x
    assert p0(lo) == pytest.approx(450.0, rel=1e-9)
