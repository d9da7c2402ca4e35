"""The result of the kinetostatics: reactions, balancing moment, friction, virtual work and reduced quantities.

Virtual work (Zhukovsky's lever): the balancing moment also follows from the
power of all loads, inertia and friction included, without any reaction:
``M_b omega_1 = -sum(F . v + M omega)``; :attr:`ForceResult.virtual_moment`
computes it independently.

Reduced quantities (for :mod:`cams.machine.flywheel`):
``J_red = sum(m |v_S|^2 + J_S omega^2) / omega_1^2`` and the reduced moment
of the external loads and weights ``Mr = -sum(F . v + M omega) / |omega_1|``
(positive resists), of friction ``Mf = (losses) / |omega_1|``.

Angles are radians (:attr:`ForceResult.rotation`); the report
(:meth:`ForceResult.to_dict`) gives degrees.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from cams.machine.kinetostatics.model import Model
from laws.units import omega_to_rpm, turn_degrees

__all__ = ["ForceResult", "cross"]


def cross(a, b):
    """The z component of the planar cross product of complex vectors ``a x b``."""
    return np.imag(np.conj(a) * b)


@dataclass(frozen=True, eq=False)
class ForceResult:
    """Reactions, balancing moment, friction and reduced quantities over the crank angles.

    Attributes
    ----------
    model : Model
        Bodies, joints and external loads (SI).
    reactions : dict of str to ndarray (complex)
        Force on each pair's first link from its second, N (``Rx + i Ry``);
        for a prismatic pair also ``name + ":N"`` (normal force along ``i u``)
        and ``name + ":M"`` (couple, N m).
    balancing_moment : ndarray
        M_b on the crank from the drive, N m, counter-clockwise positive.
    friction_loads : tuple of AppliedLoad
        The reaction-dependent friction of the last pass.
    passes : int
        Passes made (1: no reaction-dependent friction).
    change : float
        Largest change of |M_b| in the last pass, N m (0 for one pass).
    reference : str
        What the reported angles (:attr:`rotation`: the crank's rotation in
        its own sense from the first crank angle) are called, e.g. ``"cycle
        angle from position 1"`` when the first angle is a machine's position
        1; empty: ``"crank rotation from <phi[0]> deg (frame)"``.
    """

    model: Model
    reactions: dict
    balancing_moment: np.ndarray
    friction_loads: tuple
    passes: int
    change: float
    reference: str = ""

    @property
    def phi(self) -> np.ndarray:
        """Frame crank angles, radians."""
        return self.model.phi

    @property
    def rotation(self) -> np.ndarray:
        """The crank's rotation in its own sense from the first crank angle, radians in [0, 2 pi).

        In [0, 4 pi) when the loads' cycle is two turns (a gas table of period 720).
        """
        return np.mod(self.model.sense * (self.phi - self.phi[0]), self.model.cycle)

    @property
    def angle_reference(self) -> str:
        """The name of the angle of :attr:`rotation` in reports and plots."""
        return self.reference or f"crank rotation from {turn_degrees(self.phi[0]):.1f} deg (frame)"

    @property
    def omega(self) -> float:
        """Crank angular velocity, rad/s (signed)."""
        return self.model.omega

    def magnitude(self, pair: str) -> np.ndarray:
        """|R| of a pair, N."""
        return np.abs(self.reactions[pair])

    def _powers(self, loads) -> np.ndarray:
        m = self.model
        P = np.zeros_like(m.phi)
        for ld in loads:
            v = m.velocity(ld.body, ld.point)
            P += np.real(np.conj(ld.force) * v) + ld.moment * m.bodies[ld.body].link.omega
        return P

    def _inertia_gravity_power(self) -> tuple[np.ndarray, np.ndarray]:
        m = self.model
        Pi = np.zeros_like(m.phi)
        Pg = np.zeros_like(m.phi)
        for b in m.bodies:
            Pi += np.real(np.conj(-b.mass * b.cg.acc) * b.cg.vel) - b.inertia * b.link.alpha * b.link.omega
            Pg += np.real(np.conj(b.mass * (-1j * m.gravity)) * b.cg.vel)
        return Pi, Pg

    @property
    def virtual_moment(self) -> np.ndarray:
        """M_b from the power of every load (Zhukovsky's lever), without the reactions, N m."""
        Pi, Pg = self._inertia_gravity_power()
        P = self._powers(self.model.loads) + self._powers(self.friction_loads) + Pi + Pg
        return -P / self.omega

    @property
    def friction_power(self) -> dict:
        """Power lost to reaction-dependent friction in each pair, W (>= 0).

        The power of the friction actually applied (for ``passes=2``: from the
        first pass's reactions, as in the seeds' two-stage method):
        ``|M_f omega_rel|`` in a revolute pair, ``|F_f v_rel|`` in a prismatic one.
        """
        m = self.model
        out: dict = {}
        for ld in self.friction_loads:
            v = m.velocity(ld.body, ld.point)
            P = np.real(np.conj(ld.force) * v) + ld.moment * m.bodies[ld.body].link.omega
            name = ld.name.removeprefix("friction in ")
            out[name] = out.get(name, 0.0) - P
        return out

    @property
    def reduced_inertia(self) -> np.ndarray:
        """J_red = sum(m |v_S|^2 + J omega^2) / omega_1^2, kg m^2."""
        m = self.model
        T2 = sum(b.mass * np.abs(b.cg.vel) ** 2 + b.inertia * b.link.omega**2 for b in m.bodies)
        return np.asarray(T2, dtype=float) / self.omega**2 + np.zeros_like(m.phi)

    @property
    def reduced_resisting(self) -> np.ndarray:
        """Reduced moment of the external loads and weights, N m (positive resists)."""
        _, Pg = self._inertia_gravity_power()
        return -(self._powers(self.model.loads) + Pg) / abs(self.omega)

    @property
    def reduced_friction(self) -> np.ndarray:
        """Reduced moment of the friction in the pairs (reaction-dependent), N m (>= 0)."""
        return -self._powers(self.friction_loads) / abs(self.omega)

    def residuals(self) -> np.ndarray:
        """Sum of forces (x, y) and of moments about the frame's origin on every body, shape (K, bodies, 3).

        Computed from the stored reactions and loads (not from the solver's
        matrix); zero to round-off when every link is in equilibrium.
        """
        m = self.model
        K = m.phi.size
        out = np.zeros((K, len(m.bodies), 3))

        def add(k, F, P, M):
            out[:, k, 0] += np.real(F)
            out[:, k, 1] += np.imag(F)
            out[:, k, 2] += cross(P, F) + M

        zero = np.zeros(K)
        for k, b in enumerate(m.bodies):
            add(k, b.mass * (-1j * m.gravity) - b.mass * b.cg.acc, b.cg.pos, -b.inertia * b.link.alpha)
        for ld in (*m.loads, *self.friction_loads):
            add(ld.body, ld.force, ld.point, ld.moment)
        for j in m.joints:
            R = self.reactions[j.name]
            M = self.reactions.get(j.name + ":M", zero)
            add(j.a, R, j.point, M)
            if j.b >= 0:
                add(j.b, -R, j.point, -M)
        out[:, m.driver, 2] += self.balancing_moment
        return out

    def flywheel(self, *, delta: float, interpolation: str = "linear", friction: bool = True,
                 cycle: float | None = None):
        """The flywheel for this machine (:func:`cams.machine.flywheel.flywheel`) from its reduced moments and inertia.

        The crank angles become the cycle's angles in the crank's sense from
        the first one. ``friction`` adds the pairs' friction to the resisting
        moment. ``cycle``: the cycle, radians (2 pi or 4 pi); default the
        loads' own (:attr:`Model.cycle`: 4 pi with a gas table of two turns,
        which needs crank angles over two turns).
        """
        from cams.machine.flywheel import flywheel

        cycle = self.model.cycle if cycle is None else cycle
        c = np.mod(self.model.sense * (self.phi - self.phi[0]), cycle)
        order = np.argsort(c)
        Mr = self.reduced_resisting + (self.reduced_friction if friction else 0.0)
        rpm = omega_to_rpm(abs(self.omega))
        return flywheel(c[order], Mr[order], self.reduced_inertia[order], rpm=rpm, delta=delta,
                        interpolation=interpolation, cycle=cycle, reference=self.angle_reference)

    def to_dict(self) -> dict:
        """JSON-ready summary: extremes of the reactions and the balancing moment, friction losses.

        The angles (``at_deg``) are :attr:`rotation` in degrees, named by ``angle_reference``.
        """
        deg = np.degrees(self.rotation)
        pairs = {}
        for j in self.model.joints:
            R = self.magnitude(j.name)
            k = int(np.argmax(R))
            pairs[j.name] = {"kind": j.kind, "max": float(R[k]), "at_deg": float(deg[k]), "mean": float(np.mean(R))}
        Mb = self.balancing_moment
        k = int(np.argmax(np.abs(Mb)))
        fp = {k_: float(np.mean(v)) for k_, v in self.friction_power.items()}
        return {
            "angle_reference": self.angle_reference,
            "rpm": omega_to_rpm(abs(self.omega)),
            "passes": self.passes,
            "balancing_moment": {"max_abs": float(abs(Mb[k])), "at_deg": float(deg[k]), "mean": float(np.mean(Mb)),
                                 "virtual_work_max_difference": float(np.max(np.abs(Mb - self.virtual_moment)))},
            "pairs": pairs,
            "friction_power_mean_W": fp,
            "friction_power_total_mean_W": float(sum(fp.values())),
            "drive_power_mean_W": float(np.mean(Mb * self.omega)),
        }
