"""docs/files.md documents every key the file loaders accept, every law, and its complete examples load.

The key sets are read from the loaders themselves (module-level sets, and the literal key sets and option tuples
passed to ``_keys`` / ``check_option`` inside them), so a key or an option added to a loader without a line in
docs/files.md fails here. A key counts as documented when it appears as a code span (`key`, `[key]` or
`[[key]]`) in the section of docs/files.md for its table.
"""

from __future__ import annotations

import ast
import importlib
import inspect
import re
import tomllib
from pathlib import Path

import pytest

import cams.io.designfile as designfile
import cams.machine.kinetostatics as kinetostatics
import cams.machine.kinetostatics.loads as kinetostatics_loads
import cams.machine.machinefile as machinefile
import cams.machine.timing.cycle as timing_cycle
import cams.machine.timing.placement as timing_placement
import cams.model.design as design_mod
import cams.profile.roller as profile_mod
from laws.registry import LAWS

DOC = Path(__file__).resolve().parents[1] / "docs" / "files.md"


def _text() -> str:
    return DOC.read_text(encoding="utf-8")


def _lines_outside_code(text: str):
    """(index, line, is_heading) for every line; lines inside fenced code blocks are never headings."""
    fenced = False
    for i, line in enumerate(text.splitlines()):
        if line.startswith("```"):
            fenced = not fenced
            yield i, line, False
            continue
        yield i, line, (not fenced and re.match(r"#{1,6} ", line) is not None)


def _section(text: str, heading: str) -> str:
    """The first section whose heading contains ``heading``, down to the next heading of its level or above."""
    lines = text.splitlines()
    start = level = None
    for i, line, is_heading in _lines_outside_code(text):
        if not is_heading:
            continue
        lv = len(line) - len(line.lstrip("#"))
        if start is None:
            if heading in line:
                start, level = i, lv
        elif lv <= level:
            return "\n".join(lines[start:i])
    assert start is not None, f"docs/files.md has no section headed {heading!r}"
    return "\n".join(lines[start:])


def _design() -> str:
    return _section(_text(), "## Design files")


def _machine() -> str:
    return _section(_text(), "## Machine files")


def _documented(text: str, key: str) -> bool:
    """``key`` appears as `key`, `[key]` or `[[key]]` in ``text``."""
    return re.search(r"`(?:\[\[|\[)?" + re.escape(key) + r"(?:\]\]|\])?`", text) is not None


def _missing(text: str, keys) -> list[str]:
    return sorted(k for k in keys if not _documented(text, k))


# --------------------------------------------------------------------------- design files
#: Each key set of cams.io.designfile._KEYS and the section of the design-file part that documents it.
DESIGN_SECTIONS = {
    "": "### Top level",
    "follower": "### `[follower]`",
    "cam": "### `[cam]`",
    "motion": "### `[[motion]]`",
    "limits": "### `[limits]`",
    "solve": "### `[solve]`",
    "profile": "### `[profile]`",
    "flat_rocker": "### Flat-faced followers",
    "flat_translating": "### Flat-faced followers",
    "flat_cam": "### Flat-faced followers",
    "flat_limits": "### Flat-faced followers",
    "flat_profile": "### Flat-faced followers",
}


def test_every_design_key_set_has_a_section():
    """A new key set in cams.io.designfile._KEYS needs a section here (and in docs/files.md)."""
    assert set(designfile._KEYS) == set(DESIGN_SECTIONS)


@pytest.mark.parametrize("table", sorted(DESIGN_SECTIONS))
def test_design_keys_documented(table):
    section = _section(_design(), DESIGN_SECTIONS[table])
    assert _missing(section, designfile._KEYS[table]) == [], f"undocumented keys of design-file table {table!r}"


def test_profile_keys_documented():
    assert _missing(_section(_design(), "### `[profile]`"), profile_mod.PROFILE_KEYS) == []


def test_dynamics_keys_documented():
    assert _missing(_section(_design(), "### `[dynamics]`"), designfile.DYNAMICS_KEYS) == []


def test_contact_keys_documented():
    """The [contact] table's keys and the JSON contact object's keys, each in the section."""
    from cams.model.contact import CONTACT_KEYS

    section = _section(_design(), "### `[contact]`")
    assert _missing(section, CONTACT_KEYS) == []
    json_keys = (
        "max_pressure",
        "max_pressure_at_deg",
        "at_max.force",
        "at_max.cam_curvature_radius",
        "at_max.follower_radius",
        "at_max.half_width",
        "max_shear",
        "max_shear_depth",
        "max_von_mises",
        "min_film",
        "min_film_parameter",
        "zero_entrainment_at_deg",
        "min_width",
        "bearing_life_hours",
        "limit",
    )
    assert _missing(section, json_keys) == []


def test_flat_face_refusals_documented():
    """The keys a flat face refuses or alone takes are named in the flat-face section."""
    section = _section(_design(), "### Flat-faced followers")
    for field in (*designfile._NOT_FLAT, *designfile._ONLY_FLAT):
        key = field.split(".", 1)[1]
        assert _documented(section, key) or _documented(section, field), field


# --------------------------------------------------------------------------- machine files
MACHINE_SECTIONS = {
    "": "### Top level",
    "cutting": "### `[cutting]`",
    "drive": "### `[drive]`",
    "timing": "### `[timing]`",
    "cam": "### `[cam]`",
}


def test_every_machine_key_set_has_a_section():
    assert set(machinefile._KEYS) == set(MACHINE_SECTIONS)


@pytest.mark.parametrize("table", sorted(MACHINE_SECTIONS))
def test_machine_keys_documented(table):
    section = _section(_machine(), MACHINE_SECTIONS[table])
    assert _missing(section, machinefile._KEYS[table]) == [], f"undocumented keys of machine-file table {table!r}"


def test_linkage_common_keys_and_types_documented():
    section = _section(_machine(), "### `[linkage]`")
    assert _missing(section, machinefile._COMMON) == []
    assert set(machinefile.LINKAGE_TYPES) == set(machinefile._LINKAGE)
    assert _missing(section, [f'"{t}"' for t in machinefile.LINKAGE_TYPES]) == []


@pytest.mark.parametrize("kind", sorted(machinefile._LINKAGE))
def test_linkage_keys_documented_per_type(kind):
    """Course data, lengths and options of each linkage type, in that type's own subsection."""
    section = _section(_machine(), f'#### `type = "{kind}"`')
    keys = set().union(*machinefile._LINKAGE[kind])
    assert _missing(section, keys) == [], f"undocumented [linkage] keys of type {kind!r}"


def test_linkage_side_words_documented():
    section = _section(_machine(), "### `[linkage]`")
    for key, words in machinefile._SIDES.items():
        assert _documented(section, key), key
        assert _missing(section, [f'"{w}"' for w in words]) == [], key


# --------------------------------------------------------------------------- [forces]
def _resolve(node: ast.AST, modules) -> set[str] | None:
    """The strings of a set/tuple/list literal, or of a module-level constant (or ``tuple(NAME)``) it names."""
    if isinstance(node, (ast.Set, ast.Tuple, ast.List)):
        return {e.value for e in node.elts if isinstance(e, ast.Constant) and isinstance(e.value, str)}
    if (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id in ("tuple", "set", "sorted")
        and len(node.args) == 1
    ):
        return _resolve(node.args[0], modules)
    if isinstance(node, ast.Name):
        for m in modules:
            if hasattr(m, node.id):
                v = getattr(m, node.id)
                if isinstance(v, (set, frozenset, tuple, list, dict)) and all(isinstance(x, str) for x in v):
                    return set(v)
        # a local variable (the per-type sets: LINKS[kind], _SIDES[key], ... are tested on their own); a
        # module-level CONSTANT that cannot be found means the loaders changed and this test must follow
        assert not node.id.lstrip("_")[:1].isupper(), f"cannot resolve {node.id!r}: update tests/test_docs_files.py"
    return None


def _call_args(func, callee: str, index: int, modules) -> set[str]:
    """The strings of argument ``index`` of every call to ``callee`` in the source of ``func``."""
    tree = ast.parse(inspect.getsource(func).lstrip() if inspect.isfunction(func) else inspect.getsource(func))
    out: set[str] = set()
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id == callee
            and len(node.args) > index
        ):
            vals = _resolve(node.args[index], modules)
            if vals:
                out |= vals
    return out


def _forces() -> str:
    return _section(_machine(), "### `[forces]`")


def test_forces_keys_documented():
    assert _missing(_forces(), machinefile.FORCES_KEYS) == []


def test_forces_inline_key_sets_documented():
    """Keys of the sub-tables (links, friction entries) checked by _keys(...) inside force_spec_from_dict."""
    keys = _call_args(machinefile.force_spec_from_dict, "_keys", 1, [machinefile])
    assert {"mass", "inertia", "cg", "coefficient", "radius", "revolute", "prismatic"} <= keys
    assert _missing(_forces(), keys) == []


@pytest.mark.parametrize("kind", sorted(machinefile._LINKAGE))
def test_forces_link_and_pair_names_documented(kind):
    assert _missing(_section(_machine(), "#### `[forces.links.NAME]`"), kinetostatics.LINKS[kind]) == []
    assert _missing(_section(_machine(), "#### `[forces.friction]`"), kinetostatics.JOINTS[kind]) == []


def test_forces_load_kinds_and_keys_documented():
    section = _section(_machine(), "#### `[[forces.loads]]`")
    for kind, keys in machinefile._LOAD_KEYS.items():
        assert _documented(section, f'"{kind}"'), kind
        assert _missing(section, keys) == [], f"undocumented keys of a {kind!r} load"
    assert _missing(section, [f'"{w}"' for w in kinetostatics.WINDOWS]) == []


# --------------------------------------------------------------------------- option words and laws
OPTION_MODULES = [designfile, design_mod, machinefile, timing_cycle, timing_placement, kinetostatics_loads]


@pytest.mark.parametrize("module", OPTION_MODULES, ids=lambda m: m.__name__)
def test_option_words_documented(module):
    """Every word a loader accepts through check_option (closure, method, placement, ...) is in docs/files.md."""
    extra = [
        importlib.import_module(n) for n in ("cams.machine.flywheel", "cams.machine.linkage.analysis", "cams.solve")
    ]
    words = _call_args(module, "check_option", 2, [module, *extra])
    assert words, f"no check_option options found in {module.__name__}"
    assert _missing(_text(), [f'"{w}"' for w in words]) == []


def test_every_law_documented():
    section = _section(_design(), "#### Motion laws")
    assert _missing(section, LAWS) == []
    assert "`cams laws`" in section


def test_seeds_explained():
    section = _section(_text(), "## The seeds")
    for n in ("000", "001", "002", "003", "004"):
        assert f"**{n}**" in section, n
    assert "(seeds.md)" in section


# --------------------------------------------------------------------------- complete examples
def _complete_blocks() -> list[str]:
    """Fenced ```toml blocks whose first line is the comment ``# complete``."""
    blocks = re.findall(r"^```toml\n(.*?)^```", _text(), re.S | re.M)
    return [b for b in blocks if b.splitlines()[0].strip() == "# complete"]


def test_complete_examples_cover_both_formats():
    docs = [tomllib.loads(b) for b in _complete_blocks()]
    assert sum("linkage" in d for d in docs) >= 1
    assert sum("linkage" not in d for d in docs) >= 2
    assert any(d.get("follower", {}).get("face") == "flat" for d in docs)


@pytest.mark.parametrize("index", range(len(_complete_blocks())))
def test_complete_example_loads(index, tmp_path):
    block = _complete_blocks()[index]
    path = tmp_path / "example.toml"
    path.write_text(block, encoding="utf-8")
    if "linkage" in tomllib.loads(block):
        spec = machinefile.load_machine(path)
        assert spec.linkage.kind in machinefile.LINKAGE_TYPES
    else:
        d = designfile.load_design(path)
        assert d.program.phases


# --------------------------------------------------------------------------- [optimize], law tables, sweep files
def test_optimize_keys_documented():
    from cams.io.optimizetable import OPTIMIZE_KEYS

    assert _missing(_section(_design(), "### `[optimize]`"), OPTIMIZE_KEYS) == []


def test_law_table_keys_documented():
    """Each kind of law table (`kind = "spline"`, `"polynomial"`) and its keys, in "Law tables"."""
    from cams.io.lawtable import LAW_KEYS

    section = _section(_design(), "#### Law tables")
    for kind, keys in LAW_KEYS.items():
        assert _documented(section, f'"{kind}"'), kind
        assert _missing(section, keys) == [], kind


def test_sweep_file_keys_documented():
    from cams.sweep.grid import SWEEP_FILE_KEYS

    assert _missing(_section(_text(), "## Sweeps"), SWEEP_FILE_KEYS) == []
