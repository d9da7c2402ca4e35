"""The README's examples run as written: its design-file block and its main command's output."""

from __future__ import annotations

from pathlib import Path

from cams.cli import main

README = Path(__file__).resolve().parents[1] / "README.md"


def _blocks(lang: str) -> list[str]:
    """The fenced code blocks of the README whose info string is ``lang``."""
    blocks, current, info = [], None, ""
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
    """The output shown under the set-up command is what cams solve prints (but the timing and bound digits)."""
    shown = next(b for b in _blocks("") if b.startswith("rocker cam, force closure"))
    assert main(["solve", str(README.parent / "examples" / "rocker_force.toml")]) == 0
    out = capsys.readouterr().out
    for line in shown.splitlines():
        if line.strip().startswith(("R0", "Rmin", "L ", "centre", "max pressure", "binding")) or line.startswith("rocker cam"):
            assert line in out, line
