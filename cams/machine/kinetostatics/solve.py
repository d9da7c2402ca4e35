"""The linear solve of the kinetostatics: reactions and the balancing moment at every crank angle at once.

Method (seeds 000, 002, 004: "кинетостатика", d'Alembert): every moving link
is in equilibrium under its loads, its weight, its inertia force ``-m a_S``
and moment ``-J_S epsilon`` and the reactions of its pairs; the crank also
carries the balancing moment ``M_b``. For a one-input linkage without
redundant constraints the ``3 n`` equations determine the ``2 p`` reaction
components and ``M_b``: one linear system per crank angle, solved for all of
them at once (``numpy.linalg.solve`` on a stack).

Friction proportional to the reactions (seed 002's "two-stage method", seed
004's 2.6): a moment ``mu r |R|`` in a revolute pair, a force ``mu |N|`` along
a prismatic guide, each opposing the relative motion; each pass applies the
friction of the previous pass's reactions.
"""

from __future__ import annotations

import numpy as np

from cams.machine.kinetostatics.loads import ForceSpec
from cams.machine.kinetostatics.model import AppliedLoad, Joint, Model, build_model
from cams.machine.kinetostatics.result import ForceResult, cross
from laws.errors import InputError, show_value

__all__ = ["solve_model", "analyse_forces"]


def _relative(model: Model, j: Joint) -> np.ndarray:
    """Relative angular velocity omega_a - omega_b (revolute, rad/s) or sliding velocity of a on b along the guide
    (m/s)."""
    wa = model.bodies[j.a].link.omega
    wb = 0.0 if j.b < 0 else model.bodies[j.b].link.omega
    if j.kind == "revolute":
        return np.broadcast_to(wa - wb, model.phi.shape).astype(float)
    dv = model.velocity(j.a, j.point) - model.velocity(j.b, j.point)
    assert j.axis is not None  # a prismatic pair has its guide's axis (build_model)
    return np.real(np.conj(j.axis) * dv)


def _friction_loads(model: Model, reactions: dict) -> list[AppliedLoad]:
    out = []
    zero = np.zeros_like(model.phi)
    for j in model.joints:
        if j.friction is None or j.friction.coefficient == 0:
            continue
        rel = _relative(model, j)
        s = np.sign(rel)
        if j.kind == "revolute":
            M = -s * j.friction.coefficient * j.friction.radius * np.abs(reactions[j.name])
            out.append(AppliedLoad(f"friction in {j.name}", j.a, zero + 0j, j.point, M, "friction"))
            if j.b >= 0:
                out.append(AppliedLoad(f"friction in {j.name}", j.b, zero + 0j, j.point, -M, "friction"))
        else:
            F = -s * j.friction.coefficient * np.abs(reactions[j.name + ":N"]) * j.axis
            out.append(AppliedLoad(f"friction in {j.name}", j.a, F, j.point, zero.copy(), "friction"))
            if j.b >= 0:
                out.append(AppliedLoad(f"friction in {j.name}", j.b, -F, j.point, zero.copy(), "friction"))
    return out


def _solve(model: Model, loads) -> tuple[dict, np.ndarray]:
    K, B, J = model.phi.size, len(model.bodies), len(model.joints)
    nu = 2 * J + 1
    if 3 * B != nu:  # pragma: no cover - the machines are statically determinate
        raise InputError("linkage", f"{B} links and {J} pairs are not statically determinate")
    A = np.zeros((K, 3 * B, nu))
    rhs = np.zeros((K, 3 * B))
    S = [b.cg.pos for b in model.bodies]
    for c, j in enumerate(model.joints):
        for k, s in ((j.a, 1.0), (j.b, -1.0)):
            if k < 0:
                continue
            r = j.point - S[k]
            if j.kind == "revolute":
                A[:, 3 * k, 2 * c] = s
                A[:, 3 * k + 1, 2 * c + 1] = s
                A[:, 3 * k + 2, 2 * c] = -s * np.imag(r)
                A[:, 3 * k + 2, 2 * c + 1] = s * np.real(r)
            else:
                n = 1j * j.axis
                A[:, 3 * k, 2 * c] = s * np.real(n)
                A[:, 3 * k + 1, 2 * c] = s * np.imag(n)
                A[:, 3 * k + 2, 2 * c] = s * cross(r, n)
                A[:, 3 * k + 2, 2 * c + 1] = s
    A[:, 3 * model.driver + 2, -1] = 1.0
    for k, b in enumerate(model.bodies):
        F = b.mass * (-1j * model.gravity) - b.mass * b.cg.acc
        rhs[:, 3 * k] -= np.real(F)
        rhs[:, 3 * k + 1] -= np.imag(F)
        rhs[:, 3 * k + 2] -= -b.inertia * b.link.alpha
    for ld in loads:
        k = ld.body
        rhs[:, 3 * k] -= np.real(ld.force)
        rhs[:, 3 * k + 1] -= np.imag(ld.force)
        rhs[:, 3 * k + 2] -= cross(ld.point - S[k], ld.force) + ld.moment
    x = np.linalg.solve(A, rhs[..., None])[..., 0]
    out = {}
    for c, j in enumerate(model.joints):
        if j.kind == "revolute":
            out[j.name] = x[:, 2 * c] + 1j * x[:, 2 * c + 1]
        else:
            out[j.name + ":N"] = x[:, 2 * c]
            out[j.name + ":M"] = x[:, 2 * c + 1]
            out[j.name] = x[:, 2 * c] * 1j * j.axis
    return out, x[:, -1]

def solve_model(model: Model, *, passes: int = 2, tol: float = 1e-9, max_passes: int = 50) -> ForceResult:
    """Reactions and the balancing moment of a model, with friction by successive passes.

    Parameters
    ----------
    model : Model
    passes : int or None
        1: no reaction-dependent friction; 2: the seeds' two-stage method
        (friction from the first pass's reactions); None: iterate until
        |M_b| changes by less than ``tol`` x its largest value.
    tol : float
    max_passes : int

    Returns
    -------
    ForceResult
    """
    if passes is not None and (isinstance(passes, bool) or not isinstance(passes, (int, np.integer)) or passes < 1):
        raise InputError("forces.passes", f"must be an integer >= 1 or None, got {show_value(passes)}")
    has_friction = any(j.friction is not None and j.friction.coefficient > 0 for j in model.joints)
    R, Mb = _solve(model, model.loads)
    fl: list = []
    n, change = 1, 0.0
    limit = 1 if not has_friction else (max_passes if passes is None else passes)
    while n < limit:
        fl = _friction_loads(model, R)
        R, Mb2 = _solve(model, (*model.loads, *fl))
        change = float(np.max(np.abs(Mb2 - Mb)))
        Mb = Mb2
        n += 1
        if passes is None and change <= tol * max(float(np.max(np.abs(Mb))), 1e-300):
            break
    return ForceResult(model, R, Mb, tuple(fl), n, change)


def analyse_forces(linkage, spec: ForceSpec, *, phi=None, samples: int = 360, rpm: float | None = None, passes: int = 2,
                   origin: float = 0.0) -> ForceResult:
    """Kinetostatics of a machine over its cycle: :func:`build_model` then :func:`solve_model`.

    Examples
    --------
    A crank-slider with a 10 kg piston at 120 rpm, no friction: the balancing
    moment equals the one from Zhukovsky's lever.

    >>> from cams.machine.kinetostatics.loads import LinkMass
    >>> from cams.machine.linkage.machines import CrankSlider
    >>> m = CrankSlider(crank=100.0, rod=400.0, rpm=120)
    >>> r = analyse_forces(m, ForceSpec(links={"slider": LinkMass(10.0)}), samples=36)
    >>> bool(np.allclose(r.balancing_moment, r.virtual_moment, atol=1e-9))
    True
    """
    return solve_model(build_model(linkage, spec, phi=phi, samples=samples, rpm=rpm, origin=origin), passes=passes)
