"""Whole ``cams`` command processes, this tree against a base revision's, in one run.

Usage (from the project folder)::

    python benchmarks/bench_commands.py [--base REV] [--runs 5] [--out benchmarks/results]

The base (default: the merge-base of HEAD with ``main``) is checked out into a temporary ``git worktree``; every
command runs as a fresh process, ``python -c "from cams.cli import main; ..."`` with ``PYTHONPATH`` at the tree,
on the tree's own example files, the base's and this tree's runs interleaved (their order alternating from one
run to the next), so that both see the same load. The children get the user's environment as it is, less the
BLAS thread counts a benchmark sets for itself (``OPENBLAS_NUM_THREADS`` ...): each tree's command line chooses
its own. Writes ``commands.json`` into ``--out``:

* ``floor``: ``python -c pass`` (the interpreter) and ``python -c "import numpy"`` (the interpreter and numpy,
  the floor under every command), min and median seconds;
* ``commands``: per command, the base's and this tree's wall times and CPU times (user + system; every run, min
  and median, seconds), their
  exit codes (the same in both, or the comparison is void), the ratio new/base of the minima and of the medians,
  the issue's target (a ratio at most ``target``) and whether it is met on the medians, and how far this tree's
  median is above the numpy floor;
* ``breakdown``: for each command and tree, one more run under ``python -X importtime``: the import time by top
  package (self time of every module summed under its top-level package, seconds) and the remainder of the
  wall time (the interpreter's start, the parsing and the work).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from hardware import BLAS_THREADS, machine, write_results

ROOT = Path(__file__).resolve().parents[1]
#: The command line's entry, run the same way in both trees: the console script's function (``cams.cli.entry``,
#: ``main`` in a tree that has no other; the base has no ``cams/__main__.py``), on the arguments after ``-c``.
ENTRY = ("import sys; import cams.cli as cli; sys.argv[0] = 'cams'; "
         "sys.exit(cli.entry() if hasattr(cli, 'entry') else cli.main(sys.argv[1:]))")
#: The least-pressure-angle objective: the motion-design example with its objective changed (written per tree).
PRESSURE_OBJECTIVE = ('objective = "R0"', 'objective = "pressure_angle"')


def commands(out: Path) -> list[dict]:
    """The commands timed: name, arguments (``{out}`` is a scratch folder, ``{tree}`` the tree), the issue's
    target (the most new/base may be, on the medians); ``new_args``: more arguments in this tree only (an option
    the base does not have); ``within_s``: the most this tree's median may take, seconds (the issue's "under 3 s");
    ``json_seconds``: a key path in the command's ``--json`` output whose seconds are recorded once a tree."""
    ex = "examples/rocker_force.toml"
    return [
        {"name": "solve", "args": ["solve", ex], "target": 1.0},
        {
            "name": "solve --json (translating flat)",
            "args": ["solve", "--json", "examples/translating_flat.toml"],
            "target": 1.0,
        },
        {"name": "check", "args": ["check", ex], "target": 1.0},
        {"name": "profile --csv", "args": ["profile", ex, "--csv", "{out}/profile.csv"], "target": 1.0},
        {"name": "plot", "args": ["plot", ex, "--out", "{out}/plot"], "target": 0.5},
        # the same pictures drawn one after another in one process: what the drawing itself gained
        {"name": "plot --jobs 1", "args": ["plot", ex, "--out", "{out}/plot1"], "new_args": ["--jobs", "1"],
         "target": 1.0},
        {
            "name": "plot --animate (turn only)",
            "args": ["plot", ex, "--out", "{out}/turn", "--only", "motion", "--animate"],
            "target": 0.5,
            "within_s": 3.0,
        },
        # the examples whose follower train vibrates: their checks solve the train's response first
        *(
            {
                "name": f"plot --animate (turn only, {name})",
                "args": ["plot", f"examples/{name}.toml", "--out", f"{{out}}/turn-{name}", "--only", "motion",
                         "--animate"],
                "target": 0.5,
                "within_s": 3.0,
                "runs": 2,
            }
            for name in ("slotting_feed_cam_train", "translating_train")
        ),
        {"name": "report", "args": ["report", ex, "--out", "{out}/report"], "target": 0.5},
        {"name": "report --jobs 1", "args": ["report", ex, "--out", "{out}/report1"], "new_args": ["--jobs", "1"],
         "target": 1.0},
        {
            "name": "solve motion design (R0)",
            "args": ["solve", "examples/translating_designed_rise.toml"],
            "target": 0.5,
        },
        # tens of seconds a run: timed once in each tree
        {
            "name": "solve motion design (pressure_angle)",
            "args": ["solve", "{out}/designed_pressure.toml"],
            "target": 0.5,
            "runs": 1,
            "json_seconds": ("optimize", "seconds"),
        },
    ]


def _env(tree: Path) -> dict:
    """The children's environment: the user's, less the BLAS thread counts a benchmark sets for itself."""
    env = {k: v for k, v in os.environ.items() if k not in BLAS_THREADS}
    env["PYTHONPATH"] = str(tree)
    return env


def _argv(cmd: dict, tree: Path, out: Path, new: bool) -> list[str]:
    return [a.format(out=out, tree=tree) for a in (*cmd["args"], *(cmd.get("new_args", ()) if new else ()))]


def _json_seconds(cmd: dict, tree: Path, out: Path, new: bool) -> float | None:
    """The seconds at ``cmd["json_seconds"]`` in the ``--json`` output of ``cmd`` (after its subcommand)."""
    argv = _argv(cmd, tree, out, new)
    argv.insert(1, "--json")
    r = subprocess.run([sys.executable, "-c", ENTRY, *argv], cwd=tree, env=_env(tree), capture_output=True,
                       text=True)
    try:
        value = json.loads(r.stdout)
        for key in cmd["json_seconds"]:
            value = value[key]
        return round(float(value), 4)
    except (ValueError, KeyError, TypeError):
        return None


def _time(argv: list[str], tree: Path, *, python_args: tuple[str, ...] = ()) -> tuple[float, int, str, float]:
    """Wall seconds, exit code, stderr and CPU seconds (user + system) of one process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    r = subprocess.run([sys.executable, *python_args, *argv], cwd=tree, env=_env(tree), capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, r.returncode, r.stderr, cpu


def _stats(xs: list[float]) -> dict:
    return {"runs": [round(x, 4) for x in xs], "min": round(min(xs), 4), "median": round(statistics.median(xs), 4)}


def _imports_by_package(stderr: str) -> tuple[dict, float]:
    """``-X importtime``'s lines summed by top-level package (self times, seconds), and their total."""
    by: dict[str, float] = {}
    for line in stderr.splitlines():
        if not line.startswith("import time:") or "|" not in line:
            continue
        parts = line[len("import time:") :].split("|")
        try:
            self_us = int(parts[0])
        except ValueError:  # the header
            continue
        top = parts[2].strip().split(".")[0]
        by[top] = by.get(top, 0.0) + self_us / 1e6
    total = sum(by.values())
    groups = {
        "numpy": 0.0,
        "scipy": 0.0,
        "matplotlib": 0.0,
        "PIL": 0.0,
        "cvxpy": 0.0,
        "clarabel": 0.0,
        "typst": 0.0,
        "cams+laws+optimize": 0.0,
        "other": 0.0,
    }
    for top, s in by.items():
        key = top if top in groups else "cams+laws+optimize" if top in ("cams", "laws", "optimize") else "other"
        groups[key] += s
    return {k: round(v, 4) for k, v in groups.items() if v > 0.0005}, total


def _prepare(tree: Path, out: Path) -> None:
    """The scratch folder ``out`` with the tree's files the commands read; the tree's modules compiled to bytecode,
    as an installation has them (pip compiles them; an editable one on its first run), whatever
    ``PYTHONDONTWRITEBYTECODE`` says: every run then reads them instead of compiling the sources."""
    subprocess.run([sys.executable, "-m", "compileall", "-q", *(str(tree / p) for p in ("cams", "laws", "optimize"))],
                   check=True, capture_output=True)
    out.mkdir(parents=True, exist_ok=True)
    text = (tree / "examples" / "translating_designed_rise.toml").read_text()
    assert PRESSURE_OBJECTIVE[0] in text, "the motion-design example's objective line moved"
    (out / "designed_pressure.toml").write_text(text.replace(*PRESSURE_OBJECTIVE))


def _load() -> list[float]:
    try:
        return [round(x, 2) for x in os.getloadavg()]
    except OSError:
        return []


def _base_default() -> str:
    r = subprocess.run(["git", "merge-base", "HEAD", "main"], cwd=ROOT, capture_output=True, text=True)
    return r.stdout.strip() if r.returncode == 0 and r.stdout.strip() else "HEAD"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", default=None, help="the revision to compare with (default: merge-base with main)")
    ap.add_argument("--runs", type=int, default=5, help="timed runs of each command in each tree (default 5)")
    ap.add_argument("--only", default=None, help="comma-separated command names (default: all)")
    ap.add_argument("--out", default=str(ROOT / "benchmarks" / "results"))
    a = ap.parse_args(argv)
    base_rev = a.base or _base_default()
    base_sha = subprocess.run(
        ["git", "rev-parse", base_rev], cwd=ROOT, capture_output=True, text=True, check=True
    ).stdout.strip()
    head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    # changes to the product's files (the benchmarks' own results excepted): the "new" tree is then not HEAD
    status = subprocess.run(
        ["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT, capture_output=True, text=True
    ).stdout.splitlines()
    dirty = any(not line[3:].startswith("benchmarks/results/") for line in status)
    t0 = time.perf_counter()
    log = lambda msg: print(f"[{time.perf_counter() - t0:6.1f} s] {msg}", flush=True)  # noqa: E731
    tmp = Path(tempfile.mkdtemp(prefix="cams-bench-commands-"))
    base_tree = tmp / "base"
    subprocess.run(
        ["git", "worktree", "add", "--detach", str(base_tree), base_sha], cwd=ROOT, check=True, capture_output=True
    )
    try:
        trees = {"base": base_tree, "new": ROOT}
        outs = {k: tmp / f"out-{k}" for k in trees}
        for k in trees:
            _prepare(trees[k], outs[k])
        cmds = commands(tmp)
        if a.only:
            keep = {n.strip() for n in a.only.split(",")}
            cmds = [c for c in cmds if c["name"] in keep]
        load_before = _load()
        floor: dict[str, list[float]] = {"python -c pass": [], "python -c 'import numpy'": []}
        times: dict[str, dict[str, list[float]]] = {c["name"]: {"base": [], "new": []} for c in cmds}
        cpus: dict[str, dict[str, list[float]]] = {c["name"]: {"base": [], "new": []} for c in cmds}
        codes: dict[str, dict[str, set[int]]] = {c["name"]: {"base": set(), "new": set()} for c in cmds}
        for run in range(a.runs):
            log(f"run {run + 1} of {a.runs}")
            floor["python -c pass"].append(_time(["-c", "pass"], ROOT)[0])
            floor["python -c 'import numpy'"].append(_time(["-c", "import numpy"], ROOT)[0])
            for c in cmds:
                if run >= c.get("runs", a.runs):
                    continue
                order = ("base", "new") if run % 2 == 0 else ("new", "base")
                for k in order:
                    dt, rc, err, cpu = _time(["-c", ENTRY, *_argv(c, trees[k], outs[k], k == "new")], trees[k])
                    if rc not in (0, 1):
                        raise SystemExit(f"{c['name']} ({k}) exit {rc}: {err[-2000:]}")
                    times[c["name"]][k].append(dt)
                    cpus[c["name"]][k].append(cpu)
                    codes[c["name"]][k].add(rc)
        numpy_floor = statistics.median(floor["python -c 'import numpy'"])
        rows = []
        for c in cmds:
            b, n = _stats(times[c["name"]]["base"]), _stats(times[c["name"]]["new"])
            cb, cn = _stats(cpus[c["name"]]["base"]), _stats(cpus[c["name"]]["new"])
            ratio = n["median"] / b["median"]
            within = c.get("within_s")
            met = ratio <= c["target"] * 1.05 if c["target"] == 1.0 else ratio <= c["target"]
            extra = {} if within is None else {"within_s": within}
            if "json_seconds" in c:
                key = ".".join(c["json_seconds"])
                extra[f"{key} (--json, once a tree)"] = {
                    k: _json_seconds(c, trees[k], outs[k], k == "new") for k in ("base", "new")}
            rows.append(
                {
                    "name": c["name"],
                    "command": "cams " + " ".join([*c["args"], *c.get("new_args", ())]),
                    "base": b,
                    "new": n,
                    "cpu_base": cb,
                    "cpu_new": cn,
                    "ratio_cpu_median": round(cn["median"] / cb["median"], 3),
                    "exit_base": sorted(codes[c["name"]]["base"]),
                    "exit_new": sorted(codes[c["name"]]["new"]),
                    "ratio_min": round(n["min"] / b["min"], 3),
                    "ratio_median": round(ratio, 3),
                    "target": c["target"],
                    "met": bool(met and (within is None or n["median"] <= within)),
                    **extra,
                    "above_numpy_floor_s": round(n["median"] - numpy_floor, 3),
                    "times_numpy_floor": round(n["median"] / numpy_floor, 2),
                }
            )
        log("breakdown (-X importtime)")
        breakdown = []
        for c in cmds:
            entry = {"name": c["name"]}
            for k in ("base", "new"):
                dt, _, err, _ = _time(["-X", "importtime", "-c", ENTRY, *_argv(c, trees[k], outs[k], k == "new")],
                                      trees[k])
                groups, total = _imports_by_package(err)
                entry[k] = {
                    "wall_s": round(dt, 3),
                    "imports_s": round(total, 3),
                    "imports_by_package_s": groups,
                    "rest_s": round(dt - total, 3),
                }
            breakdown.append(entry)
        result = {
            "machine": machine(),
            "load_average_before": load_before,
            "load_average_after": _load(),
            "base": {"revision": base_rev, "commit": base_sha},
            "new": {"commit": head, "uncommitted_changes": dirty},
            "runs": a.runs,
            "seconds": round(time.perf_counter() - t0, 1),
            "floor": {k: _stats(v) for k, v in floor.items()},
            "commands": rows,
            "breakdown": breakdown,
            "notes": "wall seconds of whole processes; ratio = new / base; 'met' compares the medians with the "
            "target (a target of 1.0, 'no slower', allows 5 % for noise) and, where a row has within_s, this tree's "
            "median with it; CPU seconds (user + system, children included) beside them: a command drawing its "
            "pictures in several processes spends more CPU than wall time",
        }
    finally:
        subprocess.run(["git", "worktree", "remove", "--force", str(base_tree)], cwd=ROOT, capture_output=True)
        shutil.rmtree(tmp, ignore_errors=True)
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    target = write_results(out / "commands.json", result, indent=1)
    print(
        "| command | base median s | new median s | ratio (medians) | ratio (minima) | ratio (CPU) | target | "
        "met | new above numpy floor s |"
    )
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(
            f"| `{r['name']}` | {r['base']['median']:.2f} | {r['new']['median']:.2f} | {r['ratio_median']:.2f} | "
            f"{r['ratio_min']:.2f} | {r['ratio_cpu_median']:.2f} | <= {r['target']:g} | "
            f"{'yes' if r['met'] else 'NO'} | {r['above_numpy_floor_s']:.2f} |"
        )
    for name, st in result["floor"].items():
        print(f"floor: {name}: median {st['median']:.3f} s")
    for e in breakdown:
        print(
            f"{e['name']}: new {e['new']['wall_s']:.2f} s = imports {e['new']['imports_s']:.2f} "
            f"{e['new']['imports_by_package_s']} + rest {e['new']['rest_s']:.2f}; base {e['base']['wall_s']:.2f} "
            f"= imports {e['base']['imports_s']:.2f} + rest {e['base']['rest_s']:.2f}"
        )
    print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
