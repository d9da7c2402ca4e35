"""Shared tools of the numerical stress tests (issue 7).

* :func:`guarded` runs a call under ``signal.alarm`` and fails the test when it
  takes longer than ``LIMIT_S`` seconds (a hang), without pytest-timeout.
* :func:`check_outcome` is the contract of every hard corner: either a clear
  :class:`~laws.errors.CamsError` naming its field, or a result whose numbers
  are finite (no NaN/inf in R0, L, centre or any value of ``to_dict()``; None
  only where documented) and, for the exact method, verified by the
  independent pressure-angle check.
* :func:`zone_witness` looks for an admissible centre with a method the product
  does not use for solving (Chebyshev centre of a finely sampled zone by
  ``scipy.optimize.linprog``), confirmed by :func:`cams.verify.pressure.check_pressure`;
  it judges "infeasible" answers.
* :func:`segment_witness` finds a point at a given distance from a reference on
  the segment between two admissible centres (admissible by convexity of the
  zone), confirmed by the same independent check; it judges fixed-L and R0
  floor answers.
"""

from __future__ import annotations

import json
import math
import re
import signal
import time
from contextlib import contextmanager

import numpy as np
import pytest

from cams.io.designfile import design_from_dict
from cams.solve import solve
from cams.verify.pressure import check_pressure, check_pressure_many
from laws.errors import CamsError, InfeasibleError, InputError
from tests.conftest import rocker_dict as base_rocker_dict

#: Largest time one guarded call may take (seconds).
LIMIT_S = 20

#: Keys of ``SolveResult.to_dict()`` that may be None (documented), as paths.
NONE_OK = {
    "L",                         # translating follower
    "offset",                    # rocker follower
    "samples",                   # exact method
    "error_bound",               # sampled methods / fixed L / floor modes
    "certified",                 # sampled methods / fixed L / floor modes
    "max_pressure_angle.return", "pressure_angle_at.return",  # program without return
    "limits.return",             # force closure
    "pressure_angle_R0",         # a chosen cam
    "bore_radius", "hub_wall", "hub_wall_required",   # no bore
    "rpm",                       # no cam speed
    "peaks.acceleration.value", "peaks.jerk.value",   # a velocity or acceleration jump: unbounded
}


class _Hang(Exception):
    pass


@contextmanager
def time_limit(seconds: int = LIMIT_S, what: str = "call"):
    """Fail the test if the block runs longer than ``seconds`` (SIGALRM)."""

    def _raise(signum, frame):
        raise _Hang()

    old = signal.signal(signal.SIGALRM, _raise)
    signal.alarm(seconds)
    t0 = time.perf_counter()
    try:
        yield
    except _Hang:
        pytest.fail(f"{what} took more than {seconds} s (hang?)")
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    assert time.perf_counter() - t0 < seconds


def guarded(fn, *args, seconds: int = LIMIT_S, **kw):
    """``fn(*args, **kw)`` with a time limit; exceptions pass through."""
    with time_limit(seconds, getattr(fn, "__name__", "call")):
        return fn(*args, **kw)


def translating_dict(**over) -> dict:
    """A translating design-file dict (stroke 30, cycloidal 120/30/120/rest), with per-table overrides."""
    d = {
        "name": "stress translating",
        "follower": {"kind": "translating", "stroke": 30.0, "roller_radius": 8.0},
        "cam": {"rotation": "ccw"},
        "motion": [
            {"phase": "rise", "law": "cycloidal", "angle": 120},
            {"phase": "dwell", "angle": 30},
            {"phase": "return", "law": "cycloidal", "angle": 120},
            {"phase": "dwell"},
        ],
        "limits": {"pressure_angle": 30, "closure": "force"},
        # the solvers under stress: the pressure angle alone sizes the cam (sizing to the part is tests/faces')
        "solve": {"method": "exact", "samples": 60, "constraints": "pressure_angle"},
    }
    for k, v in over.items():
        d[k] = {**d.get(k, {}), **v} if isinstance(v, dict) else v
    return d


def rocker_dict(**over) -> dict:
    """The rocker of tests/conftest.py (arm 125, swing 15, cycloidal 120/30/120/rest), samples 60."""
    d = base_rocker_dict(name="stress rocker", solve={"samples": 60, "constraints": "pressure_angle"})
    for k, v in over.items():
        d[k] = {**d.get(k, {}), **v} if isinstance(v, dict) else v
    return d


def design_dict(kind: str, **over) -> dict:
    return rocker_dict(**over) if kind == "rocker" else translating_dict(**over)


def walk(obj, path=""):
    """Yield ``(path, value)`` for every leaf of a nested dict/list."""
    if isinstance(obj, dict):
        for k, v in obj.items():
            yield from walk(v, f"{path}.{k}" if path else str(k))
    elif isinstance(obj, (list, tuple)):
        for i, v in enumerate(obj):
            yield from walk(v, f"{path}[{i}]")
    else:
        yield path, obj


def assert_finite_report(result) -> dict:
    """R0, L, centre and every number of ``to_dict()`` finite; None only where documented."""
    assert math.isfinite(result.R0), f"R0 = {result.R0}"
    assert np.all(np.isfinite(result.centre)), f"centre = {result.centre}"
    if result.L is not None:
        assert math.isfinite(result.L), f"L = {result.L}"
    if result.offset is not None:
        assert math.isfinite(result.offset), f"offset = {result.offset}"
    rep = result.to_dict()
    bad = []
    for path, v in walk(rep):
        if v is None:
            if path not in NONE_OK:
                bad.append(f"{path}=None")
        elif isinstance(v, float) and not math.isfinite(v):
            bad.append(f"{path}={v}")
    assert not bad, f"non-finite or undocumented None in to_dict(): {', '.join(bad)}"
    # and it survives strict JSON
    json.loads(json.dumps(rep), parse_constant=_no_constant)
    return rep


def _no_constant(name):
    raise AssertionError(f"JSON holds {name}")


def assert_clear_error(err: CamsError) -> None:
    """A user-facing error: InfeasibleError/InputError naming its field in one line."""
    assert isinstance(err, (InfeasibleError, InputError)), type(err)
    assert err.field, f"no field named in {err!r}"
    msg = str(err)
    assert msg.startswith(err.field + ":"), msg
    assert "\n" not in msg, msg
    assert not re.search(r"\b(nan|inf)\b", msg, re.IGNORECASE), msg


def check_result(result, *, exact: bool) -> None:
    """The numbers of a result are sane; the exact method's is verified and has R0 > 0."""
    assert_finite_report(result)
    assert result.R0 >= 0
    if exact:
        p = result.pressure
        assert p.ok, (f"exact result not verified: rise {np.degrees(p.rise)!r} deg "
                      f"(limit {np.degrees(p.rise_limit)!r}), return "
                      f"{None if p.ret is None else np.degrees(p.ret)!r} deg; "
                      f"{None if p.safety is None else p.safety.failure()}")
        assert result.R0 > 0, "the cam centre coincides with the roller's start point (R0 = 0)"
        if result.mode in ("min_R0", "min_L", "fixed_offset"):
            assert result.error_bound is not None and math.isfinite(result.error_bound)
            assert result.error_bound <= 1e-6 * result.design.scale
            assert result.certified is True, f"exact result not certified (error bound {result.error_bound!r})"


def check_outcome(d, method: str = "exact"):
    """Solve ``d`` (dict or CamDesign) under the time guard; return the result or the clear error."""
    design = design_from_dict(d) if isinstance(d, dict) else d
    try:
        r = guarded(solve, design, method=method)
    except CamsError as e:
        assert_clear_error(e)
        return e
    check_result(r, exact=(method == "exact"))
    return r


def zone_witness(design, samples: int = 1000):
    """An admissible centre found without the solvers, or None.

    Chebyshev centre of the zone sampled at ``samples`` steps per phase
    (a superset of the continuous zone), kept only if the independent check of
    the pressure angle accepts it.
    """
    from scipy.optimize import linprog

    from optimize.zone import sample_wedges

    N, c = sample_wedges(design, samples).lines()
    s = design.scale
    box = 1e4
    res = linprog([0, 0, -1], A_ub=np.hstack([N, np.ones((len(N), 1))]), b_ub=c / s,
                  bounds=[(-box, box), (-box, box), (None, 1.0)], method="highs")
    if res.status != 0 or res.x[2] <= 0:
        return None
    O = res.x[:2] * s
    return O if check_pressure(design, O).ok else None


def segment_witness(design, a: np.ndarray, b: np.ndarray, ref: np.ndarray, dist: float):
    """Point of segment a-b at distance ``dist`` from ``ref`` (|a-ref| <= dist <= |b-ref|), checked."""
    a, b, ref = (np.asarray(x, float) for x in (a, b, ref))
    lo, hi = 0.0, 1.0
    for _ in range(200):
        m = 0.5 * (lo + hi)
        if np.linalg.norm(a + m * (b - a) - ref) < dist:
            lo = m
        else:
            hi = m
    P = a + lo * (b - a)
    rep = check_pressure(design, P)
    return P, rep


def to_toml(d: dict) -> str:
    """A design-file dict as TOML (strings, numbers, tables, arrays of tables)."""

    def val(v):
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, str):
            return json.dumps(v)
        if isinstance(v, float):
            return repr(v)
        return str(v)

    out = [f"{k} = {val(v)}" for k, v in d.items() if not isinstance(v, (dict, list))]
    for k, v in d.items():
        if isinstance(v, dict):
            out.append(f"[{k}]")
            out += [f"{a} = {val(b)}" for a, b in v.items()]
        elif isinstance(v, list):
            for t in v:
                out.append(f"[[{k}]]")
                out += [f"{a} = {val(b)}" for a, b in t.items()]
    return "\n".join(out) + "\n"


def _coarse_excess(design, centres: np.ndarray, grid: int = 400) -> np.ndarray:
    """Largest pressure angle minus its limit over the sampled cycle, for many centres at once (radians).

    By kinematic inversion (:func:`cams.verify.pressure.contact_normal`, which shares
    no formula with the zone), on ``grid + 1`` positions per phase: a sampled
    maximum is below the true one, so a positive value proves the centre
    inadmissible.
    """
    from cams.verify.pressure import contact_normal

    lim = design.limits
    u = np.linspace(0.0, 1.0, grid + 1)
    worst = np.full(len(centres), -np.inf)
    for i, limit in design.constrained_phases():
        m = design.program.evaluate_phase(i, u)
        n, e, _ = contact_normal(design, centres[:, None, :], m.s, m.ds)
        g = np.arccos(np.clip(np.sum(n * e, axis=-1), -1.0, 1.0))
        worst = np.maximum(worst, np.nanmax(np.where(np.isnan(g), -np.inf, g), axis=1) - limit)
    assert lim is not None
    return worst


def assert_minimal(result, shrink: float = 1e-6) -> None:
    """No admissible centre at ``R0 (1 - shrink)`` from the roller's start point (minimum R0 answers).

    Candidates: 360 points evenly round that circle and 161 within 1 degree
    of the answer's direction. Each is judged by the pressure angle over the
    cycle by kinematic inversion (:mod:`cams.verify.pressure`, no formula of the
    zone): first sampled (:func:`_coarse_excess`), then the few that sampling
    cannot reject by :func:`cams.verify.pressure.check_pressure_many` (every local
    maximum refined), all at once, with no tolerance. Any that passes is a
    smaller admissible cam: the answer was not minimal.
    """
    design = result.design
    A0 = design.follower.position(0.0)
    rho = result.R0 * (1.0 - shrink)
    d = result.centre - A0
    a0 = math.atan2(d[1], d[0])
    ang = np.concatenate([np.linspace(0, 2 * np.pi, 360, endpoint=False), a0 + np.radians(np.linspace(-1, 1, 161))])
    pts = A0 + rho * np.stack([np.cos(ang), np.sin(ang)], axis=1)
    maybe = pts[_coarse_excess(design, pts) <= 0]
    for p, rep in zip(maybe, check_pressure_many(design, maybe, tol=0.0), strict=True):
        assert not rep.ok, (
            f"a centre at R0 (1 - {shrink:g}) = {rho!r} is admissible: {p.tolist()} "
            f"(answer R0 = {result.R0!r}, error bound {result.error_bound!r})")
