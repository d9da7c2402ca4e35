"""The cam in its machine: the linkage, the cycle's timing, kinetostatics and the flywheel."""


def __getattr__(name: str) -> object:
    """The previous release's ``cams.machine`` module's names, from :mod:`cams.machine.timing`, for one release."""
    from cams._moved import forward

    return forward(__name__, name)
