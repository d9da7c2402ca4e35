"""Design builders for the validation tests (design-file dicts, degrees and lengths)."""

from __future__ import annotations

from cams.io.designfile import design_from_dict


def _motion(rise, dwell, ret) -> list:
    """Rise, dwell, return and a dwell taking the rest of 360 degrees; ``rise``, ``ret`` are (law, angle)."""
    return [
        {"phase": "rise", "law": rise[0], "angle": rise[1]},
        {"phase": "dwell", "angle": dwell},
        {"phase": "return", "law": ret[0], "angle": ret[1]},
        {"phase": "dwell"},
    ]


def rocker_dict(*, arm=125.0, swing=15.0, rise_direction="cw", rotation="ccw",
                rise=("cycloidal", 120.0), dwell=30.0, ret=("cycloidal", 120.0),
                limit=45.0, return_limit=None, closure="force", safety_factor=1.0,
                centre_distance=None, roller_radius=10.0, samples=120, name="rocker") -> dict:
    """A rocker design: rise, dwell, return, dwell (the last takes the rest of 360)."""
    limits = {"pressure_angle": limit, "closure": closure, "safety_factor": safety_factor}
    if return_limit is not None:
        limits["return_pressure_angle"] = return_limit
    if centre_distance is not None:
        limits["centre_distance"] = centre_distance
    return {
        "name": name,
        "follower": {"kind": "rocker", "arm": arm, "swing": swing, "roller_radius": roller_radius,
                     "rise_direction": rise_direction},
        "cam": {"rotation": rotation},
        "motion": _motion(rise, dwell, ret),
        "limits": limits,
        "solve": {"samples": samples, "constraints": "pressure_angle"},   # the solvers' answer, validated
    }


def translating_dict(*, stroke=30.0, offset=None, rotation="ccw", rise=("poly4567", 150.0), dwell=30.0,
                     ret=("cycloidal", 120.0), limit=30.0, return_limit=None, closure="force",
                     roller_radius=8.0, samples=120, name="translating") -> dict:
    """A translating design: rise, dwell, return, dwell (the last takes the rest of 360)."""
    fo = {"kind": "translating", "stroke": stroke, "roller_radius": roller_radius}
    if offset is not None:
        fo["offset"] = offset
    limits = {"pressure_angle": limit, "closure": closure}
    if return_limit is not None:
        limits["return_pressure_angle"] = return_limit
    return {
        "name": name,
        "follower": fo,
        "cam": {"rotation": rotation},
        "motion": _motion(rise, dwell, ret),
        "limits": limits,
        "solve": {"samples": samples, "constraints": "pressure_angle"},   # the solvers' answer, validated
    }


def rocker(**kw):
    return design_from_dict(rocker_dict(**kw))


def translating(**kw):
    return design_from_dict(translating_dict(**kw))


#: Designs for the brute-force comparison (K_C = 1): name -> design-file dict.
BRUTE_DESIGNS = {
    # seed 001's senses: rocker cw on the rise, cam ccw (O1D = l (1 + psi'))
    "rocker force, opposite senses": rocker_dict(),
    # rocker and cam turning the same way on the rise
    "rocker force, same sense": rocker_dict(rise_direction="ccw"),
    "rocker form, opposite senses": rocker_dict(rise=("poly345", 120.0), ret=("harmonic", 100.0),
                                                limit=45.0, return_limit=50.0, closure="form"),
    "rocker form, same sense": rocker_dict(rise_direction="ccw", rotation="ccw", rise=("poly345", 120.0),
                                           ret=("cycloidal", 100.0), limit=40.0, return_limit=50.0,
                                           closure="form"),
    "rocker form, cam cw, long arm": rocker_dict(arm=300.0, swing=25.0, rise_direction="ccw", rotation="cw",
                                                 rise=("poly4567", 140.0), ret=("parabolic", 110.0),
                                                 limit=35.0, return_limit=55.0, closure="form"),
    "translating force, free offset": translating_dict(),
    "translating form, free offset, cam cw": translating_dict(rotation="cw", rise=("cycloidal", 100.0),
                                                              ret=("poly345", 140.0), limit=35.0,
                                                              return_limit=40.0, closure="form"),
}

#: Fixed offset 0 (centric) designs: searched on the line x = 0.
CENTRIC_DESIGNS = {
    "translating form, centric, cam cw": translating_dict(stroke=20.0, offset=0.0, rotation="cw",
                                                          rise=("cycloidal", 120.0), dwell=60.0,
                                                          ret=("poly345", 120.0), closure="form"),
    "translating force, centric, cam ccw": translating_dict(offset=0.0),
}
