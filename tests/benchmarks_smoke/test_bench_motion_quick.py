"""The motion-design benchmark runs on one coarse space and writes its figures."""

import json
import subprocess
import sys

from tests.conftest import ROOT


def test_bench_motion_quick_writes_json(tmp_path):
    r = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_motion.py"), "--spans", "5", "--repeats",
                        "1", "--out", str(tmp_path)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    res = json.loads((tmp_path / "motion.json").read_text())
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
