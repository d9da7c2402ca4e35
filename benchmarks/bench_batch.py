"""The batch solver against the per-design path: one sweep grid through both, in one run.

Usage (from the project folder, after ``pip install -e .``)::

    python benchmarks/bench_batch.py [--quick] [--out benchmarks/results]

Writes ``batch.json`` into ``--out``. The grid: ``examples/rocker_force.toml`` over ``limits.pressure_angle`` (deg)
x ``follower.arm`` (mm), 40 x 50 = 2,000 designs (``--quick``: 4 x 5). It goes through

* the per-design path: :func:`cams.sweep.sweep` with ``per_design=True`` on 2 processes (every design sized,
  its profile built at the design's chord tolerance and checked, :mod:`cams.assess`);
* the batch, the sweep's default: :func:`cams.sweep.sweep` on 2 processes (and, for comparison, on one): each
  chunk's designs sized, checked and judged by :func:`cams.batch.size_batch`, the designs it returns None for
  sent to the per-design path.

It reports designs/s of each (wall time, the pools' start included), their ratio, how many rows went to the
per-design path, that every row is verified and buildable, and the largest difference between the two paths'
R0 against the sum of their error bounds (and of the largest pressure angles, degrees), and the machine's load
average (1 min) before and after (the machine may be shared: the ratio is of the same run).
"""

from __future__ import annotations

import argparse
import copy
import itertools
import json
import os
import sys
import time
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from hardware import machine, one_thread_per_process, write_results  # noqa: E402

one_thread_per_process()  # one BLAS thread: before the first numpy import

import numpy as np  # noqa: E402

KEYS = ("limits.pressure_angle", "follower.arm")
#: The sweep's columns of the largest pressure angles.
PRESSURE = ("max_pressure_angle_rise", "max_pressure_angle_return")


def _grid(quick: bool) -> list[tuple[str, np.ndarray]]:
    n_angle, n_arm = (4, 5) if quick else (40, 50)
    return [
        ("limits.pressure_angle", np.linspace(25.0, 45.0, n_angle)),
        ("follower.arm", np.linspace(100.0, 200.0, n_arm)),
    ]


def _fallback(base: dict, vary) -> int:
    """How many of the grid's designs the batch sends to the per-design path (outside the timing)."""
    from cams.batch import size_batch
    from cams.io.designfile import design_from_dict
    from cams.sweep.grid import set_key

    designs = []
    for c in itertools.product(*[v for _, v in vary]):
        d = copy.deepcopy(base)
        for (k, _), v in zip(vary, c, strict=True):
            set_key(d, k, float(v))
        designs.append(design_from_dict(d))
    return sum(1 for r in size_batch(designs) if r is None)


def _usable(rows: list[dict]) -> int:
    return sum(1 for r in rows if r["verified"] and r["buildable"] and not r["failures"] and not r["error"])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="a 4 x 5 grid (seconds; a smoke test)")
    ap.add_argument("--out", default=str(ROOT / "benchmarks" / "results"))
    a = ap.parse_args(argv)
    from cams.sweep import sweep

    base = tomllib.loads((ROOT / "examples" / "rocker_force.toml").read_text())
    vary = _grid(a.quick)
    combos = list(itertools.product(*[v for _, v in vary]))
    n = len(combos)

    load_before = os.getloadavg()[0]
    t0 = time.perf_counter()
    per = sweep(base, vary, workers=2, per_design=True)
    per_s = time.perf_counter() - t0
    t0 = time.perf_counter()
    two = sweep(base, vary, workers=2)
    two_s = time.perf_counter() - t0
    two_rows = two.rows
    t0 = time.perf_counter()
    sweep(base, vary, workers=1)
    one_s = time.perf_counter() - t0
    two_fb = one_fb = _fallback(base, vary)

    # the two paths agree: the same verdicts, R0 within the sum of their error bounds, the same pressure angles
    worst_r0, worst_ratio, worst_deg, worst_blank, same = 0.0, 0.0, 0.0, 0.0, True
    for p, b in zip(per.rows, two_rows, strict=True):
        same &= (p["verified"], p["buildable"], p["failures"], p["error"]) == (
            b["verified"],
            b["buildable"],
            b["failures"],
            b["error"],
        )
        if p["R0"] is None or b["R0"] is None:
            same &= p["R0"] is b["R0"]
            continue
        d = abs(p["R0"] - b["R0"])
        worst_r0 = max(worst_r0, d)
        worst_ratio = max(worst_ratio, d / ((p["error_bound"] or 0.0) + (b["error_bound"] or 0.0) + 1e-300))
        worst_blank = max(worst_blank, abs(p["blank_diameter"] - b["blank_diameter"]) / p["blank_diameter"])
        for k in PRESSURE:
            if p[k] is not None:
                worst_deg = max(worst_deg, abs(p[k] - b[k]))
    best = "2 processes" if two_s <= one_s else "1 process"
    batch_s = min(two_s, one_s)
    summary = {
        "designs": n,
        "grid": {k: [float(v[0]), float(v[-1]), len(v)] for k, v in vary},
        "per_design_designs_per_s": n / per_s,
        "per_design_seconds": per_s,
        "batch_two_processes_designs_per_s": n / two_s,
        "batch_one_process_designs_per_s": n / one_s,
        "batch_designs_per_s": n / batch_s,
        "batch_best": best,
        "ratio": per_s / batch_s,
        "fallback_rows": two_fb,
        "fallback_rows_one_process": one_fb,
        "rows_verified_and_buildable_per_design": _usable(per.rows),
        "rows_verified_and_buildable_batch": _usable(two_rows),
        "same_verdicts": bool(same),
        "largest_R0_difference_mm": worst_r0,
        "largest_R0_difference_over_error_bounds": worst_ratio,
        "largest_pressure_angle_difference_deg": worst_deg,
        "largest_blank_diameter_difference_relative": worst_blank,
        "load_average_before_after": [load_before, os.getloadavg()[0]],
    }
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    write_results(out / "batch.json", {"machine": machine(), "summary": summary})
    print(json.dumps(summary, indent=2))
    ok = same and _usable(two_rows) == _usable(per.rows) and worst_ratio <= 1.0 and worst_blank <= 1e-9
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
