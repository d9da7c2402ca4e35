"""Checks of a solved cam: jamming, undercut, the profile as a polygon, the bore."""


def __getattr__(name: str):
    """The previous release's ``cams.checks`` module's names, from :mod:`cams.checks.profile`, for one release."""
    import importlib
    import warnings

    if not name.startswith("__"):
        module = importlib.import_module("cams.checks.profile")
        if hasattr(module, name):
            warnings.warn(f"cams.checks.{name} moved to cams.checks.profile.{name}; the old path goes in the next release",
                          DeprecationWarning, stacklevel=2)
            return getattr(module, name)
    raise AttributeError(f"module 'cams.checks' has no attribute {name!r}")
