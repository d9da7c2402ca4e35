"""Manufacturing from the cam's profile: the exports of the profile now, its tool paths next.

The exports write the profile (:mod:`cams.profile`) for the workshop, each in its own module:
:mod:`~cams.manufacture.points` (the CSV of the sampled points), :mod:`~cams.manufacture.dxf` (the DXF drawing) and
:mod:`~cams.manufacture.svg` (the SVG drawing to scale), sharing the drawings' frame, layers and the written
coordinates' digits (:mod:`~cams.manufacture.drawing`); the drawings' curves are arcs or a spline fitted to the
exact curves and certified (:mod:`~cams.manufacture.curves`), their bore carries its keyway and the timing datum
(:mod:`~cams.manufacture.keyway`). A drawing is read back by :mod:`~cams.manufacture.readback` (its ``PROFILE``'s
lines, arcs and splines) and the motion its curve gives is measured by :mod:`~cams.manufacture.motion` (``cams
profile``'s ``export_motion``). Tool paths from the profile (a cutter's centre path, its feeds) will live here too.
The package sits above :mod:`cams.profile` and :mod:`cams.io` (whose :func:`~cams.io.files.atomic_write` puts a
file in place whole or not at all) and below the commands; the design file's schema and its readers stay in
:mod:`cams.io`.
"""

__all__: list[str] = []
