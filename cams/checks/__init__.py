"""Checks of a solved cam: jamming, undercut, the profile as a polygon, the bore."""
