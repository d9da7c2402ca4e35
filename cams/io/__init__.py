"""Everything that knows the design file's schema: reading design files, templates, exports, whole-or-nothing output."""
