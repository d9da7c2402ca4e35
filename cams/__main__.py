"""``python -m cams``: the ``cams`` program, as the console script runs it (:func:`cams.cli.entry`)."""

import sys

from cams.cli import entry

sys.exit(entry())
