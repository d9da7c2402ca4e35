"""The cam's working profile: roller (and knife edge) followers, flat faces."""
