"""A sweep on a Dask cluster: a ``concurrent.futures`` executor over ``dask.distributed`` workers.

``cams sweep ... --dask ADDRESS`` runs the designs on an existing cluster (its scheduler's address,
``tcp://host:8786``); ``--dask local`` starts a ``LocalCluster`` on this machine. The client's
:meth:`~distributed.Client.get_executor` is a :class:`concurrent.futures.Executor`, so the sweep
submits its jobs to it as to a process pool.

Each job is a call of the sweep's module-level job function, which cloudpickle sends *by reference*
(module and name) with its arguments (the design file's dict, plain data): every worker imports
``cams`` itself. A worker on another machine therefore needs the same version of cams installed
(``pip install "cams[dask]"``), as well as dask.

Dask is an optional extra (``pip install "cams[dask]"``), imported only here, inside the functions.
"""

from __future__ import annotations

import contextlib
import logging
import os
from collections.abc import Callable, Iterator
from concurrent.futures import Executor

from laws.errors import InputError

__all__ = ["INSTALL", "executor", "check_spec"]

#: How to get the optional extra, said by the error when dask is missing.
INSTALL = 'pip install "cams[dask]"'

#: How long to wait for the scheduler of an existing cluster before saying it cannot be reached (s).
CONNECT_TIMEOUT = 10.0


def check_spec(spec: str, workers: int | None = None) -> None:
    """Refuse a ``--dask`` value that is neither ``local`` nor a scheduler's address, or bad ``workers``.

    Raises
    ------
    InputError
        Naming ``--dask`` (or ``--jobs`` for ``workers``).
    """
    s = spec.strip() if isinstance(spec, str) else ""
    if not s:
        raise InputError("--dask", "give a scheduler's address (tcp://host:8786) or local")
    if s != "local" and ("://" not in s and ":" not in s):
        raise InputError("--dask", f"{spec!r} is neither local nor a scheduler's address like tcp://host:8786")
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise InputError("--jobs", f"must be an integer >= 1 (worker processes), got {workers!r}")


@contextlib.contextmanager
def executor(spec: str, workers: int | None = None) -> Iterator[tuple[Executor, Callable[[], None]]]:
    """A Dask cluster's executor, and a function that stops it now.

    Parameters
    ----------
    spec : str
        ``"local"``: start a ``LocalCluster`` on this machine (``workers`` processes of one thread each, no
        dashboard, quiet logs); else the address of an existing cluster's scheduler (``tcp://host:8786``).
    workers : int, optional
        Worker processes of a local cluster (default: the machine's cores); not used with an address (the
        cluster has its own workers).

    Yields
    ------
    (executor, stop)
        ``executor``: a :class:`concurrent.futures.Executor` (``Client.get_executor()``); ``stop()``: cancels
        every pending design now and closes the client (and the local cluster, ending its worker processes).
        Leaving the block calls it too; it may be called more than once.

    Raises
    ------
    InputError
        Naming ``--dask``: dask is not installed (the pip extra to install), the address is malformed, or its
        scheduler cannot be reached.
    """
    check_spec(spec, workers)
    try:
        from distributed import Client, LocalCluster
    except ImportError:
        raise InputError("--dask", f"needs dask.distributed, an optional extra: {INSTALL}") from None

    spec = spec.strip()
    cluster = None
    for name in (
        "distributed",
        "distributed.scheduler",
        "distributed.nanny",
        "distributed.worker",
        "distributed.core",
        "distributed.batched",
        "distributed.comm",
    ):
        logging.getLogger(name).setLevel(logging.ERROR)  # quiet: a sweep's table, not the cluster's log
    try:
        if spec == "local":
            cluster = LocalCluster(
                n_workers=workers or os.cpu_count() or 1,
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,  # no dashboard; its bare HTTP server (always started) on a free port:
                scheduler_kwargs={"dashboard_address": ":0"},  # not 8787, which another cluster may hold
                silence_logs=logging.ERROR,
            )
            client = Client(cluster)
        else:
            client = Client(spec, timeout=CONNECT_TIMEOUT)
    except (OSError, TimeoutError, ValueError) as e:
        if cluster is not None:
            cluster.close()
        raise InputError("--dask", f"cannot reach the Dask scheduler at {spec!r}: {e}") from None
    ex = client.get_executor()
    stopped = False

    def stop() -> None:
        nonlocal stopped
        if stopped:
            return
        stopped = True
        try:
            ex.shutdown(wait=False)  # cancels every future this executor made: pending ones are never run
        finally:
            try:
                client.close()
            finally:
                if cluster is not None:
                    cluster.close()  # the local workers' processes end (a running design with them)

    try:
        yield ex, stop
    finally:
        stop()
