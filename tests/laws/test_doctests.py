"""The Examples sections of the laws package's docstrings run as doctests."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = [
    "laws.characteristics",
    "laws.diagnostics",
    "laws.modified",
    "laws.polynomial",
    "laws.program",
    "laws.registry",
    "laws.standard",
    "laws.table",
]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.failed == 0


@pytest.mark.parametrize("name", MODULES + ["laws.base", "laws.errors"])
def test_module_declares_all(name):
    mod = importlib.import_module(name)
    assert mod.__all__ and all(hasattr(mod, n) for n in mod.__all__)


def test_package_exports():
    import laws

    for n in laws.__all__:
        assert hasattr(laws, n), n
