"""Motion design: the free phases' laws and the cam, optimized together.

``space`` holds the spline space (Bernstein coefficients per knot span, the
joints, the caps), ``conic`` the convex programs and their proven lower
bounds, ``translating`` the translating followers' programs (roller: a
second-order cone program; flat face: a linear one), ``rocker`` the rocker
roller's sequential convex programming, ``design`` the driver that picks them.
Heavy imports (clarabel, scipy.sparse) happen inside the functions that solve.
"""
