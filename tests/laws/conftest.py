"""Shared helpers for the tests of ``laws``: a seeded hypothesis profile and finite-difference checks."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, settings

# Derandomized: the same examples on every run and machine (no flaky CI).
settings.register_profile(
    "laws", derandomize=True, database=None, max_examples=60, deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)


def _central_difference(f, u: np.ndarray, h: float = 1e-6) -> np.ndarray:
    """``(f(u + h) - f(u - h)) / (2 h)``: the numerical derivative, used in tests only."""
    return (f(u + h) - f(u - h)) / (2 * h)


@pytest.fixture
def central_difference():
    """The central finite difference ``(f, u, h=1e-6) -> array`` (tests only)."""
    return _central_difference
