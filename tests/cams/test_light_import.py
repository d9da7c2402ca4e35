"""Importing the packages, and solving a design, stays light (no matplotlib, cvxpy or ezdxf)."""

import subprocess
import sys

from tests.conftest import EXAMPLES

HEAVY = ("matplotlib", "cvxpy", "ezdxf")


def _loaded_after(code: str) -> list[str]:
    prog = code + "\nimport sys\nprint(' '.join(m for m in %r if m in sys.modules))" % (HEAVY,)
    r = subprocess.run([sys.executable, "-c", prog], capture_output=True, text=True, check=True)
    return r.stdout.split()


def test_import_cams_laws_optimize_is_light():
    assert _loaded_after("import cams, laws, optimize, cams.cli") == []


def test_exact_solve_does_not_load_heavy_packages():
    code = f"from cams.designfile import load_design\nfrom optimize.solve import solve\nsolve(load_design({str(EXAMPLES / 'rocker_form.toml')!r}))"
    assert _loaded_after(code) == []


def test_convex_loads_cvxpy_only_when_used():
    code = (f"from cams.designfile import load_design\nfrom optimize.solve import solve\n"
            f"solve(load_design({str(EXAMPLES / 'rocker_force.toml')!r}), method='convex')")
    assert _loaded_after(code) == ["cvxpy"]
