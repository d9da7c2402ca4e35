"""A cam design: follower, motion program, cam, limits and solver options.

Angles are radians inside every object here; the design file (TOML) and the
command line speak degrees, and :func:`cams.io.designfile.load_design` converts.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import ClassVar

import numpy as np

from cams.model.contact import ContactSpec
from cams.model.dynamics import DynamicsSpec, check_dynamics_follower
from cams.model.follower import (
    FlatFollower,
    FlatRocker,
    FlatTranslating,
    Rocker,
    RollerFollower,
    Translating,
    check_length,
)
from cams.model.motiondesign import MotionDesignSpec
from cams.model.options import (
    ProfileOptions,
    check_constraints,
    check_hub_wall,
    check_keyway,
    check_objective,
    check_tolerance,
)
from laws.errors import InputError, check_option, show_value
from laws.program import Program

__all__ = ["Design", "Limits", "CamDesign", "FlatFaceDesign", "METHODS", "CLOSURES", "MAX_SAMPLES",
           "check_lift", "check_optimize", "OBJECTIVE_SUPERSEDED"]

METHODS = ("exact", "convex", "exhaustive")
CLOSURES = ("force", "form")

#: The most steps per phase of the sampled methods (``[solve] samples``): memory and time grow with the
#: samples (about 1 kB a sample for the convex method), and the exact method needs none.
MAX_SAMPLES = 100_000


def _degrees_shown(angle: float) -> str:
    """An angle kept in radians as the user gave it in degrees, for a message (12 significant digits: the
    round trip through radians does not show)."""
    return show_value(float(f"{float(np.degrees(angle)):.12g}"))


def check_lift(lift: float, rocker: bool) -> None:
    """Refuse a rocker's swing outside (0, 180) degrees (``lift`` in radians) or a stroke that is not > 0.

    Raises
    ------
    InputError
        On ``follower.swing`` (rocker) or ``follower.stroke`` (translating), the value in the file's unit.
    """
    if rocker:
        if not (np.isfinite(lift) and 0 < lift < np.pi):
            raise InputError("follower.swing", f"must be in (0, 180) degrees, got {_degrees_shown(lift)}")
    elif not (np.isfinite(lift) and lift > 0):
        raise InputError("follower.stroke", f"must be > 0, got {show_value(lift)}")


#: Why ``[solve] objective`` (or ``solve(objective=...)``) is refused beside ``[optimize]``.
OBJECTIVE_SUPERSEDED = "[optimize] objective supersedes it: give the objective in [optimize] only"


def check_optimize(spec: MotionDesignSpec | None, objective: str, chosen: bool) -> None:
    """Refuse an ``[optimize]`` request that contradicts the rest of the design (one line each).

    Raises
    ------
    InputError
        Not a :class:`MotionDesignSpec`; ``[solve] objective`` given besides it
        (``[optimize] objective`` supersedes it); ``objective = "R0"`` or
        ``"L"`` for a cam the designer chose (nothing to size).
    """
    if spec is None:
        return
    if not isinstance(spec, MotionDesignSpec):
        raise InputError("optimize", f"must be a MotionDesignSpec, got {type(spec).__name__}")
    if objective != "R0":
        raise InputError("solve.objective", OBJECTIVE_SUPERSEDED)
    if chosen and spec.objective in ("R0", "L"):
        raise InputError("optimize.objective", f"{spec.objective!r} sizes the cam, but the cam is chosen "
                         "([cam] base_radius or centre): choose another objective or remove the chosen cam")


class Design:
    """What every cam design has, whatever its follower's face: the base of :class:`CamDesign` (roller and knife
    edge) and :class:`FlatFaceDesign` (flat face).

    The follower's face fixes the design's type in one place (the loader, :func:`cams.io.designfile.design_from_dict`)
    and the face's pipeline (:mod:`cams.faces`) in one other (:func:`cams.faces.face_of`); nothing above reads
    :attr:`face` to branch. Each subclass is a frozen dataclass holding these attributes (lengths in the design's
    unit, angles in radians) and checks them through :meth:`_check_common`.

    Attributes
    ----------
    follower : cams.model.follower.RollerFollower or cams.model.follower.FlatFollower
    program : laws.program.Program
        Lift in radians (rocker swing) or length (translating stroke).
    cam_sense : {+1, -1}
        The cam's sense of rotation: +1 counter-clockwise.
    rpm : float or None
        Cam speed, revolutions per minute.
    name : str
    base_radius : float or None
        A chosen R0 (length): the cam is checked, not sized.
    tolerance : float or None
        Chord tolerance of the sampled profile (length); None: the default for the cam's size.
    bore_radius : float or None
        Radius of the cam's bore (length): a constraint of the sizing and a check; None: neither.
    hub_wall : float or None
        The least material between the bore and the working profile (length, >= 0; only with ``bore_radius``);
        None: the profile need only clear the bore.
    keyway_width, keyway_depth : float or None
        The bore's keyway (length): its width, and its depth measured radially from the bore's surface on the
        keyway's centre line; None: no keyway (drawn in the exports, :mod:`cams.manufacture.keyway`).
    keyway_angle : float or None
        The keyway's centre line from the timing datum, in the cam's sense of rotation (radians); None: 0.
    constraints : {"all", "pressure_angle"}
        What the sizing keeps: ``"all"`` (the smallest cam whose pressure angle is within its limits, whose working
        profile clears the bore by the wall and passes the profile's checks) or ``"pressure_angle"`` (the face's
        own limit alone: a roller's pressure angle, a flat face's convexity).
    dynamics : DynamicsSpec or None
        The follower's dynamics (a file's ``[dynamics]``); None: no forces.
    optimize : MotionDesignSpec or None
        Design the free phases' laws with the cam (a file's ``[optimize]``); None: the laws are as given.
    width : float or None
        The cam's face width (length, > 0; ``[cam] width``): the contact's length for its stress.
    contact : ContactSpec or None
        The contact's materials, lubricant and bearing (a file's ``[contact]``); None: no contact stress.
    """

    #: The follower's face: ``"roller"`` (a knife edge is a roller of radius 0) or ``"flat"``; a label for texts
    #: and reports, never a branch (the face's pipeline, :mod:`cams.faces`, holds what differs).
    face: ClassVar[str]
    #: What the sizing minimizes (a roller design's ``[solve] objective``; a flat face's cam is sized by R0).
    objective: str = "R0"

    follower: RollerFollower | FlatFollower
    program: Program
    cam_sense: int
    rpm: float | None
    name: str
    base_radius: float | None
    tolerance: float | None
    bore_radius: float | None
    hub_wall: float | None
    constraints: str
    dynamics: DynamicsSpec | None
    optimize: MotionDesignSpec | None
    width: float | None
    contact: ContactSpec | None
    keyway_width: float | None
    keyway_depth: float | None
    keyway_angle: float | None

    def _check_common(self) -> None:
        """Refuse the common fields' bad values (one line each, named as in the design file)."""
        if self.width is not None:
            check_length("cam.width", self.width)
        if self.contact is not None:
            if not isinstance(self.contact, ContactSpec):
                raise InputError("contact", f"must be a ContactSpec, got {type(self.contact).__name__}")
            if self.width is None:
                raise InputError("cam.width", "the contact stress needs the cam's face width: give cam.width (mm)")
            train = self.dynamics is not None and self.dynamics.dynamics.train_stiffness is not None
            if self.contact.force_model == "elastic" and not train:
                raise InputError("contact.force_model", "'elastic' takes the follower train's dynamic contact force: "
                                 "give [dynamics] train_stiffness, or force_model = 'rigid'")
        if self.cam_sense not in (1, -1):
            raise InputError("cam.rotation", "must be 'cw' or 'ccw'")
        if self.rpm is not None and not (np.isfinite(self.rpm) and self.rpm > 0):
            raise InputError("cam.rpm", f"must be > 0, got {self.rpm!r}")
        if self.rpm is None and self.dynamics is not None and self.dynamics.dynamics.train_stiffness is not None:
            raise InputError("cam.rpm", "is missing: [dynamics] train_stiffness (the follower train's vibration) "
                             "needs the cam's speed; give cam.rpm (rev/min)")
        check_constraints(self.constraints)

    def _check_keyway(self) -> None:
        """Refuse a bad keyway (after the bore's own checks)."""
        check_keyway(self.keyway_width, self.keyway_depth, self.keyway_angle, self.bore_radius)

    @property
    def scale(self) -> float:
        """Characteristic length for relative tolerances (the follower's: arm, stroke or centre distance)."""
        return self.follower.scale

    @property
    def chosen(self) -> bool:
        """True when the designer chose the cam (``base_radius``, or a roller's ``centre``): checked, not sized."""
        return self.base_radius is not None

    def with_(self, **changes):
        """A copy with some fields changed (the same type)."""
        return replace(self, **changes)  # type: ignore[type-var]

    def with_floor(self, R0: float | None):
        """A copy whose sizing is floored at base radius ``R0`` (length): ``limits.min_base_radius``; None: no
        floor."""
        raise NotImplementedError

    def unchosen(self):
        """A copy without the chosen cam (``[cam] base_radius``, a roller's ``centre``): sized, not checked. What
        fixed the chosen cam's centre stays (a rocker's ``limits.centre_distance``, ``follower.offset``)."""
        raise NotImplementedError


@dataclass(frozen=True)
class Limits:
    """Pressure-angle limits and sizing constraints.

    Parameters
    ----------
    pressure_angle : float
        Allowable pressure angle on the rise, radians in (0, pi/2).
    return_pressure_angle : float or None
        Allowable on the return (form closure), radians; ``None``: as the rise.
    closure : {"force", "form"}
        Force closure limits the rise only; form closure rise and return.
    safety_factor : float
        K_C >= 1 of seed formula 3.26 (rocker followers).
    centre_distance : float or None
        Fixed centre distance L (rocker), length unit.
    min_base_radius : float or None
        Constructive floor on R0, length unit.
    """

    pressure_angle: float
    return_pressure_angle: float | None = None
    closure: str = "force"
    safety_factor: float = 1.0
    centre_distance: float | None = None
    min_base_radius: float | None = None

    def __post_init__(self):
        for name in ("pressure_angle", "return_pressure_angle"):
            v = getattr(self, name)
            if v is None:
                continue
            if not (np.isfinite(v) and 0 < v < np.pi / 2):
                raise InputError(f"limits.{name}", f"must be in (0, 90) degrees, got {_degrees_shown(v)}")
        check_option("limits.closure", self.closure, CLOSURES)
        if self.closure == "force" and self.return_pressure_angle is not None:
            raise InputError("limits.return_pressure_angle", 'applies to form closure (closure = "form"); under force '
                             "closure the spring drives the return and its pressure angle is not limited: remove it")
        if not (np.isfinite(self.safety_factor) and self.safety_factor >= 1):
            raise InputError("limits.safety_factor", f"K_C must be >= 1, got {self.safety_factor!r}")
        for name in ("centre_distance", "min_base_radius"):
            v = getattr(self, name)
            if v is not None and not (np.isfinite(v) and v > 0):
                raise InputError(f"limits.{name}", f"must be > 0, got {v!r}")

    @property
    def return_limit(self) -> float:
        """Allowable pressure angle on the return, radians."""
        return self.pressure_angle if self.return_pressure_angle is None else self.return_pressure_angle


@dataclass(frozen=True)
class CamDesign(Design):
    """Everything that defines a cam-sizing problem.

    Parameters
    ----------
    follower : Rocker or Translating
    program : Program
        Lift in radians (rocker swing) or length (translating stroke).
    limits : Limits
    cam_sense : {+1, -1}
        Cam's sense of rotation: +1 counter-clockwise (seen in the frame of
        :mod:`cams.model.follower`).
    rpm : float or None
        Cam speed, revolutions per minute.
    name : str
    method : {"exact", "convex", "exhaustive"}
    samples : int
        Steps per phase for the sampled methods (N + 1 positions per phase).
    base_radius : float or None
        A chosen R0 (length): the cam is checked, not sized. Its centre is
        fixed with ``limits.centre_distance`` (rocker) or ``follower.offset``
        (translating); see :meth:`chosen_centres`.
    centre : (float, float) or None
        A chosen cam centre in the follower's fixed frame (length,
        :mod:`cams.model.follower`): the cam is checked, not sized.
    objective : {"R0", "L"}
        What the sizing minimizes when ``limits.centre_distance`` is free:
        the base radius, or the centre distance (rocker only).
    tolerance : float or None
        Chord tolerance of the sampled profile (length); None: the default
        for the cam's size (:func:`cams.profile.roller.cap_tolerance`).
    min_curvature_radius : float or None
        Smallest radius of curvature the working profile may have (length);
        None: not checked.
    bore_radius : float or None
        Radius of the cam's bore (length): the sizing makes the working
        profile clear it (by ``hub_wall``) and the checks check it; None:
        neither.
    hub_wall : float or None
        The least material between the bore and the working profile
        (length, >= 0; only with ``bore_radius``); None: 0.
    keyway_width, keyway_depth, keyway_angle : float or None
        The bore's keyway: width and depth (length; the depth from the bore's
        surface on the keyway's centre line) and the centre line's angle from
        the timing datum in the cam's sense of rotation (radians); None: no
        keyway (the angle: 0).
    constraints : {"all", "pressure_angle"}
        ``"all"``: the smallest cam that meets the pressure angle, the bore
        and the profile's checks (:mod:`cams.faces.part`);
        ``"pressure_angle"``: the pressure angle alone.
    dynamics : DynamicsSpec or None
        The follower's dynamics (a file's ``[dynamics]``): forces, spring and
        jump speed of a force-closed cam; None: no forces.
    optimize : MotionDesignSpec or None
        Design the free phases' laws with the cam (a file's ``[optimize]``,
        :mod:`cams.motion_design`); None: the laws are as given.
    """

    follower: RollerFollower
    program: Program
    limits: Limits
    cam_sense: int = 1
    rpm: float | None = None
    name: str = "cam"
    method: str = "exact"
    samples: int = 360
    base_radius: float | None = None
    centre: tuple[float, float] | None = None
    objective: str = "R0"
    tolerance: float | None = None
    min_curvature_radius: float | None = None
    bore_radius: float | None = None
    hub_wall: float | None = None
    constraints: str = "all"
    dynamics: DynamicsSpec | None = None
    optimize: MotionDesignSpec | None = None
    width: float | None = None
    contact: ContactSpec | None = None
    keyway_width: float | None = None
    keyway_depth: float | None = None
    keyway_angle: float | None = None

    def __post_init__(self) -> None:
        # in the order a design file's tables are read, so that a file with two faults names the same one
        if isinstance(self.samples, bool) or not isinstance(self.samples, (int, np.integer)) \
                or not 2 <= self.samples <= MAX_SAMPLES:
            raise InputError("solve.samples", f"must be an integer from 2 to {MAX_SAMPLES}, got "
                             f"{show_value(self.samples)}")
        check_objective(self.objective, isinstance(self.follower, Rocker))
        if self.dynamics is not None:
            if not isinstance(self.dynamics, DynamicsSpec):
                raise InputError("dynamics", f"must be a DynamicsSpec, got {type(self.dynamics).__name__}")
            check_dynamics_follower(self.dynamics, isinstance(self.follower, Rocker))
        if self.cam_sense not in (1, -1):
            raise InputError("cam.rotation", "must be 'cw' or 'ccw'")
        check_option("solve.method", self.method, METHODS)
        self._check_chosen()
        self._check_common()
        check_lift(self.program.lift, isinstance(self.follower, Rocker))
        if isinstance(self.follower, Translating):
            if self.limits.safety_factor != 1.0:
                raise InputError(
                    "limits.safety_factor",
                    "K_C (seed formula 3.26) is defined for rocker followers; "
                    "for a translating follower lower limits.pressure_angle instead",
                )
            if self.limits.centre_distance is not None:
                raise InputError("limits.centre_distance", "applies to rocker followers only; use follower.offset")
        elif not isinstance(self.follower, Rocker):  # pragma: no cover - guarded by the type
            raise InputError("follower.kind", "must be 'rocker' or 'translating'")
        ProfileOptions(self.tolerance, self.min_curvature_radius, self.bore_radius,  # checks the four
                       hub_wall=self.hub_wall)
        self._check_keyway()
        check_optimize(self.optimize, self.objective, self.chosen)

    @property
    def chosen(self) -> bool:
        """True when the designer chose the cam (``base_radius`` or ``centre``): it is checked, not sized."""
        return self.base_radius is not None or self.centre is not None

    def _check_chosen(self) -> None:
        """Refuse chosen-cam keys that are incomplete, contradictory or admit no centre (one line each)."""
        if not self.chosen:
            return
        f, lim = self.follower, self.limits
        rocker = isinstance(f, Rocker)
        key = "cam.centre" if self.centre is not None else "cam.base_radius"
        if self.base_radius is not None and self.centre is not None:
            raise InputError("cam.centre", "give either cam.centre or cam.base_radius (with "
                             f"{'limits.centre_distance' if rocker else 'follower.offset'}), not both")
        if lim.min_base_radius is not None:
            raise InputError(key, "fixes the cam: a floor on R0 (limits.min_base_radius) has nothing to size; "
                             "remove one of them")
        if self.objective != "R0":
            raise InputError("solve.objective", f"nothing is minimized for a cam chosen by {key}; remove it")
        if self.centre is not None:
            c = self.centre
            if len(c) != 2 or not all(isinstance(v, (int, float, np.floating)) and not isinstance(v, bool)
                                      and np.isfinite(v) for v in c):
                raise InputError("cam.centre", f"must be two numbers [x, y] (mm), got {list(c)!r}")
            if rocker and lim.centre_distance is not None:
                raise InputError("cam.centre", "fixes L already: remove limits.centre_distance")
            if isinstance(f, Translating) and f.offset is not None:
                raise InputError("cam.centre", "fixes the offset already (e = -x): remove follower.offset")
            cv = np.asarray(c, float)
            # refuses only a centre within rounding of A0 (R0 = 0) or of the pivot; any other is judged by the checks
            if np.linalg.norm(cv - f.position(0.0)) <= 1e-12 * self.scale:
                raise InputError("cam.centre", "is the roller centre at the near dwell (R0 = 0); the cam centre "
                                 "must lie away from it")
            if rocker and np.linalg.norm(cv) <= 1e-12 * self.scale:
                raise InputError("cam.centre", "is the rocker's pivot (L = 0)")
            return
        R0 = self.base_radius
        if isinstance(R0, bool) or not isinstance(R0, (int, float, np.floating)) or not (np.isfinite(R0) and R0 > 0):
            raise InputError("cam.base_radius", f"must be a number > 0 (mm), got {R0!r}")
        if isinstance(f, Rocker):
            L = lim.centre_distance
            if L is None:
                raise InputError("cam.base_radius", "a rocker's cam centre needs limits.centre_distance (L) too, "
                                 "or give cam.centre = [x, y] instead")
            lo, hi = abs(L - f.arm), L + f.arm
            if not lo * (1 - 1e-12) <= R0 <= hi * (1 + 1e-12):
                raise InputError("cam.base_radius", f"R0 = {R0:g} mm admits no cam centre at L = {L:g} mm with "
                                 f"arm {f.arm:g} mm: R0 must lie in [{lo:g}, {hi:g}] mm (|L - arm| to L + arm)")
        else:
            if f.offset is None:
                raise InputError("cam.base_radius", "a translating follower's cam centre needs follower.offset too "
                                 "(0 for a centric follower), or give cam.centre = [x, y] instead")
            if not R0 > abs(f.offset):
                raise InputError("cam.base_radius", f"R0 = {R0:g} mm must be larger than |follower.offset| = "
                                 f"{abs(f.offset):g} mm (the cam centre lies on the follower's axis offset by e)")

    def chosen_centres(self) -> tuple[np.ndarray, ...]:
        """The cam centres the chosen keys admit, in the follower's fixed frame (length).

        Returns
        -------
        tuple of ndarray, shape (2,)
            ``(centre,)`` for ``cam.centre``; for ``base_radius`` the points at
            distance R0 from the roller centre A0 at the near dwell and at
            distance L from the pivot (rocker: two centres mirrored about the
            line pivot-A0, one where the circles touch), or on the follower's
            axis offset by ``e`` (translating: ``x = -e``, ``y = -sqrt(R0^2 -
            e^2)``, the centre on the -Y side of the roller, which the rise
            carries away from it: on the +Y side the cam would have to pull
            the follower up); empty when not chosen.
        """
        if self.centre is not None:
            return (np.asarray(self.centre, float),)
        if self.base_radius is None:
            return ()
        f, R0 = self.follower, float(self.base_radius)
        A0 = f.position(0.0)
        if isinstance(f, Rocker):
            # crossings of |O - pivot| = L and |O - A0| = R0 (pivot at the origin, A0 on +X)
            Lc = self.limits.centre_distance
            assert Lc is not None  # refused at construction: a rocker's chosen R0 needs L (_check_chosen)
            L, d = float(Lc), float(np.linalg.norm(A0))
            a = (L**2 - R0**2 + d**2) / (2 * d)
            h = np.sqrt(max(L**2 - a**2, 0.0))
            u = A0 / d
            v = np.array([-u[1], u[0]])
            base = a * u
        else:
            assert f.offset is not None  # refused at construction: a chosen R0 needs the offset (_check_chosen)
            e = float(f.offset)
            return (np.array([-e, -np.sqrt(R0**2 - e**2)]) + A0,)
        # only merges the two crossings of tangent circles; both candidates are on both circles and judged anyway
        if h <= 1e-12 * self.scale:
            return (base,)
        return (base + h * v, base - h * v)

    def constrained_phases(self) -> list[tuple[int, float]]:
        """Indices of the phases whose pressure angle is limited, with their limits (rad)."""
        out = []
        for i, p in enumerate(self.program.phases):
            if p.kind == "rise":
                out.append((i, self.limits.pressure_angle))
            elif p.kind == "return" and self.limits.closure == "form":
                out.append((i, self.limits.return_limit))
        return out

    face = "roller"

    def with_floor(self, R0: float | None) -> CamDesign:
        """A copy sized with the floor ``limits.min_base_radius = R0`` (length; None: no floor)."""
        return replace(self, limits=replace(self.limits, min_base_radius=R0))

    def unchosen(self) -> CamDesign:
        """A copy without ``base_radius`` and ``centre`` (L or the offset that fixed the chosen centre kept)."""
        return replace(self, base_radius=None, centre=None)


@dataclass(frozen=True)
class FlatFaceDesign(Design):
    """A cam for a flat-faced follower: sized by convexity, not by a pressure-angle limit.

    The pressure angle of a flat face is fixed by the geometry (zero for a
    translating face and for a rocker face through its pivot); the base
    radius is the smallest one whose profile keeps its radius of curvature at
    least ``min_radius`` everywhere (see :mod:`optimize.flat`).

    Parameters
    ----------
    follower : cams.model.follower.FlatTranslating or cams.model.follower.FlatRocker
    program : Program
        Lift in radians (rocker swing) or length (translating stroke).
    min_radius : float
        Smallest allowed radius of curvature of the cam profile, length, > 0.
    cam_sense : {+1, -1}
    rpm : float or None
    name : str
    min_base_radius : float or None
        Constructive floor on R0 (length).
    base_radius : float or None
        A chosen R0 (length) instead of the smallest: checked, not sized.
    bore_radius : float or None
        Bore radius (length): a constraint of the sizing and a check.
    hub_wall : float or None
        The least material between the bore and the profile (length, >= 0; only with ``bore_radius``).
    keyway_width, keyway_depth, keyway_angle : float or None
        The bore's keyway, as :class:`CamDesign`'s (the datum: the face's contact normal at cam angle 0).
    constraints : {"all", "pressure_angle"}
        ``"all"``: the smallest cam convex enough whose profile clears the bore by the wall;
        ``"pressure_angle"``: convexity alone (a flat face's own limit; its pressure angle does not size it).
    tolerance : float or None
        Chord tolerance of the sampled profile (length); None: the default
        for the cam's size (:func:`cams.profile.roller.cap_tolerance`).
    optimize : MotionDesignSpec or None
        Design the free phases' laws with the cam (a file's ``[optimize]``).
    dynamics : DynamicsSpec or None
        The follower's dynamics (a file's ``[dynamics]``): spring, contact force, camshaft torque (with the face's
        sliding friction, ``face_friction``) and jump speed of the force-closed follower
        (:mod:`cams.dynamics.flat_forces`); None: no forces. A translating face takes no ``journal_radius``.
    """

    follower: FlatFollower
    program: Program
    min_radius: float
    cam_sense: int = 1
    rpm: float | None = None
    name: str = "cam"
    min_base_radius: float | None = None
    base_radius: float | None = None
    bore_radius: float | None = None
    tolerance: float | None = None
    optimize: MotionDesignSpec | None = None
    dynamics: DynamicsSpec | None = None
    hub_wall: float | None = None
    constraints: str = "all"
    width: float | None = None
    contact: ContactSpec | None = None
    keyway_width: float | None = None
    keyway_depth: float | None = None
    keyway_angle: float | None = None

    face = "flat"

    def __post_init__(self):
        self._check_common()
        if not isinstance(self.follower, (FlatTranslating, FlatRocker)):
            raise InputError("follower", "must be a FlatTranslating or FlatRocker follower")
        check_lift(self.program.lift, isinstance(self.follower, FlatRocker))
        for name, fld in (("min_radius", "limits.min_radius"), ("min_base_radius", "limits.min_base_radius"),
                          ("base_radius", "cam.base_radius"), ("bore_radius", "cam.bore_radius")):
            if getattr(self, name) is not None or name == "min_radius":
                check_length(fld, getattr(self, name))
        check_hub_wall(self.hub_wall, self.bore_radius)
        self._check_keyway()
        if self.tolerance is not None:
            check_tolerance(self.tolerance, "profile.tolerance")
        if self.base_radius is not None and self.min_base_radius is not None:  # as for a roller follower
            raise InputError("cam.base_radius", "fixes the cam: a floor on R0 (limits.min_base_radius) has nothing "
                             "to size; remove one of them")
        check_optimize(self.optimize, "R0", self.base_radius is not None)
        if self.dynamics is not None:
            if not isinstance(self.dynamics, DynamicsSpec):
                raise InputError("dynamics", f"must be a DynamicsSpec, got {type(self.dynamics).__name__}")
            check_dynamics_follower(self.dynamics, isinstance(self.follower, FlatRocker), flat=True)

    def with_floor(self, R0: float | None) -> FlatFaceDesign:
        """A copy sized with the floor ``min_base_radius = R0`` (length; None: no floor)."""
        return replace(self, min_base_radius=R0)

    def unchosen(self) -> FlatFaceDesign:
        """A copy without ``base_radius``: sized, not checked."""
        return replace(self, base_radius=None)
