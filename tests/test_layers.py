"""The layer rule: which part of the project may import which, counting imports inside functions.

The rule is written once, as data (:data:`MAY_IMPORT`): each layer names the layers it may import. A layer is
a package (``cams.model`` holds ``cams.model.design``...) or a single module (``cams.words``); a module belongs
to the longest layer name that prefixes it. Imports within a layer are free, but no module may sit on an import
cycle (:func:`test_no_cycle`). Importing a module counts the packages above it that Python runs first (their
``__init__``), but for the importer's own. The same table is drawn in the README's map of the layers.
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
    # the zone and the solvers: no check formula (importing cams.model runs the package's entry, cams)
    "optimize": (*_BASE, "cams", "cams.model", "cams.kinematics"),
    "cams.profile": (*_BASE, "cams.model", "cams.kinematics", "cams._moved"),
    "cams.checks": (*_BASE, "cams.model", "cams.kinematics", "cams.profile", "cams._moved"),
    "cams.dynamics": (*_BASE, "cams.model", "cams.kinematics"),
    "cams.io": (*_BASE, "cams.model", "cams.kinematics", "cams.profile", "cams.dynamics"),
    # rooms for what comes next: the cam's strength (contact stress, film, life), below the faces' pipelines
    # (a stage of each); manufacture (the profile's exports now, tool paths next), above the file's schema, which
    # keeps only the readers
    "cams.strength": (*_BASE, "cams.model", "cams.kinematics", "cams.profile", "cams.dynamics"),
    "cams.manufacture": (*_BASE, "cams.model", "cams.kinematics", "cams.profile", "cams.io"),
    # the follower faces' pipelines: size, profile, checks, forces of one face each (cams.faces.face_of chooses)
    "cams.faces": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                   "cams.checks", "cams.dynamics", "cams.strength"),
    # the motion design: the laws designed (optimize.motion), their cam sized by the face's pipeline
    "cams.motion_design": (*_BASE, "cams.model", "optimize", "cams.faces"),
    # the facade: a design of fixed laws to its face's pipeline, one with [optimize] to the motion design
    "cams.solve": (*_BASE, "cams.model", "cams.faces", "cams.motion_design", "cams.strength"),
    "cams.assess": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                    "cams.checks", "cams.dynamics", "cams.faces"),
    "cams.cam": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                 "cams.checks", "cams.dynamics", "cams.io", "cams.faces", "cams.solve", "cams.assess"),
    # the batch solver of sweeps: many designs of one kind sized, checked by its own inversion and judged at once;
    # what it cannot vouch for goes back to the faces' pipelines (it imports what they import, and them)
    "cams.batch": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                   "cams.checks", "cams.dynamics", "cams.strength", "cams.faces"),
    "cams.sweep": (*_BASE, "cams.model", "cams.io", "cams.cam", "cams.batch"),
    "cams.machine": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                     "cams.checks", "cams.dynamics", "cams.io", "cams.faces", "cams.solve", "cams.assess", "cams.cam",
                     "cams._moved"),
    "cams.present": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                     "cams.checks", "cams.dynamics", "cams.io", "cams.faces", "cams.solve", "cams.assess", "cams.cam",
                     "cams.machine"),
    "cams.commands": (*_BASE, "cams.model", "cams.kinematics", "cams.verify", "optimize", "cams.profile",
                      "cams.checks", "cams.dynamics", "cams.io", "cams.faces", "cams.solve", "cams.assess", "cams.cam",
                      "cams.sweep", "cams.machine", "cams.present", "cams.manufacture"),
    "cams.cli": ("laws", "cams.commands"),
    "cams.__main__": ("cams.cli",),
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
    return found | _packages_run(name, found, mods)


def _packages_run(name: str, targets: set[str], mods: dict[str, Path]) -> set[str]:
    """The packages whose ``__init__`` Python runs to import ``targets`` from ``name``: importing ``a.b.c`` runs
    ``a`` and ``a.b`` first, except the packages ``name`` itself belongs to (they ran before it)."""
    inside = _ancestors(name) | {name}
    return {p for t in targets for p in _ancestors(t) if p in mods and p not in inside}


def _ancestors(module: str) -> set[str]:
    """The packages above ``module``: ``a.b.c`` -> ``{"a.b", "a"}``."""
    parts = module.split(".")
    return {".".join(parts[:i]) for i in range(1, len(parts))}


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
    """No import cycle among the project's modules."""
    cycles = _cycles(_graph())
    assert not cycles, "import cycles: " + "; ".join(", ".join(c) for c in cycles)


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The import cycles of ``graph``, each as its sorted modules (Tarjan's strongly connected components)."""
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
    return cycles


def test_the_checker_sees_function_level_imports(tmp_path: Path) -> None:
    """The rule counts imports inside functions: a known upward import is caught."""
    mods = {"cams.model.design": tmp_path / "design.py", "optimize.zone": tmp_path / "zone.py"}
    mods["cams.model.design"].write_text("def f():\n    from optimize.zone import x\n")
    mods["optimize.zone"].write_text("")
    assert _imports("cams.model.design", mods["cams.model.design"], mods) == {"optimize.zone"}
    assert "optimize" not in MAY_IMPORT[layer_of("cams.model.design")]


def test_the_checker_sees_a_package_s_init(tmp_path: Path) -> None:
    """Importing ``a.b.c`` runs ``a.b``'s ``__init__`` first: the rule counts it (not the importer's own packages,
    which ran before it), so a loop through an ``__init__`` is caught. The machine's timing and kinetostatics
    made one: the timing's ``__init__`` re-exported ``design_machine``, whose module imported the kinetostatics'
    loads, whose ``__init__`` imports the coupling, which imports the timing."""
    texts = {
        "cams.machine.timing": "from cams.machine.timing.result import design_machine\n",
        "cams.machine.timing.result": "from cams.machine.kinetostatics.loads import ForceSpec\n",
        "cams.machine.kinetostatics": "from cams.machine.kinetostatics.coupling import machine_forces\n",
        "cams.machine.kinetostatics.loads": "",
        "cams.machine.kinetostatics.coupling": ("from cams.machine.kinetostatics.loads import G\n"
                                                "def machine_forces():\n    from cams.machine.timing import windows\n"),
    }
    packages = {"cams.machine.timing", "cams.machine.kinetostatics"}
    mods = {}
    for name, text in texts.items():
        path = tmp_path.joinpath(*name.split("."), "__init__.py") if name in packages else \
            tmp_path.joinpath(*name.split(".")).with_suffix(".py")
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        mods[name] = path
    graph = {m: _imports(m, p, mods) for m, p in mods.items()}
    assert graph["cams.machine.timing.result"] == {"cams.machine.kinetostatics.loads", "cams.machine.kinetostatics"}
    assert graph["cams.machine.kinetostatics.coupling"] == {"cams.machine.kinetostatics.loads", "cams.machine.timing"}
    assert graph["cams.machine.timing"] == {"cams.machine.timing.result"}
    assert _cycles(graph) == [["cams.machine.kinetostatics", "cams.machine.kinetostatics.coupling",
                               "cams.machine.timing", "cams.machine.timing.result"]]
