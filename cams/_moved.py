"""The import paths of the previous release, kept for one release: each forwards to the module's new home.

``import cams.design`` still works and gives a module that forwards every
attribute to :mod:`cams.model.design`, with a :class:`DeprecationWarning` naming
the new path. Installed by ``cams/__init__`` at the end of ``sys.meta_path``,
so it is asked only for names no package holds; it imports nothing until an
old path is used. The README lists the same table.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import importlib.util
import sys
import types
import warnings

#: old module -> new module (a package's submodules follow it: ``cams.linkage.machines``).
MOVED: dict[str, str] = {
    "cams.follower": "cams.model.follower",
    "cams.design": "cams.model.design",
    "cams.pressure": "cams.verify.pressure",
    "cams.flatface": "cams.profile.flat",
    "cams.camforces": "cams.dynamics.forces",
    "cams.files": "cams.io.files",
    "cams.designfile": "cams.io.designfile",
    "cams.export": "cams.io.export",
    "cams.templates": "cams.io.templates",
    "cams.machinefile": "cams.machine.machinefile",
    "cams.linkage": "cams.machine.linkage",
    "cams.kinetostatics": "cams.machine.kinetostatics",
    "cams.flywheel": "cams.machine.flywheel",
    "cams.plots": "cams.present.plots",
    "cams.report": "cams.present.report",
}


def new_name(old: str) -> str | None:
    """The module's new name, or None when ``old`` is not a moved path."""
    for before, after in MOVED.items():
        if old == before or old.startswith(before + "."):
            return after + old[len(before):]
    return None


class _Forward(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old path and loads a module that forwards its attributes to the new one."""

    def find_spec(self, fullname, path, target=None):  # noqa: ANN001 - the finder protocol
        new = new_name(fullname)
        if new is None:
            return None
        real = importlib.util.find_spec(new)
        if real is None:
            return None
        return importlib.machinery.ModuleSpec(fullname, self, is_package=real.submodule_search_locations is not None)

    def create_module(self, spec):  # noqa: ANN001
        return None

    def exec_module(self, module: types.ModuleType) -> None:
        new = new_name(module.__name__)
        assert new is not None
        warnings.warn(f"{module.__name__} moved to {new}; the old path goes in the next release",
                      DeprecationWarning, stacklevel=3)
        real = importlib.import_module(new)
        module.__getattr__ = lambda name: getattr(real, name)  # type: ignore[method-assign]
        module.__doc__ = f"Moved to :mod:`{new}`."
        if module.__spec__ is not None and module.__spec__.submodule_search_locations is not None:
            module.__path__ = []


def install() -> None:
    """Put the forwarding finder at the end of ``sys.meta_path`` (once)."""
    if not any(isinstance(f, _Forward) for f in sys.meta_path):
        sys.meta_path.append(_Forward())
