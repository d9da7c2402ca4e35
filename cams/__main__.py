"""``python -m cams``: the ``cams`` program, as the console script runs it (:func:`cams.cli.entry`)."""

import sys

if __name__ == "__main__":  # run as ``python -m cams``; imported (a walk over the modules), it does nothing
    from cams.cli import entry

    sys.exit(entry())
