"""A flat-face cam far larger than its follower: the convexity check's tolerance follows R0 (issue 12, item 1).

Independent reference: the definition ``rho = R0 + s + s''`` of a translating flat face. With rise and
return angles of hundredths of a degree, ``s''`` reaches about ``-1e9`` mm, so R0 ~ 1e9 mm for a 20 mm
stroke; ``rho`` at the minimum then carries the rounding of a sum of 1e9-sized terms (``eps * R0`` ~ 1e-7 mm),
more than the former tolerance of 1e-9 of the stroke (2e-8 mm): the minimal cam was reported "verified: no".
The tolerance must still refuse a base radius really too small.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from cams.cli import main
from cams.io.designfile import design_from_dict
from optimize.flat import size_flat_face

RMIN = 10.123456789  # not a multiple of R0's unit in the last place: R0 + s + s'' does not round back to it


def _dict(angle: float) -> dict:
    return {"name": "flat, tiny phases",
            "follower": {"kind": "translating", "face": "flat", "stroke": 20.0},
            "cam": {"rotation": "ccw"},
            "motion": [{"phase": "rise", "law": "cycloidal", "angle": angle},
                       {"phase": "dwell", "angle": (360 - 2 * angle) / 2},
                       {"phase": "return", "law": "poly345", "angle": angle},
                       {"phase": "dwell"}],
            "limits": {"min_radius": RMIN},
            "profile": {"tolerance": 1000.0}}


@pytest.mark.parametrize("angle", [0.014466, 0.017275])
def test_minimal_flat_face_cam_far_larger_than_its_follower_is_verified(angle, tmp_path):
    sol = size_flat_face(design_from_dict(_dict(angle)))
    assert sol.R0 > 1e9
    # rho = R0 + s + s'' is RMIN at the minimum, to the rounding of terms of size R0
    assert abs(sol.min_rho - RMIN) <= 8 * np.finfo(float).eps * sol.R0
    assert sol.verified
    # a radius of curvature 1e-4 mm short of the limit (a thousand times the rounding) is still refused
    assert not replace(sol, min_rho=RMIN - 1e-4).verified
    f = tmp_path / "d.toml"
    f.write_text(_toml(_dict(angle)))
    assert main(["solve", str(f)]) == 0


def _toml(d: dict) -> str:
    out = [f'name = "{d["name"]}"', "[follower]", 'kind = "translating"', 'face = "flat"', "stroke = 20.0",
           "[cam]", 'rotation = "ccw"']
    for m in d["motion"]:
        out.append("[[motion]]")
        out += [f'{k} = "{v}"' if isinstance(v, str) else f"{k} = {v!r}" for k, v in m.items()]
    out += ["[limits]", f"min_radius = {RMIN!r}", "[profile]", "tolerance = 1000.0"]
    return "\n".join(out) + "\n"
