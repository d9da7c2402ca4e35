"""Numbers in messages are shown plainly (laws.errors.show_value)."""

from __future__ import annotations

import numpy as np
import pytest

from cams.machine.linkage.machines import CrankSlider
from laws.errors import InputError, show_value


@pytest.mark.parametrize(
    "value, shown",
    [(np.float64(-5.0), "-5.0"), (0.25, "0.25"), (3, "3"), (np.int64(7), "7"), ("abc", "'abc'"),
     ([1, np.float64(2.5)], "[1, 2.5]"), (np.array([1.0, 2.0]), "[1.0, 2.0]"), (np.float64("nan"), "nan"),
     (True, "True"), (np.float32(0.5), "0.5")],
)
def test_show_value(value, shown):
    assert show_value(value) == shown


def test_linkage_messages_show_plain_numbers():
    with pytest.raises(InputError) as e:
        CrankSlider(crank=np.float64(-1.0), rod=100.0)
    assert str(e.value) == "linkage.crank: must be > 0, got -1.0"


def test_check_number_shows_plain_values():
    """The shared number check shows NumPy values plainly (was 'got np.float64(nan)')."""
    import numpy as np
    import pytest

    from laws.errors import InputError, check_number

    with pytest.raises(InputError) as e:
        check_number("dynamics.mass", np.float64(np.nan))
    assert str(e.value) == "dynamics.mass: must be a finite number, got nan"
    with pytest.raises(InputError) as e:
        check_number("dynamics.mass", np.float64(-2.0), lo=0.0)
    assert str(e.value) == "dynamics.mass: must be >= 0, got -2.0"
