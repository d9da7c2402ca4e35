"""The batch benchmark runs on its quick grid and writes its figures: both paths agree row by row."""

from tests.benchmarks_smoke.run import run_benchmark


def test_bench_batch_quick_writes_json(tmp_path):
    res = run_benchmark("bench_batch.py", tmp_path, "--quick", result="batch.json")
    s = res["summary"]
    assert s["designs"] == 20 and {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
    assert s["rows_verified_and_buildable_batch"] == s["rows_verified_and_buildable_per_design"] == 20
    assert s["same_verdicts"] and s["largest_R0_difference_over_error_bounds"] <= 1.0
    assert s["per_design_designs_per_s"] > 0 and s["batch_designs_per_s"] > 0
    assert 0 <= s["fallback_rows"] <= 20
