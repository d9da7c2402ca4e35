"""Importing the packages, and solving a design, stays light (no matplotlib, cvxpy or ezdxf;
no scipy.optimize or scipy.interpolate, 0.3 s each to import, where they are not used)."""

import subprocess
import sys

from tests.conftest import EXAMPLES

HEAVY = ("matplotlib", "cvxpy", "ezdxf")


def _loaded_after(code: str, heavy: tuple[str, ...] = HEAVY) -> list[str]:
    prog = code + f"\nimport sys\nprint(' '.join(m for m in {heavy!r} if m in sys.modules))"
    r = subprocess.run([sys.executable, "-c", prog], capture_output=True, text=True, check=True)
    return r.stdout.split()


def test_import_cams_laws_optimize_is_light():
    assert _loaded_after("import cams, laws, optimize, cams.cli") == []


def test_exact_solve_does_not_load_heavy_packages():
    code = f"from cams.io.designfile import load_design\nfrom cams.solve import solve\nsolve(load_design({str(EXAMPLES / 'rocker_form.toml')!r}))"
    assert _loaded_after(code) == []


def test_convex_loads_cvxpy_only_when_used():
    code = (f"from cams.io.designfile import load_design\nfrom cams.solve import solve\n"
            f"solve(load_design({str(EXAMPLES / 'rocker_force.toml')!r}), method='convex')")
    assert _loaded_after(code) == ["cvxpy"]


def test_cli_and_minimum_r0_solve_do_not_load_scipy_solvers():
    """``cams solve`` on a minimum-R0 design runs without scipy.optimize or scipy.interpolate."""
    slow = ("scipy.optimize", "scipy.interpolate")
    assert _loaded_after("import cams, laws, optimize, cams.cli", slow) == []
    for example in ("rocker_force.toml", "slotting_feed_cam.toml"):  # the second with [dynamics]: cam forces too
        code = (f"import contextlib, io\nfrom cams.cli import main\n"
                f"with contextlib.redirect_stdout(io.StringIO()):\n"
                f"    assert main(['solve', {str(EXAMPLES / example)!r}]) in (0, None)")
        assert _loaded_after(code, slow) == [], example


def test_importing_every_module_loads_no_heavy_library():
    """Heavy libraries are imported where they are used: importing every module of the three packages loads none."""
    code = """
import importlib, pkgutil, sys
for pkg in ("laws", "optimize", "cams"):
    for info in pkgutil.walk_packages(importlib.import_module(pkg).__path__, pkg + "."):
        importlib.import_module(info.name)
heavy = ("matplotlib", "cvxpy", "ezdxf", "shapely", "scipy.optimize")
print(sorted(h for h in heavy if h in sys.modules))
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "[]", r.stdout


def test_the_package_re_exports_its_api_lazily():
    """``cams.Cam``, ``cams.solve`` and ``cams.load_design`` come on first use: ``import cams`` loads none of their
    modules, and ``cams.solve`` is the one function whichever of the module or the name was imported first."""
    assert _loaded_after("import cams", ("cams.cam", "cams.solve", "cams.io.designfile")) == []
    code = (f"import cams\nd = cams.load_design({str(EXAMPLES / 'rocker_force.toml')!r})\n"
            "a = cams.solve(d).R0\nimport cams.solve\nb = cams.solve.solve(d).R0\nc = cams.Cam(d).solution.R0\n"
            "assert a == b == c, (a, b, c)")
    assert _loaded_after(code) == []


def test_progress_library_loads_only_to_draw_a_bar():
    """tqdm comes only for a bar (a terminal's stderr, no --quiet): importing the commands and solving, even the
    motion design's [optimize], with stderr not a terminal, loads none of it."""
    code = (f"import contextlib, io\nfrom cams.cli import main\nimport cams.commands.progress\n"
            f"with contextlib.redirect_stdout(io.StringIO()):\n"
            f"    assert main(['solve', {str(EXAMPLES / 'rocker_force.toml')!r}]) == 0\n")
    assert _loaded_after(code, ("tqdm",)) == []


def test_named_laws_peaks_and_the_zone_picture_need_no_scipy_optimize():
    """A law's peak (laws.characteristics) and the R0-L trade-off of the zone picture (optimize.circle) are
    refined in numpy: the law table (every named law's peaks, the motion design's caps) and a rocker's trade-off
    load no scipy.optimize."""
    code = (f"from laws.characteristics import law_table\nlaw_table()\n"
            f"from cams.cam import Cam\nCam.from_file({str(EXAMPLES / 'rocker_force.toml')!r}).tradeoff\n")
    assert _loaded_after(code, ("scipy.optimize",)) == []


def test_the_command_line_runs_blas_on_one_thread_unless_told():
    """``cams.cli.main`` sets the BLAS thread counts to 1 when numpy is not loaded yet and the user set none;
    a count the user set is kept."""
    code = ("import os, contextlib, io\nfrom cams.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n    main(['laws'])\n"
            "print(os.environ['OPENBLAS_NUM_THREADS'], os.environ['OMP_NUM_THREADS'])")
    import os

    env = {k: v for k, v in os.environ.items() if k not in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS")}
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, env=env)
    assert r.stdout.split() == ["1", "1"]
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                       env={**env, "OPENBLAS_NUM_THREADS": "2"})
    assert r.stdout.split() == ["2", "1"]


def test_the_motion_design_solves_without_cvxpy_or_scipy_optimize():
    """``cams solve`` of the motion-design example (its programs solved by Clarabel, called directly) loads
    neither cvxpy (0.8 s to import, and it brings scipy.optimize and scipy.stats) nor scipy.optimize."""
    code = (f"import contextlib, io\nfrom cams.cli import main\n"
            f"with contextlib.redirect_stdout(io.StringIO()):\n"
            f"    assert main(['solve', {str(EXAMPLES / 'translating_designed_rise.toml')!r}]) == 0\n")
    assert _loaded_after(code, ("cvxpy", "scipy.optimize", "scipy.stats", "matplotlib")) == []
