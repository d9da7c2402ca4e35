"""Every package of the source tree goes into the distribution (not only with ``pip install -e``)."""

import tomllib

from setuptools import find_packages

from tests.conftest import ROOT


def test_every_subpackage_is_distributed():
    cfg = tomllib.loads((ROOT / "pyproject.toml").read_text())
    include = cfg["tool"]["setuptools"]["packages"]["find"]["include"]
    shipped = set(find_packages(where=str(ROOT), include=include))
    on_disk = {str(p.parent.relative_to(ROOT)).replace("/", ".")
               for top in ("cams", "laws", "optimize") for p in (ROOT / top).rglob("__init__.py")}
    assert on_disk and on_disk <= shipped
    assert {"cams.commands", "cams.machine.linkage"} <= shipped
