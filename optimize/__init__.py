"""Solvers for the allowable-centre zone and the minimum-size cam."""

__all__: list[str] = []
