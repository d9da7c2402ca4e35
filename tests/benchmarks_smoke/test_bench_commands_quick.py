"""The command benchmark runs one command once in both trees (the base a temporary worktree) and writes its
figures; no timing is asserted."""

import json
import subprocess
import sys

from tests.conftest import ROOT


def _worktrees() -> set[str]:
    """The repository's worktrees' paths (not their commits: another checkout may move on meanwhile)."""
    out = subprocess.run(["git", "worktree", "list", "--porcelain"], cwd=ROOT, capture_output=True, text=True).stdout
    return {line.removeprefix("worktree ") for line in out.splitlines() if line.startswith("worktree ")}


def test_bench_commands_quick_writes_json(tmp_path):
    before = _worktrees()
    r = subprocess.run(
        [
            sys.executable,
            str(ROOT / "benchmarks" / "bench_commands.py"),
            "--base",
            "HEAD",
            "--runs",
            "1",
            "--only",
            "check",
            "--out",
            str(tmp_path),
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert r.returncode == 0, r.stderr
    res = json.loads((tmp_path / "commands.json").read_text())
    (row,) = res["commands"]
    assert row["name"] == "check" and row["exit_base"] == row["exit_new"] == [0]
    assert len(row["base"]["runs"]) == len(row["new"]["runs"]) == 1 and row["ratio_median"] > 0
    assert set(res["floor"]) == {"python -c pass", "python -c 'import numpy'"}
    (parts,) = res["breakdown"]
    assert parts["new"]["imports_by_package_s"]["numpy"] > 0 and parts["new"]["imports_s"] <= parts["new"]["wall_s"]
    # the base's worktree is gone: no worktree is left that was not there before
    assert _worktrees() <= before
