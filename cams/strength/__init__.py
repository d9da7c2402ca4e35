"""The cam's strength, a room for what comes next: contact stress, the lubricant film, the cam's life.

It will hold what follows from the loads on the cam and its profile: the contact stress between the cam and its
roller or flat face (from the contact force of :mod:`cams.dynamics` and the profile's curvature of
:mod:`cams.profile`), the lubricant film, and the life they give. It sits above :mod:`cams.dynamics` and
:mod:`cams.profile` and below the facade (:mod:`cams.solve`), as the layer rule (``tests/test_layers.py``) has
it; nothing lives here yet.
"""

__all__: list[str] = []
