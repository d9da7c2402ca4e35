"""A small table of common cam and follower materials, each value with its source.

Units: elastic modulus ``E`` and stresses in MPa (N/mm^2, the unit of a force in N over a length in mm squared),
Poisson's ratio dimensionless. ``allowable`` is an allowable (limiting) Hertzian contact stress ``p0`` for long life;
``yield_strength`` the tensile yield (0.2 % proof) stress, None where no single value stands for the material.

Sources, cited by title:

* elastic constants of steels and cast iron: J. E. Shigley, C. R. Mischke, R. G. Budynas, *Mechanical Engineering
  Design* (Shigley), table A-5, "Physical constants of materials" (carbon steel E = 207 GPa, nu = 0.292; grey cast
  iron E = 100 GPa, nu = 0.211); R. L. Norton, *Machine Design: An Integrated Approach*, appendix C (steel 30 Mpsi =
  206.8 GPa, nu = 0.28) -- the values below (206 GPa, 0.30) are the **typical** values contact calculations use;
* bearing steel (100Cr6, AISI 52100): the rolling-bearing catalogues' E = 208 GPa, nu = 0.3 (typical);
* allowable contact stress of gear steels: ISO 6336-5, *Calculation of load capacity of spur and helical gears --
  Part 5: Strength and quality of materials*, its allowable stress number (contact) sigma_Hlim, quality MQ:
  case-hardened (carburized) wrought steels 1500 MPa, nitrided (nitriding steels) 1250 MPa, through-hardened alloy
  steel about 770 MPa at 300 HV (read off its graph: a **typical** value, it rises with the hardness);
  grey cast iron about 370 MPa at 200 HB (its graph: typical);
* R. L. Norton, *Cam Design and Manufacturing Handbook*, chapter on failure of cams (surface fatigue), uses these
  allowables for cams and warns that they are for gears at 5e7 cycles: a cam's contact turns once per revolution.

Every value is a typical one: the material's certificate, its heat treatment and its hardness decide; a design
file may give the values themselves (``[contact] cam_modulus``... and ``allowable_stress``).
"""

from __future__ import annotations

from dataclasses import dataclass

from laws.errors import InputError

__all__ = ["Material", "MATERIALS", "material"]


@dataclass(frozen=True)
class Material:
    """A material's elastic constants and strength.

    Attributes
    ----------
    name : str
        The name a design file gives (``[contact] cam_material``).
    modulus : float
        Young's modulus E (MPa).
    poisson : float
        Poisson's ratio nu (dimensionless).
    allowable : float or None
        Allowable Hertzian contact stress p0 (MPa), None where not stated.
    yield_strength : float or None
        Tensile yield strength (MPa), None where no single value stands for the material.
    source : str
        Where the values come from (titles), and whether they are typical.
    """

    name: str
    modulus: float
    poisson: float
    allowable: float | None
    yield_strength: float | None
    source: str


_SHIGLEY = "Shigley's Mechanical Engineering Design, table A-5 (typical)"
_ISO = "ISO 6336-5, sigma_Hlim quality MQ"

#: The known materials, by name.
MATERIALS: dict[str, Material] = {
    m.name: m
    for m in (
        Material("steel", 206e3, 0.30, None, None, f"{_SHIGLEY}; no allowable: give the heat treatment's material"),
        Material(
            "through_hardened_steel",
            206e3,
            0.30,
            770.0,
            700.0,
            f"{_SHIGLEY}; {_ISO}, through-hardened alloy steel about 300 HV (typical, read off its graph); "
            "yield typical of a quenched and tempered 42CrMo4",
        ),
        Material(
            "case_hardened_steel",
            206e3,
            0.30,
            1500.0,
            None,
            f"{_SHIGLEY}; {_ISO}, case-hardened wrought steel; yield: the core's, not one value",
        ),
        Material("nitrided_steel", 206e3, 0.30, 1250.0, None, f"{_SHIGLEY}; {_ISO}, nitrided nitriding steel"),
        Material(
            "bearing_steel",
            208e3,
            0.30,
            1500.0,
            None,
            "rolling-bearing catalogues' 100Cr6 (AISI 52100) elastic constants (typical); allowable taken as "
            "case-hardened steel's (ISO 6336-5 MQ)",
        ),
        Material(
            "grey_cast_iron",
            100e3,
            0.21,
            370.0,
            None,
            f"{_SHIGLEY} (grey cast iron); {_ISO}, grey cast iron about 200 HB (typical, read off its graph)",
        ),
    )
}


def material(name: object, field: str) -> Material:
    """The material named ``name`` (a design file's ``field``), or an :class:`InputError` listing the known ones."""
    if not isinstance(name, str) or name not in MATERIALS:
        raise InputError(field, f"unknown material {name!r}; known: {', '.join(MATERIALS)}")
    return MATERIALS[name]
