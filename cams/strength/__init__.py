"""The cam's strength: the contact stress, the lubricant film and the roller bearing's life.

:mod:`~cams.strength.materials` (a table of cam and follower materials with their sources),
:mod:`~cams.strength.hertz` (Hertz's line contact and McEwen's subsurface field), :mod:`~cams.strength.film`
(entrainment, the EHL film, the film parameter), :mod:`~cams.strength.life` (ISO 281) and
:mod:`~cams.strength.along` (all of it along the cycle, from a face's contact geometry and the contact force of
:mod:`cams.dynamics`). It sits above :mod:`cams.dynamics` and :mod:`cams.profile` and below the faces' pipelines
(their ``contact`` stage) and the facade, as the layer rule (``tests/test_layers.py``) has it.
"""

__all__: list[str] = []
