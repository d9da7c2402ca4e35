"""The contact along the cycle: at every cam angle the force, the radii, the Hertz stresses, the film and the life.

Each face gives its contact's geometry (:func:`roller_geometry`, :func:`flat_geometry`: the cam's signed radius of
curvature at the contact, the follower's, the entrainment velocity and, for a roller, its revolutions); the
``[dynamics]`` forces give the contact force (``force_model = "rigid"``: the rigid, kinetostatic force of
:mod:`cams.dynamics`); :func:`contact_cycle` computes the rest with :mod:`cams.strength.hertz`,
:mod:`cams.strength.film` and :mod:`cams.strength.life`.

Units: lengths mm, forces N, stresses MPa, film thickness and roughness micrometres, velocities m/s, angles radians
inside (degrees in :meth:`ContactCycle.to_dict`), the life in hours. Radii of curvature: positive convex, negative
concave (the cam's), ``inf`` a plane (a flat face).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.model.contact import ContactSpec
from cams.strength import film, hertz, life
from cams.strength.materials import material
from laws.errors import InputError
from laws.units import omega_to_rpm, turn_degrees

__all__ = [
    "ContactGeometry",
    "ContactMaterials",
    "materials_of",
    "roller_geometry",
    "flat_geometry",
    "ContactCycle",
    "contact_cycle",
    "EDGE_NOTE",
    "CONTACT_LIMITS",
]

#: What the output says of an uncrowned roller (and of any line contact's figure).
EDGE_NOTE = (
    "the line-contact figures assume a uniform load along the width: at an uncrowned roller's (or a "
    "flat face's) edges the pressure rises above them (edge loading), so they are unconservative there; "
    "crown the roller or relieve the edges"
)
#: The contact's limits, as :attr:`ContactCycle.limit` names them.
CONTACT_LIMITS = ("contact_stress", "film_parameter", "bearing_life")


@dataclass(frozen=True)
class ContactMaterials:
    """The contact's elastic constants and allowable stress, resolved from a :class:`ContactSpec`.

    Attributes
    ----------
    cam_modulus, follower_modulus : float
        Young's moduli (MPa).
    cam_poisson, follower_poisson : float
    allowable : float or None
        Allowable p0 (MPa): the file's, else the lower of the materials' known ones; None when none is known.
    """

    cam_modulus: float
    cam_poisson: float
    follower_modulus: float
    follower_poisson: float
    allowable: float | None

    @property
    def E_star(self) -> float:
        """The contact modulus E* (MPa): ``1/E* = sum (1 - nu^2)/E``."""
        return hertz.contact_modulus(self.cam_modulus, self.cam_poisson, self.follower_modulus, self.follower_poisson)


def materials_of(spec: ContactSpec) -> ContactMaterials:
    """The elastic constants of ``spec`` (a value given in the file overrides its material's; moduli GPa -> MPa).

    Raises
    ------
    InputError
        An unknown material name (the known ones listed).
    """
    out = []
    allow = []
    for side in ("cam", "follower"):
        name = getattr(spec, f"{side}_material")
        m = None if name is None else material(name, f"contact.{side}_material")
        E = getattr(spec, f"{side}_modulus")
        nu = getattr(spec, f"{side}_poisson")
        out.append(E * 1e3 if E is not None else m.modulus)  # type: ignore[union-attr]
        out.append(nu if nu is not None else m.poisson)  # type: ignore[union-attr]
        if m is not None and m.allowable is not None:
            allow.append(m.allowable)
    allowable = spec.allowable_stress if spec.allowable_stress is not None else (min(allow) if allow else None)
    return ContactMaterials(out[0], out[1], out[2], out[3], allowable)


@dataclass(frozen=True, eq=False)
class ContactGeometry:
    """A face's contact geometry at cam angles ``phi``.

    Attributes
    ----------
    phi : ndarray
        Cam angles (radians from the program's start).
    cam_radius : ndarray
        The cam's radius of curvature at the contact (mm; negative concave, inf straight).
    follower_radius : float
        The follower's (mm): the roller radius, ``inf`` for a flat face.
    entrainment : ndarray
        The entrainment velocity ``(u1 + u2)/2`` per unit cam speed (m/s per rad/s, signed: m/rad).
    roller_turns : ndarray or None
        The roller's turns relative to its pin per radian of cam angle (signed); None for a flat face.
    """

    phi: np.ndarray
    cam_radius: np.ndarray
    follower_radius: float
    entrainment: np.ndarray
    roller_turns: np.ndarray | None


def roller_geometry(design, centre, phi: np.ndarray, length_unit: float = 1e-3) -> ContactGeometry:
    """The roller's contact geometry on the cam centred at ``centre`` (fixed frame, mm).

    The working profile ``W = P - r n`` (``P`` the pitch curve, ``n`` its outward normal, ``kappa`` its signed
    curvature) has the radius of curvature ``rho_p - r`` and travels at ``|dW/dphi| = |w1| |1 - r kappa|``; the
    roller rolls, so both surfaces move at that speed relative to the contact: the entrainment velocity. The roller
    rolls round the pitch curve against the cam's sense: relative to the cam it turns by ``-eps |w1| / r`` per
    radian, the cam turns by ``eps``, the follower's arm by ``sense psi'`` (a rocker; 0 for a translating follower),
    so relative to its pin the roller turns ``(-eps |w1| / r + eps - sense psi') / (2 pi)`` per radian.
    """
    from cams.kinematics.inversion import curvature, invert_at
    from cams.model.follower import Rocker

    r = float(design.follower.roller_radius)
    if not r > 0:
        raise InputError(
            "follower.roller_radius",
            "a knife edge's contact stress is unbounded (a line of zero "
            "radius): give the roller's radius for [contact]",
        )
    inv = invert_at(design, np.asarray(centre, float), phi)
    kappa = curvature(inv)
    speed = np.linalg.norm(inv.w1, axis=-1)
    kw = kappa / (1.0 - r * kappa)
    with np.errstate(divide="ignore"):
        rho = np.where(kw == 0, np.inf, 1.0 / np.where(kw == 0, 1.0, kw))
    eps = design.cam_sense
    f = design.follower
    arm_rate = f.sense * inv.ds if isinstance(f, Rocker) else np.zeros_like(phi)
    turns = (-eps * speed / r + eps - arm_rate) / (2.0 * np.pi)
    return ContactGeometry(
        phi=np.asarray(phi, float),
        cam_radius=rho,
        follower_radius=r,
        entrainment=speed * np.abs(1.0 - r * kappa) * length_unit,
        roller_turns=turns,
    )


def flat_geometry(design, R0: float, phi: np.ndarray, length_unit: float = 1e-3) -> ContactGeometry:
    """A flat face's contact geometry on the cam of base radius ``R0`` (mm).

    The cam's radius of curvature is the envelope's, ``rho = p + p_thetatheta`` (a translating face: ``R0 + s +
    s''``). The face slides: relative to the contact the cam's surface moves along the face's direction ``u`` at
    ``sigma rho theta' omega`` (``theta'`` the face normal's turn in the cam frame per radian, ``sigma`` the rocker's
    rise sense, 1 for a translating face) and the face's at that less the sliding velocity ``v_sl``
    (:meth:`cams.dynamics.flat_forces.FlatContact.sliding_per_radian`); the entrainment velocity is their mean,
    ``sigma rho theta' - v_sl / 2`` per radian (a translating face: ``-eps (R0 + s + 2 s'') / 2``), which passes
    through zero where the contact's travels along the two surfaces cancel.
    """
    from cams.dynamics.flat_forces import flat_contact
    from cams.kinematics.flat import curvature_radius, oscillating_setup, oscillating_terms
    from cams.model.follower import FlatTranslating

    fo, prog, eps = design.follower, design.program, design.cam_sense
    phi = np.asarray(phi, float)
    if isinstance(fo, FlatTranslating):
        m = prog.evaluate(phi)
        rho = R0 + m.s + m.d2s
        sigma, dth = 1, -eps * np.ones_like(phi)
    else:
        L, f, sigma = fo.centre_distance, fo.face_offset, fo.sense
        a0 = oscillating_setup(prog, L, R0, f, sigma)
        _, _, _, dth, d2th, p, dp, d2p = oscillating_terms(prog, L, f, sigma, eps, a0, phi=phi)
        rho = curvature_radius(dth, d2th, p, dp, d2p)
    v_sl = flat_contact(design, R0, phi).sliding_per_radian(eps)
    u = sigma * rho * dth - 0.5 * v_sl
    return ContactGeometry(
        phi=phi,
        cam_radius=np.asarray(rho, float),
        follower_radius=np.inf,
        entrainment=u * length_unit,
        roller_turns=None,
    )


@dataclass(frozen=True, eq=False)
class ContactCycle:
    """The contact over one cam turn (arrays at the cam angles ``phi``) and its summary.

    Attributes
    ----------
    phi : ndarray
        Cam angles (radians).
    force : ndarray
        Contact force (N, >= 0: where contact is lost, 0).
    cam_radius, follower_radius, effective_radius : ndarray
        Radii of curvature (mm; the cam's signed, the follower's inf on a flat face).
    half_width : ndarray
        The contact's half-width b (mm).
    pressure : ndarray
        The maximum Hertz pressure p0 (MPa).
    shear, von_mises : ndarray
        The largest subsurface principal shear and von Mises stress (MPa) in the cam (von Mises with the cam's
        Poisson's ratio, plane strain); their depths are fixed fractions of b.
    shear_depth, von_mises_depth : ndarray
        Their depths below the surface (mm).
    entrainment : ndarray
        Entrainment velocity (m/s, signed).
    film : ndarray or None
        Minimum film thickness (um, Dowson-Higginson); None without the lubricant.
    film_parameter : ndarray or None
        Lambda; None without the lubricant or the roughness.
    width : float
        The cam's face width (mm).
    materials : ContactMaterials
    spec : ContactSpec
    life_hours : float or None
        The roller bearing's L10 life (hours; None without a rating or for a flat face).
    roller_turns_per_rev : float or None
        The roller's revolutions relative to its pin per cam turn.
    rpm : float
        The cam speed (rev/min).
    """

    phi: np.ndarray
    force: np.ndarray
    cam_radius: np.ndarray
    follower_radius: np.ndarray
    effective_radius: np.ndarray
    half_width: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    shear_depth: np.ndarray
    von_mises: np.ndarray
    von_mises_depth: np.ndarray
    entrainment: np.ndarray
    film: np.ndarray | None
    film_parameter: np.ndarray | None
    width: float
    materials: ContactMaterials
    spec: ContactSpec
    life_hours: float | None
    roller_turns_per_rev: float | None
    rpm: float

    @property
    def at_max(self) -> int:
        """The index of the largest p0 (the first of equals)."""
        return int(np.argmax(np.where(np.isnan(self.pressure), -np.inf, self.pressure)))

    @property
    def max_pressure(self) -> float:
        """The largest p0 over the turn (MPa)."""
        return float(self.pressure[self.at_max])

    @property
    def min_width(self) -> float | None:
        """The least face width that keeps p0 within the allowable (mm): p0^2 is proportional to the force per
        width, so ``width (max p0 / allowable)^2``; None without an allowable."""
        a = self.materials.allowable
        return None if a is None else float(self.width * (self.max_pressure / a) ** 2)

    @property
    def min_film_parameter(self) -> float | None:
        """The smallest Lambda over the turn, or None."""
        return None if self.film_parameter is None else float(np.min(self.film_parameter))

    @property
    def zero_entrainment(self) -> list[float]:
        """The cam angles (radians) where the entrainment velocity passes through zero."""
        return film.zero_crossings(self.phi, self.entrainment)

    def roller_radius_range(self) -> tuple[float, float] | None:
        """The roller radii (mm) that keep p0 within the allowable on this cam (its pitch curve and forces held: the
        rigid force does not depend on the roller), or None (no allowable, a flat face, or no radius does).

        At each cam angle the pitch curve's radius of curvature ``rho_p = rho_cam + r`` is the roller's; with a
        roller of radius ``x`` the effective radius is ``1/R = 1/(rho_p - x) + 1/x`` and p0 stays within the
        allowable ``p_a`` where ``1/R <= K = pi width p_a^2 / (N E*)``: on a convex piece ``x`` between the roots
        of ``K x (rho_p - x) = rho_p`` (p0 is not monotone in ``x``: the effective radius peaks at ``rho_p / 2``);
        on a concave one above the root of ``K x (|rho_p| + x) = |rho_p|``; on a straight one ``x >= 1/K``. The
        answer is the intersection over the turn, bounded above by undercut (``x`` below the least convex
        ``rho_p``). Returns ``(least, largest)``.
        """
        a = self.materials.allowable
        r = float(self.follower_radius[0])
        if a is None or not np.isfinite(r):
            return None
        rho_p = self.cam_radius + r
        N = self.force
        lo, hi = 0.0, np.inf
        convex = rho_p[np.isfinite(rho_p) & (rho_p > 0)]
        if convex.size:
            hi = float(np.min(convex))
        for rp, f in zip(rho_p, N, strict=True):
            if not f > 0:
                continue
            if not np.isfinite(f):
                return None
            K = np.pi * self.width * a**2 / (f * self.materials.E_star)
            if not np.isfinite(rp):
                lo = max(lo, 1.0 / K)
            elif rp > 0:
                disc = rp * rp - 4.0 * rp / K
                if disc < 0:
                    return None
                lo = max(lo, 0.5 * (rp - np.sqrt(disc)))
                hi = min(hi, 0.5 * (rp + np.sqrt(disc)))
            else:
                q = -rp
                lo = max(lo, 0.5 * (-q + np.sqrt(q * q + 4.0 * q / K)))
        return (lo, hi) if lo <= hi else None

    def ratios(self) -> dict[str, float]:
        """Each judged limit's ratio of what the cam achieves to what is asked (>= 1 passes): ``contact_stress``
        allowable / p0, ``film_parameter`` Lambda / its minimum, ``bearing_life`` life / target."""
        out = {}
        if self.materials.allowable is not None:
            out["contact_stress"] = self.materials.allowable / self.max_pressure
        lam = self.min_film_parameter
        if lam is not None:
            out["film_parameter"] = lam / self.spec.min_film_parameter
        if self.life_hours is not None and self.spec.life_hours is not None:
            out["bearing_life"] = self.life_hours / self.spec.life_hours
        return out

    @property
    def limit(self) -> str | None:
        """The contact limit that binds: the one with the smallest ratio (:meth:`ratios`), None if none is judged."""
        r = self.ratios()
        return min(r, key=lambda k: r[k]) if r else None

    def failures(self) -> list[tuple[str, str]]:
        """``(short, line)`` of each contact limit the cam fails."""
        out = []
        i = self.at_max
        at = turn_degrees(self.phi[i])
        a = self.materials.allowable
        if a is not None and not self.max_pressure <= a:
            out.append(
                (
                    "contact stress",
                    f"contact stress: p0 = {self.max_pressure:.4g} MPa at cam angle "
                    f"{at:.2f} deg exceeds the allowable {a:.4g} MPa (the least face width is "
                    f"{self.min_width:.4g} mm)",
                )
            )
        lam = self.min_film_parameter
        if lam is not None and not lam >= self.spec.min_film_parameter:
            j = int(np.argmin(self.film_parameter))  # type: ignore[arg-type]
            out.append(
                (
                    "film",
                    f"lubricant film: film parameter {lam:.3g} at cam angle "
                    f"{turn_degrees(self.phi[j]):.2f} deg is below contact.min_film_parameter "
                    f"{self.spec.min_film_parameter:g}",
                )
            )
        t = self.spec.life_hours
        if t is not None and self.life_hours is not None and not self.life_hours >= t:
            out.append(
                ("bearing life", f"bearing life: L10 = {self.life_hours:.4g} h is below contact.life_hours {t:.4g} h")
            )
        return out

    def notes(self) -> list[str]:
        """What the contact's figures need said: edge loading, zero entrainment, a basic rating on a track roller."""
        out = [EDGE_NOTE]
        z = self.zero_entrainment
        if z:
            out.append(
                "the entrainment velocity falls to zero at cam angle "
                + ", ".join(f"{turn_degrees(p):.2f} deg" for p in z)
                + ": no film is drawn in there (only squeezed); a larger nose radius lowers p0 but can bring "
                "this about"
            )
        rr = self.roller_radius_range()
        if rr is not None:
            top = (
                "any larger"
                if not np.isfinite(rr[1])
                else f"{rr[1]:.4g} mm (the least convex radius of "
                "curvature of the pitch curve: a larger roller undercuts)"
            )
            out.append(f"roller radius that keeps p0 within the allowable on this cam: from {rr[0]:.4g} mm to {top}")
        if self.life_hours is not None and self.spec.bearing_rating_type == "basic":
            out.append(
                "bearing life from the basic rating C: a bearing running as a track roller has a lower "
                "effective rating (its outer ring bends), so this life is an upper bound; give "
                'bearing_rating_type = "track_roller" with the catalogue\'s effective rating'
            )
        return out

    def to_dict(self) -> dict:
        """JSON-ready: ``force_model``, ``max_pressure`` (MPa) and ``max_pressure_at_deg``, ``at_max`` (``force`` N,
        ``cam_curvature_radius`` mm, ``follower_radius`` mm, ``half_width`` mm), ``max_shear`` (MPa),
        ``max_shear_depth`` (mm), ``max_von_mises`` (MPa), ``min_film`` (um), ``min_film_parameter``,
        ``zero_entrainment_at_deg`` (list), ``min_width`` (mm), ``bearing_life_hours``, ``limit``. Non-finite
        numbers (a flat face's radius) as None."""
        i = self.at_max
        fin = lambda x: None if x is None or not np.isfinite(x) else float(x)  # noqa: E731
        return {
            "force_model": self.spec.force_model,
            "max_pressure": fin(self.max_pressure),
            "max_pressure_at_deg": float(turn_degrees(self.phi[i])),
            "at_max": {
                "force": fin(self.force[i]),
                "cam_curvature_radius": fin(self.cam_radius[i]),
                "follower_radius": fin(self.follower_radius[i]),
                "half_width": fin(self.half_width[i]),
            },
            "max_shear": fin(float(np.max(self.shear))),
            "max_shear_depth": fin(float(self.shear_depth[int(np.argmax(self.shear))])),
            "max_von_mises": fin(float(np.max(self.von_mises))),
            "min_film": None if self.film is None else fin(float(np.min(self.film))),
            "min_film_parameter": fin(self.min_film_parameter),
            "zero_entrainment_at_deg": [float(turn_degrees(p)) for p in self.zero_entrainment],
            "min_width": fin(self.min_width),
            "bearing_life_hours": fin(self.life_hours),
            "limit": self.limit,
        }


def contact_cycle(design, geometry: ContactGeometry, force, omega: float) -> ContactCycle:
    """The contact of ``design`` (its ``contact`` and ``width``) over the turn of ``geometry`` under the contact
    force ``force`` (N, at ``geometry.phi``; negative where contact is lost: taken as 0), the cam at ``omega``
    (rad/s).

    Raises
    ------
    InputError
        An unknown material; a bearing rating on a flat face.
    """
    spec: ContactSpec = design.contact
    mats = materials_of(spec)
    width = float(design.width)
    phi = geometry.phi
    N = np.maximum(np.asarray(force, float), 0.0)
    E = mats.E_star
    rf = np.full_like(phi, geometry.follower_radius)
    R = hertz.effective_radius(geometry.cam_radius, rf)
    R = np.where(np.isnan(R), 0.0, R)  # no line contact (a concave face sharper than the roller): p0 inf
    w = N / width
    with np.errstate(divide="ignore", invalid="ignore"):
        p0 = np.where(R > 0, hertz.max_pressure(w, np.where(R > 0, R, 1.0), E), np.inf)
        p0 = np.where(w == 0, 0.0, p0)
        b = np.where(R > 0, hertz.half_width(w, np.where(R > 0, R, 1.0), E), 0.0)
    k = hertz.subsurface_maxima(float(mats.cam_poisson))
    u = geometry.entrainment * omega
    h = lam = None
    if spec.viscosity is not None and spec.pressure_viscosity is not None:
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            hm = film.dowson_higginson(
                u,
                R * 1e-3,
                np.maximum(w, 1e-300) * 1e3,
                2.0 * E * 1e6,
                float(spec.viscosity),
                float(spec.pressure_viscosity) * 1e-9,
            )
        h = np.where(np.isfinite(hm), hm, 0.0) * 1e6
        if spec.cam_roughness is not None and spec.follower_roughness is not None:
            lam = film.film_parameter(h, spec.cam_roughness, spec.follower_roughness)
    hours = per_rev = None
    if geometry.roller_turns is not None:
        dphi = 2.0 * np.pi / len(phi)
        turns = np.abs(geometry.roller_turns) * dphi
        per_rev = float(np.sum(turns))
        if spec.bearing_rating is not None:
            rpm = omega_to_rpm(omega)
            hours = life.life_hours(float(spec.bearing_rating), N, turns, per_rev, rpm)
    elif spec.bearing_rating is not None:
        raise InputError("contact.bearing_rating", "applies to a roller follower's bearing; a flat face has none")
    return ContactCycle(
        phi=phi,
        force=N,
        cam_radius=np.asarray(geometry.cam_radius, float),
        follower_radius=rf,
        effective_radius=R,
        half_width=b,
        pressure=p0,
        shear=k.shear * p0,
        shear_depth=k.shear_depth * b,
        von_mises=k.von_mises * p0,
        von_mises_depth=k.von_mises_depth * b,
        entrainment=u,
        film=h,
        film_parameter=lam,
        width=width,
        materials=mats,
        spec=spec,
        life_hours=hours,
        roller_turns_per_rev=per_rev,
        rpm=omega_to_rpm(omega),
    )
