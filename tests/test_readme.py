"""The README's examples run as written: its design-file block and its main command's output."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from cams.cli import main

README = Path(__file__).resolve().parents[1] / "README.md"


def _blocks(lang: str) -> list[str]:
    """The fenced code blocks of the README whose info string is ``lang``."""
    blocks: list[str] = []
    current: list[str] | None = None
    info = ""
    for line in README.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            if current is None:
                current, info = [], line[3:].strip()
            else:
                if info == lang:
                    blocks.append("\n".join(current) + "\n")
                current = None
        elif current is not None:
            current.append(line)
    return blocks


def test_design_file_block_solves(tmp_path, capsys):
    """The schema block of "Using it" is a valid design file: cams solve sizes it (fixed L, floor not binding)."""
    block = next(b for b in _blocks("toml") if "[follower]" in b and "[limits]" in b)
    path = tmp_path / "readme.toml"
    path.write_text(block, encoding="utf-8")
    assert main(["solve", str(path)]) == 0
    out = capsys.readouterr().out
    assert "L       = 115.000000 mm" in out and "verified: yes" in out
    assert "not binding" in out


def test_main_command_output_matches(capsys):
    """The output shown under the set-up command is what cams solve prints, every line (but the bound and time)."""
    shown = next(b for b in _blocks("") if b.startswith("rocker cam, force closure"))
    assert main(["solve", str(README.parent / "examples" / "rocker_force.toml")]) == 0
    out = capsys.readouterr().out
    lines = shown.splitlines()
    assert len(lines) == 14
    for line in lines:
        if not line.strip().startswith("error bound"):  # its bound's last digits and the time vary
            assert line in out.splitlines(), line
    assert "verified: yes" in out


EXAMPLE = README.parent / "examples" / "rocker_force.toml"


def _variant(tmp_path, name: str, cam: str = "", limits: str = "", law: str | None = None) -> str:
    """rocker_force.toml with lines added to [cam] and [limits] (and its cycloidal laws replaced)."""
    text = EXAMPLE.read_text(encoding="utf-8")
    text = text.replace('rotation = "ccw"', 'rotation = "ccw"\n' + cam, 1).replace(
        "[limits]\n", "[limits]\n" + limits, 1
    )
    if law:
        text = text.replace('"cycloidal"', f'"{law}"')
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return str(path)


def _readme() -> str:
    """The README's prose on one line per paragraph (its quotes wrap at the margin)."""
    return " ".join(README.read_text(encoding="utf-8").split())


def test_sizing_to_the_part_block_matches(tmp_path, capsys):
    """The block under "Sizing to the part" is what rocker_force.toml with bore_radius = 10, hub_wall = 5 prints,
    and the harmonic variant's figures in the text after it too."""
    shown = next(b for b in _blocks("") if "floor_R0" in b and "bore    =" in b)
    assert main(["solve", _variant(tmp_path, "bore", cam="bore_radius = 10\nhub_wall = 5\n")]) == 0
    out = capsys.readouterr().out
    for line in shown.splitlines():
        assert line in out, line
    assert main(["solve", _variant(tmp_path, "harmonic", law="harmonic")]) == 0
    out = capsys.readouterr().out
    assert "R0      = 10.000000 mm" in out and "the pressure angle alone: R0 = 9.467812 mm" in out
    assert "pressure angle alone gives R0 = 9.467812 mm" in _readme()


def test_quoted_failures_are_printed(tmp_path, capsys):
    """The two failures the README quotes, from the files it names, exit 1 with those very lines."""
    text = _readme()
    chosen = _variant(tmp_path, "chosen", cam="base_radius = 13\n", limits="centre_distance = 135\n")
    assert main(["solve", chosen]) == 1
    line = "rise pressure angle 48.4174 deg exceeds the limit 45.0000 deg by 3.4174 deg at cam angle 0.0000 deg"
    assert line in capsys.readouterr().out and line in text
    kc = _variant(tmp_path, "kc", cam="centre = [137.2, 26.6]\n")
    body = Path(kc).read_text(encoding="utf-8").replace("safety_factor = 1.0", "safety_factor = 1.3")
    Path(kc).write_text(body, encoding="utf-8")
    assert main(["check", kc]) == 1
    line = (
        "safety factor K_C = 1.3 not met: the largest K_C the centre meets is 1.1302; it lies 13.259 mm outside "
        "the K_C zone's t-t line at cam angle 50.4854 deg in phase 0 (rise)"
    )
    assert line in capsys.readouterr().out and line in text


def _anchors(path: Path) -> set[str]:
    """The anchors a renderer gives the headings of ``path`` (lower case, punctuation dropped, spaces to -)."""
    text = re.sub(r"^```.*?^```", "", path.read_text(encoding="utf-8"), flags=re.S | re.M)
    out: set[str] = set()
    seen: dict[str, int] = {}
    for m in re.finditer(r"^#{1,6} (.*)$", text, flags=re.M):
        a = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
        n = seen.get(a, 0)
        seen[a] = n + 1
        out.add(a if n == 0 else f"{a}-{n}")
    return out


def test_links_stay_in_the_repository_and_resolve():
    """Every link of the README and docs/*.md is to a file of the repository (and a heading of it, when named)."""
    pages = [README, *sorted((README.parent / "docs").glob("*.md"))]
    bad = []
    for page in pages:
        text = re.sub(r"^```.*?^```", "", page.read_text(encoding="utf-8"), flags=re.S | re.M)
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            file, _, anchor = target.partition("#")
            path = page.parent / file if file else page
            if (
                re.match(r"[a-z]+:", target)
                or not path.exists()
                or (anchor and path.suffix == ".md" and anchor not in _anchors(path))
            ):
                bad.append((page.name, target))
    assert bad == []
    assert "(docs/files.md#the-seeds)" in README.read_text(encoding="utf-8")  # the check reads what it should


def test_every_example_is_in_the_examples_table():
    """A newcomer finds each file of examples/ (design and machine files) in the README's table of examples."""
    text = README.read_text(encoding="utf-8")
    table = text[text.index("### Examples") :].split("\n### ", 1)[0]
    files = sorted(p.relative_to(README.parent).as_posix() for p in (README.parent / "examples").rglob("*.toml"))
    assert len(files) >= 16
    assert [f for f in files if f"`{f}`" not in table] == []


def test_python_blocks_run(capsys, monkeypatch):
    """The README's Python blocks run in order from the repository's root and print what their comments say."""
    monkeypatch.chdir(README.parent)
    scope: dict = {}
    for block in _blocks("python"):
        exec(compile(block, "README.md", "exec"), scope)
    lines = capsys.readouterr().out.splitlines()
    assert lines[2] == "True True ()"
    # "its to_dict() is what cams solve FILE --json prints": R0, L (mm) and the rise's pressure angle (degrees there)
    assert main(["solve", "examples/rocker_form.toml", "--json"]) == 0
    shown = json.loads(capsys.readouterr().out)
    own = scope["result"].to_dict()
    added = {"forces", "failures"}  # the command's: [dynamics] and the one rule's verdict
    assert set(shown) - set(own) == added and set(own) <= set(shown)
    assert {k: v for k, v in own.items() if k != "seconds"} == {k: shown[k] for k in own if k != "seconds"}
    assert [float(v) for v in lines[0].split()] == [shown["R0"], shown["L"]]
    assert math.degrees(float(lines[1])) == pytest.approx(shown["max_pressure_angle"]["rise"], rel=1e-12)


def test_commands_table_lists_every_option():
    """Each row of the README's commands table names every option its command's parser takes (but --help)."""
    import argparse

    from cams.cli import build_parser

    text = README.read_text(encoding="utf-8")
    table = text[text.index("| command | what it does |") :].split("\n\n", 1)[0]
    rows = {m.group(1): m.group(0) for m in re.finditer(r"^\| `cams (\w+) [^\n]*", table, flags=re.M)}
    sub = next(a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction))
    assert set(sub.choices) == set(rows)
    missing = {
        name: [
            o
            for a in parser._actions
            for o in a.option_strings
            if o.startswith("--") and o != "--help" and o not in rows[name]
        ]
        for name, parser in sub.choices.items()
    }
    assert {k: v for k, v in missing.items() if v} == {}
