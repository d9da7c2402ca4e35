"""The motion-design benchmark runs on one coarse space and writes its figures."""

from tests.benchmarks_smoke.run import run_benchmark


def test_bench_motion_quick_writes_json(tmp_path):
    res = run_benchmark("bench_motion.py", tmp_path, "--spans", "5", "--repeats", "1", result="motion.json")
    (row,) = res["rows"]
    assert row["spans"] == 5 and row["verified"] and row["certified"]
    assert row["lower_bound_mm"] <= row["R0_mm"] < res["original_R0_mm"]
    assert {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
    rk = res["rocker"]
    assert rk["verified"] and rk["R0_mm"] < rk["original_R0_mm"] and rk["iterations"] >= 1
    rp = res["rocker_pressure_angle"]
    assert rp["verified"] and rp["ratio"] < 1 and rp["R0_mm"] <= rp["held_R0_mm"] * (1 + 1e-12)
    fr = res["flat_rocker"]
    assert fr["verified"] and fr["R0_mm"] < fr["original_R0_mm"]
