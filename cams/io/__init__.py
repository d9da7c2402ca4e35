"""Everything that knows the design file's schema: reading design files, templates, whole-or-nothing output.

The exports of the profile (CSV, DXF, SVG) are in :mod:`cams.manufacture`.
"""
