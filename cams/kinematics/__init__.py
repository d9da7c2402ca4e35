"""The product's kinematics kernel: one home for every geometric fact of the cam.

:mod:`cams.kinematics.vectors` holds the planar vectors (arrays whose last axis
is ``(x, y)``), :mod:`cams.kinematics.inversion` the one inversion of a roller
or knife-edge follower's motion (pitch curve, its derivatives, outward normal,
signed curvature, pressure angle and their rates), :mod:`cams.kinematics.flat`
the flat face's envelope, :mod:`cams.kinematics.extremum` the one vectorized
extremum search, :mod:`cams.kinematics.exported` the follower in contact with an exported curve
(lines, arcs, spline pieces: the motion an export really gives). Profiles, checks, forces and pictures use
them; the independent check (:mod:`cams.verify`) and the solvers
(:mod:`optimize`) keep their own formulas by design.
"""
