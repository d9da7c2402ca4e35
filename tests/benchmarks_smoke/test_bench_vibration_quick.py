"""The follower train's benchmark runs and writes its figures."""

import json
import subprocess
import sys

from tests.conftest import ROOT


def test_bench_vibration_quick_writes_json(tmp_path):
    r = subprocess.run(
        [sys.executable, str(ROOT / "benchmarks" / "bench_vibration.py"), "--repeats", "1", "--out", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert r.returncode == 0, r.stderr
    res = json.loads((tmp_path / "vibration.json").read_text())
    assert len(res["rows"]) == 2 and {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
    for row in res["rows"]:
        assert row["steady_state_ms"] > 0 and row["jump_search_speeds"] >= 2
        assert 0 < row["dynamic_jump_rpm"] and row["flights_last_turn"] >= 1
