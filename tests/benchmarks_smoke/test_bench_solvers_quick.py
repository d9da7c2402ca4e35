"""The solver benchmark runs end to end on its quick subset and writes its figures."""

from tests.benchmarks_smoke.run import run_benchmark


def test_bench_solvers_quick_writes_json_and_png(tmp_path):
    res = run_benchmark("bench_solvers.py", tmp_path, "--quick", "--repeats", "1", result="solvers.json")
    s = res["summary"]
    assert s["exact_default_tol_worst_rel_error"] <= 1e-9
    assert s["exact_worst_rel_error_by_tol"][f"{s['exact_tol_for_1e-9']:g}"] <= 1e-9
    assert s["exact_median_ms_at_1e-9"] > 0
    assert {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
    methods = {row["method"] for row in res["rows"]}
    assert methods == {"exact", "convex", "exhaustive"}
    assert (tmp_path / "solvers.png").stat().st_size > 0
    assert [r["phases"] for r in res["phases"]] == [20, 60] and all(r["certified"] for r in res["phases"])
