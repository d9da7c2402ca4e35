"""The solver benchmark runs end to end on its quick subset and writes its figures."""

import json
import subprocess
import sys

from tests.conftest import ROOT


def test_bench_solvers_quick_writes_json_and_png(tmp_path):
    r = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_solvers.py"), "--quick", "--repeats", "1",
                        "--out", str(tmp_path)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    res = json.loads((tmp_path / "solvers.json").read_text())
    s = res["summary"]
    assert s["exact_default_tol_worst_rel_error"] <= 1e-9
    assert s["exact_worst_rel_error_by_tol"][f"{s['exact_tol_for_1e-9']:g}"] <= 1e-9
    assert s["exact_median_ms_at_1e-9"] > 0
    assert {"cpu", "cores", "python", "numpy"} <= set(res["machine"])
    methods = {row["method"] for row in res["rows"]}
    assert methods == {"exact", "convex", "exhaustive"}
    assert (tmp_path / "solvers.png").stat().st_size > 0
    assert [r["phases"] for r in res["phases"]] == [20, 60] and all(r["certified"] for r in res["phases"])
