"""The ``cams`` program's entry (cams.cli.entry): the console script, the same output and exit code as
cams.cli.main, with the objects frozen out of the collector only once the command is done."""

from __future__ import annotations

import subprocess
import sys
import tomllib

from tests.conftest import ROOT
from tests.inprocess import cams_cli


def test_the_console_script_is_the_entry():
    scripts = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["scripts"]
    assert scripts == {"cams": "cams.cli:entry"}


def test_entry_prints_and_exits_as_main():
    for args, code in ((["check", "examples/rocker_force.toml"], 0), (["solve", "examples/no_such_design.toml"], 2)):
        here = cams_cli(*args)
        there = subprocess.run([sys.executable, "-m", "cams.cli", *args], cwd=ROOT, capture_output=True, text=True)
        assert here.returncode == there.returncode == code
        mask = lambda text: [ln for ln in text.splitlines() if " ms" not in ln]  # noqa: E731  (times vary)
        assert mask(there.stdout) == mask(here.stdout) and mask(there.stderr) == mask(here.stderr)


def test_entry_freezes_only_after_the_command():
    """In a process of its own: the collector has nothing frozen while the command runs, everything after."""
    code = (
        "import gc, sys; import cams.cli as cli\n"
        "seen = []\n"
        "real = cli.main\n"
        "cli.main = lambda argv=None: seen.append(gc.get_freeze_count()) or real(argv)\n"
        "sys.argv = ['cams', 'check', 'examples/rocker_force.toml']\n"
        "rc = cli.entry()\n"
        "print(rc, seen[0], gc.get_freeze_count() > 1000)\n"
    )
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert r.stdout.split()[-3:] == ["0", "0", "True"], r.stderr
