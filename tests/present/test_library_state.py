"""The library draws without touching the user's matplotlib: no backend set, no pyplot state."""

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

CODE = """
import sys, tempfile, pathlib
import matplotlib
matplotlib.use("svg")  # the user's choice, which the library must keep
from cams.cam import Cam
from cams.present import plots
from cams.present.report import write_report
cam = Cam.from_file(sys.argv[1])
figs = [plots.plot_motion(cam.design), plots.plot_zone(cam.solution), plots.plot_profile(cam)]
assert all(type(f).__name__ == "Figure" for f in figs), figs
out = pathlib.Path(tempfile.mkdtemp())
write_report(cam, out)
print(matplotlib.get_backend(), "matplotlib.pyplot" in sys.modules)
"""


def test_pictures_and_report_keep_the_backend_and_load_no_pyplot():
    r = subprocess.run([sys.executable, "-c", CODE, str(ROOT / "examples" / "rocker_force.toml")],
                       capture_output=True, text=True, cwd=ROOT, timeout=600)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split() == ["svg", "False"]


def test_no_backend_call_nor_pyplot_in_the_library():
    """A source scan: no module of the packages calls matplotlib.use or imports pyplot."""
    found = []
    for pkg in ("cams", "laws", "optimize"):
        for p in (ROOT / pkg).rglob("*.py"):
            text = p.read_text(encoding="utf-8")
            for bad in re.findall(r"matplotlib\.use\(|matplotlib\.pyplot|pyplot\s+import|from\s+matplotlib\s+import\s+pyplot"
                                  r"|\bplt\.", text):
                found.append(f"{p.relative_to(ROOT)}: {bad}")
    assert not found, found
