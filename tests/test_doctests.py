"""The Examples sections of the docstrings run as doctests; the modules declare ``__all__``.

One list for the whole project: a module with ``>>>`` examples must be named in
``DOCTEST_MODULES`` (checked by :func:`test_every_module_with_examples_is_listed`).
"""

from __future__ import annotations

import doctest
import importlib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("cams", "laws", "optimize")

#: Modules whose docstrings are run as doctests (some have no examples yet).
DOCTEST_MODULES = [
    # laws
    "laws.bernstein",
    "laws.characteristics",
    "laws.diagnostics",
    "laws.errors",
    "laws.modified",
    "laws.polynomial",
    "laws.program",
    "laws.registry",
    "laws.search",
    "laws.standard",
    "laws.spline",
    "laws.table",
    "laws.units",
    # linkage and machines
    "cams.machine.linkage",
    "cams.machine.linkage.primitives",
    "cams.machine.linkage.synthesis",
    "cams.machine.linkage.analysis",
    "cams.machine.linkage.machines",
    "cams.machine.linkage.common",
    "cams.machine.linkage.slotting",
    "cams.machine.linkage.crank_slider",
    "cams.machine.linkage.opposed_twin",
    "cams.machine.linkage.pump",
    "cams.machine.timing",
    "cams.machine.timing.cycle",
    "cams.machine.timing.placement",
    "cams.machine.timing.diagram",
    "cams.machine.design",
    "cams.machine.machinefile",
    "cams.commands.machine",
    # forces
    "cams.machine.flywheel",
    "cams.dynamics.forces",
    "cams.dynamics.impacts",
    "cams.machine.kinetostatics",
    "cams.machine.kinetostatics.solve",
    # the kinematics kernel
    "cams.kinematics.vectors",
    "cams.kinematics.extremum",
    "cams.kinematics.inversion",
    "cams.kinematics.peaks",
    # profiles
    "cams.profile.flat",
    "cams.kinematics.flat",
    "optimize.flat",
    "cams.checks.flat",
    "cams.words",
    "cams.present.text",
    "cams.sweep",
    "cams.sweep.grid",
    "cams.sweep.output",
    "cams.sweep.pareto",
    "cams.sweep.outfile",
    "cams.profile.roller",
    # exports for manufacture
    "cams.manufacture.drawing",
    "cams.manufacture.points",
    "cams.manufacture.dxf",
    "cams.manufacture.svg",
    # the design, typed, and its file
    "cams.model.dynamics",
    "cams.model.options",
    "cams.io.designfile",
    "cams.io.lawtable",
    "cams.io.tomlwrite",
]

#: Modules checked for a complete ``__all__``.
ALL_MODULES = [*DOCTEST_MODULES, "laws.base"]


@pytest.mark.parametrize("name", DOCTEST_MODULES)
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.failed == 0


@pytest.mark.parametrize("name", ALL_MODULES)
def test_module_declares_all(name):
    mod = importlib.import_module(name)
    assert mod.__all__ and all(hasattr(mod, n) for n in mod.__all__)


def test_package_exports():
    import laws

    for n in laws.__all__:
        assert hasattr(laws, n), n


def test_every_module_with_examples_is_listed():
    """A ``>>>`` example anywhere in the packages is run by this file."""
    found = []
    for pkg in PACKAGES:
        for path in sorted((ROOT / pkg).rglob("*.py")):
            if ">>>" in path.read_text(encoding="utf-8"):
                parts = path.relative_to(ROOT).with_suffix("").parts
                found.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    assert found, "no module with examples found: wrong root?"
    missing = sorted(set(found) - set(DOCTEST_MODULES))
    assert not missing, f"modules with doctest examples not run: {missing}"
