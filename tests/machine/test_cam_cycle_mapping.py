"""The cam's angle against the machine's cycle angle, checked by simulating the machine from first principles.

``cams machine`` reports the cam's timing (its mounting angle, the rises), the
cutting window and, with ``--forces``, where the cam's force peaks fall, all
in cycle angles (the crank's rotation from position 1). Here none of that is
recomputed with :mod:`cams.machine.timing`'s own formula. Instead the machine is run
by hand:

* position 1 is found from the linkage's own motion (its output's dead
  positions; the end of the slow, working stroke);
* the crank is stepped through the cycle angle ``c`` in the sense the file
  gives (``crank_rotation``), ``phi = phi_1 + sense * c``;
* the cam's frame rotation follows from the gear train as written in the file:
  ``dpsi = k * dphi`` with ``k = 1`` on the crank's shaft and
  ``k = -+ z_crank / z_cam`` for an external (internal) mesh, ``dphi`` the crank's
  rotation since the cam's program started (at the reported ``mount_deg``);
* the cam's program angle is that rotation measured in the cam's own sense
  of rotation (the sign of ``k`` times the crank's sense), and the follower's
  displacement is the motion program of the file's ``[[motion]]`` tables
  (built here with :mod:`laws.program`) evaluated there.

Then the reported rises must be where the simulated follower rises, the
simulated follower must not rise (nor, where the report gives no
return-overlap note, move at all) in the reported cutting window, the
reported cycle diagram must be the simulated follower, and the reported
``*_at_cycle_deg`` of the cam's force peaks must be the cycle angles at which
the simulated cam is at their ``*_at_deg``. Shaft drive (ratio 1) and gears
(ratio 1/2 and 1/3, external and internal mesh).
"""

from __future__ import annotations

import contextlib
import io
import json
import tomllib
from dataclasses import dataclass
from fractions import Fraction
from math import gcd
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from cams.cli import main
from cams.machine.machinefile import load_machine
from laws.program import Phase, Program

ROOT = Path(__file__).resolve().parents[2]
MACHINES = ROOT / "examples" / "machines"
SLOTTING = MACHINES / "slotting_machine.toml"
SLOTTING_FORCES = MACHINES / "slotting_machine_forces.toml"
PUMP = MACHINES / "pump.toml"

STEP_DEG = 0.01  # simulation step of the cycle angle
GRID_TOL_DEG = 2.5 * STEP_DEG  # where a simulated event can be located on that grid
ANGLE_TOL_DEG = 1e-6  # reported angles vs angles solved on the simulation


def _replace(text: str, old: str, new: str) -> str:
    assert old in text, f"the example file changed: {old!r} not found"
    return text.replace(old, new, 1)


def _dynamics_table() -> str:
    text = SLOTTING_FORCES.read_text(encoding="utf-8")
    return text[text.index("[dynamics]"):text.index("[forces]")]


_PUMP_GEARS = 'kind = "gears"\nz_crank = 20              # Z5, on the crank\'s shaft\nz_cam = 40                # Z6, on the cam\'s shaft\nmesh = "external"'
_PUMP_PROGRAM = ('angle = 40\n[[motion]]\nphase = "dwell"\nangle = 60\n[[motion]]\nphase = "return"\nlaw = "cycloidal"\n'
                 'angle = 60')
# rise 20 + dwell 5 + return 20 cam degrees = 90 crank degrees at ratio 1/2: all of it fits the 120 degree
# out-of-work window (margin 10) when pushed to its start, so the follower rests at 0 through every cut
_PUMP_SHORT_PROGRAM = ('angle = 20\n[[motion]]\nphase = "dwell"\nangle = 5\n[[motion]]\nphase = "return"\n'
                       'law = "cycloidal"\nangle = 20')


def _mirrored(text: str) -> str:
    """The pump's follower swinging the other way: the mirror image of the example's cam.

    With the cam turning with the crank (clockwise: shaft, or an internal mesh) the example's follower
    (rise clockwise, roller 12 mm) undercuts, so ``cams machine`` rightly fails; the mirror image of the
    example's cam (which turns counter-clockwise) is the same buildable cam.
    """
    return _replace(text, 'rise_direction = "cw"', 'rise_direction = "ccw"')


def _variants() -> dict[str, str]:
    """Machine files of the cases by name (text)."""
    pump = PUMP.read_text(encoding="utf-8")
    short = _replace(_replace(pump, _PUMP_PROGRAM, _PUMP_SHORT_PROGRAM), 'placement = "centre"', 'placement = "early"')
    return {
        "slotting-shaft": SLOTTING.read_text(encoding="utf-8"),
        "slotting-shaft-forces": SLOTTING_FORCES.read_text(encoding="utf-8"),
        "pump-gears-external": pump,
        "pump-gears-internal": _mirrored(_replace(pump, 'mesh = "external"', 'mesh = "internal"')),
        "pump-shaft": _mirrored(_replace(pump, _PUMP_GEARS, 'kind = "shaft"')),
        # ratio 1/3: the pattern repeats every 3 crank turns (a 25 degree rise = 75 crank degrees fits the window)
        "pump-gears-external-1to3": _replace(_replace(pump, "z_cam = 40", "z_cam = 60"), "angle = 40", "angle = 25"),
        "pump-gears-external-short": short,
        "pump-gears-internal-short": _mirrored(_replace(short, 'mesh = "external"', 'mesh = "internal"')),
    }


CASES = list(_variants())
ZERO_LIFT_CASES = ["slotting-shaft", "slotting-shaft-forces", "pump-gears-external-short", "pump-gears-internal-short"]
FORCE_CASES = ["slotting-shaft-forces", "pump-gears-external", "pump-gears-internal", "pump-shaft",
               "pump-gears-external-1to3", "pump-gears-external-short"]


@pytest.fixture(scope="module")
def files(tmp_path_factory) -> dict[str, Path]:
    """The cases written out; ``name + "+dynamics"`` is the pump's file with slotting_machine_forces.toml's [dynamics]."""
    d = tmp_path_factory.mktemp("cam_cycle_mapping")
    dyn = _dynamics_table()
    out = {}
    for name, text in _variants().items():
        out[name] = d / f"{name}.toml"
        out[name].write_text(text, encoding="utf-8")
        if "[dynamics]" not in text:
            out[name + "+dynamics"] = d / f"{name}_dynamics.toml"
            out[name + "+dynamics"].write_text(text + "\n" + dyn, encoding="utf-8")
    return out


_REPORTS: dict = {}


def cli_report(path: Path, *flags: str) -> tuple[int, dict]:
    """Exit code and the JSON of ``cams machine PATH --json FLAGS``."""
    key = (str(path), flags)
    if key not in _REPORTS:
        buf = io.StringIO()
        with contextlib.redirect_stdout(buf):
            rc = main(["machine", str(path), "--json", *flags])
        _REPORTS[key] = (rc, json.loads(buf.getvalue()))
    return _REPORTS[key]


# ---------------------------------------------------------------------------------------------------------------
# the machine run by hand


def _program_from_file(raw: dict) -> Program:
    """The follower's motion program from the file's [follower] and [[motion]] tables (radians of cam, swing in rad)."""
    fo = raw["follower"]
    assert fo["kind"] == "rocker", "these cases use rocker followers"
    lift = np.radians(fo["swing"])
    given = sum(m["angle"] for m in raw["motion"] if "angle" in m)
    phases = []
    for m in raw["motion"]:
        angle = m.get("angle", 360.0 - given)  # one phase without an angle takes the rest of the turn
        phases.append(Phase(m["phase"], float(np.radians(angle)), m.get("law")))
    return Program(tuple(phases), float(lift))


def _position_1(linkage, crank_sense: int) -> tuple[float, float, float]:
    """(frame angle of position 1, output there, output at the working stroke's start) from the linkage's motion.

    Position 1 ends the working stroke; the working stroke is the slow one (the files use the default
    ``working = "slow"``): the longer crank rotation between the output's two dead positions.
    """
    phi = np.linspace(0.0, 2 * np.pi, 7200, endpoint=False)
    ds = linkage.output(phi).ds
    dead = []
    for i in range(phi.size):
        j = (i + 1) % phi.size
        if np.sign(ds[i]) != np.sign(ds[j]) and ds[i] != 0:
            b = phi[j] if j else 2 * np.pi
            dead.append(brentq(lambda x: float(linkage.output(np.array([x])).ds[0]), phi[i], b, xtol=1e-14))
    assert len(dead) == 2, f"expected two dead positions, got {np.degrees(dead)}"
    a, b = dead
    ab = np.mod(crank_sense * (b - a), 2 * np.pi)  # crank rotation from a to b, in the crank's sense
    start, end = (a, b) if ab > np.pi else (b, a)
    s = linkage.output(np.array([start, end])).s
    return float(end), float(s[1]), float(s[0])


@dataclass
class Sim:
    """A machine file's machine stepped through its cycle by hand."""

    name: str
    raw: dict
    report: dict
    linkage: object
    crank_sense: int
    phi_1: float  # frame crank angle of position 1
    s_1: float  # tool at position 1 (end of the working stroke)
    s_0: float  # tool at the working stroke's start
    k: Fraction  # cam's frame rotation per crank frame rotation
    cam_sense: int  # +1: the cam turns counter-clockwise
    period: tuple[int, int]  # (cam turns, crank turns) of the repeating pattern
    program: Program
    mount: float  # reported cycle angle where the cam's program starts, radians

    @property
    def turns(self) -> int:
        return self.period[1]

    def crank_frame(self, c):
        """Frame angle of the crank after rotating ``c`` from position 1 in its own sense."""
        return self.phi_1 + self.crank_sense * np.asarray(c, dtype=float)

    def cam_angle(self, c):
        """Cam's program angle (radians, in its own sense of rotation, unwrapped) at cycle angles ``c``."""
        dphi = self.crank_frame(c) - self.crank_frame(self.mount)  # crank's frame rotation since the program started
        dpsi = float(self.k) * dphi  # the cam's frame rotation through the drive
        return self.cam_sense * dpsi

    def follower(self, c):
        """Follower's swing (radians) at cycle angles ``c``."""
        return self.program.evaluate(self.cam_angle(c)).s

    def tool_travel(self, c):
        """Tool's distance from the working stroke's start and its velocity sign toward position 1, at cycle angles c."""
        out = self.linkage.output(self.crank_frame(c))
        towards_1 = np.sign(out.ds * self.crank_sense) == np.sign(self.s_1 - self.s_0)
        return np.abs(out.s - self.s_0), towards_1

    def cycle_angles_of(self, cam_deg: float) -> list[float]:
        """Every cycle angle (degrees, in [0, 360 q)) at which the simulated cam is at program angle ``cam_deg``."""
        target = np.radians(cam_deg)

        def off(c):  # cam angle minus the target, wrapped to (-pi, pi]
            return float(np.pi - np.mod(np.pi - (self.cam_angle(c) - target), 2 * np.pi))

        c = np.radians(np.arange(0.0, 360.0 * self.turns + 0.5, 0.5))
        f = np.array([off(x) for x in c])
        out = []
        for i in range(c.size - 1):
            if f[i] == 0:
                out.append(c[i])
            elif f[i] * f[i + 1] < 0 and abs(f[i] - f[i + 1]) < np.pi:  # a crossing, not the wrap of the angle
                out.append(brentq(off, c[i], c[i + 1], xtol=1e-14))
        return sorted(float(np.mod(np.degrees(x), 360.0 * self.turns)) for x in out)


_SIMS: dict = {}


def simulate(files, name: str) -> Sim:
    if name in _SIMS:
        return _SIMS[name]
    path = files[name]
    raw = tomllib.loads(path.read_text(encoding="utf-8"))
    rc, rep = cli_report(path)
    assert rc == 0, f"{name}: cams machine failed: overlap {rep['overlap']}, notes {rep['notes']}"
    assert raw.get("cutting", {}).get("working", "slow") == "slow"
    crank_sense = {"ccw": 1, "cw": -1}[raw["linkage"]["crank_rotation"]]
    linkage = load_machine(path).linkage
    assert linkage.crank_sense == crank_sense, "the linkage turns its crank against the file's crank_rotation"
    phi_1, s_1, s_0 = _position_1(linkage, crank_sense)
    dr = raw.get("drive", {})
    if dr.get("kind", "shaft") == "shaft":
        k, period = Fraction(1), (1, 1)
    else:
        z1, z2 = dr["z_crank"], dr["z_cam"]
        # at the pitch point both wheels' rims move together: z1 * dphi = -+ z2 * dpsi (external: they turn apart)
        k = Fraction(z1, z2) * (-1 if dr.get("mesh", "external") == "external" else 1)
        g = gcd(z1, z2)
        period = (z1 // g, z2 // g)  # after z2/g crank turns both wheels are back where they started
    cam_sense = int(np.sign(float(k))) * crank_sense
    sim = Sim(name, raw, rep, linkage, crank_sense, phi_1, s_1, s_0, k, cam_sense, period,
              _program_from_file(raw), float(np.radians(rep["timing"]["mount_deg"])))
    _SIMS[name] = sim
    return sim


def _intervals(flags: np.ndarray, c_deg: np.ndarray, period_deg: float) -> list[tuple[float, float]]:
    """Intervals (start in [0, period), end > start) where ``flags[i]`` (step from c[i] to c[i+1]) holds, periodic."""
    n = flags.size
    if flags.all():
        return [(0.0, period_deg)]
    first_off = int(np.argmin(flags))
    out, i = [], 0
    while i < n:
        j = (first_off + i) % n
        if flags[j]:
            start = i
            while i < n and flags[(first_off + i) % n]:
                i += 1
            a = c_deg[(first_off + start) % n]
            length = (i - start) * (c_deg[1] - c_deg[0])
            out.append((float(np.mod(a, period_deg)), float(np.mod(a, period_deg) + length)))
        else:
            i += 1
    return sorted(out)


def _cycle_grid(sim: Sim) -> np.ndarray:
    n = round(360.0 * sim.turns / STEP_DEG)
    return np.arange(n + 1) * STEP_DEG  # 0 .. 360 q inclusive


# ---------------------------------------------------------------------------------------------------------------
# the frame of the simulation agrees with the report


@pytest.mark.parametrize("name", CASES)
def test_position_1_drive_and_mount_as_reported(files, name):
    sim = simulate(files, name)
    rep = sim.report
    w, t, dr = rep["windows"], rep["timing"], rep["drive"]
    # position 1 from the linkage's own motion is the reported origin of the cycle angle
    assert np.mod(w["origin_frame_deg"] - np.degrees(sim.phi_1) + 180.0, 360.0) - 180.0 == pytest.approx(0.0, abs=1e-7)
    assert w["crank_rotation"] == sim.raw["linkage"]["crank_rotation"]
    # the tool is at the end of the working stroke there and at its start after the return span
    assert float(sim.linkage.output(sim.crank_frame(np.array([0.0]))).s[0]) == pytest.approx(sim.s_1, abs=1e-9)
    ws = np.radians(w["working"][0])
    assert float(sim.linkage.output(sim.crank_frame(np.array([ws]))).s[0]) == pytest.approx(sim.s_0, abs=1e-7)
    # the drive as derived from the teeth and the mesh
    assert t["ratio"] == pytest.approx(abs(float(sim.k)), rel=1e-15)
    assert dr["sense"] == ("same" if sim.k > 0 else "opposite")
    assert (t["period"]["cam_turns"], t["period"]["crank_turns"]) == sim.period
    # the crank's frame angle when the program starts
    assert np.mod(t["mount_frame_deg"] - np.degrees(sim.crank_frame(sim.mount)) + 180.0, 360.0) - 180.0 == pytest.approx(
        0.0, abs=1e-7)
    # the cam the product sizes turns the way the gear train turns it
    assert load_machine(files[name]).cam.cam_sense == sim.cam_sense
    # sanity of the simulated cam: p turns of the cam in q crank turns, at the program's start at the mount
    assert sim.cam_angle(sim.mount) == 0.0
    assert sim.cam_angle(sim.mount + 2 * np.pi * sim.turns) == pytest.approx(2 * np.pi * sim.period[0], rel=1e-12)


def test_external_mesh_turns_the_cam_against_the_crank(files):
    """pump.toml's crank turns cw; through the external Z5-Z6 pair the cam turns ccw, through an internal one cw."""
    ext, inn, shaft = (simulate(files, n) for n in ("pump-gears-external", "pump-gears-internal", "pump-shaft"))
    assert ext.crank_sense == inn.crank_sense == shaft.crank_sense == -1
    assert (ext.cam_sense, inn.cam_sense, shaft.cam_sense) == (1, -1, -1)
    assert (ext.k, inn.k, shaft.k) == (Fraction(-1, 2), Fraction(1, 2), Fraction(1))
    # one crank turn in its sense (frame angle -360 deg) turns the cam +180 deg (ext) or -180 deg (int) in the frame
    for sim, frame_turn in ((ext, 180.0), (inn, -180.0)):
        dphi = sim.crank_frame(2 * np.pi) - sim.crank_frame(0.0)
        assert np.degrees(dphi) == pytest.approx(-360.0)
        assert np.degrees(float(sim.k) * dphi) == pytest.approx(frame_turn)


# ---------------------------------------------------------------------------------------------------------------
# (1) the reported rises are where the simulated follower rises


@pytest.mark.parametrize("name", CASES)
def test_reported_rises_are_where_the_follower_rises(files, name):
    sim = simulate(files, name)
    c = _cycle_grid(sim)
    s = sim.follower(np.radians(c))
    lift = sim.program.lift
    period_deg = 360.0 * sim.turns
    assert s[-1] == pytest.approx(s[0], abs=1e-12 * lift), "the simulated follower does not repeat over the period"
    rising = s[1:] > s[:-1]
    simulated = _intervals(rising, c[:-1], period_deg)
    reported = [tuple(r) for r in sim.report["timing"]["rises_deg"]]
    assert len(simulated) == len(reported), f"simulated rises {simulated}, reported {reported}"
    n_rises = sum(p.kind == "rise" for p in sim.program.phases)
    assert len(simulated) == n_rises * sim.period[0]
    for a, b in reported:
        # the report gives the rise's start within the first crank turn (start in [0, 360)); the simulated rise
        # is at that angle in one of the period's crank turns
        hits = [(x, y) for x, y in simulated
                if min(abs(np.mod(x - a + 180.0, 360.0) - 180.0), 360.0) <= GRID_TOL_DEG]
        assert len(hits) == 1, f"reported rise {a:.4f}..{b:.4f} deg: simulated rises {simulated}"
        x, y = hits[0]
        assert y - x == pytest.approx(b - a, abs=2 * GRID_TOL_DEG)
        # and the follower goes through the whole rise there: from its lower level to the upper one
        lo, hi = sim.follower(np.radians([x, y]))
        assert hi - lo == pytest.approx(lift, abs=1e-9 * lift)


@pytest.mark.parametrize("name", CASES)
def test_first_rise_starts_at_the_mount_in_the_simulated_crank_turn(files, name):
    """The program's start at ``mount_deg`` is the first rise's start (all cases begin with a rise) in crank turn 0."""
    sim = simulate(files, name)
    c = _cycle_grid(sim)
    s = sim.follower(np.radians(c))
    first = _intervals(s[1:] > s[:-1], c[:-1], 360.0 * sim.turns)
    assert sim.program.phases[0].kind == "rise"
    starts = [x for x, _ in first]
    assert min(abs(x - sim.report["timing"]["mount_deg"]) for x in starts) <= GRID_TOL_DEG


@pytest.mark.parametrize("name", CASES)
def test_reported_cycle_diagram_is_the_simulated_follower(files, name):
    sim = simulate(files, name)
    dia = sim.report["diagram"]
    assert dia["follower_unit"] == "deg"
    c = np.asarray(dia["crank_deg"])
    assert c[0] == 0.0 and c[-1] == pytest.approx(360.0 * sim.turns)
    got = np.asarray(dia["follower"])
    want = np.degrees(sim.follower(np.radians(c)))
    worst = int(np.argmax(np.abs(got - want)))
    assert np.allclose(got, want, rtol=0, atol=1e-9), (
        f"at cycle angle {c[worst]:g} deg the report's follower is {got[worst]:.6f} deg, the simulated {want[worst]:.6f} deg")


# ---------------------------------------------------------------------------------------------------------------
# (2) no feeding in the reported cutting window


def _cut_samples(sim: Sim, *, inset_deg: float = 0.0) -> list[np.ndarray]:
    """Cycle angles (deg) through the reported cutting window in each crank turn of the period."""
    a, b = sim.report["windows"]["cutting"]
    a, b = a + inset_deg, b - inset_deg
    base = np.linspace(a, b, int(np.ceil((b - a) / STEP_DEG)) + 1)  # increasing, both ends included
    return [base + 360.0 * j for j in range(sim.turns)]


@pytest.mark.parametrize("name", CASES)
def test_reported_cutting_window_is_the_tools_cut(files, name):
    sim = simulate(files, name)
    cu = sim.raw.get("cutting", {})
    H = abs(sim.s_1 - sim.s_0)
    a, b = np.radians(sim.report["windows"]["cutting"])
    travel, towards_1 = sim.tool_travel(np.array([a, b]))
    assert travel[0] == pytest.approx(cu.get("approach", 0.0) * H, abs=1e-7 * H)
    assert travel[1] == pytest.approx((1 - cu.get("overrun", 0.0)) * H, abs=1e-7 * H)
    inner = np.radians(_cut_samples(sim, inset_deg=STEP_DEG)[0])
    travel, towards_1 = sim.tool_travel(inner)
    assert towards_1.all() and np.all(np.diff(travel) > 0)


@pytest.mark.parametrize("name", CASES)
def test_follower_does_not_rise_during_the_cut(files, name):
    sim = simulate(files, name)
    lift = sim.program.lift
    for c in _cut_samples(sim):
        s = sim.follower(np.radians(c))
        up = np.diff(s)
        i = int(np.argmax(up))
        assert up[i] <= 1e-12 * lift, (
            f"the simulated follower rises by {np.degrees(up[i]):.3g} deg at cycle angle {c[i]:.3f} deg, inside the "
            f"reported cut {sim.report['windows']['cutting']}")


@pytest.mark.parametrize("name", ZERO_LIFT_CASES)
def test_follower_rests_at_zero_lift_during_the_cut(files, name):
    """Where the report has no return-overlap note the follower is in its dwell at 0 through every cut."""
    sim = simulate(files, name)
    assert not any("return overlaps the cut" in n for n in sim.report["notes"])
    for c in _cut_samples(sim):
        s = sim.follower(np.radians(c))
        i = int(np.argmax(np.abs(s)))
        assert abs(s[i]) <= 1e-12 * sim.program.lift, (
            f"the simulated follower is at {np.degrees(s[i]):.4g} deg at cycle angle {c[i]:.3f} deg, inside the "
            f"reported cut {sim.report['windows']['cutting']}")


@pytest.mark.parametrize("name", sorted(set(CASES) - set(ZERO_LIFT_CASES)))
def test_return_overlap_note_is_where_the_follower_returns_in_the_cut(files, name):
    """pump.toml's return (not a feed) falls in the delivery stroke; the report says so and the simulation agrees."""
    sim = simulate(files, name)
    assert any("return overlaps the cut" in n for n in sim.report["notes"])
    moves_down = False
    for c in _cut_samples(sim, inset_deg=STEP_DEG):
        s = sim.follower(np.radians(c))
        moves_down |= bool(np.any(np.diff(s) < -1e-6 * sim.program.lift))
    assert moves_down


# ---------------------------------------------------------------------------------------------------------------
# (3) the cam's force peaks in cycle angles


@pytest.mark.parametrize("name", FORCE_CASES)
def test_cam_force_peaks_at_the_simulated_cycle_angles(files, name):
    path = files.get(name + "+dynamics", files[name])
    sim = simulate(files, name)
    rc, rep = cli_report(path, "--forces")
    assert rep["timing"] == sim.report["timing"]  # the [dynamics] table does not move the cam
    cam = rep["forces"]["cam"]
    checked = 0
    for key in ("max_contact_at", "max_torque_at", "jump_at"):
        at = cam.get(key + "_deg")
        if at is None:
            assert cam.get(key + "_cycle_deg") is None
            continue
        want = sim.cycle_angles_of(at)
        got = cam[key + "_cycle_deg"]
        assert len(want) == sim.period[0]
        assert got == pytest.approx(want, abs=ANGLE_TOL_DEG), (
            f"{key}: cam angle {at} deg; reported cycle angles {got}, simulated {want}")
        for c in want:  # the follower there is the program's at the cam angle
            assert float(sim.follower(np.radians(c))) == pytest.approx(
                float(sim.program.evaluate(np.radians(at)).s), abs=1e-9 * sim.program.lift)
        checked += 1
    for imp in cam["impacts"]:
        assert imp["cycle_deg"] == pytest.approx(sim.cycle_angles_of(imp["cam_angle_deg"]), abs=ANGLE_TOL_DEG)
    assert checked >= 2


def test_pump_torque_peak_lies_in_the_simulated_rise(files):
    """pump.toml's largest camshaft torque is in the rise (cam 0..40 deg): at the reported cycle angle the simulated
    follower is rising, inside the reported rise and out of the cut."""
    sim = simulate(files, "pump-gears-external")
    _, rep = cli_report(files["pump-gears-external+dynamics"], "--forces")
    cam = rep["forces"]["cam"]
    assert 0 < cam["max_torque_at_deg"] < 40
    (c,) = cam["max_torque_at_cycle_deg"]
    (a, b), = rep["timing"]["rises_deg"]
    assert a < c < b
    s0, s1 = sim.follower(np.radians([c - 0.1, c + 0.1]))
    assert s1 > s0
    cut = rep["windows"]["cutting"]
    assert not cut[0] <= np.mod(c, 360.0) <= cut[1]
