"""The roller's bearing life: ISO 281's basic rating life under a variable load, in hours at the cam's speed.

ISO 281, *Rolling bearings -- Dynamic load ratings and rating life*: the basic rating life (90 % reliability) of a
bearing of basic dynamic load rating ``C`` under the equivalent load ``P`` is ``L10 = (C / P)^p`` million
revolutions, ``p = 10/3`` for **roller bearings** (3 for ball bearings): a cam follower's roller runs on needle or
cylindrical rollers, so :data:`EXPONENT` is 10/3. Under a load that varies over the revolutions, ISO 281's mean
load is weighted by the **revolutions** turned at each load::

    P_m = ( sum P_i^p dN_i / sum dN_i )^(1/p)

-- by the roller's revolutions, which are not uniform in cam angle (the roller turns fastest where the contact
travels fastest along the cam), so a mean weighted by cam angle is wrong by tens of percent.

``bearing_rating_type``: ``"basic"`` is the catalogue's basic dynamic radial load rating C_r of a bearing mounted
in a rigid housing; ``"track_roller"`` the track roller's effective dynamic load rating (e.g. Schaeffler's C_w), which
accounts for the outer ring's bending as it runs on the cam. Both go through the same formula; a ``"basic"`` C of a
bearing used as a track roller overstates its life (the report says so).
"""

from __future__ import annotations

import numpy as np

__all__ = ["EXPONENT", "RATING_TYPES", "rating_life", "mean_load", "life_hours"]

#: ISO 281's life exponent of roller bearings.
EXPONENT = 10.0 / 3.0
#: The kinds of load rating a design file may give (``[contact] bearing_rating_type``).
RATING_TYPES = ("basic", "track_roller")


def rating_life(C: float, P, p: float = EXPONENT) -> np.ndarray:
    """The basic rating life ``L10 = (C/P)^p`` in millions of revolutions (``C``, ``P`` in N); inf at P = 0."""
    with np.errstate(divide="ignore"):
        return (C / np.asarray(P, float)) ** p


def mean_load(load, revolutions, p: float = EXPONENT) -> float:
    """ISO 281's mean load (N) of loads ``load`` (N) each acting over ``revolutions`` (any count, >= 0):
    ``(sum P^p dN / sum dN)^(1/p)``."""
    P = np.abs(np.asarray(load, float))
    dN = np.abs(np.asarray(revolutions, float))
    return float((np.sum(P**p * dN) / np.sum(dN)) ** (1.0 / p))


def life_hours(C: float, load, revolutions, per_turn: float, rpm: float, p: float = EXPONENT) -> float:
    """The L10 life in hours: ``(C / P_m)^p`` million revolutions of the roller, at ``per_turn`` roller revolutions
    per cam turn and the cam's ``rpm`` (rev/min). ``load`` and ``revolutions``: :func:`mean_load`'s."""
    L10 = float(rating_life(C, mean_load(load, revolutions, p), p))
    return L10 * 1e6 / (per_turn * rpm * 60.0)
