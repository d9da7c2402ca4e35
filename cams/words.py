"""How the product prints its quantities and names: one home per quantity.

Every command, the report and the pictures format a quantity through this
module, so the same quantity reads the same (unit, precision) everywhere:

* angles in degrees, 4 decimals (:func:`deg`);
* lengths in mm with enough decimals for the design's size (:func:`length_format`);
* forces in N, torques in N m, spring rates in N/m (translating) or N m/rad
  (rocker, a torsional spring) (:func:`spring_text`, :func:`force`);
* the seed's constraint lines with their phase and cam angle (:func:`binding_text`);
* the checks of a profile in words a student reads (:data:`CHECK_WORDS`).

Light: imports nothing heavier than the standard library.
"""

from __future__ import annotations

import math

__all__ = [
    "ANGLE_DECIMALS",
    "CHECK_WORDS",
    "deg",
    "length_format",
    "length",
    "number",
    "force",
    "torque",
    "spring_units",
    "spring_text",
    "spring_words",
    "torque_words",
    "binding_text",
    "check_words",
    "FAULT_WORDS",
    "fault_words",
    "phase_words",
    "bore_text",
    "check_value",
    "off_by",
    "duration",
    "COUNT_UNITS",
    "check_unit",
]

#: Decimals of an angle in degrees, everywhere.
ANGLE_DECIMALS = 4

#: The checks of :mod:`cams.checks.profile` and :mod:`cams.checks.flat` in words (name: what it checks).
CHECK_WORDS = {
    "jamming_rise": "pressure angle, rise",
    "jamming_return": "pressure angle, return",
    "undercut": "no undercut: pitch curve's smallest convex radius of curvature, limit the roller radius",
    "undercut_outer": "no undercut of the groove's outer wall: smallest concave radius of curvature, limit the "
                      "roller radius",
    "min_curvature_radius": "working profile's smallest radius of curvature",
    "profile_polygon": "working profile is one closed curve",
    "outer_polygon": "groove's outer wall is one closed curve",
    "bore": "bore inside the cam: working profile's smallest radius, limit the bore radius plus the hub wall",
    "convexity": "convex profile: smallest radius of curvature, limit limits.min_radius",
}


#: A failed check in a few words (name: what is wrong), for the lines and titles of a failing cam.
FAULT_WORDS = {
    "jamming_rise": "pressure angle above its limit on the rise",
    "jamming_return": "pressure angle above its limit on the return",
    "undercut": "undercut",
    "undercut_outer": "undercut of the groove's outer wall",
    "min_curvature_radius": "radius of curvature too small",
    "profile_polygon": "working profile crosses itself",
    "outer_polygon": "groove's outer wall crosses itself",
    "bore": "bore",
    "convexity": "profile not convex (radius of curvature below limits.min_radius)",
}


#: The checks whose values are counts (no unit in their record), and what they count.
COUNT_UNITS = {"profile_polygon": "self-crossing(s)", "outer_polygon": "self-crossing(s)"}


def check_unit(name: str, unit: str) -> str:
    """The unit printed beside the check ``name``'s values: its own, or what its count counts.

    >>> check_unit("profile_polygon", "")
    'self-crossing(s)'
    >>> check_unit("bore", "mm")
    'mm'
    """
    return unit or COUNT_UNITS.get(name, "")


def fault_words(name: str) -> str:
    """What is wrong when the check ``name`` fails, in a few words (the name itself when it has none).

    >>> fault_words("profile_polygon")
    'working profile crosses itself'
    """
    return FAULT_WORDS.get(name, name.replace("_", " "))


def check_words(name: str) -> str:
    """The words of a check's internal ``name`` (the name itself when it has none).

    >>> check_words("profile_polygon")
    'working profile is one closed curve'
    """
    return CHECK_WORDS.get(name, name.replace("_", " "))


def number(x: float, digits: int = 6) -> str:
    """A value with ``digits`` significant digits, round-off noise removed.

    >>> number(29.999999999999993)
    '30'
    >>> number(0.1 + 0.2)
    '0.3'
    """
    if x is None:
        return "-"
    return f"{float(x):.{digits}g}"


def deg(x: float | None, *, radians: bool = False) -> str:
    """An angle for print: degrees with :data:`ANGLE_DECIMALS` decimals and its unit, ``-`` for None.

    >>> deg(45.0)
    '45.0000 deg'
    >>> deg(math.pi / 4, radians=True)
    '45.0000 deg'
    """
    if x is None:
        return "-"
    v = math.degrees(x) if radians else float(x)
    return f"{v:.{ANGLE_DECIMALS}f} deg"


def length_format(scale: float) -> str:
    """Format spec for lengths of a design of size ``scale``: 6 decimals, more for designs under 1 mm.

    Keeps about seven significant digits of the design's size, so a
    micrometre cam does not print as ``0.000000``; at 1 mm and above it is
    ``.6f``.

    >>> length_format(13.2)
    '.6f'
    >>> length_format(0.001)
    '.9f'
    """
    if not (scale > 0 and math.isfinite(scale)):
        return ".6f"
    return f".{min(15, max(6, 6 - math.floor(math.log10(scale))))}f"


def length(x: float | None, scale: float | None = None) -> str:
    """A length in mm for print, decimals by :func:`length_format` (``scale`` defaults to ``|x|``).

    >>> length(13.2407931)
    '13.240793 mm'
    """
    if x is None:
        return "-"
    return f"{x:{length_format(abs(x) if scale is None else scale)}} mm"


def force(x: float | None, digits: int = 6) -> str:
    """A force in N: ``UNBOUNDED`` for ``inf`` (a rigid impact) or None (its JSON form).

    >>> force(12.09481234)
    '12.0948 N'
    """
    if x is None or x == float("inf"):
        return "UNBOUNDED"
    if x == float("-inf"):
        return "-UNBOUNDED"
    return f"{x:.{digits}g} N"


def torque(x: float | None, digits: int = 6) -> str:
    """A torque in N m (``UNBOUNDED`` as :func:`force`)."""
    t = force(x, digits)
    return t if "UNBOUNDED" in t else t[:-2] + " N m"


def spring_units(follower: str) -> tuple[str, str]:
    """Units of a closing spring's rate and preload: ``("N/m", "N")``, or ``("N m/rad", "N m")`` for a rocker.

    >>> spring_units("rocker")
    ('N m/rad', 'N m')
    """
    return ("N m/rad", "N m") if follower == "rocker" else ("N/m", "N")


def spring_text(rate: float, preload: float, follower: str, digits: int = 6) -> str:
    """A closing spring for print: ``rate 3 N m/rad, preload 0 N m`` (torsional for a rocker).

    >>> spring_text(2000.0, 15.0, "translating")
    'rate 2000 N/m, preload 15 N'
    """
    ru, pu = spring_units(follower)
    return f"rate {rate:.{digits}g} {ru}, preload {preload:.{digits}g} {pu}"


def spring_words(sp: dict, follower: str, digits: int = 6) -> str:
    """A chosen or given spring for print (from ``Spring.to_dict``): rate, preload, installed compression (a
    rocker's torsional spring: installed twist) and largest force, each with its unit.

    >>> spring_words({"rate": 2000.0, "preload": 15.0, "installed_compression": 7.5, "max_force": 75.0},
    ...              "translating")
    'rate 2000 N/m, preload 15 N, installed compression 7.5 mm, largest force 75 N'
    >>> spring_words({"rate": 0.0, "preload": 9.0, "installed_compression": None, "max_force": 9.0},
    ...              "translating")
    'rate 0 N/m, preload 9 N, installed compression - (a constant-force spring), largest force 9 N'
    """
    _, pu = spring_units(follower)
    key, unit = ("installed_twist", "deg") if follower == "rocker" else ("installed_compression", "mm")
    inst = sp.get(key)
    if inst is None:
        installed = "- (no spring)" if sp["rate"] == 0 and sp["preload"] == 0 else "- (a constant-force spring)"
    else:
        installed = f"{inst:.{digits}g} {unit}"
    out = f"{spring_text(sp['rate'], sp['preload'], follower, digits)}, installed {key[10:]} {installed}"
    if sp.get("max_force") is not None:
        out += f", largest force {sp['max_force']:.{digits}g} {pu}"
    return out


def torque_words(value: float | None, at_deg: float | None, kind: str, digits: int = 6, *,
                 where: str | None = None) -> str:
    """The largest ``kind`` ("driving" or "braking") camshaft torque for print, its size in N·m and its cam angle.

    A braking torque is negative in the JSON (the sign convention: positive in the cam's sense of rotation, where
    the camshaft delivers work); its words give its size. ``inf`` or None: unbounded (a rigid impact).
    ``where`` replaces the cam angle's words (e.g. a machine's cycle angles beside it).

    >>> torque_words(-3.14729, 254.0, "braking")
    'largest braking torque 3.14729 N·m at 254.0000 deg'
    >>> torque_words(0.0, None, "driving")
    'no driving torque'
    >>> torque_words(float("inf"), 0.0, "driving")
    'largest driving torque unbounded (rigid impact at 0.0000 deg)'
    """
    if at_deg is None:
        return f"no {kind} torque"
    at = deg(at_deg) if where is None else where
    if value is None or math.isinf(value):
        return f"largest {kind} torque unbounded (rigid impact at {at})"
    return f"largest {kind} torque {abs(value):.{digits}g} N·m at {at}"


def phase_words(kind: str | None, index: int) -> str:
    """A phase for print: its number, the index of its ``[[motion]]`` table from 0 (as JSON's ``phase``), and kind.

    One numbering everywhere: the text, the pictures' legends, the messages and JSON's ``binding[].phase``.

    >>> phase_words("rise", 0)
    'phase 0 (rise)'
    """
    return f"phase {index}" + (f" ({kind})" if kind else "")


def binding_text(b: dict) -> str:
    """A binding line (as in ``SolveResult.to_dict()["binding"]``): name, cam angle and phase.

    >>> binding_text({"line": "t-t", "phi": 48.86221, "phase": 0, "phase_kind": "rise"})
    't-t at 48.8622 deg in phase 0 (rise)'
    """
    return f"{b['line']} at {deg(b['phi'])} in {phase_words(b.get('phase_kind'), b['phase'])}"


def bore_text(radius: float, suggested: bool) -> str:
    """The bore for print: a given one (``[cam] bore_radius``), or the automatic one as a suggestion.

    The suggested bore is not checked and not drawn in the manufacturing files.

    >>> bore_text(2.59244, True)
    'suggested bore radius 2.592440 mm (not checked, not in the files: set [cam] bore_radius)'
    """
    if suggested:
        return f"suggested bore radius {length(radius)} (not checked, not in the files: set [cam] bore_radius)"
    return f"bore radius {length(radius)}"


def check_value(x: float | None, unit: str, f: str = ".6f") -> str:
    """A check's value (:class:`cams.checks.profile.Check`).

    Lengths in mm with format ``f``, angles by :func:`deg`, counts.

    >>> check_value(2.0, "")
    '2'
    >>> check_value(6.6203969, "mm")
    '6.620397 mm'
    """
    if x is None:
        return "-"
    if not unit and float(x).is_integer():
        return str(int(x))
    if unit == "deg":
        return deg(x)
    if unit == "mm":
        return f"{x:{f}} mm"
    return f"{number(x)} {unit}".rstrip()


def off_by(worst: float | None, limit: float | None, unit: str) -> str:
    """How far a failed check's ``worst`` value is on the wrong side of its ``limit``: ``": off by 6.620397 mm"``.

    "" when either is unknown.

    >>> off_by(13.240793, 19.86119, "mm")
    ': off by 6.620397 mm'
    """
    if worst is None or limit is None:
        return ""
    return f": off by {check_value(abs(worst - limit), unit)}"


def duration(seconds: float) -> str:
    """A run time for print: milliseconds under a second, seconds from there.

    >>> duration(0.0152)
    '15.2 ms'
    >>> duration(5.4123)
    '5.41 s'
    """
    return f"{seconds * 1e3:.1f} ms" if seconds < 1.0 else f"{seconds:.3g} s"
