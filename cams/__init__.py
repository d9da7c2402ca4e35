"""cams: disk-cam design: follower geometry, profiles, checks, machines, command line.

Importing ``cams`` stays light: it imports nothing itself (the error classes
are loaded on first use), and matplotlib, cvxpy and ezdxf are imported only by
the code paths that use them. The command line (:mod:`cams.cli`) relies on
this to take Ctrl-C from its first instant.
"""

from cams import _moved

_moved.install()  # the previous release's import paths (cams.design, cams.linkage, ...) for one release

__version__ = "0.1.0"
__all__ = ["CamsError", "InputError", "InfeasibleError", "__version__"]


def __getattr__(name: str):
    """``cams.CamsError``, ``cams.InputError``, ``cams.InfeasibleError``: from :mod:`laws.errors` on first use."""
    if name in ("CamsError", "InputError", "InfeasibleError"):
        import laws.errors

        return getattr(laws.errors, name)
    raise AttributeError(f"module 'cams' has no attribute {name!r}")
