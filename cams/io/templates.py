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
# To check a cam you chose instead of sizing the smallest (no min_base_radius then):
# base_radius = 18.0         # R0, with limits.centre_distance (L) below; or
# centre = [133.0, 13.0]     # the cam centre in the rocker's frame (pivot at the origin, X along the arm)

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
# To check a cam you chose instead of sizing the smallest (no min_base_radius then):
# base_radius = 26.0         # R0, with follower.offset above; or
# centre = [-8.0, -16.0]     # the cam centre (origin at the roller centre at the bottom, Y along the rise)

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

_TRANSLATING_FLAT = '''# A translating flat-faced (mushroom) follower disk cam. Lengths in mm, angles in degrees.
# The face's pressure angle is fixed by the geometry (0: the face is perpendicular to the axis);
# the cam is sized by convexity: the smallest base radius whose profile keeps its radius of
# curvature >= limits.min_radius. No roller_radius, pressure-angle limits or [solve] table.
name = "my translating flat-face cam"

[follower]
kind = "translating"
face = "flat"
stroke = 20.0                # total stroke
offset = 0.0                 # axis offset; it only moves the contact along the face

[cam]
rotation = "ccw"             # "cw" | "ccw"
# rpm = 120                  # optional: time derivatives in the motion diagrams
# base_radius = 30.0         # optional: check this R0 instead of sizing the smallest

# Laws without velocity jumps (a drop of the follower's velocity gives the cam a cusp).
[[motion]]
phase = "rise"
law = "cycloidal"
angle = 120
[[motion]]
phase = "dwell"
angle = 60
[[motion]]
phase = "return"
law = "poly345"
angle = 120
[[motion]]
phase = "dwell"

[limits]
min_radius = 5.0             # smallest radius of curvature of the profile (default stroke / 10)
# min_base_radius = 25.0     # constructive floor on R0

[profile]
tolerance = 0.001            # chord tolerance of the exported profile, mm
'''

_ROCKER_FLAT = '''# A rocker (oscillating) flat-faced follower disk cam. Lengths in mm, angles in degrees.
# The face's pressure angle is fixed by the geometry (0 when the face passes through the pivot);
# the cam is sized by convexity: the smallest base radius whose profile keeps its radius of
# curvature >= limits.min_radius. No arm, roller_radius, pressure-angle limits or [solve] table.
name = "my rocker flat-face cam"

[follower]
kind = "rocker"
face = "flat"
swing = 15.0                 # total swing, degrees (< 180)
centre_distance = 120.0      # L, pivot to cam centre (required)
face_offset = 0.0            # pivot to face line; positive: the pivot on the cam's side of the face
rise_direction = "cw"        # the rocker's sense of rotation during the rise

[cam]
rotation = "ccw"             # "cw" | "ccw"
# rpm = 60
# base_radius = 45.0         # optional: check this R0 instead of sizing the smallest

[[motion]]
phase = "rise"
law = "cycloidal"
angle = 120
[[motion]]
phase = "dwell"
angle = 40
[[motion]]
phase = "return"
law = "poly345"
angle = 120
[[motion]]
phase = "dwell"

[limits]
min_radius = 5.0             # smallest radius of curvature of the profile (default L * swing[rad] / 10)

[profile]
tolerance = 0.001
'''

#: Template text by follower kind (``_flat``: flat-faced follower).
TEMPLATES = {"rocker": _ROCKER, "translating": _TRANSLATING, "rocker_flat": _ROCKER_FLAT,
             "translating_flat": _TRANSLATING_FLAT}
