"""cams: disk-cam design: follower geometry, profiles, checks, machines, command line.

Importing ``cams`` stays light: it imports nothing itself (the error classes
are loaded on first use), and matplotlib, cvxpy and ezdxf are imported only by
the code paths that use them. The command line (:mod:`cams.cli`) relies on
this to take Ctrl-C from its first instant.
"""

from cams import _moved

_moved.install()  # the previous release's import paths (cams.design, cams.linkage, ...) for one release

__version__ = "0.1.0"
__all__ = ["Cam", "solve", "load_design", "CamsError", "InputError", "InfeasibleError", "__version__"]


#: The public API re-exported lazily: name -> (module, attribute; None: the module itself). ``cams.solve`` is the
#: module :mod:`cams.solve`, callable as its ``solve`` (Python binds the package's attribute ``solve`` to that
#: submodule whenever it is imported, so the function and the module must be one object).
_API = {"Cam": ("cams.cam", "Cam"), "load_design": ("cams.io.designfile", "load_design"),
        "solve": ("cams.solve", None)}


def __getattr__(name: str):
    """The public API, each name imported on first use (``import cams`` itself stays light).

    ``cams.Cam`` (:class:`cams.cam.Cam`), ``cams.solve`` (:func:`cams.solve.solve`), ``cams.load_design``
    (:func:`cams.io.designfile.load_design`); ``cams.CamsError``, ``cams.InputError``, ``cams.InfeasibleError``
    (:mod:`laws.errors`).
    """
    if name in ("CamsError", "InputError", "InfeasibleError"):
        import laws.errors

        return getattr(laws.errors, name)
    if name in _API:
        # by name, as cams._moved forwards: the package's entry imports nothing above it until a name is asked for
        import importlib

        module, attr = _API[name]
        found = importlib.import_module(module)
        return found if attr is None else getattr(found, attr)
    raise AttributeError(f"module 'cams' has no attribute {name!r}")
