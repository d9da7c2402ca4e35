"""The sweep on a Dask cluster: a local cluster of two workers gives the process pool's rows; stop() is prompt.

One cluster is started for the module (it takes seconds): the fixture runs the whole scenario once and one test
reads what it recorded.
"""

from __future__ import annotations

import os
import sys
import time

import psutil
import pytest

import cams
import cams.sweep.cluster as cluster
from cams.io.document import read_toml
from cams.sweep import engine, run_grid
from cams.sweep.cluster import check_spec, executor
from cams.sweep.grid import BaseFile, make_grid
from laws.errors import InputError
from tests.conftest import EXAMPLES

VARY = [("follower.arm", [100.0, 160.0]), ("limits.pressure_angle", [35.0, 50.0])]  # 4 designs


def _grid():
    return make_grid([BaseFile("", read_toml(EXAMPLES / "rocker_force.toml"))], VARY)


def _alive(pid: int) -> bool:
    try:
        return psutil.Process(pid).status() != psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return False


@pytest.fixture(scope="module")
def scenario():
    rec = {}
    # the whole engine on the cluster: chunks submitted to the cluster's executor, rows streamed back
    rec["sweep"] = run_grid(_grid(), workers=2, cluster="local").rows
    grid = _grid()
    with executor("local", 2) as (ex, stop):
        client = ex._client  # the executor's client: ask the workers who they are
        rec["pids"] = list(client.run(os.getpid).values())
        rec["cams"] = set(client.run(lambda: __import__("cams").__file__).values())
        pending = [ex.submit(engine.evaluate, (grid.chunk([k % grid.size]), True)) for k in range(40)]
        t0 = time.perf_counter()
        stop()
        rec["stop_seconds"] = time.perf_counter() - t0
        rec["done"] = sum(1 for f in pending if f.done() and not f.cancelled())
        rec["cancelled"] = sum(1 for f in pending if f.cancelled())
        stop()  # a second call does nothing
    rec["alive_after"] = [p for p in rec["pids"] if _alive(p)]
    return rec


def test_local_cluster_of_two_workers(scenario):
    """One test for the one cluster (xdist could send a second test to another process, which would start its own).

    The sweep's rows on a local cluster of two workers equal the process pool's; two worker processes import this
    checkout's cams; stop() with designs pending returns promptly (40 designs take ~10 s on two workers), cancels
    most of them and leaves no worker.
    """
    expected = run_grid(_grid(), workers=2).rows
    assert len(scenario["sweep"]) == 4
    assert scenario["sweep"] == expected
    assert sum(1 for r in expected if r["R0"] is not None) >= 3  # designs solved, not rows of errors compared
    assert len(scenario["pids"]) == 2 and os.getpid() not in scenario["pids"]
    assert scenario["cams"] == {cams.__file__}
    assert scenario["stop_seconds"] < 5.0
    assert scenario["cancelled"] >= 30 and scenario["done"] + scenario["cancelled"] <= 40
    assert scenario["alive_after"] == []


def test_missing_dask_names_the_option_and_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(
        InputError, match=r'^--dask: needs dask\.distributed, an optional extra: pip install "cams\[dask\]"$'
    ):
        with executor("local", 1):
            pass


@pytest.mark.parametrize("spec", ["", "   ", "somewhere"])
def test_malformed_address_refused(spec):
    with pytest.raises(InputError, match="^--dask: "):
        check_spec(spec)


def test_workers_checked():
    with pytest.raises(InputError, match=r"^--jobs: must be an integer >= 1"):
        check_spec("local", 0)


def test_unreachable_scheduler_is_one_line(monkeypatch):
    monkeypatch.setattr(cluster, "CONNECT_TIMEOUT", 0.5)
    with pytest.raises(InputError, match=r"^--dask: cannot reach the Dask scheduler at 'tcp://127\.0\.0\.1:9'"):
        with executor("tcp://127.0.0.1:9"):
            pass


def test_job_function_travels_by_reference():
    """cloudpickle sends the job function as its module and name (the workers import cams), not as code."""
    import cloudpickle

    blob = cloudpickle.dumps(engine.evaluate)
    assert b"cams.sweep.engine" in blob and b"evaluate" in blob and len(blob) < 200
    assert cloudpickle.loads(blob) is engine.evaluate
    job = (_grid().chunk([0, 3]), True)
    back = cloudpickle.loads(cloudpickle.dumps(job))
    assert back[0].design_dict(1) == job[0].design_dict(1)  # plain data: the design file's dict and the values
