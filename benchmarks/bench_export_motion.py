"""The motion an exported drawing gives: the follower's errors against the law, per format, curve and tolerance.

Usage (from the project folder, after ``pip install -e .``)::

    python benchmarks/bench_export_motion.py [--tolerances 0.01 0.001 0.0001] [--quick] [--out benchmarks/results]

Writes ``export_motion.json`` into ``--out``: for ``examples/rocker_force.toml`` (a rocker) and
``examples/translating_force.toml`` (a translating follower), at each chord tolerance, each drawing (DXF, SVG) is
written by the product's exporter, read back (:mod:`cams.manufacture.readback`) and followed exactly
(:func:`cams.kinematics.exported.export_motion`): the largest errors of displacement, velocity and acceleration
against the law (per radian of cam angle; a rocker's in degrees), the acceleration's share of the law's peak, the
number of elements and the time of the measure. The curves are those ``cams profile --curve`` draws: the arcs, the
spline (:func:`cams.manufacture.curves.fit_curves`) and the polyline.
``--quick``: one example, one tolerance, no spline.
"""

from __future__ import annotations

import argparse
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from hardware import machine, one_thread_per_process, write_results  # noqa: E402

one_thread_per_process()  # one BLAS thread: before the first numpy import


EXAMPLES = ("rocker_force.toml", "translating_force.toml")


CURVES = ("arcs", "spline", "polyline")


def run(examples: tuple[str, ...], tolerances: list[float], curves: tuple[str, ...] = CURVES) -> dict[str, Any]:
    from cams.cam import Cam
    from cams.kinematics.exported import export_motion
    from cams.manufacture.curves import fit_curves
    from cams.manufacture.dxf import write_dxf
    from cams.manufacture.motion import export_entry
    from cams.manufacture.readback import read_profile
    from cams.manufacture.svg import write_svg
    from cams.model.options import profile_options

    rows = []
    for name in examples:
        cam = Cam.from_file(ROOT / "examples" / name)
        design, sol = cam.design, cam.solution
        for tol in tolerances:
            prof = cam.face.profile(design, sol, profile_options(design, tolerance=tol))
            exact = cam.face.exact(design, sol)
            for curve in curves:
                kw = {"curves": fit_curves(exact, prof.tolerance, curve)}
                for fmt, writer in (("dxf", write_dxf), ("svg", write_svg)):
                    with tempfile.TemporaryDirectory() as tmp:
                        path = writer(prof, Path(tmp) / f"cam.{fmt}", **kw)
                        t0 = time.perf_counter()
                        els = read_profile(path)
                        em = export_motion(design, els, centre=sol.centre, R0=sol.R0)
                        seconds = time.perf_counter() - t0
                    row = {
                        "example": name,
                        **export_entry(fmt, tol, els, em),
                        "seconds": seconds,
                        "unit": "deg" if em.rocker else "mm",
                    }
                    rows.append(row)
                    print(
                        f"{name} {fmt} {row['curve']} tol {tol:g} mm: {row['elements']} elements, ds "
                        f"{row['max_ds']:.3g}, dv {row['max_dv']:.3g}, da {row['max_da']:.3g} {row['unit']}/rad² "
                        f"({100 * row['max_da_ratio']:.3g} % of the peak), {seconds:.1f} s",
                        flush=True,
                    )
    return {"examples": list(examples), "tolerances_mm": tolerances, "rows": rows, "machine": machine()}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tolerances", type=float, nargs="+", default=[0.01, 0.001])
    ap.add_argument("--quick", action="store_true",
                    help="one example (translating), one tolerance (0.01 mm), arcs and polyline (no spline)")
    ap.add_argument("--out", type=Path, default=ROOT / "benchmarks" / "results")
    a = ap.parse_args(argv)
    examples = EXAMPLES[1:] if a.quick else EXAMPLES
    res = run(examples, [0.01] if a.quick else a.tolerances, ("arcs", "polyline") if a.quick else CURVES)
    a.out.mkdir(parents=True, exist_ok=True)
    write_results(a.out / "export_motion.json", res)
    print(f"wrote {a.out / 'export_motion.json'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
