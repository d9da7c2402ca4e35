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
rpm = 60                     # optional: time derivatives in the motion diagrams; needed by [dynamics]
# The shaft's bore (optional): the cam is sized to clear it by the hub wall, cams check checks it and the
# drawings show it; without it the commands suggest one.
# bore_radius = 6.0           # mm
# hub_wall = 3.0             # mm of material at least between the bore and the working profile
# keyway_width = 4.0         # mm: a keyway in the bore (with keyway_depth, mm from the bore's surface,
# keyway_depth = 1.8         #   and keyway_angle, degrees from the datum in the cam's sense of rotation)
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

# Forces at the cam (optional; force closure, needs [cam] rpm): the spring chosen, the contact force, the
# camshaft torque and the speed at which the follower jumps; cams check fails a cam that loses contact.
# [dynamics]
# mass = 0.003               # kg m^2: the rocker's moment of inertia about its pivot
# load = 0.5                 # N m opposing the rise
# friction = 0.1             # in the pivot's journal
# journal_radius = 8.0       # mm
# margin = 1.2               # the spring's force >= margin x the force pulling the follower off the cam

# Design a law together with the cam (optional; cams solve then takes seconds, a rocker's about a
# minute): the rise's law becomes a spline, the smallest cam under caps on its normalized peaks, with a
# proven lower bound.
# [optimize]
# free = ["rise"]            # "rise", "return" or phase numbers (the [[motion]] tables' order from 0)
# objective = "R0"           # "R0" | "pressure_angle" | "Ca" | "Cj" | "jerk_squared" | "snap_squared"
# max_Ca = "cycloidal"       # caps on the normalized peaks: a law's name (its peak) or a number
# max_Cj = "cycloidal"
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
# rpm = 120                  # optional: time derivatives in the motion diagrams; needed by [dynamics]
# The shaft's bore (optional): the cam is sized to clear it by the hub wall, cams check checks it and the
# drawings show it; without it the commands suggest one.
# bore_radius = 5.0           # mm
# hub_wall = 3.0             # mm of material at least between the bore and the working profile
# keyway_width = 4.0         # mm: a keyway in the bore (with keyway_depth, mm from the bore's surface,
# keyway_depth = 1.8         #   and keyway_angle, degrees from the datum in the cam's sense of rotation)
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

# Forces at the cam (optional; force closure, needs [cam] rpm): the spring chosen, the contact force, the
# camshaft torque and the speed at which the follower jumps; cams check fails a cam that loses contact.
# [dynamics]
# mass = 0.5                 # kg: the follower's mass (add a third of the spring's)
# load = 5.0                 # N opposing the rise
# friction = 0.1             # in the follower's guide
# margin = 1.2               # the spring's force >= margin x the force pulling the follower off the cam

# Design a law together with the cam (optional; cams solve then takes seconds): the rise's law becomes a
# spline, the smallest cam under caps on its normalized peaks, with a proven lower bound.
# [optimize]
# free = ["rise"]            # "rise", "return" or phase numbers (the [[motion]] tables' order from 0)
# objective = "R0"           # "R0" | "pressure_angle" | "Ca" | "Cj" | "jerk_squared" | "snap_squared"
# max_Ca = "poly345"         # caps on the normalized peaks: a law's name (its peak) or a number
# max_Cj = "poly345"
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
# The shaft's bore (optional): the cam is sized to clear it by the hub wall, cams check checks it and the
# drawings show it; without it the commands suggest one.
# bore_radius = 8.0           # mm
# hub_wall = 3.0             # mm of material at least between the bore and the working profile
# keyway_width = 4.0         # mm: a keyway in the bore (with keyway_depth, mm from the bore's surface,
# keyway_depth = 1.8         #   and keyway_angle, degrees from the datum in the cam's sense of rotation)

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

# Forces at the cam (optional; force closure, needs [cam] rpm): the spring chosen, the contact force, the
# camshaft torque and the speed at which the follower jumps; cams check fails a cam that loses contact.
# [dynamics]
# mass = 0.5                 # kg: the follower's mass (add a third of the spring's)
# load = 5.0                 # N opposing the rise
# friction = 0.1             # in the follower's guide
# face_friction = 0.05        # sliding at the flat face (dimensionless)
# margin = 1.2               # the spring's force >= margin x the force pulling the follower off the cam

# Design a law together with the cam (optional; cams solve then takes seconds): the rise's law becomes a
# spline, the smallest cam under caps on its normalized peaks, with a proven lower bound.
# [optimize]
# free = ["rise"]            # "rise", "return" or phase numbers (the [[motion]] tables' order from 0)
# objective = "R0"           # "R0" | "pressure_angle" | "Ca" | "Cj" | "jerk_squared" | "snap_squared"
# max_Ca = "cycloidal"       # caps on the normalized peaks: a law's name (its peak) or a number
# max_Cj = "cycloidal"
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
# The shaft's bore (optional): the cam is sized to clear it by the hub wall, cams check checks it and the
# drawings show it; without it the commands suggest one.
# bore_radius = 8.0           # mm
# hub_wall = 3.0             # mm of material at least between the bore and the working profile
# keyway_width = 4.0         # mm: a keyway in the bore (with keyway_depth, mm from the bore's surface,
# keyway_depth = 1.8         #   and keyway_angle, degrees from the datum in the cam's sense of rotation)

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

# Forces at the cam (optional; force closure, needs [cam] rpm): the spring chosen, the contact force, the
# camshaft torque and the speed at which the follower jumps; cams check fails a cam that loses contact.
# [dynamics]
# mass = 0.003               # kg m^2: the rocker's moment of inertia about its pivot
# load = 0.5                 # N m opposing the rise
# friction = 0.1             # in the pivot's journal
# face_friction = 0.05        # sliding at the flat face (dimensionless)
# journal_radius = 8.0       # mm
# margin = 1.2               # the spring's force >= margin x the force pulling the follower off the cam

# Design a law together with the cam (optional; cams solve then takes seconds): the rise's law becomes a
# spline, the smallest cam under caps on its normalized peaks, with a proven lower bound.
# [optimize]
# free = ["rise"]            # "rise", "return" or phase numbers (the [[motion]] tables' order from 0)
# objective = "R0"           # "R0" | "pressure_angle" | "Ca" | "Cj" | "jerk_squared" | "snap_squared"
# max_Ca = "cycloidal"       # caps on the normalized peaks: a law's name (its peak) or a number
# max_Cj = "cycloidal"
'''

#: Template text by follower kind (``_flat``: flat-faced follower).
TEMPLATES = {"rocker": _ROCKER, "translating": _TRANSLATING, "rocker_flat": _ROCKER_FLAT,
             "translating_flat": _TRANSLATING_FLAT}
