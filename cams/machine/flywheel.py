"""The flywheel: a machine's motion under reduced moments, and the flywheel for a speed fluctuation.

Dynamic model (seed 004, sections 1.7-1.16; seed 003, steps 3-5)
----------------------------------------------------------------
The whole machine is replaced by its input link (the crank) carrying

* the reduced moment of inertia ``J(phi)``, kg m^2: ``1/2 J omega^2`` is the
  kinetic energy of every link (seed 004's "приведенный момент инерции");
* the reduced moment of the driving forces ``Md(phi)`` and of the resisting
  forces ``Mr(phi)``, N m, both as *magnitudes that do work of their own sign*:
  ``Md`` positive gives work to the machine, ``Mr`` positive takes work from it
  (seed 003's 等效阻力矩 Mr; a negative Mr is a resisting force that helps).

The crank angle ``phi`` (radians) is counted in the crank's sense of rotation,
from the start of the cycle; ``omega`` is the crank's speed in that sense
(> 0). The energy equation over the cycle (energy-mass form)::

    1/2 (J(phi) + J_F) omega(phi)^2 = T0 + dE(phi),   dE(phi) = Ad(phi) - Ar(phi)

with the works ``Ad = int Md dphi``, ``Ar = int Mr dphi`` from the start of
the cycle (J). With no driving moment given, ``Md`` is the constant that
balances one cycle, ``Md = Ar(2 pi) / (2 pi)`` (seed 003: "驱动力矩 Md 为恒定";
seed 004: "приведенный момент движущих сил").

Flywheel for a coefficient of speed fluctuation ``delta``
---------------------------------------------------------
``delta = (omega_max - omega_min) / omega_m`` with ``omega_m = (omega_max +
omega_min) / 2 = pi n / 30``. The Wittenbauer construction (seed 004, 1.15-1.16:
tangents to the curve dE over J at the angles psi_max and psi_min) is here exact:
with ``omega_max = omega_m (1 + delta/2)`` and ``omega_min = omega_m (1 - delta/2)``
the flywheel's moment of inertia is::

    J_F = dA / (omega_m^2 delta),
    dA  = max_phi [dE - 1/2 J omega_max^2] - min_phi [dE - 1/2 J omega_min^2]

(``dA``: the segment KL the tangents cut on the energy axis, the seed's
"избыточная работа"), because ``omega_max^2 - omega_min^2 = 2 delta omega_m^2``.
With a constant ``J`` this is seed 003's formula
``J_F = 900 dA_max / (pi^2 n^2 [delta])`` with ``dA_max = max dE - min dE``
(:attr:`FlywheelResult.energy_range`), less the machine's own constant inertia.

The speed over the cycle then follows from the energy equation, and the
angular acceleration from its derivative:
``(J + J_F) epsilon = Md - Mr - 1/2 J'(phi) omega^2``.

Sampling
--------
The moments and the inertia are given as samples over one cycle. Between the
samples they are interpolated piecewise-linearly (``interpolation="linear"``)
or by a periodic cubic spline (``"spline"``); the curves are evaluated on a
dense grid of ``dense`` points per cycle. With few samples (seed 004's 12
positions) the result depends on that choice: see :mod:`tests.machine.forces`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from laws.errors import InputError, check_option, check_positive, show_value
from laws.units import (  # rpm_to_omega re-exported (cams.machine.flywheel.rpm_to_omega)
    omega_to_rpm,
    rpm_to_omega,
)

__all__ = ["FlywheelResult", "flywheel", "INTERPOLATIONS", "rpm_to_omega"]

INTERPOLATIONS = ("linear", "spline")


def _array(field: str, v, n: int | None = None) -> np.ndarray:
    try:
        a = np.asarray(v, dtype=float)
    except (TypeError, ValueError):
        raise InputError(field, f"must be numbers, got {show_value(v)}") from None
    if a.ndim > 1 or not np.all(np.isfinite(a)):
        raise InputError(field, "must be a finite number or a 1-D array of finite numbers")
    if n is not None:
        if a.ndim == 0:
            a = np.full(n, float(a))
        elif a.size != n:
            raise InputError(field, f"has {a.size} values, the crank angles {n}")
    return a


def _check_cycle(phi: np.ndarray, cycle: float) -> None:
    if phi.ndim != 1 or phi.size < 3:
        raise InputError("flywheel.phi", "needs at least 3 crank angles over one cycle")
    if np.any(np.diff(phi) <= 0):
        raise InputError("flywheel.phi", "crank angles must increase strictly")
    if phi[-1] - phi[0] >= cycle - 1e-12:
        raise InputError(
            "flywheel.phi",
            f"the samples span {np.degrees(phi[-1] - phi[0]):.6g} deg; give one cycle without its end "
            f"(angles in [phi0, phi0 + {np.degrees(cycle):g}) deg: the cycle closes on the first sample)",
        )


@dataclass(frozen=True, eq=False)
class FlywheelResult:
    """The machine's motion over one cycle with its flywheel.

    All arrays are on the dense grid :attr:`phi` (``dense + 1`` points from
    the cycle's start to its end, both included).

    Attributes
    ----------
    phi : ndarray
        Crank angle from the cycle's start, radians, in the crank's sense.
    resisting, driving : ndarray
        Reduced moments Mr and Md, N m (signs: see the module).
    inertia : ndarray
        Reduced moment of inertia of the linkage J(phi), kg m^2 (without the flywheel).
    work_resisting, work_driving : ndarray
        Ar(phi) and Ad(phi), J, from the cycle's start.
    energy : ndarray
        dE = Ad - Ar, the change of the machine's kinetic energy, J.
    omega_mean : float
        Mean crank speed omega_m = pi n / 30, rad/s.
    delta : float
        The coefficient of speed fluctuation asked for.
    excess_work : float
        dA of the Wittenbauer tangents, J (seed 004's "избыточная работа").
    flywheel_inertia : float
        J_F = dA / (omega_m^2 delta), kg m^2; 0 when the linkage alone keeps the
        fluctuation below ``delta`` (then ``needed_inertia`` < 0).
    needed_inertia : float
        dA / (omega_m^2 delta) before clipping at 0.
    omega : ndarray
        Crank speed over the cycle with the flywheel, rad/s.
    epsilon : ndarray
        Crank angular acceleration, rad/s^2 (positive: speeding up).
    kinetic_energy : ndarray
        ``1/2 (J + J_F) omega^2``, J.
    interpolation : str
        How the samples were joined.
    reference : str
        What :attr:`phi` is measured from, as the plot's axis and the JSON
        name it (e.g. ``"cycle angle from position 1"`` in a machine).
    """

    phi: np.ndarray
    resisting: np.ndarray
    driving: np.ndarray
    inertia: np.ndarray
    work_resisting: np.ndarray
    work_driving: np.ndarray
    energy: np.ndarray
    omega_mean: float
    delta: float
    excess_work: float
    flywheel_inertia: float
    needed_inertia: float
    omega: np.ndarray
    epsilon: np.ndarray
    kinetic_energy: np.ndarray
    interpolation: str
    reference: str = "crank angle from the cycle's start"

    @property
    def driving_moment(self) -> float:
        """Mean driving moment over the cycle, N m (the constant Md when none was given)."""
        return float(self.work_driving[-1] / (self.phi[-1] - self.phi[0]))

    @property
    def energy_range(self) -> float:
        """max dE - min dE, J: seed 003's dA_max (the excess work for a constant J)."""
        return float(np.ptp(self.energy))

    @property
    def achieved_delta(self) -> float:
        """(omega_max - omega_min) / ((omega_max + omega_min) / 2) of :attr:`omega`."""
        hi, lo = float(np.max(self.omega)), float(np.min(self.omega))
        return 2.0 * (hi - lo) / (hi + lo)

    @property
    def rpm(self) -> float:
        """Mean crank speed, rev/min."""
        return omega_to_rpm(self.omega_mean)

    def at(self, phi) -> dict:
        """Values at crank angles ``phi`` (radians from the cycle's start) by linear interpolation."""
        x = np.mod(np.asarray(phi, dtype=float) - self.phi[0], self.phi[-1] - self.phi[0]) + self.phi[0]
        names = ("resisting", "driving", "inertia", "work_resisting", "work_driving", "energy", "omega", "epsilon")
        return {n: np.interp(x, self.phi, getattr(self, n)) for n in names}

    def to_dict(self, *, step_deg: float = 5.0) -> dict:
        """JSON-ready summary and curves every ``step_deg`` degrees."""
        k = max(1, round(float(np.radians(step_deg) / (self.phi[1] - self.phi[0]))))
        pick = slice(None, None, k)
        return {
            "angle_reference": self.reference,
            "rpm": self.rpm,
            "delta": self.delta,
            "interpolation": self.interpolation,
            "driving_moment": self.driving_moment,
            "excess_work": float(self.excess_work),
            "energy_range": self.energy_range,
            "flywheel_inertia": float(self.flywheel_inertia),
            "achieved_delta": self.achieved_delta,
            "omega_min": float(np.min(self.omega)),
            "omega_max": float(np.max(self.omega)),
            "curves": {
                "phi_deg": [round(float(x), 6) for x in np.degrees(self.phi[pick])],
                "resisting": [float(x) for x in self.resisting[pick]],
                "inertia": [float(x) for x in self.inertia[pick]],
                "energy": [float(x) for x in self.energy[pick]],
                "omega": [float(x) for x in self.omega[pick]],
            },
        }


def _cycle(cycle) -> float:
    """One crank turn or two, radians (exactly ``2 pi`` or ``4 pi``); refused otherwise on ``flywheel.cycle``."""
    ok = not isinstance(cycle, bool) and isinstance(cycle, (int, float, np.integer, np.floating)) and np.isfinite(cycle)
    for turns in (1, 2):
        if ok and abs(float(cycle) - turns * 2 * np.pi) <= 1e-9:
            return turns * 2 * np.pi
    raise InputError("flywheel.cycle",
                     f"must be 2 pi or 4 pi radians (one or two crank turns), got {show_value(cycle)}")


def _resample(phi: np.ndarray, y: np.ndarray, x: np.ndarray, how: str, cycle: float):
    """Values and exact cumulative integral (from phi[0]) of the periodic samples on the grid x."""
    from scipy.interpolate import CubicSpline

    p = np.append(phi, phi[0] + cycle)
    v = np.append(y, y[0])
    if how == "spline":
        cs = CubicSpline(p, v, bc_type="periodic")
        return cs(x), cs.antiderivative()(x) - cs.antiderivative()(p[0]), cs.derivative()(x)
    vals = np.interp(x, p, v)
    # exact integral of the piecewise-linear curve on a grid that contains the samples
    cum = np.concatenate([[0.0], np.cumsum(0.5 * (vals[1:] + vals[:-1]) * np.diff(x))])
    slope = np.diff(v) / np.diff(p)
    k = np.clip(np.searchsorted(p, x, side="right") - 1, 0, len(slope) - 1)
    return vals, cum, slope[k]


def flywheel(
    phi,
    resisting,
    inertia,
    *,
    rpm: float,
    delta: float,
    driving=None,
    interpolation: str = "linear",
    dense: int = 7200,
    cycle: float = 2 * np.pi,
    reference: str = "crank angle from the cycle's start",
) -> FlywheelResult:
    """The flywheel for a coefficient of speed fluctuation, and the crank's speed with it.

    Parameters
    ----------
    phi : array_like
        Crank angles of the samples, radians, in the crank's sense, strictly
        increasing over one cycle without its end (``[phi0, phi0 + 2 pi)``,
        or ``4 pi`` with ``cycle=4 pi``; the cycle closes on the first sample).
    resisting : array_like or float
        Reduced moment of the resisting forces Mr at ``phi``, N m (positive
        takes work from the machine).
    inertia : array_like or float
        Reduced moment of inertia of the linkage J at ``phi``, kg m^2, >= 0.
    rpm : float
        Mean crank speed n, rev/min (> 0).
    delta : float
        Coefficient of speed fluctuation [delta], in (0, 1).
    driving : array_like, float or None
        Reduced driving moment Md at ``phi``, N m; ``None``: the constant that
        balances the cycle. A driving moment whose work differs from the
        resisting work over the cycle is rejected (no steady motion).
    interpolation : {"linear", "spline"}
        How samples are joined (piecewise linear, or a periodic cubic spline).
    dense : int
        Grid points per cycle for the curves (the samples are added to it
        for linear interpolation, so its integrals are exact).
    cycle : {2 pi, 4 pi}
        Crank rotation of one cycle, radians (4 pi: a four-stroke engine).
    reference : str
        The name of the angle ``phi`` (what its 0 is), for the result's plot
        and JSON.

    Returns
    -------
    FlywheelResult

    Raises
    ------
    InputError
        ``delta`` outside (0, 1), ``rpm`` <= 0, a negative inertia, angles not
        covering one cycle, or a driving moment that does not balance it.

    Examples
    --------
    A constant inertia of 2 kg m^2 and Mr = 100 sin(phi) N m: no mean
    driving moment, dE = 100 (cos(phi) - 1) swings by 200 J, and seed 003's
    formula less the linkage's own inertia gives the flywheel:

    >>> import numpy as np
    >>> phi = np.linspace(0, 2 * np.pi, 360, endpoint=False)
    >>> r = flywheel(phi, 100 * np.sin(phi), 2.0, rpm=300, delta=0.05, interpolation="spline")
    >>> round(r.driving_moment, 9), round(r.energy_range, 6)
    (0.0, 200.0)
    >>> round(r.flywheel_inertia, 6), round(200 / (np.pi * 300 / 30) ** 2 / 0.05 - 2, 6)
    (2.052847, 2.052847)
    >>> round(r.achieved_delta, 12)
    0.05
    """
    how = check_option("flywheel.interpolation", interpolation, INTERPOLATIONS)
    cycle = _cycle(cycle)
    rpm = check_positive("flywheel.rpm", rpm)
    if (isinstance(delta, bool) or not isinstance(delta, (int, float, np.floating)) or not np.isfinite(delta)
            or not 0 < delta < 1):
        raise InputError("flywheel.delta",
                         f"the coefficient of speed fluctuation must be in (0, 1), got {show_value(delta)}")
    delta = float(delta)
    phi = _array("flywheel.phi", phi)
    _check_cycle(phi, cycle)
    n = phi.size
    Mr = _array("flywheel.resisting", resisting, n)
    J = _array("flywheel.inertia", inertia, n)
    if np.any(J < 0):
        k = int(np.argmin(J))
        raise InputError("flywheel.inertia",
                         f"a moment of inertia cannot be negative: {J[k]:.6g} kg m^2 at {np.degrees(phi[k]):.6g} deg")
    if isinstance(dense, bool) or not isinstance(dense, (int, np.integer)) or dense < 12:
        raise InputError("flywheel.dense", f"must be an integer >= 12, got {show_value(dense)}")

    x = np.linspace(phi[0], phi[0] + cycle, dense + 1)
    if how == "linear":
        x = np.union1d(x, np.append(phi, phi[0] + cycle))
    Mr_x, Ar, _ = _resample(phi, Mr, x, how, cycle)
    J_x, _, dJ = _resample(phi, J, x, how, cycle)
    if np.any(J_x < 0):
        raise InputError("flywheel.inertia",
                         "the spline through the inertias dips below 0; use interpolation = 'linear'")
    if driving is None:
        Md_x = np.full_like(x, Ar[-1] / cycle)
        Ad = Md_x * (x - x[0])
    else:
        Md = _array("flywheel.driving", driving, n)
        Md_x, Ad, _ = _resample(phi, Md, x, how, cycle)
        imbalance = Ad[-1] - Ar[-1]
        if abs(imbalance) > 1e-9 * max(abs(Ar[-1]), abs(Ad[-1]), 1.0):
            raise InputError(
                "flywheel.driving",
                f"the driving work over the cycle ({Ad[-1]:.6g} J) differs from the resisting work ({Ar[-1]:.6g} J); "
                f"a steady cycle needs them equal (a constant Md = {Ar[-1] / cycle:.6g} N m would balance it)",
            )
    dE = Ad - Ar
    wm = rpm_to_omega(rpm)
    w_hi2, w_lo2 = (wm * (1 + delta / 2)) ** 2, (wm * (1 - delta / 2)) ** 2
    dA = float(np.max(dE - 0.5 * J_x * w_hi2) - np.min(dE - 0.5 * J_x * w_lo2))
    needed = dA / (wm**2 * delta)
    JF = max(needed, 0.0)
    Jt = J_x + JF
    if np.any(Jt <= 0):
        raise InputError("flywheel.inertia",
                         "the machine has no inertia at some angle; give the crank's own moment of inertia")
    if JF > 0:
        T0 = -float(np.max(dE - 0.5 * Jt * w_hi2))
    else:  # the linkage alone: choose T0 so that the mean speed is omega_m
        T0 = _mean_speed_energy(dE, J_x, wm)
    T = T0 + dE
    omega = np.sqrt(np.maximum(2 * T / Jt, 0.0))
    eps = (Md_x - Mr_x - 0.5 * dJ * omega**2) / Jt
    return FlywheelResult(
        phi=x,
        resisting=Mr_x,
        driving=Md_x,
        inertia=J_x,
        work_resisting=Ar,
        work_driving=Ad,
        energy=dE,
        omega_mean=wm,
        delta=delta,
        excess_work=dA,
        flywheel_inertia=float(JF),
        needed_inertia=float(needed),
        omega=omega,
        epsilon=eps,
        kinetic_energy=0.5 * Jt * omega**2,
        interpolation=how,
        reference=str(reference),
    )


def _mean_speed_energy(dE: np.ndarray, J: np.ndarray, wm: float) -> float:
    """T0 with (max omega + min omega) / 2 = wm for the linkage without a flywheel."""
    from laws.search import bracketed_root

    def f(T0):
        w = np.sqrt(2 * (T0 + dE) / J)
        return 0.5 * (w.max() + w.min()) - wm

    lo = -float(np.min(dE)) + 1e-12
    hi = lo + 0.5 * float(np.max(J)) * (2 * wm) ** 2 + float(np.ptp(dE))
    return bracketed_root(f, lo, hi, xtol=1e-12)
