"""What the user sees: pictures (each returns a Figure) and the report."""
