"""Run one benchmark script as a process and read the results file it writes (the smoke tests' one way)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from tests.conftest import ROOT


def run_benchmark(script: str, out: Path, *args: str, result: str, timeout: float = 300) -> dict:
    """``python benchmarks/SCRIPT ARGS --out OUT``: assert it exits 0 (its stderr as the message), return
    ``OUT/RESULT`` parsed."""
    r = subprocess.run([sys.executable, str(ROOT / "benchmarks" / script), *args, "--out", str(out)],
                       capture_output=True, text=True, timeout=timeout)
    assert r.returncode == 0, r.stderr
    return json.loads((out / result).read_text())
