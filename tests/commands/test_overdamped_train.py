"""An overdamped follower train (``[dynamics] damping_ratio`` > 1, valid input) solved without a warning: the
oscillator's flow ``exp(mu t) cosh(w t)`` overflowed in each factor (``RuntimeWarning: overflow encountered in
cosh``, then ``invalid value`` in the products) on stderr, though the product is below 1."""

from __future__ import annotations

import numpy as np
import pytest

from tests.conftest import EXAMPLES
from tests.inprocess import cams_cli


@pytest.mark.parametrize("zeta", [1.5, 3.0])
def test_an_overdamped_train_solves_without_warnings(tmp_path, zeta):
    text = (EXAMPLES / "translating_train.toml").read_text(encoding="utf-8")
    assert "damping_ratio = 0.05" in text
    design = tmp_path / "d.toml"
    design.write_text(text.replace("damping_ratio = 0.05", f"damping_ratio = {zeta}", 1), encoding="utf-8")
    r = cams_cli("solve", design)
    assert r.returncode == 0 and r.stderr == "", r.stderr
    assert "nan" not in r.stdout.lower() and "inf" not in r.stdout.replace("info", "")


@pytest.mark.parametrize("zeta", [1.0 + 1e-9, 1.5, 40.0])
def test_the_overdamped_flow_is_the_matrix_exponential(zeta):
    """Against scipy's Pade matrix exponential of A t, from w t near 0 (where e^x - 1 cancels) to the times where
    cosh alone overflowed (w t > 710)."""
    from scipy.linalg import expm

    from laws.response import _oscillator

    rho = 3.0
    a = np.array([[0.0, rho], [-rho, -2 * zeta * rho]])
    w = rho * np.sqrt(zeta**2 - 1)
    t = np.array([0.0, 1e-9, 1e-3, 0.3, 2.0, 800.0 / max(w, 1e-6)])
    with np.errstate(over="raise", invalid="raise", divide="raise", under="ignore"):
        got = _oscillator(rho, zeta, t)
    for k, tk in enumerate(t):
        ref = expm(a * tk)
        assert np.allclose(got[k], ref, rtol=1e-9, atol=1e-12 * max(1.0, np.abs(ref).max())), (tk, got[k], ref)
