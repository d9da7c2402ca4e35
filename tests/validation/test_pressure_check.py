"""The independent pressure check (:mod:`cams.verify.pressure`) against a brute force that shares none of its formulas.

The brute force inverts the mechanism on a million positions per phase: the
roller centre's fixed path ``A(s)`` (:func:`.reference.path`, written from the
frame definitions), the pitch curve ``P(phi) = Rot(-eps phi) (A(s(phi)) - O)``,
its tangent by numerical differentiation of those positions
(``numpy.gradient``, second order, over the dense cam angles), turned back to
the fixed frame; the force is the outward normal on a rise (the tangent turned
by ``eps * 90 deg``), the velocity direction a central difference of ``A``
along the path. Every local maximum of that dense sampling is then refined by
a bounded scalar search on :func:`.reference.pressure_angles` (a 4th-order
finite difference of the same positions).

The designs have two nearly equal peaks in one rise (rockers with a
modified-cycloid rise, two smooth peaks, and with a parabolic rise, a kink and
a smooth peak); a coarse scan lowers one of them more than the other, so a
check that zooms only into the highest sample reports the lower peak. Two
peaks within one step of the scan stay beyond any scan's reach; the default
scan (2000 steps a phase) separates these.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from cams.verify.pressure import check_pressure, check_pressure_many
from laws.errors import InputError

from .designs import BRUTE_DESIGNS, rocker, rocker_dict
from .reference import D_PATH, max_pressure, path, pressure_angles, spec_of

#: Rockers whose rise has two peaks of the pressure angle, and centres (mm) across the one where they are equal.
#: Modified cycloid: smooth peaks after each acceleration pulse (u near 0.23 and 0.77), equal near
#: x = 64.8545; at x = 64.86 the first is higher by about 7e-6 rad, at 64.87 by about 2e-5 rad.
#: Parabolic: a kink at u = 0.5 (the acceleration jumps) and a smooth peak near u = 0.74, equal near x = 41.3616.
TWO_PEAKS = {
    "modified cycloid": (dict(swing=60.0, rise=("modified_cycloid", 120.0), limit=60.0),
                         [(64.84, 51.1), (64.85, 51.1), (64.86, 51.1), (64.87, 51.1)]),
    "parabolic": (dict(swing=90.0, rise=("parabolic", 120.0), limit=60.0),
                  [(41.35, 44.9), (41.36, 44.9), (41.37, 44.9), (41.38, 44.9)]),
}


def _turn(v: np.ndarray, a) -> np.ndarray:
    c, s = np.cos(a), np.sin(a)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def _dense_angles(design, centre, phase: int, u: np.ndarray) -> np.ndarray:
    """Rise pressure angle (radians) on the dense positions ``u`` by differentiating the inverted positions."""
    spec = spec_of(design)
    p = spec.program.phases[phase]
    assert p.kind == "rise"
    phi = spec.program.starts[phase] + u * p.angle
    s = spec.program.evaluate_phase(phase, u).s
    pitch = _turn(path(spec, s) - np.asarray(centre, float), -spec.eps * phi)
    tangent = _turn(np.gradient(pitch, phi, axis=0, edge_order=2), spec.eps * phi)
    force = _turn(tangent, spec.eps * np.pi / 2)
    d = D_PATH * (1.0 if spec.kind == "rocker" else spec.scale)
    v = path(spec, s + d) - path(spec, s - d)
    c = np.sum(force * v, axis=-1) / (np.linalg.norm(force, axis=-1) * np.linalg.norm(v, axis=-1))
    return np.arccos(np.clip(c, -1.0, 1.0))


def brute_force_rise(design, centre, phase: int = 0, n: int = 10**6) -> float:
    """Largest rise pressure angle (radians): ``n + 1`` positions, every local maximum refined."""
    u = np.linspace(0.0, 1.0, n + 1)
    g = _dense_angles(design, centre, phase, u)
    k = np.flatnonzero((g >= np.r_[-1.0, g[:-1]]) & (g >= np.r_[g[1:], -1.0]))
    best = -np.inf
    for j in k[np.argsort(-g[k])][:10]:
        # four steps each side: the dense difference smears a kink (a law's breakpoint) over a step or two;
        # searched as an offset from u[j], since the search's tolerance grows with |x| (1.5e-8 |x|)
        r = minimize_scalar(lambda t: -float(pressure_angles(design, centre, phase, [u[j] + t])[0]),
                            bounds=(u[max(j - 4, 0)] - u[j], u[min(j + 4, n)] - u[j]), method="bounded",
                            options={"xatol": 1e-14})
        best = max(best, float(-r.fun), float(pressure_angles(design, centre, phase, [u[j]])[0]))
    return best


@pytest.fixture(scope="module", params=list(TWO_PEAKS))
def two_peaks(request):
    kw, centres = TWO_PEAKS[request.param]
    d = rocker(**kw)
    return d, {c: brute_force_rise(d, np.array(c)) for c in centres}


def test_brute_force_sees_two_nearly_equal_peaks(two_peaks):
    """The construction: two maxima, within 3e-5 rad of each other, the higher one changing side."""
    d, truth = two_peaks
    u = np.linspace(0.0, 1.0, 20001)
    sides = []
    for c in truth:
        g = pressure_angles(d, np.array(c), 0, u)
        first, second = g[:12001].max(), g[12001:].max()  # split at u = 0.6
        assert abs(first - second) < 3e-5
        sides.append(first > second)
    assert not sides[0] and sides[-1]


@pytest.mark.parametrize("grid", [8, 13, 21, 34, 55, 2000])
def test_check_finds_the_peak_the_sampling_lowered(two_peaks, grid):
    """Every local maximum is refined: the check equals the brute force at every scan that separates the peaks."""
    d, truth = two_peaks
    for c, ref in truth.items():
        got = check_pressure(d, np.array(c), grid=grid).rise
        assert got == pytest.approx(ref, abs=1e-9), (c, grid, got - ref)


@pytest.mark.parametrize("n", [8, 21, 55])
def test_reference_max_pressure_refines_every_peak(two_peaks, n):
    """The validation reference's own maximum (a coarse scan, scalar search) also keeps the lowered peak."""
    d, truth = two_peaks
    for c, ref in truth.items():
        assert max_pressure(d, np.array(c), n=n)[0] == pytest.approx(ref, abs=1e-9), (c, n)


def test_check_at_a_join_of_two_rises():
    """Two rises meeting with a jump of velocity: the largest angle sits at a phase end (one side of the join)."""
    from cams.io.designfile import design_from_dict

    dd = rocker_dict(limit=60.0)
    dd["motion"] = [{"phase": "rise", "law": "linear", "angle": 60.0, "height": 5.0},
                    {"phase": "rise", "law": "linear", "angle": 40.0, "height": 10.0},
                    {"phase": "dwell", "angle": 30.0}, {"phase": "return", "law": "cycloidal", "angle": 120.0},
                    {"phase": "dwell"}]
    d = design_from_dict(dd)
    for c in [(60.0, -40.0), (-30.0, -90.0), (80.0, 20.0)]:
        ref = max(brute_force_rise(d, np.array(c), phase, n=200_000) for phase in (0, 1))
        assert check_pressure(d, np.array(c), grid=50).rise == pytest.approx(ref, abs=1e-9), c


def test_check_matches_brute_force_on_validation_designs():
    """Rise maxima of the validation designs at a few centres, default scan, against the brute force."""
    rng = np.random.default_rng(12)
    for name in ("rocker force, opposite senses", "rocker form, cam cw, long arm"):
        from cams.io.designfile import design_from_dict

        d = design_from_dict(BRUTE_DESIGNS[name])
        for c in rng.normal(size=(2, 2)) * d.scale:
            got = check_pressure(d, c).rise
            assert got == pytest.approx(brute_force_rise(d, c, n=200_000), abs=1e-9), (name, c)


#: Laws evaluated by a matrix product (:func:`laws.standard._poly`), whose rounding depends on how many positions
#: are evaluated together: with them a batch equals one centre at a time to rounding only.
MATRIX_LAWS = {"poly345", "poly4567"}


def test_many_equals_one_at_a_time():
    """The batched check gives, per centre, the one-at-a-time report: to the last digit (angles, cam angles and
    verdicts) whatever the batch (the centres in another order, or split), at coarse and default scans; to
    rounding where a law's values depend on the batch (:data:`MATRIX_LAWS`)."""
    rng = np.random.default_rng(7)
    from cams.io.designfile import design_from_dict

    designs = [design_from_dict(dd) for dd in BRUTE_DESIGNS.values()] + [rocker(**kw) for kw, _ in TWO_PEAKS.values()]
    exact = 0
    for d in designs:
        C = np.vstack([rng.normal(size=(30, 2)) * d.scale, rng.normal(size=(6, 2)) * 4 * d.scale,
                       d.follower.position(0.0)])  # the last: the roller centre itself (undefined normal there)
        for grid in (13, 300):
            many = check_pressure_many(d, C, grid=grid)
            one = [check_pressure(d, c, grid=grid) for c in C]
            order = rng.permutation(len(C))
            again = check_pressure_many(d, C[order], grid=grid)
            if not {p.law.name for p in d.program.phases if p.kind != "dwell"} & MATRIX_LAWS:
                exact += 1
                assert many == one, (d.name, grid)
                assert again == [many[q] for q in order]
                continue
            for m, o in zip(many, one, strict=True):
                assert m.ok == o.ok
                for a, b in ((m.rise, o.rise), (m.ret, o.ret)):
                    assert (a is None) == (b is None)
                    if a is not None:
                        assert a == pytest.approx(b, abs=1e-12)
    assert exact >= 6
    assert check_pressure_many(d, C[0]) == [check_pressure(d, C[0])]
    assert check_pressure_many(d, np.empty((0, 2))) == []


def test_many_in_blocks_equals_one_block(monkeypatch):
    """Centres checked in several blocks (memory bound, :data:`cams.verify.pressure.CHUNK`) give the same reports."""
    import cams.verify.pressure as pressure

    d = rocker(**TWO_PEAKS["parabolic"][0])
    C = np.random.default_rng(3).normal(size=(25, 2)) * d.scale
    whole = check_pressure_many(d, C, grid=40)
    monkeypatch.setattr(pressure, "CHUNK", 7 * 41)
    assert check_pressure_many(d, C, grid=40) == whole


@pytest.mark.parametrize("bad", [[1.0], [[1.0, 2.0, 3.0]], [np.nan, 0.0], "x", [[[1.0, 2.0]]]])
def test_bad_centres_are_refused(bad):
    d = rocker()
    with pytest.raises(InputError) as exc:
        check_pressure_many(d, bad)
    assert exc.value.field == "centre"


def test_one_centre_only():
    with pytest.raises(InputError):
        check_pressure(rocker(), [[0.0, -60.0], [0.0, -70.0]])


@pytest.mark.parametrize("grid", [0, -3, 2.5, True])
def test_bad_grid_is_refused(grid):
    with pytest.raises(InputError) as exc:
        check_pressure(rocker(), [0.0, -60.0], grid=grid)
    assert exc.value.field == "grid"
