"""A follower face's pipeline: the stages every face implements once (size, profile, checks, forces).

Each face (:mod:`cams.faces.roller`, :mod:`cams.faces.flat`) is a :class:`Face`; :func:`cams.faces.face_of` picks
it once from the design's type, and everything above calls its stages without asking which face it has. A stage a
face lacks refuses in that face's module, in one place, with one message.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import replace
from typing import TYPE_CHECKING, Any, ClassVar

import numpy as np

from laws.errors import InputError
from laws.units import turn_degrees

if TYPE_CHECKING:
    from cams.checks.base import Check
    from cams.faces.result import SolveResult
    from cams.model.options import ProfileOptions

__all__ = ["Face", "SEARCH_CHORD"]

#: :meth:`Face.profile_passes` with ``search=True`` samples a cam at a chord of this fraction of R0 when that is
#: coarser than the default (a search over many candidate cams of kilometres is not sampled at a micrometre).
SEARCH_CHORD = 1e-7


class Face(ABC):
    """The stages of one follower face's cam (one instance per face, no state).

    Lengths are in the design's unit, angles in radians. ``design`` is a :class:`cams.model.design.Design` of
    the face, ``solution`` the :class:`cams.faces.result.SolveResult` of :meth:`size`.
    """

    #: The face's label, as :attr:`cams.model.design.Design.face` (for texts, never for a branch).
    name: ClassVar[str]
    #: True when :meth:`forces` computes the ``[dynamics]`` table's forces (the reports then have ``forces``).
    forces_computed: ClassVar[bool] = False

    @abstractmethod
    def size(self, design, *, method: str | None = None, objective: str | None = None) -> SolveResult:
        """The cam of ``design``'s fixed laws, sized (or the chosen cam) and verified independently.

        Raises
        ------
        InputError
            A method or objective the face does not take, or one not among the allowed values.
        InfeasibleError
            No cam meets the limits.
        """

    @abstractmethod
    def part_checks(self, design, solution: SolveResult) -> list[Check]:
        """The checks of the cam that need no sampled profile, on exact extrema (the pressure angle or convexity,
        undercut, the least radius of curvature, the bore and its hub wall): what the sizing to the part
        (:mod:`cams.faces.part`) judges its candidates by."""

    @abstractmethod
    def radii(self, design, solution: SolveResult) -> tuple[float, float, float, float]:
        """The cam's exact smallest and largest radius and their cam angles: ``(smallest, at, largest, at)``
        (lengths, radians); the largest is the blank's radius."""

    @abstractmethod
    def bore_R0(self, design) -> float | None:
        """The least R0 whose cam can clear the bore by the hub wall (length; None without a bore): the working
        profile's smallest radius is at most its value at the near dwell, so no smaller cam can."""

    @abstractmethod
    def table(self, design, solution: SolveResult, phi: np.ndarray) -> list[tuple[str, np.ndarray]]:
        """The lift table at cam angles ``phi`` (radians from the first ``[[motion]]`` row's start): columns
        ``(name with its unit, values)``, the cam angle first (``cams profile --table``)."""

    def check_method(self, method: str | None, field: str) -> None:
        """Refuse a zone solver's ``method`` the face does not take (``field``: the key or option that gave it)."""
        return None

    def no_profile(self, design) -> str | None:
        """Why no profile of ``design`` can be built at any size (a knife edge in a groove), or None."""
        return None

    @abstractmethod
    def profile(self, design, solution: SolveResult, options: ProfileOptions) -> Any:
        """The sampled working profile of the cam at the chord tolerance of ``options`` (cam frame).

        The roller's is a :class:`cams.profile.roller.Profile`, the flat face's a
        :class:`cams.profile.flat.FlatFaceProfile`; the exports read their common attributes (``phi``, ``work``,
        ``pitch``, ``outer``, ``R0``, ``roller_radius``, ``tolerance``, ``min_work_radius``).
        """

    @abstractmethod
    def exact(self, design, solution: SolveResult) -> Any:
        """The cam's exact curves by drawing layer and its timing datum (:class:`cams.profile.exact.ExactCam`),
        cam frame: what the exports' arcs and spline are fitted to (:mod:`cams.manufacture.curves`)."""

    @abstractmethod
    def checks(self, design, solution: SolveResult, profile: Any, options: ProfileOptions) -> Any:
        """The checks of the finished profile (``profile``: :meth:`profile`'s, or None to build it); a report
        with ``checks`` (:class:`cams.checks.base.Check`), ``passed`` and ``to_dict()``."""

    def forces(self, design, solution: SolveResult) -> tuple[Any, str | None]:
        """``(DesignForces or None, note or None)``: the ``[dynamics]`` table's spring, forces and jump speed."""
        return None, None

    def contact(self, design, solution: SolveResult, forces: Any, vibration: Any = None) -> tuple[Any, str | None]:
        """``(ContactCycle or None, note or None)``: the ``[contact]`` table's stresses, film and life along the
        cycle (:mod:`cams.strength.along`) under the contact force ``[contact] force_model`` names: ``"rigid"``,
        that of ``forces`` (:meth:`forces`' DesignForces); ``"elastic"``, the follower train's dynamic one of
        ``vibration`` (:meth:`vibration`'s, at its periodic steady state; where it falls below 0 the contact is
        lost and taken as unloaded). None without ``[contact]``; None with a note without forces."""
        if design.contact is None:
            return None, None
        if forces is None:
            return None, "[contact] needs the contact force of [dynamics] (a force-closed cam and cam.rpm)"
        from cams.strength.along import contact_cycle

        f = forces.forces
        if design.contact.force_model == "elastic":
            if vibration is None:
                return None, "[contact] force_model = 'elastic' needs the follower train's response"
            return contact_cycle(design, self.contact_geometry(design, solution, vibration.phi, f.length_unit),
                                 vibration.contact, vibration.omega), None
        return contact_cycle(design, self.contact_geometry(design, solution, f.phi, f.length_unit), f.contact,
                             f.omega), None

    def contact_check(self, design, solution: SolveResult) -> Check | None:
        """The largest Hertz pressure along the cycle against ``[contact]``'s allowable (a check in MPa named
        ``contact_stress``): what the sizing to the part (:mod:`cams.faces.part`) judges a candidate's contact by.
        None without ``[contact]``, without an allowable, or without forces (no speed, form closure)."""
        if design.contact is None:
            return None
        from cams.strength.along import materials_of

        allowable = materials_of(design.contact).allowable
        if allowable is None:
            return None
        forces, _ = self.forces(design, solution)
        elastic = design.contact.force_model == "elastic" and forces is not None
        cycle, _ = self.contact(design, solution, forces, self.vibration(design, solution, forces) if elastic else None)
        if cycle is None:
            return None
        from cams.checks.base import Check

        i = cycle.at_max
        p0 = cycle.max_pressure
        return Check("contact_stress", bool(p0 <= allowable), p0, float(cycle.phi[i]), float(allowable), "MPa",
                     f"largest Hertz pressure {p0:.6g} MPa at cam angle {turn_degrees(cycle.phi[i]):.2f} deg "
                     f"against the allowable {allowable:.6g} MPa")

    def contact_geometry(self, design, solution: SolveResult, phi: np.ndarray, length_unit: float) -> Any:
        """The contact's geometry at cam angles ``phi`` (:class:`cams.strength.along.ContactGeometry`)."""
        raise InputError("contact", f"a {self.name} follower's contact stress is not computed")

    def vibration(self, design, solution: SolveResult, forces) -> Any:
        """The elastic follower train's response (:class:`cams.dynamics.vibration.Vibration`) from the forces
        stage's ``DesignForces`` (``forces``), or None without ``[dynamics] train_stiffness``."""
        from cams.dynamics.vibration import design_vibration

        return design_vibration(design, forces)

    def tradeoff(self, design) -> Any:
        """The R0-L trade-off of the cam (a rocker roller's), or None where the face has none."""
        return None

    def unbuildable(self, design, solution: SolveResult) -> list[tuple[str, str]]:
        """The face's own reasons (short, line) the cam cannot be built, before its profile's checks."""
        return []

    def not_verified(self, solution: SolveResult) -> list[str]:
        """Which of the verified side's limits the cam exceeds and by how much (one line each; [] if unsaid)."""
        return []

    def profile_passes(self, solution: SolveResult, *, search: bool = False) -> bool:
        """True when the cam of ``solution`` can be built and its profile passes every check but the verified
        side's (the pressure angle, checked by :meth:`size`): buildability without the ``[dynamics]`` checks.

        ``search``: a design without a tolerance of its own is sampled at :data:`SEARCH_CHORD` times R0 when that
        is coarser than the default (for a search; the answer is then checked without it).
        """
        from cams.checks.base import PRESSURE_CHECKS
        from cams.model.options import profile_options
        from cams.profile.roller import DEFAULT_TOLERANCE

        d = solution.design
        if search and d.tolerance is None and SEARCH_CHORD * solution.R0 > DEFAULT_TOLERANCE:
            d = replace(d, tolerance=SEARCH_CHORD * float(solution.R0))  # type: ignore[type-var]
        if self.unbuildable(d, solution):
            return False
        try:
            report = self.checks(d, solution, None, profile_options(d))
        except InputError:          # a profile the chord tolerance cannot carry
            return False
        return all(c.passed or c.name in PRESSURE_CHECKS for c in report.checks)
