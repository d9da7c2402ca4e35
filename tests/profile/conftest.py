"""Fixtures of the profile tests: the example designs, solved once per session."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from cams.io.designfile import design_from_dict, load_design

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
NAMES = ("rocker_force", "rocker_form", "translating_force", "translating_form_centric")


@pytest.fixture(scope="session")
def solved():
    """``name -> (design, centre)`` for every example, solved by :func:`cams.solve.solve`."""
    from cams.solve import solve

    out = {}
    for n in NAMES:
        d = load_design(EXAMPLES / f"{n}.toml")
        out[n] = (d, np.asarray(solve(d).centre, float))
    return out


def _example_dict(name: str, **tables) -> dict:
    import tomllib

    d = tomllib.loads((EXAMPLES / f"{name}.toml").read_text(encoding="utf-8"))
    for k, v in tables.items():
        d[k] = {**d.get(k, {}), **v} if isinstance(v, dict) else v
    return d


@pytest.fixture
def example_dict():
    """``f(name, **tables)``: an example's parsed file with tables updated (a fresh dict)."""
    return _example_dict


@pytest.fixture
def design_with():
    """``f(name, **tables)``: an example design with tables updated, e.g. ``follower={"roller_radius": 20}``."""
    return lambda name, **tables: design_from_dict(_example_dict(name, **tables))
