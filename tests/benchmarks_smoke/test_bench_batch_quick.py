"""The batch benchmark runs on its quick grid and writes its figures: both paths agree row by row."""

import json
import subprocess
import sys

from tests.conftest import ROOT


def test_bench_batch_quick_writes_json(tmp_path):
    r = subprocess.run(
        [sys.executable, str(ROOT / "benchmarks" / "bench_batch.py"), "--quick", "--out", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert r.returncode == 0, r.stderr
    res = json.loads((tmp_path / "batch.json").read_text())
    s = res["summary"]
    assert s["designs"] == 20 and {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
    assert s["rows_verified_and_buildable_batch"] == s["rows_verified_and_buildable_per_design"] == 20
    assert s["same_verdicts"] and s["largest_R0_difference_over_error_bounds"] <= 1.0
    assert s["per_design_designs_per_s"] > 0 and s["batch_designs_per_s"] > 0
    assert 0 <= s["fallback_rows"] <= 20
