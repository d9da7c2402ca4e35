"""cams: disk-cam design: follower geometry, profiles, checks, machines, command line.

Importing ``cams`` stays light: matplotlib, cvxpy and ezdxf are imported only by
the code paths that use them.
"""

from laws.errors import CamsError, InfeasibleError, InputError

__version__ = "0.1.0"
__all__ = ["CamsError", "InputError", "InfeasibleError", "__version__"]
