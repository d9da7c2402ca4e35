"""What every benchmark sets up the same way (no project import, and numpy only inside :func:`machine`).

* :func:`one_thread_per_process`: one BLAS thread, called before the first numpy import;
* :func:`machine`: the machine a benchmark ran on, for its results file;
* :func:`write_results`: the results file, JSON, written whole or not at all;
* :func:`median_time`: the median wall time of repeated calls.

>>> sorted(machine())
['cores', 'cpu', 'numpy', 'platform', 'python']
>>> median_time(lambda: 7, 3)[0]
7
"""

from __future__ import annotations

import json
import os
import platform
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

T = TypeVar("T")

#: The BLAS libraries' thread counts: a benchmark sets each to 1 for itself (one core per process, the timings
#: comparable from run to run); a user's shell does not.
BLAS_THREADS = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def one_thread_per_process() -> None:
    """Set each of :data:`BLAS_THREADS` to 1 unless the environment already sets it.

    numpy reads them when first imported: call this before importing numpy or the project.
    """
    for name in BLAS_THREADS:
        os.environ.setdefault(name, "1")


def machine() -> dict:
    """The machine: CPU model and cores, Python and numpy versions, the platform."""
    import numpy as np

    model = "unknown"
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {
        "cpu": model,
        "cores": os.cpu_count(),
        "python": sys.version.split()[0],
        "numpy": np.__version__,
        "platform": platform.platform(),
    }


def write_results(path: Path, data: Any, *, indent: int = 2) -> Path:
    """Write ``data`` as JSON (and a final newline) to ``path``, whole or not at all (``path`` + ``.part``
    beside it, renamed over it); returns ``path``."""
    path = Path(path)
    text = json.dumps(data, indent=indent) + "\n"
    part = path.with_name(path.name + ".part")
    try:
        part.write_text(text, encoding="utf-8")
        os.replace(part, path)
    except BaseException:
        part.unlink(missing_ok=True)
        raise
    return path


def median_time(
    fn: Callable[[], T], repeats: int, *, warm_up: bool = False, before: Callable[[], object] | None = None
) -> tuple[T, float]:
    """The last result of ``fn()`` and the median wall time of ``repeats`` timed calls (seconds).

    Parameters
    ----------
    fn : callable
        The work timed, no arguments.
    repeats : int
        Timed calls, >= 1.
    warm_up : bool
        One untimed call first (disk caches, lazy imports).
    before : callable or None
        Called untimed before each timed call (a cache cleared, for a cold time).
    """
    if repeats < 1:
        raise ValueError(f"repeats must be >= 1, got {repeats}")
    if warm_up:
        fn()
    times = []
    for _ in range(repeats):
        if before is not None:
            before()
        t0 = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t0)
    return out, statistics.median(times)
