"""The elastic follower train at a speed: its vibration, the dynamic contact force and the dynamic jump speed.

Model
-----
One degree of freedom, the follower's coordinate ``q`` (m for a translating follower; rad for a rocker), as in
:mod:`cams.dynamics.forces`, but the follower is no longer rigid: its mass ``m`` (``[dynamics] mass``, kg; a
rocker's moment of inertia about its pivot, kg m^2) is joined to the cam by the train, a spring ``k_t``
(``train_stiffness``, N/m; a rocker's torsional stiffness about the pivot, N m/rad: the train's compliance
reduced to the pivot, the cam's rigid swing ``q_cam`` at one end and the inertia at the other) and a damper ``c``
across it, acting on the relative velocity ``q_cam' - q'``. The closing spring (``F0 + k_s q``) and the load ``P``
act on the mass::

    m q'' = Q - (F0 + k_s q) - P,      Q = k_t (q_cam - q) + c (q_cam' - q')

``Q`` is the generalized force the cam transmits into the train (N, or N m about a rocker's pivot), positive when
the cam pushes the follower in the sense of the rise. The damping ratio is defined against the total stiffness,
``zeta = c / (2 sqrt((k_t + k_s) m))`` (``damping_ratio``), the natural frequency is
``f_n = sqrt((k_t + k_s) / m) / (2 pi)`` and a phase's period ratio ``lambda`` is its duration over ``1 / f_n``.
Friction in the guide or the pivot is left out of the train (it changes the contact force's size, not its sign).

The contact force at the face is ``N = Q a``, with ``a`` the rigid contact geometry of the face's forces stage
(:attr:`cams.dynamics.forces.CamForces.amplification`: ``1 / cos(gamma)`` for a translating roller, the pressure
angle's and arm's for a rocker, 1 for a translating flat face whose normal is along its motion); ``a > 0``, so the
contact holds while ``Q > 0``.

The response while the contact holds is linear and is computed exactly, span by span
(:mod:`laws.response`): the cycle's periodic steady state by default, each rise and return from rest too.
Under force closure ``Q`` can turn negative: the follower then leaves the cam. The contact law is the train itself
acting as a stiff one-sided contact: ``Q = max(0, k_t d + c d')`` while the train is compressed (``d = q_cam - q >
0``), else 0 -- the contact opens when ``Q`` falls to 0 and closes again when both ``k_t d`` and ``k_t d + c d'``
are positive (re-impact, its force the train's); no coefficient of restitution and no extra key. Where the steady
state loses contact an event-driven integrator (``scipy.integrate.solve_ivp`` with events) follows the flights
over some turns (:func:`simulate`). Form closure: the groove drives both ways, ``Q`` may take either sign (no
backlash).

Units: SI inside (m or rad, s, N, kg); the program's displacements in the design's unit (mm) or rad; angles in
radians, degrees only in :meth:`Vibration.to_dict`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from laws.errors import InputError
from laws.program import Program
from laws.response import Train, grid_least_loads, grid_response, phase_residuals, steady_state
from laws.units import TWO_PI, omega_to_rpm, rpm_to_omega

__all__ = [
    "TrainModel",
    "train_model",
    "Flight",
    "simulate",
    "Vibration",
    "PhaseVibration",
    "vibration",
    "dynamic_jump_rpm",
    "JumpSearch",
    "design_vibration",
    "vibration_failure",
    "vibration_lines",
]


@dataclass(frozen=True)
class TrainModel:
    """The physical train of one follower, SI.

    Attributes
    ----------
    mass : float
        kg (kg m^2 for a rocker).
    stiffness : float
        ``k_t``, N/m (N m/rad).
    damping_ratio : float
        ``zeta`` against ``k_t + k_s``.
    spring_rate, preload, load : float
        ``k_s`` (N/m; N m/rad), ``F0`` and ``P`` (N; N m); 0 for form closure.
    si : float
        SI units of ``q`` per unit of the program's displacement (m per mm, or 1 for rad).
    force_closed : bool
        Contact can be lost (a closing spring); False: a groove (form closure).
    """

    mass: float
    stiffness: float
    damping_ratio: float
    spring_rate: float
    preload: float
    load: float
    si: float
    force_closed: bool

    @property
    def total(self) -> float:
        """``k_t + k_s`` (N/m; N m/rad)."""
        return self.stiffness + self.spring_rate

    @property
    def omega_n(self) -> float:
        """Natural frequency, rad/s."""
        return float(np.sqrt(self.total / self.mass))

    @property
    def damping(self) -> float:
        """``c = 2 zeta sqrt((k_t + k_s) m)``: N s/m (N m s/rad)."""
        return 2 * self.damping_ratio * float(np.sqrt(self.total * self.mass))

    def train(self, omega: float) -> Train:
        """The dimensionless train at the cam speed ``omega`` (rad/s), the program's displacement unit."""
        return Train(
            rho=self.omega_n / omega,
            ratio=self.stiffness / self.total,
            zeta=self.damping_ratio,
            offset=(self.preload + self.load) / self.total / self.si,
        )


def train_model(design, dyn) -> TrainModel | None:
    """The train of a design's follower dynamics (``dyn`` with its spring for force closure); None without
    ``train_stiffness``."""
    if dyn.train_stiffness is None:
        return None
    force = design.limits.closure == "force" if hasattr(design, "limits") else True
    spring = dyn.spring if force else None
    if force and spring is None:
        raise InputError("dynamics.spring_rate", "the train's vibration under force closure needs the spring")
    si = 1.0 if design.follower.kind == "rocker" else dyn.length_unit
    return TrainModel(
        dyn.mass,
        float(dyn.train_stiffness),
        dyn.damping_ratio,
        spring.rate if spring else 0.0,
        spring.preload if spring else 0.0,
        dyn.load,
        si,
        force,
    )


@dataclass(frozen=True)
class Flight:
    """The event-driven response over the last of some turns (force closure, contact lost).

    ``phi`` the cam angles (rad), ``q`` the output (program unit), ``load`` ``Q`` (N; N m, 0 in flight),
    ``intervals`` the flights ``(leave, land)`` as cam angles (rad, mod 2 pi; ``land`` None when the turn ends in
    flight), ``max_gap`` the largest ``q - q_cam`` (program unit).
    """

    phi: np.ndarray
    q: np.ndarray
    load: np.ndarray
    intervals: tuple[tuple[float, float | None], ...]
    max_gap: float
    turns: int = 6
    rocker: bool = False


def simulate(program: Program, tm: TrainModel, omega: float, y0, *, turns: int = 6, samples: int = 720) -> Flight:
    """Follow the follower over ``turns`` turns from ``y0 = (q, dq/dt)`` (program unit, per s) at cam angle 0.

    The one-sided contact of the module, its switches found by ``solve_ivp`` events (DOP853, rtol 1e-10).
    Returns the last turn at ``samples`` equally spaced cam angles.
    """
    from scipy.integrate import solve_ivp

    si, m, kt, c = tm.si, tm.mass, tm.stiffness, tm.damping
    hold = tm.preload + tm.load

    def cam(t):
        mo = program.evaluate(omega * t)
        return float(mo.s) * si, float(mo.ds) * si * omega

    def press(t, y):  # min(k_t d, Q): both positive in contact
        s, ds = cam(t)
        d = s - y[0]
        return min(kt * d, kt * d + c * (ds - y[1]))

    def transmitted(t, y):  # Q = k_t d + c d'
        s, ds = cam(t)
        return kt * (s - y[0]) + c * (ds - y[1])

    def rhs(contact):
        def f(t, y):
            q = transmitted(t, y) if contact else 0.0
            return [y[1], (q - hold - tm.spring_rate * y[0]) / m]

        return f

    leave = lambda t, y: press(t, y)  # noqa: E731
    leave.terminal, leave.direction = True, -1  # type: ignore[attr-defined]
    land = lambda t, y: press(t, y)  # noqa: E731
    land.terminal, land.direction = True, 1  # type: ignore[attr-defined]
    period = TWO_PI / omega
    t_end = turns * period
    y = np.array([y0[0] * si, y0[1] * si])
    t = 0.0
    contact = press(0.0, y) > 0 or not tm.force_closed
    ts, ys, modes, switches = [], [], [], []
    step = period / samples
    while t < t_end - 1e-15 * t_end:
        ev = leave if contact else land
        grid = np.arange(np.ceil(t / step - 1e-9), np.floor(t_end / step + 1e-9) + 1) * step
        grid = grid[(grid >= t) & (grid <= t_end)]
        sol = solve_ivp(
            rhs(contact),
            (t, t_end),
            y,
            method="DOP853",
            rtol=1e-10,
            atol=1e-14 + 1e-12 * abs(y[0]),
            events=ev if tm.force_closed else None,
            dense_output=True,
            max_step=step * 4,
        )
        t_stop = sol.t[-1]
        keep = grid[grid <= t_stop]
        if keep.size:
            assert sol.sol is not None  # dense_output=True
            ts.append(keep)
            ys.append(sol.sol(keep))
            modes.append(np.full(keep.size, contact))
        y = sol.y[:, -1]
        if sol.status == 1:  # an event: switch
            switches.append((t_stop, contact))
            contact = not contact
            t = t_stop
            if t_stop - (switches[-2][0] if len(switches) > 1 else -1.0) < 1e-12 * period:
                t += 1e-9 * period  # chattering at a switch: step over it
        else:
            t = t_end
    T = np.concatenate(ts)
    Y = np.concatenate(ys, axis=1)
    M = np.concatenate(modes)
    last = T >= t_end - period - 1e-9 * period
    T, Y, M = T[last][:samples], Y[:, last][:, :samples], M[last][:samples]
    phi = np.mod(omega * T, TWO_PI)
    mo = program.evaluate(phi)
    s, ds = mo.s * si, mo.ds * si * omega
    Q = np.where(M, kt * (s - Y[0]) + c * (ds - Y[1]), 0.0)
    flights: list[tuple[float, float | None]] = []
    start = t_end - period
    for ts_, was_contact in switches:
        if ts_ < start:
            continue
        if was_contact:
            flights.append((_angle(omega * ts_), None))
        elif flights and flights[-1][1] is None:
            flights[-1] = (flights[-1][0], _angle(omega * ts_))
        else:
            flights.append((_angle(omega * start), _angle(omega * ts_)))
    gap = float(np.max(Y[0] - s)) / si
    return Flight(phi, Y[0] / si, Q, tuple(flights), gap, turns, si == 1.0)


def _angle(phi: float) -> float:
    """A cam angle in [0, 2 pi) (rad): a turn's end (2 pi less a rounding) is its start."""
    a = float(np.mod(phi, TWO_PI))
    return 0.0 if a > TWO_PI - 1e-9 else a


@dataclass(frozen=True)
class PhaseVibration:
    """One rise or return: ``phase`` its ``[[motion]]`` index, ``kind``, ``period_ratio`` (its duration over the
    natural period), the residual vibration's amplitude at its end over its height, from rest and in the steady
    state (None: no steady state)."""

    phase: int
    kind: str
    period_ratio: float
    residual_from_rest: float
    residual: float | None


def _min_load(program: Program, tm: TrainModel, omega: float, samples: int) -> tuple[float, float]:
    """The steady state's least ``Q`` (N; N m) over ``samples`` angles a turn and its angle (rad); ``-inf`` without a
    steady state (an undamped train at resonance)."""
    tr = tm.train(omega)
    try:
        y0 = steady_state(program, tr)
    except InputError:
        return -np.inf, 0.0
    r = grid_response(program, tr, y0, samples)
    k = int(np.argmin(r.load))
    return float(r.load[k]) * tm.total * tm.si, float(r.phi[k])


def dynamic_jump_rpm(
    program: Program, tm: TrainModel, *, start_rpm: float, top_rpm: float, samples: int = 720, step: float = 0.01
) -> float | None:
    """The least cam speed (rev/min) at which the steady state's ``Q`` turns negative somewhere, or None up to
    ``top_rpm``.

    Scanned upward from ``start_rpm`` (where contact must hold) in relative steps of ``step`` (a window of lost
    contact narrower than a step may be missed), then bisected to 1e-6 relative between the last speed that holds
    and the first that does not. Each speed's ``Q`` is sampled at ``samples`` angles a turn. The scan's speeds are
    taken in blocks (:func:`laws.response.grid_least_loads`); a speed whose least ``Q`` that batch cannot answer,
    or finds within ``1e-8`` of its largest ``|Q|`` of 0, is decided by :func:`_min_load` itself, so the scan stops
    at the same speed as one :func:`_min_load` a speed.
    """
    if not tm.force_closed:
        return None
    lo = start_rpm
    if _min_load(program, tm, rpm_to_omega(lo), samples)[0] < 0:
        return None if lo <= 0 else _bisect(program, tm, 0.0, lo, samples)
    speeds = []
    n = lo
    while n < top_rpm:
        n = min(n * (1 + step), top_rpm)
        speeds.append(n)
    for i in range(0, len(speeds), _BLOCK):
        block = speeds[i : i + _BLOCK]
        for j, lost in enumerate(_losses(program, tm, block, samples)):
            if lost:
                return _bisect(program, tm, speeds[i + j - 1] if i + j else lo, block[j], samples)
    return None


#: Speeds of the jump speed's scan taken at once.
_BLOCK = 64


def _losses(program: Program, tm: TrainModel, rpms: list[float], samples: int) -> list[bool]:
    """Whether the steady state's least ``Q`` is negative at each speed (rev/min): :func:`_min_load`'s sign, from
    one batch (:func:`laws.response.grid_least_loads`) where it is sure and clear of 0."""
    trains = [tm.train(rpm_to_omega(n)) for n in rpms]
    t0 = trains[0]
    with np.errstate(over="ignore", invalid="ignore"):  # a speed whose figures overflow is asked again below
        least, size, sure = grid_least_loads(
            program, np.array([t.rho for t in trains]), samples, ratio=t0.ratio, zeta=t0.zeta, offset=t0.offset
        )
    return [
        bool(least[j] < 0)
        if sure[j] and abs(least[j]) > 1e-8 * size[j]
        else _min_load(program, tm, rpm_to_omega(n), samples)[0] < 0
        for j, n in enumerate(rpms)
    ]


def _bisect(program, tm, lo, hi, samples) -> float:
    while hi - lo > 1e-6 * hi:
        mid = 0.5 * (lo + hi)
        if mid <= 0 or _min_load(program, tm, rpm_to_omega(mid), samples)[0] >= 0:
            lo = mid
        else:
            hi = mid
    return hi


@dataclass(frozen=True)
class JumpSearch:
    """What :func:`dynamic_jump_rpm` needs to find a design's dynamic jump speed, kept until it is asked for.

    ``start_rpm`` and ``top_rpm`` bound the scan (rev/min), ``samples`` the angles a turn of each speed's ``Q``.
    """

    program: Program
    train: TrainModel
    start_rpm: float
    top_rpm: float
    samples: int

    def run(self) -> float | None:
        """The dynamic jump speed (rev/min), None: none found up to ``top_rpm``."""
        return dynamic_jump_rpm(
            self.program, self.train, start_rpm=self.start_rpm, top_rpm=self.top_rpm, samples=self.samples
        )


@dataclass(frozen=True, eq=False)
class Vibration:
    """The elastic train's response at the design's speed (:func:`vibration`).

    Attributes
    ----------
    phi : ndarray
        Cam angles, rad.
    omega : float
        Cam speed, rad/s.
    q, dq, d2q : ndarray
        The output's displacement (program unit: mm or rad) and its time derivatives (per s, s^2), steady state.
    s, ds, d2s : ndarray
        The rigid motion, same units.
    load : ndarray
        ``Q``, N (N m), steady state assuming contact.
    contact : ndarray
        The dynamic contact force at the face, ``Q a`` (N).
    natural_frequency : float
        Hz.
    phases : tuple of PhaseVibration
    contact_lost_at : float or None
        The first sampled cam angle (rad) with ``Q < 0`` under force closure.
    jump_search : JumpSearch or None
        The dynamic jump speed's search, run when :attr:`jump_rpm` is first read (its ``top_rpm``: the top of the
        search, rev/min); None under form closure.
    flight : Flight or None
        The event-driven response when contact is lost.
    force_closed : bool
    """

    phi: np.ndarray
    omega: float
    q: np.ndarray
    dq: np.ndarray
    d2q: np.ndarray
    s: np.ndarray
    ds: np.ndarray
    d2s: np.ndarray
    load: np.ndarray
    contact: np.ndarray
    natural_frequency: float
    phases: tuple[PhaseVibration, ...]
    contact_lost_at: float | None
    jump_search: JumpSearch | None
    flight: Flight | None
    force_closed: bool

    @property
    def contact_lost(self) -> bool:
        """The follower leaves the cam (force closure, ``Q < 0`` at a sample of the steady state)."""
        return self.contact_lost_at is not None

    @cached_property
    def jump_rpm(self) -> float | None:
        """The dynamic jump speed (rev/min), None: none found (form closure, or up to the search's top).

        Searched (:func:`dynamic_jump_rpm`) the first time it is read, then kept: the response at the design's
        speed, its assessment and its pictures do not need it.
        """
        return None if self.jump_search is None else self.jump_search.run()

    @property
    def jump_top_rpm(self) -> float | None:
        """The top of the jump speed's search (rev/min); None under form closure (no search)."""
        return None if self.jump_search is None else self.jump_search.top_rpm

    @property
    def rpm(self) -> float:
        """Cam speed, rev/min."""
        return omega_to_rpm(self.omega)

    def to_dict(self) -> dict:
        """JSON-ready: ``natural_frequency_hz`` (Hz), ``phases`` (``phase``, ``kind``, ``period_ratio``,
        ``residual_from_rest``, ``residual``: over the phase's height, dimensionless), ``dynamic_max_contact_force``
        and ``dynamic_min_contact_force`` (the contact force at the face, N, a rocker's too), ``contact_lost``,
        ``contact_lost_at_deg`` (cam angle, deg), ``dynamic_jump_rpm`` (rev/min)."""
        finite = np.isfinite(self.contact)
        return {
            "natural_frequency_hz": self.natural_frequency,
            "phases": [
                {
                    "phase": p.phase,
                    "kind": p.kind,
                    "period_ratio": p.period_ratio,
                    "residual_from_rest": p.residual_from_rest,
                    "residual": p.residual,
                }
                for p in self.phases
            ],
            "dynamic_max_contact_force": float(np.max(self.contact[finite])),
            "dynamic_min_contact_force": float(np.min(self.contact[finite])),
            "contact_lost": self.contact_lost,
            "contact_lost_at_deg": None if self.contact_lost_at is None else float(np.degrees(self.contact_lost_at)),
            "dynamic_jump_rpm": self.jump_rpm,
        }


def vibration(
    design, dyn, amplification: np.ndarray, *, rigid_jump_rpm: float | None = None, rpm: float | None = None
) -> Vibration | None:
    """The train's response at the design's speed; None without ``train_stiffness``.

    Parameters
    ----------
    design : cams.model.design.Design
    dyn : cams.model.dynamics.FollowerDynamics
        With the spring (force closure).
    amplification : ndarray
        The face's contact force per unit of ``Q`` (:attr:`cams.dynamics.forces.CamForces.amplification`) at
        ``len(amplification)`` equally spaced cam angles from 0.
    rigid_jump_rpm : float, optional
        Today's jump speed: the dynamic search runs up to three times it (or the speed), at least 3 times the
        design's speed.
    rpm : float, optional
        Default ``design.rpm``.
    """
    tm = train_model(design, dyn)
    if tm is None:
        return None
    n_rpm = design.rpm if rpm is None else rpm
    if n_rpm is None:
        raise InputError("cam.rpm", "is missing: the follower train's vibration needs the cam's speed")
    omega = rpm_to_omega(n_rpm)
    prog = design.program
    samples = len(amplification)
    tr = tm.train(omega)
    y0 = steady_state(prog, tr)
    r = grid_response(prog, tr, y0, samples)
    load = r.load * tm.total * tm.si
    contact = load * np.asarray(amplification)
    rho = tr.rho
    phases = []
    for i, rest, steady in phase_residuals(prog, tr, y0):
        p = prog.phases[i]
        phases.append(PhaseVibration(i, p.kind, float(rho * p.angle / TWO_PI), rest, steady))
    lost = np.flatnonzero(load < 0) if tm.force_closed else np.array([], int)
    lost_at = float(r.phi[lost[0]]) if lost.size else None
    search = None
    if tm.force_closed:
        top = 3 * max(n_rpm, rigid_jump_rpm if rigid_jump_rpm and np.isfinite(rigid_jump_rpm) else 0.0)
        speeds = [n for n in (n_rpm, rigid_jump_rpm) if n is not None and 0 < n < np.inf]
        start = 0.05 * min(speeds)  # a rigid jump speed of 0 (a velocity drop) is no place to start
        search = JumpSearch(prog, tm, start, top, samples)  # run only when the jump speed is read
    flight = None
    if lost_at is not None:
        flight = simulate(prog, tm, omega, (y0[0], y0[1] * rho * omega), samples=samples)
    to_t = omega
    return Vibration(
        r.phi,
        omega,
        r.x,
        r.dx * to_t,
        r.d2x * to_t**2,
        r.s,
        r.ds * to_t,
        prog.evaluate(r.phi).d2s * to_t**2,
        load,
        contact,
        tm.omega_n / TWO_PI,
        tuple(phases),
        lost_at,
        search,
        flight,
        tm.force_closed,
    )


def design_vibration(design, forces, amplification: np.ndarray | None = None) -> Vibration | None:
    """The vibration of a design with ``[dynamics] train_stiffness`` and a speed, from its face's forces stage.

    Parameters
    ----------
    design : cams.model.design.Design
    forces : cams.dynamics.forces.DesignForces or None
        The rigid forces (force closure): their spring, contact geometry and jump speed.
    amplification : ndarray, optional
        The contact geometry for form closure (no rigid forces): the face's contact force per unit of ``Q`` at
        equally spaced cam angles.

    Returns
    -------
    Vibration or None
        None without ``train_stiffness``, or under force closure without the rigid forces.
    """
    spec = design.dynamics
    if spec is None or spec.dynamics.train_stiffness is None:
        return None
    if forces is not None:
        dyn = spec.dynamics.with_spring(forces.spring)
        return vibration(design, dyn, forces.forces.amplification, rigid_jump_rpm=forces.jump.rpm)
    if amplification is None:
        return None
    return vibration(design, spec.dynamics, amplification)


def vibration_failure(v: Vibration | None) -> str | None:
    """Why the elastic train fails (the follower leaves the cam under force closure), or None."""
    if v is None or not v.contact_lost or v.contact_lost_at is None:
        return None
    said = (
        f"dynamics: the elastic follower train leaves the cam at {np.degrees(v.contact_lost_at):.2f} deg "
        f"(dynamic contact force down to {float(np.min(v.contact)):.4g} N at {v.rpm:.6g} rpm)"
    )
    f = v.flight
    if f is not None and f.intervals:
        unit = "deg" if f.rocker else "mm"
        gap = np.degrees(f.max_gap) if f.rocker else f.max_gap
        flights = ", ".join(
            f"{np.degrees(a):.1f} to " + ("the turn's end" if b is None else f"{np.degrees(b):.1f} deg")
            for a, b in f.intervals[:3]
        ) + (f" and {len(f.intervals) - 3} more flights" if len(f.intervals) > 3 else "")
        said += f"; followed over {f.turns} turns, the last one flies {flights}, gap up to {gap:.4g} {unit}"
    return said


def vibration_lines(vi: dict, *, rigid_jump_rpm: float | None, indent: str = "  ") -> list[str]:
    """The ``vibration`` part of a report (from :meth:`Vibration.to_dict`) in words, units beside."""
    from cams.words import force

    lines = [f"{indent}follower train: natural frequency {vi['natural_frequency_hz']:.6g} Hz"]
    from cams.words import phase_words

    for p in vi["phases"]:
        steady = "none (undamped)" if p["residual"] is None else f"{p['residual']:.4g}"
        lines.append(
            f"{indent}  {phase_words(p['kind'], p['phase'])}: period ratio lambda {p['period_ratio']:.4g}; "
            f"residual vibration / height: {p['residual_from_rest']:.4g} from rest, {steady} steady"
        )
    lines.append(
        f"{indent}  dynamic contact force: max {force(vi['dynamic_max_contact_force'])}, "
        f"min {force(vi['dynamic_min_contact_force'])}"
    )
    rigid = "none" if rigid_jump_rpm is None or not np.isfinite(rigid_jump_rpm) else f"{rigid_jump_rpm:.6g} rpm"
    dyn = "none found" if vi["dynamic_jump_rpm"] is None else f"{vi['dynamic_jump_rpm']:.6g} rpm"
    lost = "no" if not vi["contact_lost"] else f"YES, at {vi['contact_lost_at_deg']:.2f} deg"
    if rigid_jump_rpm is None and vi["dynamic_jump_rpm"] is None:  # no rigid forces: a groove
        lines.append(f"{indent}  jump speed: none (form closure: the groove drives both ways); contact lost: {lost}")
    else:
        lines.append(f"{indent}  jump speed: elastic {dyn} (rigid {rigid}); contact lost: {lost}")
    return lines
