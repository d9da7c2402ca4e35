"""The R0-L trade-off: ends are the two optima, the front is monotone and admissible."""

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.solve import solve
from cams.verify.pressure import check_pressure
from optimize.tradeoff import tradeoff
from tests.conftest import rocker_dict


def test_tradeoff_front():
    d = design_from_dict(rocker_dict(limits={"closure": "form"}))
    t = tradeoff(d, 9)
    r = solve(d)
    rl = solve(d, objective="L")
    assert t.R0[-1] == pytest.approx(r.R0, rel=1e-12)
    assert t.L[0] == pytest.approx(rl.L, rel=1e-12)
    assert np.all(np.diff(t.L) > 0) and np.all(np.diff(t.R0) < 0)
    for c in t.centres[1:-1]:
        rep = check_pressure(d, c)
        assert rep.rise <= rep.rise_limit + 1e-4 and rep.ret <= rep.return_limit + 1e-4
