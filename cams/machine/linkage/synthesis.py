"""Dimensional synthesis from course data: the slotted-lever (guide-bar) and crank-slider mechanisms.

Formulas
--------
Slotted lever with a swinging guide bar (seed 003, 插床; seed 004, pump with a
swinging slotted lever). At the two dead positions the crank O2A is
perpendicular to the bar O3A, so the bar's swing theta equals the angle between
the two dead crank positions' supplements and

* theta = 180 deg (K - 1) / (K + 1)        (time ratio K = slow / fast crank span),
* l_O2A = L_O2O3 sin(theta / 2),
* l_O3B = H / (2 sin(theta / 2))            (the chord of B's arc is the stroke H),
* guide y-y at the middle of the sagitta of B's arc: at the distance
  l_O3B (1 + cos(theta / 2)) / 2 from O3 along the bar's mid-position.

Crank-slider (seed 002): central, l_OA = H / 2 (seed formula 1.1), extreme
slider positions l_AB + l_OA and l_AB - l_OA (1.2, 1.3); with an offset e the
stroke ``sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2) = H`` is solved for r.

Lengths in the caller's unit; angles radians inside.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laws.errors import InfeasibleError, InputError, check_positive
from laws.errors import show_value as _show

__all__ = [
    "rounded_down",
    "swing_from_time_ratio",
    "time_ratio_from_swing",
    "slotting_time_ratio_limit",
    "slotting_rod_ratio_min",
    "MAX_TIME_RATIO",
    "SlottedLeverSynthesis",
    "slotted_lever_synthesis",
    "crank_slider_crank",
]


MAX_TIME_RATIO = 1000.0
"""Largest time ratio K the synthesis accepts for any swinging-lever linkage.

Geometrically K may approach infinity (the swing theta approaches 180 deg and
the crank the centre distance), but beyond ~1000 the return stroke takes less
than 0.36 deg of crank, the crank's pin passes within ~5e-6 L of the lever's
pivot and the linkage's own time ratio can no longer be checked to 1e-9.
"""


def rounded_down(x: float) -> str:
    """``x`` to 6 significant digits, rounded down (an upper limit quoted in a message stays valid)."""
    t = f"{x:.6g}"
    if float(t) > x:  # rounded up: step down by one unit of the 6th digit
        t = f"{x - 10 ** (np.floor(np.log10(abs(x))) - 5):.6g}"
    return t


def swing_from_time_ratio(K: float, *, field: str = "linkage.time_ratio") -> float:
    """Swing (crank-angle excess) theta = pi (K - 1) / (K + 1), radians.

    Parameters
    ----------
    K : float
        Time ratio (coefficient of advance of the return), > 1.
    field : str
        Field named in an error.

    Raises
    ------
    InputError
        K <= 1 (no quick return: a swinging guide bar needs K > 1).

    Examples
    --------
    >>> round(float(np.degrees(swing_from_time_ratio(2.0))), 9)
    60.0
    """
    if isinstance(K, bool) or not isinstance(K, (int, float, np.floating, np.integer)) or not np.isfinite(K) or K <= 1:
        raise InputError(field, f"K must be > 1 for a quick return, got {_show(K)}")
    return float(np.pi * (K - 1) / (K + 1))


def time_ratio_from_swing(theta: float) -> float:
    """Inverse of :func:`swing_from_time_ratio`: K = (pi + theta) / (pi - theta)."""
    return float((np.pi + theta) / (np.pi - theta))


def slotting_time_ratio_limit(rod_ratio: float) -> float:
    """Largest time ratio of a slotting machine (seed 003) synthesized with the rod ratio l_BC / l_O3B.

    With the guide y-y through the middle of the sagitta of B's arc
    (:func:`slotted_lever_synthesis`), the tool's coordinate along y-y,
    ``y(psi) = b sin psi + sqrt(l^2 - b^2 (cos psi - (1 + cos(theta/2)) / 2)^2)``
    (up to signs; ``psi`` the bar's angle, ``b = l_O3B``, ``l = rho b``),
    is monotonic over the swing ``|psi| <= theta/2`` exactly when
    ``cos(theta/2) > 1 / (1 + 2 rho)``: at the limit the rod BC lies along the
    bar at its extreme positions, so the tool stops before the bar does.
    Beyond it the tool reverses near both ends of its stroke (four dead
    positions a turn) and neither the stroke nor the time ratio is the one asked.

    Parameters
    ----------
    rod_ratio : float
        rho = l_BC / l_O3B, > 0.

    Returns
    -------
    float
        K_max = (pi + theta_max) / (pi - theta_max), theta_max = 2 acos(1 / (1 + 2 rho)).

    Examples
    --------
    >>> round(slotting_time_ratio_limit(0.5), 9), round(slotting_time_ratio_limit(1.0), 6)
    (5.0, 8.244413)
    """
    rho = check_positive("linkage.rod_ratio", rod_ratio)
    return time_ratio_from_swing(2 * float(np.arccos(1 / (1 + 2 * rho))))


def slotting_rod_ratio_min(time_ratio: float) -> float:
    """Smallest rod ratio l_BC / l_O3B for which a slotting machine with time ratio K keeps two dead positions.

    The inverse of :func:`slotting_time_ratio_limit`: ``(1 / cos(theta/2) - 1) / 2``.

    Examples
    --------
    >>> round(slotting_rod_ratio_min(5.0), 9)
    0.5
    """
    half = swing_from_time_ratio(time_ratio) / 2
    return float((1 / np.cos(half) - 1) / 2)


@dataclass(frozen=True)
class SlottedLeverSynthesis:
    """Lengths of a slotted-lever (swinging guide-bar) mechanism from its course data.

    Attributes
    ----------
    time_ratio, stroke, centre_distance : float
        The course data K, H, L_O2O3 (lengths in the caller's unit).
    rod_ratio : float or None
        l_BC / l_O3B (slotting machine), None when there is no rod.
    swing : float
        Swing of the bar theta, radians.
    crank : float
        l_O2A = L sin(theta/2).
    bar : float
        l_O3B = H / (2 sin(theta/2)).
    rod : float or None
        l_BC = rod_ratio * l_O3B.
    guide_distance : float
        Distance from O3 to the guide y-y along the bar's mid-position:
        l_O3B (1 + cos(theta/2)) / 2 (middle of the sagitta of B's arc).
    sagitta : float
        l_O3B (1 - cos(theta/2)).
    """

    time_ratio: float
    stroke: float
    centre_distance: float
    rod_ratio: float | None
    swing: float
    crank: float
    bar: float
    rod: float | None
    guide_distance: float
    sagitta: float

    def to_dict(self) -> dict:
        """JSON-ready: lengths in the caller's unit, the swing in degrees."""
        return {
            "time_ratio": self.time_ratio,
            "stroke": self.stroke,
            "centre_distance": self.centre_distance,
            "rod_ratio": self.rod_ratio,
            "swing_deg": float(np.degrees(self.swing)),
            "crank": self.crank,
            "bar": self.bar,
            "rod": self.rod,
            "guide_distance": self.guide_distance,
            "sagitta": self.sagitta,
        }


def slotted_lever_synthesis(
    time_ratio: float,
    stroke: float,
    centre_distance: float,
    rod_ratio: float | None = None,
) -> SlottedLeverSynthesis:
    """Synthesis of the slotted-lever mechanism (seeds 003 and 004).

    Parameters
    ----------
    time_ratio : float
        K > 1.
    stroke : float
        H, the output's stroke (chord of B's arc), > 0.
    centre_distance : float
        L_O2O3 (crank centre to bar pivot), > 0.
    rod_ratio : float, optional
        l_BC / l_O3B, > 0 (slotting machine); None for the pump (no rod).

    Returns
    -------
    SlottedLeverSynthesis

    Raises
    ------
    InputError
        Field ``linkage.time_ratio``: K <= 1, K > :data:`MAX_TIME_RATIO`, or,
        with a rod, K >= :func:`slotting_time_ratio_limit` (the tool would
        reverse near the ends of its stroke); other fields: a length <= 0.

    Examples
    --------
    Seed 004 (pump): K = 2, H = 250 mm, O1O2 = 525 mm.

    >>> s = slotted_lever_synthesis(2.0, 250.0, 525.0)
    >>> round(float(np.degrees(s.swing)), 6), round(s.crank, 6), round(s.bar, 6)
    (60.0, 262.5, 250.0)
    """
    theta = swing_from_time_ratio(time_ratio)
    H = check_positive("linkage.stroke", stroke)
    L = check_positive("linkage.centre_distance", centre_distance)
    rr = None if rod_ratio is None else check_positive("linkage.rod_ratio", rod_ratio)
    K = float(time_ratio)
    if rr is not None:
        kmax = slotting_time_ratio_limit(rr)
        if K >= kmax and kmax <= MAX_TIME_RATIO:
            need = slotting_rod_ratio_min(K) if K <= MAX_TIME_RATIO else None
            raise InputError(
                "linkage.time_ratio",
                f"K = {K:.6g} is too large for rod_ratio = {rr:.6g}: the tool would stop and turn back near both ends "
                f"of its stroke (4 dead positions a turn); a slotting linkage with rod_ratio = {rr:.6g} allows "
                f"1 < K < {rounded_down(kmax)}"
                + ("" if need is None else f" (K = {K:.6g} needs rod_ratio > {need:.6g})"),
            )
    if K > MAX_TIME_RATIO:
        what = "slotting" if rr is not None else "slotted-lever"
        raise InputError(
            "linkage.time_ratio",
            f"K = {K:.6g} is too large: a {what} linkage allows 1 < K <= {MAX_TIME_RATIO:g} (at larger K the "
            f"return stroke takes under {360 / (MAX_TIME_RATIO + 1):.2g} deg of crank and the crank passes next to the "
            "pivot)"
            + ("" if rr is None
               else f"; with rod_ratio = {rr:.6g} also K < {rounded_down(slotting_time_ratio_limit(rr))}"),
        )
    half = theta / 2
    bar = H / (2 * np.sin(half))
    return SlottedLeverSynthesis(
        time_ratio=float(time_ratio),
        stroke=H,
        centre_distance=L,
        rod_ratio=rr,
        swing=theta,
        crank=float(L * np.sin(half)),
        bar=float(bar),
        rod=None if rr is None else float(rr * bar),
        guide_distance=float(bar * (1 + np.cos(half)) / 2),
        sagitta=float(bar * (1 - np.cos(half))),
    )


def crank_slider_crank(stroke: float, rod: float, offset: float = 0.0) -> float:
    """Crank length of a crank-slider with the given stroke (seed 002, formula 1.1).

    Parameters
    ----------
    stroke : float
        H > 0.
    rod : float
        Connecting-rod length l_AB > 0.
    offset : float, optional
        Offset e of the slider's line from the crank centre (0: central).

    Returns
    -------
    float
        r with ``sqrt((l + r)^2 - e^2) - sqrt((l - r)^2 - e^2) = H``; H/2 when e = 0.

    Raises
    ------
    InputError
        Non-positive stroke or rod, or a stroke under 1e-6 of the rod (too
        small to resolve against the rod).
    InfeasibleError
        No crank gives the stroke (the rod too short for it); the message
        states the largest stroke the rod and offset allow.

    Examples
    --------
    >>> crank_slider_crank(0.35, 1.4)
    0.175
    """
    H = check_positive("linkage.stroke", stroke)
    l = check_positive("linkage.rod", rod)
    e = abs(float(offset))
    if H < 1e-6 * l:
        raise InputError("linkage.stroke", f"{H:.6g} is too small against the rod {l:.6g} to be checked to 1e-9: "
                         f"a crank-slider is synthesized for stroke >= 1e-6 x rod = {1e-6 * l:.6g}")
    if e == 0:
        r = H / 2
        if r >= l:
            raise InfeasibleError(
                "linkage.rod", f"a rod of {l:.6g} needs a crank shorter than itself; the stroke must be < {2 * l:.6g}"
            )
        return r
    rmax = l - e  # beyond this the rod cannot reach the slider's line at every angle
    if rmax <= 0:
        raise InfeasibleError("linkage.offset", f"the offset {e:.6g} must be smaller than the rod {l:.6g}")

    def f(r):
        return np.sqrt((l + r) ** 2 - e**2) - np.sqrt(max((l - r) ** 2 - e**2, 0.0)) - H

    Hmax = f(rmax) + H
    if H >= Hmax:
        raise InfeasibleError("linkage.stroke",
                              f"rod {l:.6g} with offset {e:.6g} allows a stroke < {Hmax:.6g}, got {H:.6g}")
    from laws.search import bracketed_root

    return float(bracketed_root(f, 0.0, rmax, xtol=1e-14 * l, rtol=1e-15))
