"""The cam's working profile: roller (and knife edge) followers, flat faces."""


def __getattr__(name: str):
    """The previous release's ``cams.profile`` module's names, from :mod:`cams.profile.roller`, for one release."""
    import importlib
    import warnings

    if not name.startswith("__"):
        module = importlib.import_module("cams.profile.roller")
        if hasattr(module, name):
            warnings.warn(f"cams.profile.{name} moved to cams.profile.roller.{name}; the old path goes in the next release",
                          DeprecationWarning, stacklevel=2)
            return getattr(module, name)
    raise AttributeError(f"module 'cams.profile' has no attribute {name!r}")
