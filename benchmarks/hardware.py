"""The machine a benchmark ran on, for its results file: one home for every benchmark (no project import).

>>> sorted(machine())
['cores', 'cpu', 'numpy', 'platform', 'python']
"""

from __future__ import annotations

import os
import platform
import sys
from pathlib import Path


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
    return {"cpu": model, "cores": os.cpu_count(), "python": sys.version.split()[0], "numpy": np.__version__,
            "platform": platform.platform()}
