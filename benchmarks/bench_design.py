"""Whole designs: solve + profile + checks, the `cams solve` process, light imports, a sweep.

Usage (from the project folder, after ``pip install -e .``)::

    python benchmarks/bench_design.py [--sweep-size 10000] [--repeats 7] [--out benchmarks/results]

Writes ``design.json`` into ``--out``:

* ``whole_design``: every example design file, a fresh :class:`cams.cam.Cam`
  each run (zone table cache cleared), the time to the solution, then the
  profile at the default chord tolerance of 1 micrometre, then the checks
  (median of ``--repeats`` runs, one process, one core);
* ``cli``: ``python -m cams.cli solve FILE`` and the ``cams`` console script as
  processes, imports included (median wall time; target under 1 s), and
  Python's own start-up (``python -c pass``) for comparison;
* ``imports``: the heavy packages (matplotlib, cvxpy, ezdxf) found in
  ``sys.modules`` after ``import cams`` and after the solve command's imports,
  and the import time of ``cams.cli`` from ``python -X importtime``;
* ``sweep``: ``--sweep-size`` designs (pressure-angle limit times arm of the
  rocker example) through :func:`cams.sweep.sweep` on every core, designs per
  second.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from hardware import machine, median_time, one_thread_per_process, write_results  # noqa: E402

one_thread_per_process()  # one BLAS thread: before the first numpy import

import numpy as np  # noqa: E402

EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
HEAVY = ("matplotlib", "cvxpy", "ezdxf")
#: Target wall time of one ``cams solve`` process, seconds.
CLI_TARGET = 1.0


def whole_design(repeats: int) -> list[dict]:
    """Solve, profile (1 um chord tolerance) and check each example, timed per stage."""
    from cams.cam import Cam
    from cams.io.designfile import load_design
    from optimize import zone

    rows = []
    for path in EXAMPLES:
        design = load_design(path)
        stages: dict[str, list[float]] = {"solve": [], "profile": [], "checks": [], "total": []}
        for k in range(repeats + 1):
            zone.clear_cache()
            cam = Cam(design)
            t0 = time.perf_counter()
            _ = cam.solution  # the lazy property: solving is what is timed
            t1 = time.perf_counter()
            prof = cam.profile
            t2 = time.perf_counter()
            checks = cam.checks
            t3 = time.perf_counter()
            if k:  # the first run warms imports and caches of the laws
                for name, t in (("solve", t1 - t0), ("profile", t2 - t1), ("checks", t3 - t2), ("total", t3 - t0)):
                    stages[name].append(t)
        rows.append({
            "file": str(path.relative_to(ROOT)),
            "tolerance_mm": cam.options.tolerance,
            "profile_points": len(prof),
            "checks_passed": bool(checks.passed),
            **{f"{name}_ms": 1e3 * statistics.median(ts) for name, ts in stages.items()},
        })
        r = rows[-1]
        print(f"{r['file']}: solve {r['solve_ms']:.1f} ms, profile {r['profile_ms']:.1f} ms, "
              f"checks {r['checks_ms']:.1f} ms, total {r['total_ms']:.1f} ms", flush=True)
    return rows


def _wall(cmd: list[str], repeats: int) -> tuple[float, subprocess.CompletedProcess]:
    """Median wall time of a command (one untimed run first: disk caches) and its last run."""
    r, t = median_time(lambda: subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT), repeats, warm_up=True)
    return t, r


def cli(repeats: int) -> dict:
    """``cams solve`` as a process, imports included."""
    example = str(ROOT / "examples" / "rocker_force.toml")
    out: dict[str, Any] = {"file": "examples/rocker_force.toml", "target_s": CLI_TARGET}
    t, _ = _wall([sys.executable, "-c", "pass"], repeats)
    out["python_startup_s"] = t
    t, r = _wall([sys.executable, "-m", "cams.cli", "solve", example], repeats)
    out["python_m_cams_cli_s"] = t
    out["exit_code"] = r.returncode
    script = shutil.which("cams") or str(Path(sys.executable).parent / "cams")
    if Path(script).exists():
        t, r2 = _wall([script, "solve", example], repeats)
        out["console_script_s"] = t
        out["console_script_exit_code"] = r2.returncode
    out["meets_target"] = out["python_m_cams_cli_s"] < CLI_TARGET
    print(f"cams solve as a process: {t:.3f} s (python -m cams.cli {out['python_m_cams_cli_s']:.3f} s; "
          f"python start-up {out['python_startup_s']:.3f} s)", flush=True)
    return out


def imports() -> dict:
    """Heavy packages loaded by ``import cams`` and by the solve command; import time of cams.cli."""
    def loaded(code: str) -> list[str]:
        prog = code + f"\nimport sys\nprint(' '.join(m for m in {HEAVY!r} if m in sys.modules))"
        r = subprocess.run([sys.executable, "-c", prog], capture_output=True, text=True, check=True, cwd=ROOT)
        return r.stdout.split()

    example = str(ROOT / "examples" / "rocker_force.toml")
    out: dict[str, Any] = {
        "heavy": list(HEAVY),
        "after_import_cams": loaded("import cams"),
        "after_import_cams_cli": loaded("import cams.cli"),
        "after_cams_solve": loaded("import contextlib, io\nfrom cams.cli import main\n"
                                   "with contextlib.redirect_stdout(io.StringIO()):\n"
                                   f"    main(['solve', {example!r}])"),
    }
    r = subprocess.run([sys.executable, "-X", "importtime", "-c", "import cams.cli"], capture_output=True,
                       text=True, cwd=ROOT)
    rows = []
    for line in r.stderr.splitlines():
        parts = line.split("|")
        if len(parts) == 3 and parts[0].startswith("import time:") and parts[1].strip().isdigit():
            rows.append((int(parts[1]), parts[2].rstrip()))
    top = [(us, name) for us, name in rows if not name.startswith("  ")]
    out["import_cams_cli_ms"] = 1e-3 * sum(us for us, _ in top)
    out["slowest_top_level_imports_ms"] = {name.strip(): us / 1e3 for us, name in sorted(top, reverse=True)[:8]}
    # the large packages and the modules of ours that pull them in (cumulative, each counted where first imported)
    watch = ("numpy", "scipy", "scipy.optimize", "laws.characteristics", "laws", "cams")
    out["cumulative_import_ms"] = {name.strip(): us / 1e3 for us, name in rows if name.strip() in watch}
    out["light"] = not (out["after_import_cams"] or out["after_import_cams_cli"] or out["after_cams_solve"])
    print(f"heavy packages after import cams: {out['after_import_cams'] or 'none'}, after cams solve: "
          f"{out['after_cams_solve'] or 'none'}; import cams.cli {out['import_cams_cli_ms']:.0f} ms", flush=True)
    return out


def sweep_designs(size: int) -> dict:
    """``size`` designs through :func:`cams.sweep.sweep` on every core."""
    from cams.io.document import read_toml
    from cams.sweep import sweep

    base = read_toml(ROOT / "examples" / "rocker_force.toml")
    if size >= 100:
        n1, n2 = 100, size // 100
        vary = [("limits.pressure_angle", np.linspace(30.0, 60.0, n1)), ("follower.arm", np.linspace(100.0, 150.0, n2))]
    else:
        vary = [("limits.pressure_angle", np.linspace(30.0, 60.0, size))]
    workers = os.cpu_count() or 1
    from cams.commands.progress import progress

    with progress(sys.stderr.isatty(), "solving the designs", unit="design") as bar:
        res = sweep(base, vary, workers=workers, progress=bar.to)
    errors = sum(1 for r in res.rows if r["error"])
    verified = sum(1 for r in res.rows if r["verified"])
    out = {"base": "examples/rocker_force.toml", "vary": {k: [float(v[0]), float(v[-1]), len(v)] for k, v in vary},
           "designs": len(res.rows), "workers": res.workers, "seconds": res.seconds,
           "designs_per_second": res.per_second, "errors": errors, "verified": verified}
    print(f"sweep: {out['designs']} designs on {workers} processes in {res.seconds:.1f} s = "
          f"{res.per_second:.0f} designs/s ({verified} verified, {errors} errors)", flush=True)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sweep-size", type=int, default=10_000, help="designs in the sweep (default 10,000)")
    ap.add_argument("--repeats", type=int, default=7, help="timed runs of each whole design and command")
    ap.add_argument("--out", default=str(ROOT / "benchmarks" / "results"))
    a = ap.parse_args(argv)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    result: dict[str, Any] = {"machine": machine()}
    result["whole_design"] = whole_design(a.repeats)
    result["cli"] = cli(a.repeats)
    result["imports"] = imports()
    result["sweep"] = sweep_designs(a.sweep_size)
    result["total_seconds"] = time.perf_counter() - t0
    write_results(out / "design.json", result, indent=1)
    print(json.dumps({k: result[k] for k in ("cli", "sweep")}, indent=1))


if __name__ == "__main__":
    main()
