"""A cam design: follower, motion program, cam, limits and solver options.

Angles are radians inside every object here; the design file (TOML) and the
command line speak degrees, and :func:`cams.designfile.load_design` converts.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from cams.follower import Follower, Rocker, Translating
from laws.errors import InputError, check_option, show_value
from laws.program import Program

__all__ = ["Limits", "CamDesign", "FlatFaceDesign", "METHODS", "CLOSURES"]

METHODS = ("exact", "convex", "exhaustive")
CLOSURES = ("force", "form")


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
                raise InputError(f"limits.{name}", f"must be in (0, 90) degrees, got {show_value(np.degrees(v))}")
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
class CamDesign:
    """Everything that defines a cam-sizing problem.

    Parameters
    ----------
    follower : Rocker or Translating
    program : Program
        Lift in radians (rocker swing) or length (translating stroke).
    limits : Limits
    cam_sense : {+1, -1}
        Cam's sense of rotation: +1 counter-clockwise (seen in the frame of
        :mod:`cams.follower`).
    rpm : float or None
        Cam speed, revolutions per minute.
    name : str
    method : {"exact", "convex", "exhaustive"}
    samples : int
        Steps per phase for the sampled methods (N + 1 positions per phase).
    """

    follower: Follower
    program: Program
    limits: Limits
    cam_sense: int = 1
    rpm: float | None = None
    name: str = "cam"
    method: str = "exact"
    samples: int = 360
    extra: dict = field(default_factory=dict, compare=False, hash=False)

    def __post_init__(self):
        if self.cam_sense not in (1, -1):
            raise InputError("cam.rotation", "must be 'cw' or 'ccw'")
        check_option("solve.method", self.method, METHODS)
        if not (isinstance(self.samples, (int, np.integer)) and self.samples >= 2):
            raise InputError("solve.samples", f"must be an integer >= 2, got {self.samples!r}")
        if self.rpm is not None and not (np.isfinite(self.rpm) and self.rpm > 0):
            raise InputError("cam.rpm", f"must be > 0, got {self.rpm!r}")
        if isinstance(self.follower, Rocker):
            if not self.program.lift < np.pi:
                raise InputError("follower.swing", "must be < 180 degrees")
        elif isinstance(self.follower, Translating):
            if self.limits.safety_factor != 1.0:
                raise InputError(
                    "limits.safety_factor",
                    "K_C (seed formula 3.26) is defined for rocker followers; "
                    "for a translating follower lower limits.pressure_angle instead",
                )
            if self.limits.centre_distance is not None:
                raise InputError("limits.centre_distance", "applies to rocker followers only; use follower.offset")
        else:  # pragma: no cover - guarded by the type
            raise InputError("follower.kind", "must be 'rocker' or 'translating'")

    @property
    def scale(self) -> float:
        """Characteristic length for relative tolerances (arm or stroke)."""
        return self.follower.scale

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

    def with_(self, **changes) -> "CamDesign":
        """A copy with some fields changed."""
        from dataclasses import replace

        return replace(self, **changes)


@dataclass(frozen=True)
class FlatFaceDesign:
    """A cam for a flat-faced follower: sized by convexity, not by a pressure-angle limit.

    The pressure angle of a flat face is fixed by the geometry (zero for a
    translating face and for a rocker face through its pivot); the base
    radius is the smallest one whose profile keeps its radius of curvature at
    least ``min_radius`` everywhere (see :mod:`cams.flatface`).

    Parameters
    ----------
    follower : cams.flatface.FlatTranslating or cams.flatface.FlatRocker
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
        Bore radius (length) to check the profile against.
    tolerance : float
        Chord tolerance of the sampled profile (length).
    """

    follower: object
    program: Program
    min_radius: float
    cam_sense: int = 1
    rpm: float | None = None
    name: str = "cam"
    min_base_radius: float | None = None
    base_radius: float | None = None
    bore_radius: float | None = None
    tolerance: float = 1e-3
    extra: dict = field(default_factory=dict, compare=False, hash=False)

    face = "flat"

    def __post_init__(self):
        from cams.flatface import FlatRocker, FlatTranslating

        if self.cam_sense not in (1, -1):
            raise InputError("cam.rotation", "must be 'cw' or 'ccw'")
        if self.rpm is not None and not (np.isfinite(self.rpm) and self.rpm > 0):
            raise InputError("cam.rpm", f"must be > 0, got {self.rpm!r}")
        if not isinstance(self.follower, (FlatTranslating, FlatRocker)):
            raise InputError("follower", "must be a FlatTranslating or FlatRocker follower")
        if isinstance(self.follower, FlatRocker) and not self.program.lift < np.pi:
            raise InputError("follower.swing", "must be < 180 degrees")
        for name, fld in (("min_radius", "limits.min_radius"), ("min_base_radius", "limits.min_base_radius"),
                          ("base_radius", "cam.base_radius"), ("bore_radius", "cam.bore_radius"),
                          ("tolerance", "profile.tolerance")):
            v = getattr(self, name)
            if v is None and name not in ("min_radius", "tolerance"):
                continue
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not (np.isfinite(v) and v > 0):
                raise InputError(fld, f"must be a number > 0, got {v!r}")
        floor = self.min_base_radius
        if self.base_radius is not None and floor is not None and self.base_radius < floor:
            raise InputError("cam.base_radius", f"{self.base_radius:g} is below limits.min_base_radius = "
                             f"{self.min_base_radius:g}")

    @property
    def scale(self) -> float:
        """Characteristic length for relative tolerances (stroke or centre distance)."""
        return self.follower.scale
