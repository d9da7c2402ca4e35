"""Commented design files to start from (``cams new KIND``)."""

from __future__ import annotations

__all__ = ["TEMPLATES"]

_ROCKER = '''# A rocker-roller disk cam (seed 001). Lengths in mm, angles in degrees.
name = "my rocker cam"

[follower]
kind = "rocker"
arm = 125.0                  # pivot to roller centre
swing = 15.0                 # total swing of the rocker, degrees (< 180)
roller_radius = 10.0         # 0 = knife edge
rise_direction = "cw"        # the rocker's sense of rotation during the rise

[cam]
rotation = "ccw"             # the cam's sense of rotation ("cw" | "ccw")
rpm = 60                     # optional: time derivatives in the motion diagrams

# Phases in order over one turn; one dwell may omit its angle (the rest of 360).
# Laws: linear, parabolic, harmonic, cycloidal, poly345, poly4567,
#       modified_trapezoid, modified_sine, modified_cycloid  (see: cams laws)
[[motion]]
phase = "rise"
law = "cycloidal"
angle = 120
[[motion]]
phase = "dwell"
angle = 30
[[motion]]
phase = "return"
law = "cycloidal"
angle = 120
[[motion]]
phase = "dwell"

[limits]
pressure_angle = 45          # allowable on the rise, (0, 90)
# return_pressure_angle = 50 # form closure: allowable on the return
closure = "force"            # "force" (spring) | "form" (groove)
safety_factor = 1.0          # K_C >= 1, seed formula 3.26
# centre_distance = 130.0    # fixed L (seed 3.23-3.25)
# min_base_radius = 30.0     # constructive floor on R0

[solve]
method = "exact"             # "exact" | "convex" | "exhaustive"
samples = 360                # convex/exhaustive: steps per phase

[profile]
tolerance = 0.001            # chord tolerance of the exported profile, mm
'''

_TRANSLATING = '''# A translating roller follower disk cam. Lengths in mm, angles in degrees.
name = "my translating cam"

[follower]
kind = "translating"
stroke = 30.0                # total stroke
roller_radius = 8.0          # 0 = knife edge
# offset = 0.0               # fixed offset (0 = centric); omit to let the solver choose it

[cam]
rotation = "ccw"

[[motion]]
phase = "rise"
law = "poly345"
angle = 150
[[motion]]
phase = "dwell"
angle = 30
[[motion]]
phase = "return"
law = "cycloidal"
angle = 120
[[motion]]
phase = "dwell"

[limits]
pressure_angle = 30          # allowable on the rise, (0, 90)
closure = "force"            # "force" | "form"

[solve]
method = "exact"

[profile]
tolerance = 0.001
'''

#: Template text by follower kind.
TEMPLATES = {"rocker": _ROCKER, "translating": _TRANSLATING}
