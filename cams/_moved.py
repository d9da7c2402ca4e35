"""The import paths of the previous release, kept for one release: each forwards to the names' new homes.

``import cams.design`` still works and gives a module that forwards every
attribute to :mod:`cams.model.design`, with a :class:`DeprecationWarning` naming
the new path; a module split by stage forwards each name to the first of its
new homes that holds it (``cams.flatface.size_flat_face`` is
:func:`optimize.flat.size_flat_face`). The finder is installed by
``cams/__init__`` at the end of ``sys.meta_path``, so it is asked only for
names no package holds. An old module whose name is now a package
(``cams.profile``, ``cams.checks``, ``cams.machine``) forwards its old names
through the package's ``__getattr__`` (:func:`forward`).

This module is outside the layer rule (``tests/test_layers.py``): it imports
by name, at run time, only when an old path is used. It goes in the next
release; the README lists the same table.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import importlib.util
import sys
import types
import warnings

#: old module -> its names' new homes, searched in order (a package's submodules follow it:
#: ``cams.linkage.machines`` -> ``cams.machine.linkage.machines``).
MOVED: dict[str, tuple[str, ...]] = {
    "cams.follower": ("cams.model.follower",),
    "cams.design": ("cams.model.design",),
    "cams.pressure": ("cams.verify.pressure",),
    "cams.flatface": ("cams.profile.flat", "optimize.flat", "cams.checks.flat", "cams.kinematics.flat",
                      "cams.model.follower", "cams.model.design", "cams.checks.base"),
    "cams.camforces": ("cams.dynamics.forces", "cams.dynamics.impacts", "cams.dynamics.jump", "cams.dynamics.motion",
                       "cams.model.dynamics", "cams.io.designfile"),
    "cams.files": ("cams.io.files", "cams.io.document"),
    "cams.designfile": ("cams.io.designfile",),
    "cams.export": ("cams.manufacture.points", "cams.manufacture.dxf", "cams.manufacture.svg",
                    "cams.manufacture.drawing"),
    "cams.templates": ("cams.io.templates",),
    "cams.machinefile": ("cams.machine.machinefile",),
    "cams.linkage": ("cams.machine.linkage",),
    "cams.kinetostatics": ("cams.machine.kinetostatics", "cams.machine.machinefile", "cams.present.machine_plots"),
    "cams.flywheel": ("cams.machine.flywheel",),
    "cams.plots": ("cams.present.plots",),
    "cams.report": ("cams.present.report",),
    # old modules whose names are packages now: their __init__ forwards the old names
    "cams.profile": ("cams.profile.roller", "cams.model.options", "cams.kinematics.inversion"),
    "cams.checks": ("cams.checks.profile", "cams.checks.base", "cams.solve"),
    "cams.machine": ("cams.machine.timing", "cams.machine.design"),
}


def new_homes(old: str) -> tuple[str, ...] | None:
    """The new homes of an old module path, or None when ``old`` is not a moved path."""
    for before, after in MOVED.items():
        if old == before:
            return after
        if old.startswith(before + "."):
            return (after[0] + old[len(before):],)
    return None


def new_name(old: str) -> str | None:
    """The first new home of an old module path, or None."""
    homes = new_homes(old)
    return None if homes is None else homes[0]


def forward(old: str, name: str) -> object:
    """Attribute ``name`` of the previous release's module ``old``, from its new home, with a warning.

    Raises
    ------
    AttributeError
        No new home holds ``name``.
    """
    if not name.startswith("__"):
        for home in MOVED.get(old, ()):
            module = importlib.import_module(home)
            if hasattr(module, name):
                warnings.warn(f"{old}.{name} moved to {home}.{name}; the old path goes in the next release",
                              DeprecationWarning, stacklevel=3)
                return getattr(module, name)
    raise AttributeError(f"module {old!r} has no attribute {name!r}")


class _Forward(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds an old path and loads a module that forwards its attributes to the new homes."""

    def find_spec(self, fullname, path, target=None):
        homes = new_homes(fullname)
        if homes is None:
            return None
        real = importlib.util.find_spec(homes[0])
        if real is None:
            return None
        return importlib.machinery.ModuleSpec(fullname, self, is_package=real.submodule_search_locations is not None)

    def create_module(self, spec):
        return None

    def exec_module(self, module: types.ModuleType) -> None:
        old = module.__name__
        homes = new_homes(old)
        assert homes is not None
        warnings.warn(f"{old} moved to {homes[0]}; the old path goes in the next release",
                      DeprecationWarning, stacklevel=3)
        modules = [importlib.import_module(h) for h in homes]

        def attribute(name: str) -> object:
            for m in modules:
                if hasattr(m, name):
                    return getattr(m, name)
            raise AttributeError(f"module {old!r} has no attribute {name!r}")

        module.__getattr__ = attribute  # type: ignore[method-assign]
        module.__doc__ = f"Moved to :mod:`{homes[0]}`."
        if module.__spec__ is not None and module.__spec__.submodule_search_locations is not None:
            module.__path__ = []


def install() -> None:
    """Put the forwarding finder at the end of ``sys.meta_path`` (once)."""
    if not any(isinstance(f, _Forward) for f in sys.meta_path):
        sys.meta_path.append(_Forward())
