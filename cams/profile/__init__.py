"""The cam's working profile: roller (and knife edge) followers, flat faces."""



def __getattr__(name: str) -> object:
    """The previous release's ``cams.profile`` module's names, from their new homes, for one release."""
    from cams._moved import forward

    return forward(__name__, name)
