"""Motion design: the certified joint optimum against the space's refinement, timed after imports.

Usage (from the project folder, after ``pip install -e .``)::

    python benchmarks/bench_motion.py [--spans 5 10 20 40 80] [--repeats 3] [--out benchmarks/results]

Writes ``motion.json`` into ``--out``: for ``examples/translating_force.toml`` with its rise freed under the
4-5-6-7 law's peak acceleration and jerk (degree 7, C3), at each number of spans per phase, the certified R0
(the cam of the designed law, sized by the exact method), the proven lower bound, the relative gap, whether
the design is verified and certified, and the median time of :func:`cams.solve.solve` after the imports (one
process, one core); with the R0 of the original law beside them. ``rocker``: ``examples/rocker_force.toml``
with its rise freed under the cycloidal law's peaks (degree 7, C2, 10 spans): the sequential convex
programming's R0, iterations, local-optimality measure and time; ``rocker_pressure_angle``: the same, its least
peak pressure angle at the cycloid's R0; ``flat_rocker``: ``examples/rocker_flat.toml`` with its rise and return
freed under the cycloidal law's peaks (C2, 10 spans).
"""

from __future__ import annotations

import argparse
import sys
from functools import partial
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from hardware import machine, median_time, one_thread_per_process, write_results  # noqa: E402

one_thread_per_process()  # one BLAS thread: before the first numpy import


EXAMPLE = ROOT / "examples" / "translating_force.toml"
ROCKER = ROOT / "examples" / "rocker_force.toml"
FLAT_ROCKER = ROOT / "examples" / "rocker_flat.toml"


def run(spans: list[int], repeats: int) -> dict[str, Any]:
    import cvxpy  # noqa: F401  (imports outside the timings)
    import scipy.optimize  # noqa: F401

    from cams.io.designfile import design_from_dict
    from cams.io.document import read_toml
    from cams.solve import solve

    base = read_toml(EXAMPLE)
    original = solve(design_from_dict(base))
    rows = []
    for n in spans:
        doc = dict(base)
        doc["optimize"] = {"free": ["rise"], "max_Ca": "poly4567", "max_Cj": "poly4567", "continuity": 3,
                           "degree": 7, "spans": n}
        res, seconds = median_time(partial(solve, design_from_dict(doc)), repeats)
        o = res.optimization.to_dict()
        rows.append({"spans": n, "R0_mm": res.R0, "lower_bound_mm": o["lower_bound"], "gap": o["gap"],
                     "verified": bool(res.verified), "certified": bool(o["certified"]),
                     "seconds_median": seconds})
        print(f"{n:4d} spans: R0 {res.R0:.6f} mm, lower bound {o['lower_bound']:.6f} mm, gap {o['gap']:.2e}, "
              f"{seconds:.3f} s", flush=True)
    doc = read_toml(ROCKER)
    doc["optimize"] = {"max_Ca": "cycloidal", "max_Cj": "cycloidal", "continuity": 2, "spans": 10}
    res, seconds = median_time(partial(solve, design_from_dict(doc)), repeats)
    o = res.optimization.to_dict()
    rocker = {"example": ROCKER.name, "original_R0_mm": o["reference"]["R0"], "R0_mm": res.R0,
              "iterations": o["iterations"], "local_measure": o["local_measure"], "verified": bool(res.verified),
              "seconds_median": seconds}
    print(f"rocker: R0 {res.R0:.6f} mm (was {o['reference']['R0']:.6f}), {o['iterations']} iterations, local "
          f"measure {o['local_measure']:.1e}, {seconds:.3f} s", flush=True)
    doc["optimize"] = {"objective": "pressure_angle", "max_Ca": "cycloidal", "max_Cj": "cycloidal",
                       "continuity": 2, "spans": 10}
    res, seconds = median_time(partial(solve, design_from_dict(doc)), repeats)
    o = res.optimization.to_dict()
    rocker_pressure = {"example": ROCKER.name, "held_R0_mm": o["held_R0"], "R0_mm": res.R0,
                       "ratio": o["value"], "iterations": o["iterations"], "local_measure": o["local_measure"],
                       "verified": bool(res.verified), "seconds_median": seconds}
    print(f"rocker, least pressure angle at R0 {o['held_R0']:.6f} mm: ratio {o['value']:.6f}, "
          f"{o['iterations']} iterations, local measure {o['local_measure']:.1e}, {seconds:.3f} s", flush=True)
    doc = read_toml(FLAT_ROCKER)
    doc["optimize"] = {"free": ["rise", "return"], "max_Ca": "cycloidal", "max_Cj": "cycloidal",
                       "continuity": 2, "spans": 10}
    res, seconds = median_time(partial(solve, design_from_dict(doc)), repeats)
    o = res.optimization.to_dict()
    flat_rocker = {"example": FLAT_ROCKER.name, "original_R0_mm": o["reference"]["R0"], "R0_mm": res.R0,
                   "iterations": o["iterations"], "local_measure": o["local_measure"],
                   "verified": bool(res.verified), "seconds_median": seconds}
    print(f"flat rocker: R0 {res.R0:.6f} mm (was {o['reference']['R0']:.6f}), {o['iterations']} iterations, "
          f"local measure {o['local_measure']:.1e}, {seconds:.3f} s", flush=True)
    return {"machine": machine(), "example": EXAMPLE.name, "original_R0_mm": original.R0, "rows": rows,
            "rocker": rocker, "rocker_pressure_angle": rocker_pressure, "flat_rocker": flat_rocker}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--spans", type=int, nargs="+", default=[5, 10, 20, 40, 80])
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--out", default=str(ROOT / "benchmarks" / "results"))
    args = ap.parse_args()
    res = run(args.spans, args.repeats)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    write_results(out / "motion.json", res)
    print(f"wrote {out / 'motion.json'}")


if __name__ == "__main__":
    main()
