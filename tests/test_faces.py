"""The follower's face is a type, not a fork: outside the face pipelines and the model, no module asks which face
it has.

The pipelines (:mod:`cams.faces`) hold what differs between a roller's cam and a flat face's; the model
(:mod:`cams.model`) defines the two design types; the face-specific modules below them (the flat face's envelope,
profile, checks and sizing) serve one face each. Every other module reads only what both faces have. The scan
looks for the ways a branch on the face was written before: a class test of a design, result or profile of one
face, the ``face`` attribute compared or read with a default, ``is_flat``, ``cam.flat``.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

#: Branching on the face, as it was written before the pipelines (each pattern one way of asking).
PATTERNS = {
    "a class test of one face's type": re.compile(
        r"isinstance\([^)]*\b(FlatFaceDesign|CamDesign|FlatFaceSolution|FlatFaceProfile|FlatCheckReport|"
        r"CheckReport|RollerSizing)\b"),
    "the face attribute compared": re.compile(r"""\bface\b\s*[!=]=|[!=]=\s*["'](flat|roller)["']\s*(?:$|[):])"""),
    "the face attribute read with a default": re.compile(r"""getattr\([^)]*["']face["']"""),
    "a flat flag": re.compile(r"\bis_flat\(|\bcam\.flat\b|\.flat\s+(?:if|else)\b"),
}

#: The places allowed to ask, each with its reason.
ALLOWED = {
    # the pipelines: one per face, and the one place that picks it
    "cams/faces/__init__.py": "face_of: the one place that maps a design's type to its face's pipeline",
    "cams/faces/roller.py": "the roller's pipeline",
    "cams/faces/flat.py": "the flat face's pipeline",
    # the model: the two design types and the loader that builds one of them from the file's follower.face
    "cams/model/design.py": "the design types of the two faces",
    "cams/model/follower.py": "the followers of the two faces",
    "cams/io/designfile.py": "the loader: follower.face in the file chooses the design's type, once",
    # the file schema read before any design exists, refusing what the command does not take
    "cams/machine/machinefile.py": "a machine file's follower table: a feed cam is a roller's (refused before a "
                                   "design is built)",
    "cams/sweep/__init__.py": "a sweep's base file: the sweep solves roller designs (refused before a design is built)",
    # the solvers below the pipelines: the motion design's entry picks its model by face and kind
    "optimize/motion/design.py": "the motion design's models: one program per face and follower kind, chosen in "
                                 "its entry (the optimize layer sits below the pipelines)",
    "optimize/motion/translating.py": "the translating conic program's rows per face: the pressure angle's cone "
                                      "for a roller, the curvature's rows for a flat face",
    # a command line flag, before any design exists
    "cams/commands/new.py": "cams new --flat names the template to write",
}


def _sources() -> list[Path]:
    return sorted(p for pkg in ("cams", "optimize", "laws") for p in (ROOT / pkg).rglob("*.py"))


def _code_lines(path: Path):
    """The lines of ``path`` that are code (not comments or docstrings), numbered from 1."""
    import ast
    import io
    import tokenize

    text = path.read_text(encoding="utf-8")
    doc_lines: set[int] = set()
    for node in ast.walk(ast.parse(text)):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant) \
                    and isinstance(first.value.value, str):
                doc_lines.update(range(first.lineno, (first.end_lineno or first.lineno) + 1))
    lines = text.splitlines()
    comments = {t.start[0]: t.start[1] for t in tokenize.generate_tokens(io.StringIO(text).readline)
                if t.type == tokenize.COMMENT}
    for i, line in enumerate(lines, 1):
        if i in doc_lines:
            continue
        yield i, line[:comments[i]] if i in comments else line


def _branches(path: Path) -> list[str]:
    found = []
    for i, line in _code_lines(path):
        for what, pattern in PATTERNS.items():
            if pattern.search(line):
                found.append(f"{path.relative_to(ROOT)}:{i}: {what}: {line.strip()}")
    return found


def test_no_module_outside_the_pipelines_branches_on_the_face() -> None:
    bad = []
    for p in _sources():
        rel = str(p.relative_to(ROOT))
        if rel in ALLOWED or re.search(r"/flat(_rocker)?\.py$", rel):  # a face's own module serves one face
            continue
        bad += _branches(p)
    assert not bad, "branches on the face outside the pipelines:\n" + "\n".join(bad)


@pytest.mark.parametrize("line", [
    "if isinstance(design, FlatFaceDesign):",
    'if getattr(design, "face", "roller") == "flat":',
    "flat = is_flat(design)",
    "x = FLAT if cam.flat else ROLLER",
    'if design.face == "flat":',
])
def test_the_scan_sees_each_way_of_branching(tmp_path: Path, line: str) -> None:
    """Each pattern catches the branch it is for (the scan can fail)."""
    p = tmp_path / "m.py"
    body = "\n        pass" if line.endswith(":") else ""
    p.write_text(f"def f(design, cam):\n    {line}{body}\n", encoding="utf-8")
    global ROOT
    old, ROOT = ROOT, tmp_path
    try:
        assert _branches(p)
    finally:
        ROOT = old


def test_every_allowed_place_exists_and_still_asks() -> None:
    """The allowed list is kept short: each place exists, and those outside cams/faces still branch (else drop
    them from the list)."""
    for rel in ALLOWED:
        p = ROOT / rel
        assert p.exists(), rel
        if not rel.startswith(("cams/faces/", "cams/model/")):
            assert _branches(p), f"{rel} no longer branches on the face: remove it from ALLOWED"


def test_one_result_type_for_every_face() -> None:
    """``solve()`` returns one type for every follower, roller or flat."""
    from cams.faces.result import SolveResult
    from cams.io.designfile import load_design
    from cams.solve import solve

    for name in ("rocker_force.toml", "translating_force.toml", "rocker_flat.toml", "translating_flat.toml"):
        res = solve(load_design(ROOT / "examples" / name))
        assert type(res) is SolveResult, name
        assert res.face == load_design(ROOT / "examples" / name).face
