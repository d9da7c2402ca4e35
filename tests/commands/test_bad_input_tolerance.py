"""``--tolerance`` finer than the profile can carry (more than ``MAX_POINTS`` points): bad input on the command
line, one line naming ``--tolerance``, exit 2 (in process: tests/inprocess.py). ``cams check`` reported the cam
as not buildable ("FAIL: no profile: profile.tolerance: ...", exit 1), a verdict on a cam that is buildable at any
usable tolerance; ``cams profile`` named ``profile.tolerance``, a key the design file does not hold."""

from __future__ import annotations

import os

import pytest

from cams.profile.roller import MAX_POINTS
from tests.conftest import EXAMPLES
from tests.inprocess import cams_cli

ROCKER = EXAMPLES / "rocker_force.toml"


@pytest.mark.parametrize("command", [["check"], ["profile", "--csv", "p.csv"]])
def test_a_tolerance_too_fine_is_bad_input(tmp_path, monkeypatch, command):
    """Refused where the points are counted, naming the field it came from; the failing profile is built once."""
    import cams.profile.roller as roller

    calls = []
    sample = roller._sample
    monkeypatch.setattr(roller, "_sample", lambda *a: calls.append(a[-1]) or sample(*a))
    name, *rest = command
    r = cams_cli(name, ROCKER, "--tolerance", "1e-300", *rest, cwd=tmp_path)
    assert (r.returncode, r.stdout) == (2, ""), (r.returncode, r.stdout, r.stderr)
    assert calls == ["--tolerance"]
    assert (
        r.stderr == f"cams {name}: error: --tolerance: 1e-300 needs more than {MAX_POINTS} points; choose a "
        "larger tolerance\n"
    )
    assert os.listdir(tmp_path) == []


def test_a_fine_tolerance_that_fits_still_checks(tmp_path):
    """The refusal is the tolerance's: one just fine enough to fit (1e-7 mm, some 60,000 points) checks the same
    cam as usable."""
    r = cams_cli("check", ROCKER, "--tolerance", "1e-7")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "all checks pass" in r.stdout


def test_a_flat_faces_count_of_points_is_said_in_a_few_digits():
    """The flat face's count of points a turn grows as 1/sqrt(tolerance): at 1e-300 it was printed with all its 152
    digits. It is the rounded count of ``2 pi sqrt(worst / (8 tol))``, at least 1e+150 there."""
    r = cams_cli("check", EXAMPLES / "translating_flat.toml", "--tolerance", "1e-300")
    assert (r.returncode, r.stdout) == (2, "") and r.stderr.count("\n") == 1, r.stderr
    count = r.stderr.split(" needs ", 1)[1].split(" points", 1)[0]
    assert len(count) <= 9 and float(count) > 1e150, r.stderr
