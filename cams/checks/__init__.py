"""Checks of a solved cam: jamming, undercut, the profile as a polygon, the bore."""



def __getattr__(name: str) -> object:
    """The previous release's ``cams.checks`` module's names, from their new homes, for one release."""
    from cams._moved import forward

    return forward(__name__, name)
