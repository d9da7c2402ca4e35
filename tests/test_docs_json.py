"""docs/files.md documents every JSON key the commands print, with its unit, and every CSV column.

The keys are collected from real runs (``cams solve/check/profile/machine/laws --json`` on the examples, and one
design with rigid impacts for the keys only impacts give), recursively: a key of a nested object is ``a.b``, a
key of each entry of a list ``a[].b``. A nested key counts as documented where its parent is: a dotted tail of two
keys or more is a code span (`spring.rate`), or the key is a code span in a section that names its parent
(`max_torque` beside `forces`); ``cams machine``'s ``cam`` and ``forces.cam`` are read as ``cams solve``'s result
and its ``forces``. Each command's top-level keys are named in that command's part of "## JSON output", whose
table rows all give a unit. The names that are data, not schema (a machine's pairs, a drawing's layers), are
checked against the sections that define them. The CSV headers of ``cams profile`` and ``cams sweep`` are checked
the same way, against their sections.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest

from tests.inprocess import cams_cli

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "files.md"
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))

#: Keys whose children are names from the data: the parent's path, the section of docs/files.md naming them.
NAMED_CHILDREN = {
    "forces.linkage.pairs": "#### `[forces.friction]`",
    "forces.linkage.friction_power_mean_W": "#### `[forces.friction]`",
    "curves.layers": "## Drawings",
}

#: A design whose program has velocity jumps (a linear rise) with [dynamics]: its forces carry `impacts` entries
#: and `between_impacts`, which no example has (the examples' laws are smooth).
IMPACTS = (
    (ROOT / "examples" / "translating_force.toml").read_text(encoding="utf-8")
    .replace('law = "poly4567"', 'law = "linear"')
    .replace('rotation = "ccw"', 'rotation = "ccw"\nrpm = 300')
    + "[dynamics]\nmass = 0.5\nload = 5.0\n"
)


def _fenceless(text: str) -> str:
    return re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)


def _spans(text: str) -> set[str]:
    """The code spans of ``text`` (outside fenced code; a span may wrap at the margin, never across a paragraph)."""
    out = set()
    for paragraph in re.split(r"\n\s*\n", _fenceless(text)):
        out |= {" ".join(s.split()) for s in re.findall(r"`([^`]+)`", paragraph)}
    return out


def _sections(text: str) -> list[set[str]]:
    """The code spans of each section of ``text``, cut at every heading."""
    parts = re.split(r"^#{1,6} ", _fenceless(text), flags=re.M)
    return [_spans(part) for part in parts]


#: A command's object that is another's: `cams machine`'s `cam` is `cams solve`'s result, its `forces.cam` the
#: result's `forces`.
ALIASES = (("forces.cam.", "forces."), ("cam.", ""))


def _section(text: str, heading: str) -> str:
    """The section whose heading starts with ``heading``, down to the next heading of its level or above."""
    lines = _fenceless(text).splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(heading))
    level = len(heading) - len(heading.lstrip("#"))
    end = next((j for j in range(start + 1, len(lines)) if re.match(rf"#{{1,{level}}} ", lines[j])), len(lines))
    return "\n".join(lines[start:end])


def _paths(obj, prefix: str, out: dict[str, set]) -> None:
    """Every key path of ``obj`` into ``out`` (path -> the values' types seen)."""
    if isinstance(obj, dict):
        for k, v in obj.items():
            p = f"{prefix}.{k}" if prefix else k
            out.setdefault(p, set()).add(type(v).__name__)
            _paths(v, p, out)
    elif isinstance(obj, list):
        for v in obj:
            _paths(v, prefix + "[]", out)


def _json(*args) -> Any:
    r = cams_cli(*args, "--json")
    assert r.returncode in (0, 1), (args, r.stderr)
    return json.loads(r.stdout)


@pytest.fixture(scope="module")
def runs(tmp_path_factory) -> dict[str, dict[str, set]]:
    """command -> every key path its JSON had over the runs."""
    tmp = tmp_path_factory.mktemp("json")
    impacts = tmp / "impacts.toml"
    impacts.write_text(IMPACTS, encoding="utf-8")
    ex = ROOT / "examples"
    plan: dict[str, list[tuple[Any, ...]]] = {
        "solve": [("solve", f) for f in [*EXAMPLES, impacts]],
        "check": [("check", ex / n) for n in ("rocker_form.toml", "translating_flat.toml", "rocker_contact.toml")],
        "profile": [
            ("profile", ex / "rocker_form.toml", "--dxf", tmp / "a.dxf", "--svg", tmp / "a.svg"),
            ("profile", ex / "translating_flat.toml", "--svg", tmp / "b.svg", "--csv", tmp / "b.csv"),
        ],
        "machine": [
            ("machine", ex / "machines" / "slotting_machine_forces.toml", "--forces"),
            ("machine", ex / "machines" / "pump.toml"),
        ],
        "laws": [("laws",)],
    }
    out: dict[str, dict[str, set]] = {}
    for command, calls in plan.items():
        keys: dict[str, set] = {}
        for call in calls:
            _paths(_json(*call), "", keys)
        out[command] = keys
    return out


def _named(path: str) -> tuple[str, str] | None:
    """(parent, name) when ``path`` is a data name under one of NAMED_CHILDREN (or its descendant)."""
    for parent in NAMED_CHILDREN:
        for p in (parent, "cam." + parent):
            if path.startswith(p + "."):
                return parent, path[len(p) + 1 :].split(".")[0]
    return None


def _in_context(path: str, sections: list[set[str]], types: set[str]) -> bool:
    """``path`` is documented where its parent is: a dotted tail of two keys or more (`spring.rate`) is a span
    somewhere, or its key is a span (`rate`; an object's also `rate.x`) in a section that names its parent (or a
    tail of it); a top-level key anywhere. ``cams machine``'s `cam` and `forces.cam` are read as ``solve``'s."""
    candidates = [path] + [alias + path[len(prefix) :] for prefix, alias in ALIASES if path.startswith(prefix)]
    return any(_one_in_context(c, sections, types) for c in candidates[:2])


def _one_in_context(path: str, sections: list[set[str]], types: set[str]) -> bool:
    parts = [p for p in path.replace("[]", "").split(".") if p]  # `cams laws`' list: `[].name` is `name`
    named = _named(path)
    if named:
        i = parts.index(named[1])
        if i == len(parts) - 1:
            return True  # the name itself: test_named_children_documented
        parts[i] = "NAME"
    if len(parts) == 1:
        return any(_documented(path, spans, types) for spans in sections)

    def names(spans: set[str], key: str) -> bool:
        return key in spans or any(s.startswith(key + ".") or s.startswith(key + " ") for s in spans)

    long_tails = [".".join(parts[i:]) for i in range(len(parts) - 1)]
    if any((t in spans or ("dict" in types and names(spans, t))) for t in long_tails for spans in sections):
        return True
    leaf, parent = parts[-1], parts[:-1]
    plain = [p for p in parent if p != "NAME"]  # a layer's keys are named beside `layers`
    parents = {".".join(parent[i:]) for i in range(len(parent))} | {".".join(plain[i:]) for i in range(len(plain))}

    return any(
        (leaf in spans or ("dict" in types and names(spans, leaf))) and any(names(spans, p) for p in parents)
        for spans in sections
    )


def _documented(path: str, spans: set[str], types: set[str]) -> bool:
    """``path`` or a dotted tail of it is a code span; an object's also when a span names a key of it
    (`limits.rise` documents `limits`)."""
    parts = path.replace("[]", "").split(".")
    named = _named(path)
    if named:  # a pair's or layer's keys: `NAME.key` or the key itself
        parent, name = named
        i = parts.index(name)
        parts[i] = "NAME"
        if i == len(parts) - 1:
            return True  # the name itself: checked against its section below
    tails = [".".join(parts[i:]) for i in range(len(parts))]
    if any(t in spans for t in tails):
        return True
    return "dict" in types and any(s.startswith(t + ".") for t in tails for s in spans)


@pytest.mark.parametrize("command", ["solve", "check", "profile", "machine", "laws"])
def test_every_json_key_documented(runs, command):
    sections = _sections(DOC.read_text(encoding="utf-8"))
    missing = sorted(p for p, types in runs[command].items() if not _in_context(p, sections, types))
    assert missing == [], f"`cams {command} --json` keys not documented in docs/files.md: {missing}"


@pytest.mark.parametrize("command", ["solve", "check", "profile", "machine"])
def test_top_level_keys_in_the_json_reference(runs, command):
    """Each top-level key is named in that command's part of "## JSON output", not only somewhere."""
    part = _section(DOC.read_text(encoding="utf-8"), f"### `cams {command} --json`")
    spans = _spans(part)
    top = {p: t for p, t in runs[command].items() if "." not in p and "[" not in p}
    assert top, command
    assert sorted(k for k, t in top.items() if not _documented(k, spans, t)) == []


def test_named_children_documented(runs):
    """A machine's pair names and a drawing's layer names are the ones their sections define."""
    text = DOC.read_text(encoding="utf-8")
    seen: dict[str, set[str]] = {}
    for keys in runs.values():
        for p in keys:
            named = _named(p)
            if named:
                seen.setdefault(named[0], set()).add(named[1])
    assert set(seen) == set(NAMED_CHILDREN)
    for parent, names in seen.items():
        spans = _spans(_section(text, NAMED_CHILDREN[parent]))
        assert sorted(names - spans) == [], parent


def test_every_json_table_row_has_a_unit():
    """The JSON reference's tables have three columns, the last (the unit) never empty."""
    part = _section(DOC.read_text(encoding="utf-8"), "## JSON output")
    rows = [r for r in part.splitlines() if r.startswith("| `")]
    assert len(rows) > 40
    for row in rows:
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", row)[1:-1]]
        assert len(cells) == 3 and cells[2], row


def test_impacts_run_reaches_the_impact_keys(runs):
    """The design with a linear rise does give the keys it is there for (else the check above proves less)."""
    assert {"forces.impacts[].effect", "forces.between_impacts.jump_rpm"} <= set(runs["solve"])
    assert "optimize.smoothing.first_stage_laws[].coefficients" in runs["solve"]
    assert "forces.linkage.pairs.C_guide.mean" in runs["machine"]


# --------------------------------------------------------------------------- CSV columns
@pytest.fixture(scope="module")
def csv_headers(tmp_path_factory) -> dict[str, list[str]]:
    """The header of each CSV `cams profile` writes (points, lift table) for a groove and a flat face."""
    tmp = tmp_path_factory.mktemp("csv")
    out = {}
    for name in ("rocker_form", "translating_flat"):
        points, table = tmp / f"{name}.csv", tmp / f"{name}.table.csv"
        r = cams_cli("profile", ROOT / "examples" / f"{name}.toml", "--csv", points, "--table", table)
        assert r.returncode == 0, r.stderr
        for kind, path in (("points", points), ("table", table)):
            out[f"{name} {kind}"] = path.read_text(encoding="utf-8").splitlines()[0].split(",")
    return out


def _column_documented(column: str, spans: set[str]) -> bool:
    """`column` is a span, or a family `outer_*` names it."""
    return column in spans or any(s.endswith("_*") and column.startswith(s[:-1]) for s in spans)


def test_profile_csv_columns_documented(csv_headers):
    """Every column of the profile's points and of the lift table is named in "Results" (units in the names)."""
    spans = _spans(_section(DOC.read_text(encoding="utf-8"), "## Results"))
    assert "outer_x" in csv_headers["rocker_form points"]  # the groove's wall: the widest header of each file
    assert "outer_r_mm" in csv_headers["rocker_form table"]
    for what, header in csv_headers.items():
        assert [c for c in header if not _column_documented(c, spans)] == [], what


def test_sweep_columns_documented():
    """Every result column a sweep writes (cams.sweep.output.csv_header) is in the Sweeps section's table."""
    from cams.sweep.output import csv_header

    spans = _spans(_section(DOC.read_text(encoding="utf-8"), "## Sweeps"))
    header = csv_header(())
    assert "R0_mm" in header
    assert [c for c in header if c not in spans] == []


# --------------------------------------------------------------------------- quoted output
def test_quoted_torques_are_printed():
    """The camshaft torques docs/files.md quotes are what `cams solve` prints for the file it names."""
    text = " ".join(DOC.read_text(encoding="utf-8").split())
    r = cams_cli("solve", ROOT / "examples" / "translating_contact.toml")
    assert r.returncode == 0, r.stderr
    quoted = "largest driving torque 7.79269 N·m at 69.5000 deg; largest braking torque 8.44312 N·m at 245.5000 deg"
    assert quoted in r.stdout and f'(`examples/translating_contact.toml`) "{quoted}"' in text
