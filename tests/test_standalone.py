"""The repository stands alone: no tracked file links or refers to a path outside it.

Three rules, over every tracked text file:

* a relative path climbing with ``../`` must land, from the file's folder, on something that exists inside the
  repository (a Markdown link from ``docs/`` up to a test does; one to a sibling folder of the repository does
  not);
* no absolute path into a user's or a workspace's folders (the usual top-level folders of such trees);
* a path named in the text (``folder/file.ext``) has its folder inside the repository: relative to the root,
  to the file's folder, or as the end of a tracked folder (``linkage/machines.py`` for ``cams/machine/linkage/``);
* a Markdown document named alone (``files.md``) is the name of a tracked file: a reader can open it.
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: top-level folders of user and workspace trees; system paths a program may name (/dev, /proc) are not here
_HOME_ROOTS = ("work", "home", "Users", "mnt", "srv", "opt", "root", "tmp", "workspace")
_ABSOLUTE = re.compile(r"(?<![\w.~/-])/(?:" + "|".join(_HOME_ROOTS) + r")/[\w.-]")
_CLIMB = re.compile(r"(?<![\w.])((?:\.\./)+[\w.-]+(?:/[\w.-]+)*)")
_NAMED = re.compile(r"(?<![\w./-])([\w-]+(?:/[\w.-]+)+)\.(?:md|toml|py|txt|csv|json|png|svg|dxf|html|pdf)\b")
_DOCUMENT = re.compile(r"(?<![\w./-])([\w-]+\.md)\b")


def _tracked() -> list[Path]:
    """The repository's files: git's list in a checkout, else every file outside hidden and build folders."""
    try:
        out = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True).stdout
        files = [ROOT / f for f in out.decode().split("\0") if f]
    except (OSError, subprocess.CalledProcessError):
        files = [Path(d) / f for d, ds, fs in os.walk(ROOT)
                 for f in fs if not any(part.startswith(".") or part.endswith(".egg-info") or part == "__pycache__"
                                        for part in Path(d).relative_to(ROOT).parts)]
    return [f for f in files if f.is_file()]


def _text(f: Path) -> str | None:
    try:
        return f.read_text(encoding="utf-8")
    except (UnicodeDecodeError, OSError):
        return None  # binary files (pictures) name no paths


def _inside(p: Path) -> bool:
    try:
        p.resolve().relative_to(ROOT)
        return True
    except ValueError:
        return False


def outside_references(files: list[Path]) -> list[str]:
    """``file:line: reference`` for every reference to a path outside the repository."""
    tracked = _tracked()
    folders = {str(f.parent.relative_to(ROOT)) for f in tracked}
    names = {f.name for f in tracked}
    bad = []
    for f in files:
        text = _text(f)
        if text is None:
            continue
        rel = f.relative_to(ROOT)
        for n, line in enumerate(text.splitlines(), 1):
            for m in _CLIMB.finditer(line):
                target = f.parent / m.group(1)
                if not (_inside(target) and target.exists()):
                    bad.append(f"{rel}:{n}: {m.group(1)}")
            bad += [f"{rel}:{n}: {m.group(0)}" for m in _ABSOLUTE.finditer(line)]
            for m in _NAMED.finditer(line):
                folder = str(Path(m.group(1)).parent)
                if not ((ROOT / folder).is_dir() or (f.parent / folder).is_dir()
                        or any(d == folder or d.endswith("/" + folder) for d in folders)):
                    bad.append(f"{rel}:{n}: {m.group(0)}")
            bad += [f"{rel}:{n}: {m.group(1)}" for m in _DOCUMENT.finditer(line) if m.group(1) not in names]
    return bad


def test_no_tracked_file_refers_outside_the_repository():
    files = _tracked()
    assert len(files) > 100 and any(f.name == "README.md" for f in files)
    assert outside_references(files) == []


# the probes are pieced together so that this file's own lines name no outside path
@pytest.mark.parametrize("line, found", [
    ("see [notes](" + "/".join(["..", "..", "elsewhere", "NOTES" + ".md"]) + ")", True),
    ("the sources are in /" + "home/someone/cams", True),
    ("the seeds are in /" + "work/seeds/", True),
    ("the geometry is in notes/design/GEOMETRY" + ".md", True),
    ("written to /dev/stdout or /dev/full", False),
    ("see [the test](../tests/test_standalone.py)", False),
    ("the machines are in linkage/machines.py", False),
    ("geometry (" + "DOMAIN" + ".md, seed 001)", True),
    ("every key in files.md and README.md", False),
])
def test_the_rules_find_what_they_should(tmp_path, line, found):
    """The rules on one line placed in docs/ (a file that is not tracked, so it is written inside the repository
    for the test and removed)."""
    f = ROOT / "docs" / f".standalone_probe_{os.getpid()}.md"
    f.write_text(line + "\n", encoding="utf-8")
    try:
        assert bool(outside_references([f])) is found, outside_references([f])
    finally:
        f.unlink()
