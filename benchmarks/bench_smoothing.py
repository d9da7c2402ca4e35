"""Motion design's second stage: what a share of the objective buys in smoothness, and what the optimum needs.

Usage (from the project folder, after ``pip install -e .``)::

    python benchmarks/bench_smoothing.py [--slacks 0 1e-4 1e-3 1e-2 5e-2] [--spans 20] [--out benchmarks/results]

Writes ``smoothing.json`` into ``--out``: for ``examples/translating_designed_rise.toml`` (its rise designed for
the least R0 under the 4-5-6-7 law's peak acceleration and jerk; ``--spans`` spans of degree 7, C3), at each
``smoothing_slack``, what :func:`cams.solve.solve` reports (``optimize.smoothing``: R0 of the first stage's law
and of the law returned, the integrals of S''''^2 and S'''^2 and the total variation of S''' of both) and its
time; beside them ``least_jerk_variation``: the least total variation of S''' (sampled at 64 points a span,
with the knots) any law of the space can have whose conservative program reaches R0 within that share of the
first stage's (a linear program on the same rows as the second stage's, solved here with Clarabel at tight
tolerances), and that law's R0, sized again by the exact method. The gap between the first stage's variation and
the least at slack 0 is what the solver's choice of a vertex added; the least itself is what the optimum needs.
"""

from __future__ import annotations

import argparse
import sys
import time
import warnings
from dataclasses import replace
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from hardware import machine, one_thread_per_process, write_results  # noqa: E402

one_thread_per_process()  # one BLAS thread: before the first numpy import

import numpy as np  # noqa: E402

EXAMPLE = ROOT / "examples" / "translating_designed_rise.toml"
#: Samples a span at which the linear program takes the jerk's variation.
TV_SAMPLES = 64


def least_variation(design, spec, slack: float) -> dict[str, float]:
    """The least sampled total variation of S''' over the laws of the space whose conservative program's R0 is
    within ``(1 + slack)`` of the first stage's (see the module notes), and that law's R0 and variation."""
    import cvxpy as cp
    import scipy.sparse as sps

    from cams.motion_design import jerk_variation
    from cams.solve import solve
    from optimize.motion.conic import solve as conic_solve
    from optimize.motion.design import free_phases, resolve_caps
    from optimize.motion.smooth import allowance
    from optimize.motion.space import Space
    from optimize.motion.translating import Request, build

    base = replace(design, optimize=None)
    free = free_phases(spec, base.program)
    space = Space(base.program, free, spec.degree, spec.spans, spec.continuity)
    req = Request(space=space, follower="roller", cam_sense=base.cam_sense, limits=dict(base.constrained_phases()),
                  caps=resolve_caps(spec, free), objective="R0", length=base.scale,
                  bound=100.0 * (base.scale + float(base.program.lift)))
    prog = build(req, "conservative")
    first = conic_solve(prog)
    u = np.linspace(0.0, 1.0, TV_SAMPLES * spec.spans + 1)
    D = np.diff(space.rows(0, 3, prog.n, samples=u), axis=0) / 100.0       # rows of order 1
    v = cp.Variable(prog.n)
    gn, an = np.linalg.norm(prog.G, axis=1), np.linalg.norm(prog.A, axis=1)
    cons = [sps.csr_matrix(prog.G / gn[:, None]) @ v <= prog.h / gn,
            sps.csr_matrix(prog.A / an[:, None]) @ v == prog.b / an,
            *(cp.SOC(c.a @ v + c.a0, sps.csr_matrix(c.F) @ v + c.f) for c in prog.cones),
            prog.cost @ v <= allowance(first.value, slack)]
    assert prog.enforce is not None
    ranged = prog.enforce & (prog.lo < prog.hi)
    idx = np.flatnonzero(ranged)
    cons += [v[idx] >= prog.lo[ranged], v[idx] <= prog.hi[ranged]]
    problem = cp.Problem(cp.Minimize(cp.norm1(sps.csr_matrix(D) @ v)), cons)
    with warnings.catch_warnings():     # an inaccurate end is kept in "status"; the law is sized again below
        warnings.simplefilter("ignore", UserWarning)
        problem.solve(solver="CLARABEL", tol_feas=1e-11, tol_gap_abs=1e-11, tol_gap_rel=1e-11, max_iter=500)
    laws = space.programme(space.project(np.asarray(v.value, float)), "least variation")
    sized = solve(replace(base, program=laws))
    return {"sampled": 100.0 * float(problem.value), "status": str(problem.status),
            "law": float(jerk_variation(laws.law_of(free[0]), space.breaks) or np.nan), "R0_mm": float(sized.R0),
            "verified": bool(sized.verified)}


def run(slacks: list[float], spans: int) -> dict[str, Any]:
    import cvxpy  # noqa: F401  (imports outside the timings)

    from cams.io.designfile import design_from_dict
    from cams.io.document import read_toml
    from cams.motion_design import jerk_variation
    from cams.solve import solve
    from laws.registry import get_law

    rows = []
    for slack in slacks:
        doc = read_toml(EXAMPLE)
        doc["optimize"].update({"spans": spans, "smoothing_slack": slack})
        design = design_from_dict(doc)
        t0 = time.perf_counter()
        res = solve(design)
        seconds = time.perf_counter() - t0
        o = res.optimization.to_dict()
        sm = {k: v for k, v in o["smoothing"].items() if k != "first_stage_laws"}
        rows.append({"slack": slack, "R0_mm": float(res.R0), "verified": bool(res.verified),
                     "certified": bool(o["certified"]), "lower_bound_mm": o["lower_bound"], "seconds": seconds,
                     "smoothing": sm, "least_jerk_variation": least_variation(design, design.optimize, slack)})
        print(f"slack {slack:g}: R0 {sm['value_before']:.6f} -> {sm['value_after']:.6f} mm, jerk variation "
              f"{sm['jerk_variation_before']:.1f} -> {sm['jerk_variation_after']:.1f} (least "
              f"{rows[-1]['least_jerk_variation']['law']:.1f}), {seconds:.1f} s", flush=True)
    return {"example": str(EXAMPLE.relative_to(ROOT)), "spans": spans,
            "poly4567_jerk_variation": jerk_variation(get_law("poly4567")), "rows": rows, "machine": machine()}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--slacks", type=float, nargs="+", default=[0.0, 1e-4, 1e-3, 1e-2, 5e-2])
    ap.add_argument("--spans", type=int, default=20)
    ap.add_argument("--out", type=Path, default=ROOT / "benchmarks" / "results")
    a = ap.parse_args(argv)
    res = run(a.slacks, a.spans)
    a.out.mkdir(parents=True, exist_ok=True)
    write_results(a.out / "smoothing.json", res)
    print(f"wrote {a.out / 'smoothing.json'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
