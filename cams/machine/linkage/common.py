"""What the seeds' machines share: their topology's types, the base class, the checks, :func:`describe_angles`.

The machines themselves: :mod:`cams.machine.linkage.machines`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from cams.machine.linkage.analysis import analyse
from cams.machine.linkage.primitives import Angle, AssemblyError, Slide
from cams.model.follower import rotation_word
from laws.errors import InfeasibleError, InputError, check_number
from laws.errors import show_value as _show
from laws.units import TWO_PI, rpm_to_omega

__all__ = ["Pair", "LinkStates", "describe_angles", "LinkageBase", "SwingingLever", "still", "check_sign",
           "verify_course", "swing_bar_checks"]

_CHECK_GRID = np.linspace(0.0, TWO_PI, 1440, endpoint=False)


def describe_angles(phi: np.ndarray, mask: np.ndarray, *, periodic: bool = False) -> str:
    """Contiguous runs of ``phi[mask]`` as text in degrees, e.g. ``"10.0-35.5 deg"``.

    Parameters
    ----------
    phi : ndarray
        Crank angles, radians, increasing.
    mask : ndarray of bool
        Selected entries.
    periodic : bool, optional
        ``phi`` covers one turn: a run touching both ends is one run across 0.

    Examples
    --------
    >>> describe_angles(np.radians([0, 10, 20, 30, 40]), np.array([0, 1, 1, 0, 1], bool))
    '10.0-20.0, 40.0 deg'
    >>> describe_angles(np.radians([0, 90, 180, 270]), np.array([1, 0, 0, 1], bool), periodic=True)
    '270.0-0.0 deg'
    """
    deg = np.degrees(np.ravel(phi))
    mask = np.ravel(np.broadcast_to(mask, np.shape(deg))).astype(bool)
    runs, start = [], None
    for k, m in enumerate(mask):
        if m and start is None:
            start = k
        if (not m or k == len(mask) - 1) and start is not None:
            runs.append([start, k if m else k - 1])
            start = None
    if periodic and len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == len(mask) - 1:
        runs[0][0] = runs.pop()[0]
    text = [f"{deg[a]:.1f}" if a == b else f"{deg[a]:.1f}-{deg[b]:.1f}" for a, b in runs]
    return ", ".join(text) + " deg"


def check_sign(field_: str, v, words=("+1", "-1")) -> None:
    """Refuse a sign ``v`` other than +1 or -1, naming ``field_`` and the two values in ``words``."""
    if v not in (1, -1):
        raise InputError(field_, f"must be +1 or -1 ({words[0]} or {words[1]}), got {_show(v)}")


@dataclass(frozen=True)
class Pair:
    """A lower pair of a machine's topology.

    Attributes
    ----------
    name : str
        The seed's name of the pair (``"O2"``, ``"A_slot"``...).
    kind : {"revolute", "prismatic"}
    first : str
        The link the pair's reaction acts on (a prismatic pair: the link that slides).
    second : str or None
        The other link (a prismatic pair: the one that carries the guide); None for ground.
    """

    name: str
    kind: str
    first: str
    second: str | None = None


@dataclass(frozen=True, eq=False)
class LinkStates:
    """The moving links' motion at crank angles, for the forces (machine length unit, frame of the machine).

    Attributes
    ----------
    cg : dict of str to Point
        The centre of mass of each moving link.
    angle : dict of str to Angle
        The angle of each moving link (a sliding block turns with its guide; a slider: zero).
    point : dict of str to ndarray (complex)
        Each pair's point: the revolute's centre, the prismatic guide's reference point.
    axis : dict of str to ndarray (complex)
        Each prismatic pair's guide direction (unit, fixed in the pair's second link).
    """

    cg: dict
    angle: dict
    point: dict
    axis: dict


def still(phi: np.ndarray) -> Angle:
    """The angle of a link that does not turn (a slider), zero at every crank angle."""
    z = np.zeros_like(phi)
    return Angle(z, z.copy(), z.copy())


class LinkageBase:
    """Shared plumbing: crank speed, error context, checks, the output protocol, the topology.

    Each machine declares its own topology for the forces: its moving links
    (``links``, the seeds' numbering 1..n), its lower pairs (``pairs``) and
    :meth:`link_states`; a link that slides on a guide (the first link of a
    prismatic pair, :meth:`guided`) has its centre of mass at its pin.
    """

    #: The moving links, in the seed's order (link 1 is the crank).
    links: tuple[str, ...] = ()
    #: The lower pairs.
    pairs: tuple[Pair, ...] = ()

    crank_sense: int
    rpm: float | None
    kind: str
    #: Name of the working member's :class:`Slide` among the kinematics' fields.
    _output: str

    @classmethod
    def guided(cls) -> tuple[str, ...]:
        """Links that slide on a guide (the first link of a prismatic pair): the bodies a load can act on.

        Their centre of mass is their pin: it moves with the pin, so a ``cg`` does not apply to them.
        """
        return tuple(dict.fromkeys(p.first for p in cls.pairs if p.kind == "prismatic"))

    @classmethod
    def pair_kind(cls, name: str) -> str:
        """``"revolute"`` or ``"prismatic"``: the kind of the pair ``name``."""
        return next(p.kind for p in cls.pairs if p.name == name)

    def link_states(self, phi: np.ndarray, omega: float, cg) -> LinkStates:  # pragma: no cover - each machine's own
        """Motion of the moving links' centres of mass and of the pairs at crank angles ``phi`` (radians).

        ``omega``: the crank's speed, rad/s (signed). ``cg(name, default)``: the
        distance of a turning link's centre of mass from its first joint along
        the link (machine length unit), ``default`` when the forces give none.
        """
        raise NotImplementedError

    def kinematics(self, phi: np.ndarray, *, omega: float | None = None) -> Any:  # pragma: no cover - each machine
        """Every point and link at crank angles ``phi`` (radians); each machine returns its own record."""
        raise NotImplementedError

    def lengths(self) -> dict:  # pragma: no cover - each machine has its own
        """JSON-ready: the type, the lengths (the machine's unit), the crank's rotation and speed."""
        raise NotImplementedError

    def _check_common(self) -> None:
        check_sign("linkage.crank_rotation", self.crank_sense, ("ccw", "cw"))
        if self.rpm is not None:
            check_number("linkage.rpm", self.rpm, lo=0.0, strict=True)

    @property
    def omega(self) -> float:
        """Crank angular velocity, rad/s, signed; ``crank_sense`` when no rpm is set."""
        if self.rpm is None:
            return float(self.crank_sense)
        return float(self.crank_sense * rpm_to_omega(self.rpm))

    def _w(self, omega: float | None) -> float:
        return self.omega if omega is None else float(omega)

    def _assembled(self, fn, phi):
        """Run ``fn(phi)``; re-raise an :class:`AssemblyError` with the crank angles where it fails."""
        try:
            return fn(phi)
        except AssemblyError as e:
            periodic = phi is _CHECK_GRID
            where = describe_angles(phi, e.mask, periodic=periodic) if e.mask is not None else "some positions"
            raise AssemblyError(e.field, f"{e.message}; fails at crank angles {where}", e.mask) from None

    def _check_assembly(self) -> None:
        self._assembled(lambda p: self.kinematics(p, omega=1.0), _CHECK_GRID)

    def output(self, phi, omega: float = 1.0) -> Slide:
        """The working member's coordinate along its path and its derivatives (see each machine's frame)."""
        return getattr(self.kinematics(phi, omega=omega), self._output)

    def transmission(self, phi) -> np.ndarray:
        """Transmission angle at crank angles ``phi``, radians (the kinematics' ``transmission``)."""
        return self.kinematics(phi, omega=1.0).transmission

    def _lengths(self, **dims) -> dict:
        """``lengths()``: the type, the machine's ``dims`` under the seed's names, its crank's sense and speed."""
        return {
            "type": self.kind,
            **dims,
            "crank_rotation": rotation_word(self.crank_sense),
            "rpm": self.rpm,
        }


def verify_course(machine, *, stroke: float, time_ratio: float | None = None, allowed: str = "") -> None:
    """Check a synthesized linkage against its course data: its own stroke and time ratio to 1e-9 (relative).

    Raises
    ------
    InputError
        On ``linkage.time_ratio`` (or ``linkage.stroke``) when the linkage's
        motion does not have the asked stroke or time ratio; ``allowed`` (the
        allowed range) is appended to the message.
    """
    tail = f"; {allowed}" if allowed else ""
    field_ = "linkage.stroke" if time_ratio is None else "linkage.time_ratio"
    try:
        rep = analyse(machine, working="slow")
    except InfeasibleError as e:
        if isinstance(e, AssemblyError):
            raise
        raise InputError(field_, f"the synthesized linkage does not move as asked "
                                 f"({str(e).split(': ', 1)[-1]}){tail}") from None
    if time_ratio is not None and not abs(rep.time_ratio - time_ratio) <= 1e-9 * time_ratio:
        raise InputError(
            "linkage.time_ratio",
            f"the synthesized linkage has K = {rep.time_ratio:.10g} and stroke {rep.stroke:.10g}, not the asked "
            f"K = {time_ratio:.10g} and stroke {stroke:.10g}{tail}",
        )
    if not abs(rep.stroke - stroke) <= 1e-9 * stroke:
        raise InputError(
            field_,
            f"the synthesized linkage has a stroke of {rep.stroke:.10g}, not the asked {stroke:.10g}{tail}",
        )


class SwingingLever(LinkageBase):
    """A crank driving a slotted bar or lever that swings about a pivot at ``(-centre_distance, 0)``."""

    crank: float
    centre_distance: float

    @property
    def half_swing(self) -> float:
        """Half the bar's (lever's) swing, theta/2 = asin(l_crank / L), radians."""
        return float(np.arcsin(self.crank / self.centre_distance))

    def dead_position_hints(self) -> np.ndarray:
        """Frame crank angles of the bar's extreme positions (the crank perpendicular to the bar), radians.

        ``cos phi = -l_crank / L``: ``pi/2 + theta/2`` and ``3 pi/2 - theta/2``;
        :func:`cams.machine.linkage.analysis.dead_positions` brackets them exactly.
        """
        h = self.half_swing
        return np.array([np.pi / 2 + h, 1.5 * np.pi - h])


def swing_bar_checks(crank_: float, L: float, bar: float, side: int, name: str, field_: str) -> None:
    """Refuse a swinging bar's lengths that admit no full crank turn (mm; one line naming ``field_``)."""
    if crank_ >= L:
        raise InputError(
            "linkage.crank",
            f"l = {crank_:.6g} must be shorter than the centre distance {L:.6g} for a swinging {name} "
            "(a longer crank makes the bar rotate fully)",
        )
    if side == 1 and (L - crank_) <= bar <= (L + crank_):
        raise InputError(
            field_,
            f"with the pin on the crank's side of the pivot, {bar:.6g} lies inside the block's travel "
            f"[{L - crank_:.6g}, {L + crank_:.6g}] along the {name}; use the opposite side or a length "
            f"< {L - crank_:.6g} or > {L + crank_:.6g}",
        )
