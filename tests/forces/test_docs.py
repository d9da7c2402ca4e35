"""Docstring examples of the force modules run as doctests; every module declares __all__."""

from __future__ import annotations

import doctest
import importlib

import pytest

MODULES = ["cams.flywheel", "cams.camforces", "cams.kinetostatics"]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name), optionflags=doctest.ELLIPSIS)
    assert result.failed == 0


@pytest.mark.parametrize("name", MODULES)
def test_module_declares_all(name):
    mod = importlib.import_module(name)
    assert mod.__all__ and all(hasattr(mod, n) for n in mod.__all__)
