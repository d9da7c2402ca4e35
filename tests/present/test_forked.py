"""Drawings made side by side in forked processes (cams.present.forked): the same results as one after another,
in the tasks' order, a task's exception raised as it is, and ``cams plot`` / ``cams report`` writing the same
pictures either way."""

from __future__ import annotations

import os
import sys
import threading

import numpy as np
import pytest

from cams.present.forked import forked_map, workers
from laws.errors import InputError
from tests.inprocess import cams_cli

LINUX = sys.platform.startswith("linux")


def test_workers_one_a_core_at_most_one_a_task():
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    assert workers(1, 10) == 1
    assert workers(5, 3) == (3 if LINUX else 1)
    assert workers(None, 100) == (cores if LINUX else 1)
    assert workers(4, 0) == 1


@pytest.mark.skipif(not LINUX, reason="processes are forked on Linux only; elsewhere the tasks run in order here")
def test_tasks_run_in_children_and_come_back_in_order():
    here = os.getpid()
    lock = threading.Lock()  # a closure over what cannot be pickled: the children inherit it
    tasks = [lambda k=k: (k * k, os.getpid(), lock is not None) for k in range(6)]
    ended = []
    out = forked_map(tasks, jobs=2, done=ended.append)
    assert [v for v, _, _ in out] == [k * k for k in range(6)]
    assert all(ok for _, _, ok in out)
    assert here not in {pid for _, pid, _ in out}  # drawn elsewhere ...
    assert len({pid for _, pid, _ in out}) <= 2  # ... by at most the processes asked for
    assert sorted(ended) == list(range(6))  # each counted once, as it ended


def test_one_job_runs_here_in_order():
    here = os.getpid()
    ended = []
    out = forked_map([lambda k=k: (k, os.getpid()) for k in range(3)], jobs=1, done=ended.append)
    assert out == [(0, here), (1, here), (2, here)]
    assert ended == [0, 1, 2]


def test_a_task_that_raises_raises_here_as_it_raised():
    """InputError does not survive a pickle round trip (its __init__ takes two arguments): the task is run again
    here, so the caller sees the real exception, field and message."""

    def bad():
        raise InputError("cam.rpm", "is missing")

    with pytest.raises(InputError, match=r"^cam\.rpm: is missing$"):
        forked_map([lambda: 1, bad, lambda: 3], jobs=2)


def _pixels(path):
    from matplotlib.image import imread

    return imread(path)


def test_plot_draws_the_same_pictures_side_by_side(tmp_path):
    one, two = tmp_path / "one", tmp_path / "two"
    assert cams_cli("plot", "examples/rocker_force.toml", "--out", one, "--jobs", "1", "--quiet").returncode == 0
    assert cams_cli("plot", "examples/rocker_force.toml", "--out", two, "--jobs", "2", "--quiet").returncode == 0
    names = sorted(p.name for p in one.iterdir())
    assert names == sorted(p.name for p in two.iterdir())
    assert len(names) == 8  # motion, zone, pressure, profile; PNG and SVG
    for name in names:
        if name.endswith(".png"):
            assert np.array_equal(_pixels(one / name), _pixels(two / name)), name
        else:  # the SVG's ids are random per process; its drawing is not
            a, b = ((d / name).read_text() for d in (one, two))
            assert a.count("<path") == b.count("<path") and len(a) == len(b), name


@pytest.mark.parametrize("jobs", ["0", "-1"])
def test_jobs_below_one_is_refused(tmp_path, jobs):
    for command in ("plot", "report"):
        r = cams_cli(command, "examples/rocker_force.toml", "--out", tmp_path / command, "--jobs", jobs)
        assert r.returncode == 2
        assert "--jobs" in r.stderr and ">= 1" in r.stderr and len(r.stderr.strip().splitlines()) == 1
        assert not (tmp_path / command).exists()


@pytest.mark.skipif(not LINUX, reason="processes are forked on Linux only; elsewhere the tasks run in order here")
def test_effort_orders_what_is_handed_out_not_what_comes_back():
    """Two processes, four tasks of half a second: the two of most effort are handed out first (they start
    together, the others half a second later); the results still come back in the tasks' order."""
    import time

    def task(k):
        start = time.monotonic()
        time.sleep(0.5)
        return k, start

    out = forked_map([lambda k=k: task(k) for k in range(4)], jobs=2, effort=[1.0, 4.0, 2.0, 3.0])
    assert [k for k, _ in out] == [0, 1, 2, 3]
    starts = sorted(out, key=lambda r: r[1])
    assert {k for k, _ in starts[:2]} == {1, 3}


def test_the_turn_is_drawn_beside_the_pictures_and_is_the_same(tmp_path):
    """--animate: the turn is one more task; its GIF is the same, frame for frame, drawn here or elsewhere."""
    from PIL import Image, ImageSequence

    gifs = []
    for jobs in ("1", "2"):
        out = tmp_path / jobs
        r = cams_cli("plot", "examples/translating_force.toml", "--out", out, "--only", "motion", "--animate",
                     "--jobs", jobs, "--quiet")
        assert r.returncode == 0, r.stderr
        assert [line.rsplit("_", 1)[-1] for line in r.stdout.split()] == ["motion.png", "motion.svg", "turn.gif"]
        (gif,) = out.glob("*_turn.gif")
        with Image.open(gif) as im:
            gifs.append([np.asarray(f.convert("RGB")) for f in ImageSequence.Iterator(im)])
    assert len(gifs[0]) == len(gifs[1]) == 72
    assert all(np.array_equal(a, b) for a, b in zip(*gifs, strict=True))


@pytest.mark.skipif(not LINUX, reason="processes are forked on Linux only; elsewhere the tasks run in order here")
def test_a_child_that_is_killed_costs_time_not_results():
    """A child killed mid-task (as by the kernel's out-of-memory killer): the tasks not yet back are run here, the
    results are all there in order, and the caller is told in one line; no child is left."""
    import signal

    here = os.getpid()

    def task(k):
        if k == 2 and os.getpid() != here:
            os.kill(os.getpid(), signal.SIGKILL)
        return k * k, os.getpid()

    said = []
    ended = []
    out = forked_map([lambda k=k: task(k) for k in range(5)], jobs=2, done=ended.append, note=said.append)
    assert [v for v, _ in out] == [0, 1, 4, 9, 16]
    assert out[2][1] == here  # the killed task was run here
    assert sorted(ended) == list(range(5))  # each counted once
    assert len(said) == 1 and "ended abruptly" in said[0] and "\n" not in said[0]


@pytest.mark.skipif(not LINUX, reason="processes are forked on Linux only; elsewhere the tasks run in order here")
def test_a_task_that_raises_only_in_a_child_gives_what_it_gives_here():
    here = os.getpid()

    def flaky():
        if os.getpid() != here:
            raise MemoryError("a child's own trouble")
        return "drawn here"

    said = []
    assert forked_map([lambda: 1, flaky, lambda: 3], jobs=2, note=said.append) == [1, "drawn here", 3]
    assert said == []  # nothing went wrong that the caller must hear about


_SLEEPERS = """
import os, sys, time
from cams.present.forked import forked_map

folder = sys.argv[1]

def task(k):
    open(os.path.join(folder, str(os.getpid())), "w").close()
    time.sleep(60)
    return k

try:
    forked_map([lambda k=k: task(k) for k in range(4)], jobs=2)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(130)
"""


def _alive(pid: int) -> bool:
    """Whether process ``pid`` runs (a zombie, ended but not yet reaped by whoever adopted it, does not)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] not in ("Z", "X")
    except FileNotFoundError:
        return False


@pytest.mark.skipif(not LINUX, reason="processes are forked on Linux only; elsewhere the tasks run in order here")
@pytest.mark.parametrize("how", ["ctrl-c to the group", "ctrl-c to the parent", "the parent killed"])
def test_no_child_outlives_an_interrupted_or_killed_parent(tmp_path, how):
    """Ctrl-C (to the terminal's process group, or to the parent alone) ends the parent with its
    KeyboardInterrupt at once, not when the drawings under way end (a minute here), and no child prints a
    traceback; a parent killed outright takes its children with it (none waits for work for ever)."""
    import signal
    import subprocess
    import time

    from tests.inprocess import ROOT

    p = subprocess.Popen(
        [sys.executable, "-c", _SLEEPERS, str(tmp_path)],
        cwd=ROOT,
        start_new_session=True,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
    )
    deadline = time.monotonic() + 60
    while len(list(tmp_path.iterdir())) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)
    children = [int(f.name) for f in tmp_path.iterdir()]
    assert len(children) == 2 and all(_alive(c) for c in children)
    started = time.monotonic()
    if how == "ctrl-c to the group":
        os.killpg(p.pid, signal.SIGINT)
    elif how == "ctrl-c to the parent":
        os.kill(p.pid, signal.SIGINT)
    else:
        os.kill(p.pid, signal.SIGKILL)
    rc = p.wait(timeout=30)
    while any(_alive(c) for c in children) and time.monotonic() - started < 10:
        time.sleep(0.05)
    try:
        assert not any(_alive(c) for c in children)
        assert time.monotonic() - started < 10  # not the minute the tasks would sleep
        out, err = p.communicate(timeout=10)
        if how == "the parent killed":
            assert rc == -signal.SIGKILL
        else:
            assert (rc, out, err) == (130, "interrupted\n", "")
    finally:
        for c in children:
            if _alive(c):
                os.kill(c, signal.SIGKILL)
