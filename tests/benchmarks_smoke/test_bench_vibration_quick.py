"""The follower train's benchmark runs and writes its figures."""

from tests.benchmarks_smoke.run import run_benchmark


def test_bench_vibration_quick_writes_json(tmp_path):
    res = run_benchmark("bench_vibration.py", tmp_path, "--repeats", "1", result="vibration.json")
    assert len(res["rows"]) == 2 and {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
    for row in res["rows"]:
        assert row["steady_state_ms"] > 0 and row["jump_search_speeds"] >= 2
        assert 0 < row["dynamic_jump_rpm"] and row["flights_last_turn"] >= 1
