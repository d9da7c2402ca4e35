"""The layer rule: which part of the project may import which, counting imports inside functions.

The rule is written once, as data (:data:`MAY_IMPORT`): each layer names the layers it may import. A layer is
a package (``cams.model`` holds ``cams.model.design``...) or a single module (``cams.words``); a module belongs
to the longest layer name that prefixes it. Imports within a layer are free, but no module may sit on an import
cycle (:func:`test_no_cycle`). The same table is drawn in the README's map of the layers.
"""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("laws", "optimize", "cams")

_BASE = ("laws", "cams.words")
MAY_IMPORT: dict[str, tuple[str, ...]] = {
    # the motion laws, programs, errors and units: the bottom, imports nothing of the project
    "laws": (),
    # formatting of quantities with their units: a leaf
    "cams.words": (),
    # the problem, typed
    "cams.model": ("laws",),
    # the previous release's import paths, for one release: it imports the new homes by name, at run time, only
    # when an old path is used (outside the rule; the packages that kept an old module's name ask it for names)
    "cams._moved": (),
    # the package's own entry: nothing above the model
    "cams": ("laws", "cams.model", "cams._moved"),
    # the product's kernel: the inversion, the flat-face envelope, extremum search
    "cams.kinematics": (*_BASE, "cams.model"),
    # the independent check: its own inversion and search, no solver's formula, no kernel
    "cams.verify": (*_BASE, "cams.model"),
    # the zone and the solvers: no check formula
    "optimize": (*_BASE, "cams.model", "cams.kinematics"),
    "cams.profile": (*_BASE, "cams.model", "cams.kinematics", "cams._moved"),
    "cams.checks": (*_BASE, "cams.model", "cams.kinematics", "cams.profile", "cams._moved"),
    "cams.dynamics": (*_BASE, "cams.model", "cams.kinematics"),
    "cams.io": (*_BASE, "cams.model", "cams.kinematics", "cams.profile", "cams.dynamics"),
    # the follower faces' pipelines: size, profile, checks, forces of one face each (cams.faces.face_of chooses)
    "cams.faces": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                   "cams.checks", "cams.dynamics"),
    # the motion design: the laws designed (optimize.motion), their cam sized by the face's pipeline
    "cams.motion_design": (*_BASE, "cams.model", "optimize", "cams.faces"),
    # the facade: a design of fixed laws to its face's pipeline, one with [optimize] to the motion design
    "cams.solve": (*_BASE, "cams.model", "cams.faces", "cams.motion_design"),
    "cams.assess": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                    "cams.checks", "cams.dynamics", "cams.faces"),
    "cams.cam": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                 "cams.checks", "cams.dynamics", "cams.io", "cams.faces", "cams.solve", "cams.assess"),
    "cams.sweep": (*_BASE, "cams.model", "cams.io", "cams.cam"),
    "cams.machine": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                     "cams.checks", "cams.dynamics", "cams.io", "cams.faces", "cams.solve", "cams.assess", "cams.cam", "cams._moved"),
    "cams.present": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                     "cams.checks", "cams.dynamics", "cams.io", "cams.faces", "cams.solve", "cams.assess", "cams.cam",
                     "cams.machine"),
    "cams.commands": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                      "cams.checks", "cams.dynamics", "cams.io", "cams.faces", "cams.solve", "cams.assess", "cams.cam",
                      "cams.sweep", "cams.machine", "cams.present"),
    "cams.cli": ("laws", "cams.commands"),
}


def _modules() -> dict[str, Path]:
    mods = {}
    for pkg in PACKAGES:
        for p in (ROOT / pkg).rglob("*.py"):
            parts = p.relative_to(ROOT).with_suffix("").parts
            name = ".".join(parts[:-1] if parts[-1] == "__init__" else parts)
            mods[name] = p
    return mods


def _imports(name: str, path: Path, mods: dict[str, Path]) -> set[str]:
    """The project's modules ``name`` imports anywhere in its body (module level, functions, TYPE_CHECKING)."""
    is_pkg = path.name == "__init__.py"
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            targets = [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = name.split(".") if is_pkg else name.split(".")[:-1]
                base = base[: len(base) - (node.level - 1)]
                prefix = ".".join(base + ([node.module] if node.module else []))
            else:
                prefix = node.module or ""
            targets = [f"{prefix}.{a.name}" if f"{prefix}.{a.name}" in mods else prefix for a in node.names]
        else:
            continue
        for t in targets:
            while t and t not in mods:
                t = t.rpartition(".")[0]
            if t and t != name:
                found.add(t)
    return found


def layer_of(module: str) -> str:
    """The layer a module belongs to: the longest name in :data:`MAY_IMPORT` that is it or a package above it."""
    best = ""
    for layer in MAY_IMPORT:
        if (module == layer or module.startswith(layer + ".")) and len(layer) > len(best):
            best = layer
    assert best, f"{module} belongs to no layer: add it to MAY_IMPORT"
    return best


def _graph() -> dict[str, set[str]]:
    mods = _modules()
    return {m: _imports(m, p, mods) for m, p in mods.items()}


def test_every_module_has_a_layer() -> None:
    for m in _modules():
        layer_of(m)


def test_imports_follow_the_layers() -> None:
    bad = []
    for m, targets in sorted(_graph().items()):
        lm = layer_of(m)
        for t in sorted(targets):
            lt = layer_of(t)
            if lt != lm and lt not in MAY_IMPORT[lm]:
                bad.append(f"{m} ({lm}) imports {t} ({lt})")
    assert not bad, "imports against the layers:\n" + "\n".join(bad)


def test_the_rule_itself_has_no_cycle() -> None:
    seen: dict[str, int] = {}

    def visit(layer: str, path: tuple[str, ...]) -> None:
        assert layer not in path, f"the layer rule has a cycle: {' -> '.join((*path, layer))}"
        if seen.get(layer):
            return
        for dep in MAY_IMPORT[layer]:
            visit(dep, (*path, layer))
        seen[layer] = 1

    for layer in MAY_IMPORT:
        visit(layer, ())


def test_no_cycle() -> None:
    """No import cycle among the project's modules (Tarjan's strongly connected components)."""
    graph = _graph()
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    cycles: list[list[str]] = []
    counter = [0]

    def strong(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                strong(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                cycles.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            strong(v)
    assert not cycles, "import cycles: " + "; ".join(", ".join(c) for c in cycles)


def test_the_checker_sees_function_level_imports(tmp_path: Path) -> None:
    """The rule counts imports inside functions: a known upward import is caught."""
    mods = {"cams.model.design": tmp_path / "design.py", "optimize.zone": tmp_path / "zone.py"}
    mods["cams.model.design"].write_text("def f():\n    from optimize.zone import x\n")
    mods["optimize.zone"].write_text("")
    assert _imports("cams.model.design", mods["cams.model.design"], mods) == {"optimize.zone"}
    assert "optimize" not in MAY_IMPORT[layer_of("cams.model.design")]
