"""Sizing a flat-faced follower's cam: the smallest base radius that keeps the profile convex enough.

A flat face's pressure angle is fixed by the geometry, so its cam is sized by
convexity: the profile's radius of curvature must stay at least ``rho_min``
everywhere, and the face must be wide enough for the contact's travel. The
envelope, its curvature and the contact are :mod:`cams.kinematics.flat`'s;
this module finds the base radius (:func:`min_base_radius_translating`,
:func:`min_base_radius_oscillating`) and sizes a design
(:func:`size_flat_face`, a :class:`FlatFaceSolution`).

Angles in radians, lengths in the design's unit (mm).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from cams.kinematics.flat import (
    check_cam_sense,
    curvature_radius,
    cusp_error,
    flat_parts,
    flat_radii,
    near_dwell_angle,
    oscillating_cusps,
    oscillating_parts,
    oscillating_setup,
    oscillating_support,
    phase_minimum,
    rocker_frame_turn,
    translating_cusps,
    translating_parts,
)
from cams.model.design import FlatFaceDesign
from cams.model.follower import FlatRocker, FlatTranslating, check_length
from laws.errors import InputError
from laws.program import Program
from laws.units import turn_degrees

__all__ = [
    "min_base_radius_translating",
    "min_base_radius_oscillating",
    "FlatFaceSolution",
    "size_flat_face",
]


def _illinois(fun, a: float, b: float, fa: float, fb: float, xtol: float) -> float:
    """A root of ``fun`` in ``[a, b]`` with ``fa < 0 <= fb`` (Illinois false position); the admissible end."""
    side = 0
    for _ in range(200):
        if abs(b - a) <= xtol:
            break
        c = b - fb * (b - a) / (fb - fa)
        if not (min(a, b) < c < max(a, b)):
            c = 0.5 * (a + b)
        fc = fun(c)
        if fc >= 0:
            b, fb = c, fc
            if side == 1:
                fa *= 0.5
            side = 1
        else:
            a, fa = c, fc
            if side == -1:
                fb *= 0.5
            side = -1
    return b



def min_base_radius_translating(program: Program, *, min_radius: float = 0.0) -> tuple[float, float]:
    """Smallest R0 of a translating flat-faced follower's cam with ``rho >= min_radius``.

    ``R0 = min_radius - min(s + s'')`` over the cycle (found per phase by grid
    and bounded search), at least 0.

    Returns
    -------
    R0 : float
        Length.
    at : float
        Cam angle (radians) of the binding position.

    Raises
    ------
    InputError
        Field ``motion[i]``: the follower's velocity drops somewhere (a cusp
        whatever the base radius).
    """
    rmin = check_length("min_radius", min_radius, positive=False)
    cusps = translating_cusps(program, 1)  # the same for either sense of rotation
    if cusps:
        raise cusp_error(program, cusps)
    v, at = phase_minimum(translating_parts(program, 0.0)[0], program)
    return max(rmin - v, 0.0), at



def _oscillating_scan(program: Program, L: float, f: float, sigma: int, eps: int, R0: np.ndarray,
                      grid: int = 2000, block: int = 20):
    """Smallest radius of curvature on a fixed grid (``grid + 1`` positions a phase), ``block`` R0 at a time.

    Yields ``(index, minimum)`` in the order of ``R0``.
    """
    u = np.linspace(0, 1, grid + 1)
    parts = [program.evaluate_phase(i, u) for i, p in enumerate(program.phases) if p.kind != "dwell"]
    # a dwell's profile is an arc of radius p = f - L cos(a): its smallest value is at one of the levels
    levels = np.unique(program.levels)
    s, ds, d2s = (np.concatenate([getattr(m, k) for m in parts] + [z])[None, :]
                  for k, z in (("s", levels), ("ds", 0 * levels), ("d2s", 0 * levels)))
    for k0 in range(0, len(R0), block):
        a0 = near_dwell_angle(L, f, R0[k0:k0 + block], sigma)[:, None]
        _, dth, d2th, p, dp, d2p = oscillating_support(L, f, sigma, eps, a0, s, ds, d2s)
        with np.errstate(divide="ignore", invalid="ignore"):
            rho = curvature_radius(dth, d2th, p, dp, d2p)
        rho = np.where(np.isfinite(rho), rho, -np.inf).min(axis=1)
        yield from zip(range(k0, k0 + len(rho)), rho, strict=True)


def min_base_radius_oscillating(program: Program, *, centre_distance: float, face_offset: float = 0.0,
                                rise_sense: int = -1, cam_sense: int = 1, min_radius: float = 0.0,
                                scan: int = 200) -> tuple[float, float]:
    """Smallest R0 of an oscillating flat-faced follower's cam with ``rho >= min_radius``.

    R0 ranges over ``(0, f + L cos(swing))`` (beyond, the face would turn past
    the line of centres); the smallest radius of curvature is scanned over
    ``scan`` values of R0 (on a fixed grid of cam angles, all at once) and the
    first admissible one refined by root finding on the refined minimum.

    Returns
    -------
    R0 : float
        Length.
    at : float
        Cam angle (radians) of the binding position.

    Raises
    ------
    InputError
        No R0 in the range gives a convex enough profile (field
        ``min_radius``); a velocity jump that gives a cusp whatever the size
        (field ``motion[i]``).
    """
    L = check_length("centre_distance", centre_distance)
    f = check_length("face_offset", face_offset, positive=False)
    rmin = check_length("min_radius", min_radius, positive=False)
    eps = check_cam_sense(cam_sense)
    if rise_sense not in (1, -1):
        raise InputError("follower.rise_direction", f"rise_sense must be +1 (ccw) or -1 (cw), got {rise_sense!r}")
    hi = f + L * np.cos(program.lift)
    lo = max(f - L, 0.0)
    if hi <= lo + 1e-12 * L:
        # the face's far position must stay on the cam's side of the centre: f + L cos(swing) > 0 (f < L here)
        largest = np.degrees(np.arccos(np.clip(-f / L, -1.0, 1.0)))
        need = -L * np.cos(program.lift)
        need = 0.0 if abs(need) < 1e-9 * L else need
        raise InputError("swing", f"a flat face at {f:g} from the pivot with L = {L:g} turns at most {largest:.6g} "
                         f"degrees before its line passes the cam centre (swing {np.degrees(program.lift):g}); reduce "
                         f"the swing or give a face_offset above {need:.6g}")
    grid = lo + (hi - lo) * (np.arange(1, scan + 1) / (scan + 1))
    a_mid = oscillating_setup(program, L, grid[scan // 2], f, rise_sense)
    cusps = oscillating_cusps(program, L, rise_sense, eps, a_mid)
    if cusps:
        raise cusp_error(program, cusps)

    def margin(R0):
        # the smallest radius of curvature at R0, as oscillating_flat_face finds it, without building the profile
        a0 = oscillating_setup(program, L, R0, f, rise_sense)
        cusps = oscillating_cusps(program, L, rise_sense, eps, a0)
        if cusps:
            return -np.inf, cusps[0][0]
        lo, at = phase_minimum(oscillating_parts(program, L, f, rise_sense, eps, a0)[0], program)
        return lo - rmin, at

    # the grid minimum is at least the true one: the first R0 admissible on the grid is where to start
    for k, coarse in _oscillating_scan(program, L, f, rise_sense, eps, grid):
        if coarse < rmin:
            continue
        g, at = margin(grid[k])
        if g < 0:
            continue
        if k == 0:
            return float(grid[0]), at
        # grid[k - 1] is not admissible: its grid minimum, an upper bound of the true one, is below, or
        # (an earlier k of the loop) its true minimum is
        R = _illinois(lambda x: margin(x)[0], grid[k - 1], grid[k], margin(grid[k - 1])[0], g, 1e-12 * L)
        return float(R), margin(R)[1]
    raise InputError("min_radius", f"no base radius below {hi:.6g} gives a radius of curvature >= {rmin:g}")



#: Names the design file gives the API's fields, for error messages.
_FILE_FIELDS = {"centre_distance": "follower.centre_distance", "face_offset": "follower.face_offset",
                "min_radius": "limits.min_radius", "follower.offset": "follower.offset", "swing": "follower.swing",
                "base_radius": "cam.base_radius"}


def _renamed(e: InputError, field: str | None = None) -> InputError:
    """``e`` with its field named as in a design file (``field`` overrides)."""
    msg = str(e)[len(e.field) + 2:] if e.field else str(e)
    new = field or _FILE_FIELDS.get(e.field, e.field)
    return InputError(new, msg)



def _deg(phi) -> float | None:
    return None if phi is None or not np.isfinite(phi) else float(turn_degrees(phi))


@dataclass(frozen=True, eq=False)
class FlatFaceSolution:
    """A sized flat-face cam: base radius, face travel and pressure angle.

    Lengths in the design's unit, angles in radians.

    Attributes
    ----------
    design : cams.model.design.FlatFaceDesign
    R0 : float
        The base radius used: the convexity minimum ``R0_min``, or the floor
        ``limits.min_base_radius`` when larger, or the file's
        ``cam.base_radius``.
    R0_min : float or None
        Smallest base radius with ``rho >= min_radius`` everywhere (None when
        no base radius reaches it and ``cam.base_radius`` was given).
    R0_source : {"convexity", "limits.min_base_radius", "cam.base_radius", "part"}
        What set R0; ``"part"``: the sizing to the part (:mod:`cams.faces.part`: the bore and its hub wall).
    binding_at : float or None
        Cam angle where rho is smallest at ``R0_min``.
    min_rho, min_rho_at : float
        Smallest radius of curvature at ``R0`` and its cam angle.
    face_range : (float, float)
        Smallest and largest contact position on the face: from the follower's
        axis (translating, +X) or from the foot of the perpendicular from the
        pivot (rocker, along the face, positive towards the cam; the same sign
        as ``FlatFaceProfile.contact``).
    face_range_at : (float, float)
        Their cam angles.
    pressure_range : (float, float)
        Smallest and largest pressure angle over the cycle (fixed by the
        geometry: 0 for a translating face and for a rocker face through its
        pivot).
    pressure_max_at : float
    seconds : float
    notes : tuple of str
    """

    design: FlatFaceDesign
    R0: float
    R0_min: float | None
    R0_source: str
    binding_at: float | None
    min_rho: float
    min_rho_at: float
    face_range: tuple[float, float]
    face_range_at: tuple[float, float]
    pressure_range: tuple[float, float]
    pressure_max_at: float
    seconds: float
    notes: tuple[str, ...] = ()

    @property
    def centre(self) -> np.ndarray:
        """Cam centre in the frame of the reports and drawings (length).

        Translating: ``(-e, -R0)`` in the follower's fixed frame
        (:mod:`cams.model.follower`). Rocker: ``(L, 0)`` in the line-of-centres
        frame (pivot at the origin, X towards the cam centre), the rocker's
        fixed frame turned by :attr:`frame_turn`; :attr:`rocker_frame_centre`
        gives it in the rocker's fixed frame.
        """
        fo = self.design.follower
        if isinstance(fo, FlatTranslating):
            return np.array([0.0 - fo.offset, -self.R0]) + 0.0  # + 0.0: no -0.0 in reports
        return np.array([fo.centre_distance, 0.0])

    @property
    def frame_turn(self) -> float:
        """Rocker: angle (radians, counter-clockwise) from the rocker's fixed frame to the line-of-centres frame.

        A point with line-of-centres coordinates ``x`` has rocker-frame
        coordinates ``R(-frame_turn) x`` (:func:`cams.kinematics.flat.rocker_frame_turn`);
        0 for a translating follower (one frame).
        """
        fo = self.design.follower
        if isinstance(fo, FlatTranslating):
            return 0.0
        a0 = oscillating_setup(self.design.program, fo.centre_distance, self.R0, fo.face_offset, fo.sense)
        return rocker_frame_turn(a0, fo.sense)

    @property
    def rocker_frame_centre(self) -> np.ndarray:
        """Cam centre in the follower's fixed frame of :mod:`cams.model.follower` (length).

        Rocker: X along the face at the near dwell, from the pivot's foot
        towards the cam, so the centre is ``(sqrt(L^2 - (f - R0)^2), sigma (f - R0))``;
        translating: :attr:`centre`.
        """
        b = self.frame_turn
        c, s = np.cos(b), np.sin(b)
        x, y = self.centre
        return np.array([c * x + s * y, -s * x + c * y])

    @property
    def face_width(self) -> float:
        """Length of face the contact travels over (no margins)."""
        return float(self.face_range[1] - self.face_range[0])

    @property
    def face_width_centred(self) -> float | None:
        """Translating: width of a face centred on the follower's axis, ``2 max(|lo|, |hi|)``; rocker: None."""
        if not isinstance(self.design.follower, FlatTranslating):
            return None
        return float(2 * max(abs(self.face_range[0]), abs(self.face_range[1])))

    def face_line(self, phi) -> tuple[np.ndarray, np.ndarray]:
        """The face at cam angles ``phi``: ``(origin, direction)``, in the frame of :attr:`centre`.

        Points of the face are ``origin + c * direction`` with ``c`` measured as
        ``face_range`` (from the axis, or from the pivot's foot, positive
        towards the cam); shapes ``phi.shape + (2,)``.
        """
        fo, prog = self.design.follower, self.design.program
        s = prog.evaluate(np.asarray(phi, dtype=float)).s
        if isinstance(fo, FlatTranslating):
            origin = np.stack([np.zeros_like(s), s], axis=-1)
            return origin, np.stack([np.ones_like(s), np.zeros_like(s)], axis=-1)
        a = oscillating_setup(prog, fo.centre_distance, self.R0, fo.face_offset, fo.sense) + fo.sense * s
        m = np.stack([np.cos(a), np.sin(a)], axis=-1)
        return fo.face_offset * m, -fo.sense * np.stack([-m[..., 1], m[..., 0]], axis=-1)

    def curves(self, n: int = 721) -> dict:
        """Radius of curvature, contact position and pressure angle against the cam angle.

        Each phase is sampled with both ends (one-sided values), the phases
        separated by NaN: keys ``phi``, ``rho``, ``contact``, ``pressure``
        (radians, lengths), for pictures.
        """
        prog = self.design.program
        funs = flat_parts(self.design, self.R0)
        out: dict[str, list] = {k: [] for k in ("phi", "rho", "contact", "pressure")}
        for i, p in enumerate(prog.phases):
            u = np.linspace(0.0, 1.0, max(int(n * p.angle / (2 * np.pi)), 8))
            vals = [prog.starts[i] + u * p.angle] + [np.broadcast_to(f(i, u), u.shape) for f in funs]
            for k, v in zip(out, vals, strict=True):
                out[k] += [v, [np.nan]]
        return {k: np.concatenate(v) for k, v in out.items()}

    @property
    def rho_tolerance(self) -> float:
        """Round-off allowed on ``min_rho`` (length unit).

        ``rho`` sums terms of the size of R0 (and of L for a rocker): where the
        convexity binds, ``s''`` is about ``-R0``, so a cam far larger than its
        follower (tiny rise angles) loses ``eps * R0`` on ``rho``. The
        tolerance follows those magnitudes, not the follower's size alone.
        """
        L = float(getattr(self.design.follower, "centre_distance", 0.0))
        size = abs(self.R0) + abs(L) + abs(self.design.min_radius)
        return 1e-9 * self.design.scale + 64 * np.finfo(float).eps * size

    @property
    def verified(self) -> bool:
        """True when the profile at R0 is convex enough: ``min_rho >= min_radius`` (to :attr:`rho_tolerance`)."""
        return bool(self.min_rho >= self.design.min_radius - self.rho_tolerance)

    def to_dict(self, result: object = None) -> dict:
        """JSON-ready report: lengths in the design's unit, angles in degrees.

        ``result``: the :class:`cams.faces.result.SolveResult` that holds this sizing as its detail (it adds its
        notes and the motion design's certificate to the report); its other fields are this sizing's.
        """
        fo = self.design.follower
        lo, hi = self.face_range
        deg = lambda x: None if x is None else float(np.degrees(x))  # noqa: E731
        small, small_at, large, large_at = flat_radii(self.design, self.R0)
        return {
            "name": self.design.name,
            "follower": fo.kind,
            "face": "flat",
            "R0": float(self.R0),
            "smallest_cam_radius": small,
            "smallest_cam_radius_at_deg": _deg(small_at),
            "largest_cam_radius": large,
            "largest_cam_radius_at_deg": _deg(large_at),
            "R0_min": None if self.R0_min is None else float(self.R0_min),
            "R0_source": self.R0_source,
            "binding_deg": _deg(self.binding_at),
            "min_radius": float(self.design.min_radius),
            "min_rho": float(self.min_rho),
            "min_rho_at_deg": _deg(self.min_rho_at),
            "L": float(fo.centre_distance) if isinstance(fo, FlatRocker) else None,
            "face_offset": float(fo.face_offset) if isinstance(fo, FlatRocker) else None,
            "offset": float(fo.offset) if isinstance(fo, FlatTranslating) else None,
            "centre": {"x": float(self.centre[0]), "y": float(self.centre[1])},
            "face_range": {"from": float(lo), "to": float(hi),
                           "from_at_deg": _deg(self.face_range_at[0]), "to_at_deg": _deg(self.face_range_at[1])},
            "face_width": self.face_width,
            "face_width_centred": self.face_width_centred,
            "pressure_angle": {"min": deg(self.pressure_range[0]), "max": deg(self.pressure_range[1]),
                               "max_at_deg": _deg(self.pressure_max_at)},
            "verified": self.verified,
            "seconds": float(self.seconds),
            "notes": list(self.notes),
        }


def size_flat_face(design: FlatFaceDesign) -> FlatFaceSolution:
    """Size the cam of a flat-face design (:class:`cams.model.design.FlatFaceDesign`).

    The base radius is the convexity minimum (:func:`min_base_radius_translating`,
    :func:`min_base_radius_oscillating` with ``design.min_radius``), raised to
    ``design.min_base_radius`` when that is larger, or ``design.base_radius``
    when given. At that radius the smallest radius of curvature, the extreme
    contact positions on the face and the pressure angle's range are located
    per phase (grid and bounded search).

    Raises
    ------
    InputError
        Fields named as in the design file: ``limits.min_radius`` (no base
        radius is convex enough), ``motion[i]`` (a velocity drop: a cusp
        whatever the size), ``cam.base_radius`` (outside what the face can touch).
    """
    t0 = time.perf_counter()
    fo, prog, rmin = design.follower, design.program, design.min_radius
    notes: list[str] = []
    R0_min: float | None = None
    bind: float | None = None
    try:
        if isinstance(fo, FlatTranslating):
            R0_min, bind = min_base_radius_translating(prog, min_radius=rmin)
        else:
            R0_min, bind = min_base_radius_oscillating(
                prog, centre_distance=fo.centre_distance, face_offset=fo.face_offset, rise_sense=fo.sense,
                cam_sense=design.cam_sense, min_radius=rmin)
    except InputError as e:
        if e.field == "min_radius":
            hint = ("a longer follower.centre_distance, a smaller swing, longer rise or return angles, the other "
                    "follower.rise_direction or a smaller limits.min_radius may help")
            e = _renamed(e, "limits.min_radius")
            if design.base_radius is None:
                raise InputError("limits.min_radius", f"{str(e)[len('limits.min_radius: '):]}; {hint}") from None
            notes.append(f"no base radius reaches the limit: {e!s}")
        else:
            raise _renamed(e) from None
    if design.base_radius is not None:
        R0, source = float(design.base_radius), "cam.base_radius"
        if R0_min is not None:
            notes.append(f"R0 is cam.base_radius = {R0:g} mm; the smallest convex enough is {R0_min:.6g} mm")
    elif R0_min is None:  # pragma: no cover - without cam.base_radius a failed minimum has raised above
        raise AssertionError("no base radius")
    elif design.min_base_radius is not None and design.min_base_radius > R0_min:
        R0, source = float(design.min_base_radius), "limits.min_base_radius"
        notes.append(f"R0 raised to limits.min_base_radius = {R0:g} (convexity needs {R0_min:.6g})")
    else:
        R0, source = R0_min, "convexity"
        if R0 <= 0:
            raise InputError("limits.min_radius", f"{rmin:g} is met by any base radius (s + s'' >= min_radius "
                             "everywhere); give limits.min_base_radius or cam.base_radius")
    try:
        rho, contact, gamma = flat_parts(design, R0)
    except InputError as e:
        raise _renamed(e, source if e.field == "base_radius" else None) from None
    lo_rho, lo_rho_at = phase_minimum(rho, prog)
    lo, lo_at = phase_minimum(contact, prog)
    hi, hi_at = phase_minimum(lambda i, u: -contact(i, u), prog)
    if isinstance(fo, FlatTranslating):
        g = (0.0, 0.0, 0.0)
    else:
        gmin, _ = phase_minimum(gamma, prog)
        gmax, gat = phase_minimum(lambda i, u: -gamma(i, u), prog)
        g = (gmin, -gmax, gat)
        if lo < 0 < -hi:
            notes.append("the contact passes the foot of the perpendicular from the pivot: the face must reach "
                         "both sides of it")
    return FlatFaceSolution(
        design=design, R0=float(R0), R0_min=None if R0_min is None else float(R0_min), R0_source=source,
        binding_at=bind, min_rho=float(lo_rho), min_rho_at=float(lo_rho_at), face_range=(float(lo), float(-hi)),
        face_range_at=(float(lo_at), float(hi_at)), pressure_range=(float(g[0]), float(g[1])),
        pressure_max_at=float(g[2]), seconds=time.perf_counter() - t0, notes=tuple(notes))

