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
