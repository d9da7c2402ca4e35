"""The smoothing benchmark runs on one coarse space and writes its figures."""

from tests.benchmarks_smoke.run import run_benchmark


def test_bench_smoothing_quick_writes_json(tmp_path):
    res = run_benchmark("bench_smoothing.py", tmp_path, "--slacks", "0.001", "--spans", "4", result="smoothing.json")
    (row,) = res["rows"]
    sm, least = row["smoothing"], row["least_jerk_variation"]
    assert row["verified"] and row["certified"] and row["slack"] == 0.001
    assert sm["value_after"] <= 1.001 * (1 + 1e-6) * sm["value_before"]
    # the least (sampled) variation within the share is below the returned law's, up to its sampling
    assert least["verified"] and least["law"] <= sm["jerk_variation_after"] * (1 + 1e-3)
    assert least["R0_mm"] <= 1.001 * (1 + 1e-6) * sm["value_before"]
    assert abs(res["poly4567_jerk_variation"] - 273.0) < 1e-6
    assert {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
