"""The contact's materials, lubricant and bearing, typed: a design file's ``[contact]`` table.

Plain data in the file's units, checked once here with the message the file's key gets: moduli in GPa, stresses in
MPa, roughness (Rq) in micrometres, viscosity in Pa s, the pressure-viscosity coefficient in 1/GPa, the bearing's
rating in N, the life in hours. Material names are resolved by :mod:`cams.strength.materials` (the table of known
materials lives there); what the contact gives is computed by :mod:`cams.strength`.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

from laws.errors import InputError
from laws.errors import check_number as _num

__all__ = ["ContactSpec", "CONTACT_KEYS", "FORCE_MODELS"]

#: The contact forces the stresses may be computed on: the rigid (kinetostatic) force of :mod:`cams.dynamics`.
FORCE_MODELS = ("rigid", "elastic")


@dataclass(frozen=True)
class ContactSpec:
    """A design's ``[contact]`` table (file units; None: not given).

    Attributes
    ----------
    cam_material, follower_material : str or None
        Names in :data:`cams.strength.materials.MATERIALS`; a modulus or Poisson's ratio given beside a name
        overrides the name's.
    cam_modulus, follower_modulus : float or None
        Young's moduli (GPa, > 0).
    cam_poisson, follower_poisson : float or None
        Poisson's ratios (dimensionless, in (-1, 0.5)).
    allowable_stress : float or None
        Allowable Hertz pressure p0 (MPa, > 0); None: the lower of the materials' (where known).
    cam_roughness, follower_roughness : float or None
        RMS roughness Rq of each surface (micrometres, > 0).
    viscosity : float or None
        The lubricant's dynamic viscosity at the contact's inlet temperature (Pa s, > 0).
    pressure_viscosity : float or None
        Its pressure-viscosity coefficient alpha (1/GPa, > 0).
    min_film_parameter : float
        The least film parameter Lambda allowed (dimensionless, > 0; default 1).
    bearing_rating : float or None
        The roller bearing's dynamic load rating (N, > 0).
    bearing_rating_type : {"basic", "track_roller"}
        ``"basic"``: ISO 281's basic dynamic rating C; ``"track_roller"``: the catalogue's effective rating.
    life_hours : float or None
        The bearing's target L10 life (hours, > 0); needs ``bearing_rating``.
    force_model : {"rigid", "elastic"}
        The contact force the stresses are computed on: ``"rigid"``, the rigid (kinetostatic) one of the
        ``[dynamics]`` table; ``"elastic"``, the follower train's dynamic one at its periodic steady state
        (:mod:`cams.dynamics.vibration`; needs ``[dynamics] train_stiffness``).
    """

    cam_material: str | None = None
    follower_material: str | None = None
    cam_modulus: float | None = None
    cam_poisson: float | None = None
    follower_modulus: float | None = None
    follower_poisson: float | None = None
    allowable_stress: float | None = None
    cam_roughness: float | None = None
    follower_roughness: float | None = None
    viscosity: float | None = None
    pressure_viscosity: float | None = None
    min_film_parameter: float = 1.0
    bearing_rating: float | None = None
    bearing_rating_type: str = "basic"
    life_hours: float | None = None
    force_model: str = "rigid"

    def __post_init__(self) -> None:
        for k in ("cam_material", "follower_material"):
            v = getattr(self, k)
            if v is not None and not isinstance(v, str):
                raise InputError(f"contact.{k}", f"must be a material's name (a string), got {v!r}")
        for k in (
            "cam_modulus",
            "follower_modulus",
            "allowable_stress",
            "cam_roughness",
            "follower_roughness",
            "viscosity",
            "pressure_viscosity",
            "min_film_parameter",
            "bearing_rating",
            "life_hours",
        ):
            v = getattr(self, k)
            if v is not None:
                _num(f"contact.{k}", v, lo=0.0, strict=True)
        for k in ("cam_poisson", "follower_poisson"):
            v = getattr(self, k)
            if v is not None:
                _num(f"contact.{k}", v)
                if not -1.0 < v < 0.5:
                    raise InputError(f"contact.{k}", f"must be in (-1, 0.5) (Poisson's ratio), got {v!r}")
        if self.bearing_rating_type not in ("basic", "track_roller"):
            raise InputError(
                "contact.bearing_rating_type", f"must be 'basic' or 'track_roller', got {self.bearing_rating_type!r}"
            )
        if self.force_model not in FORCE_MODELS:
            raise InputError(
                "contact.force_model",
                f"must be one of {', '.join(FORCE_MODELS)}, got {self.force_model!r}",
            )
        if self.life_hours is not None and self.bearing_rating is None:
            raise InputError(
                "contact.life_hours", "a life target needs the roller bearing's rating: give contact.bearing_rating (N)"
            )
        if (self.cam_roughness is None) != (self.follower_roughness is None):
            missing = "cam_roughness" if self.cam_roughness is None else "follower_roughness"
            raise InputError(f"contact.{missing}", "the film parameter needs both surfaces' roughness (Rq, um)")
        for k, v in (("cam_modulus", self.cam_material), ("follower_modulus", self.follower_material)):
            side = k.split("_")[0]
            if getattr(self, k) is None and v is None:
                raise InputError(
                    f"contact.{side}_material",
                    f"the contact stress needs the {side}'s material: give "
                    f"contact.{side}_material (a name) or contact.{side}_modulus (GPa) and "
                    f"contact.{side}_poisson",
                )
            if v is None and getattr(self, f"{side}_poisson") is None:
                raise InputError(
                    f"contact.{side}_poisson",
                    f"contact.{side}_modulus needs its Poisson's ratio (contact.{side}_poisson, in (-1, 0.5))",
                )


#: The keys of a design file's [contact] table, in their documented order: the fields of :class:`ContactSpec`.
CONTACT_KEYS = tuple(f.name for f in fields(ContactSpec))
