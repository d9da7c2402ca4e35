"""The export-motion benchmark runs on one example at one tolerance and writes its figures."""

import pytest

from tests.benchmarks_smoke.run import run_benchmark


def test_bench_export_motion_quick_writes_json(tmp_path):
    res = run_benchmark("bench_export_motion.py", tmp_path, "--quick", result="export_motion.json", timeout=600)
    assert res["examples"] == ["translating_force.toml"] and res["tolerances_mm"] == [0.01]
    formats = {row["format"] for row in res["rows"]}
    assert formats == {"dxf", "svg"}
    for row in res["rows"]:
        assert row["unit"] == "mm" and row["tolerance"] == 0.01 and row["elements"] > 0
        # one peak for every row: the shares are the errors over it
        assert row["max_da_ratio"] == pytest.approx(
            row["max_da"] / res["rows"][0]["max_da"] * res["rows"][0]["max_da_ratio"], rel=1e-12)
        if row["curve"] == "polyline":  # the roller rounds each vertex: the acceleration's error is above the peak
            assert row["max_da_ratio"] > 1
        else:  # the arcs keep their curvature near the curve's
            assert row["curve"] == "arcs" and row["max_da_ratio"] < 0.1
        # within a chord tolerance of the curve, the roller is off by at most tol / cos(gamma) (gamma < 60 deg here)
        assert row["max_ds"] <= 2 * row["tolerance"]
    assert {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
