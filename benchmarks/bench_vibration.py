"""The follower train's cost: one cycle's periodic steady state, the response over a turn, a jump-speed search.

Usage (from the project folder, after ``pip install -e .``)::

    python benchmarks/bench_vibration.py [--repeats 7] [--out benchmarks/results]

Writes ``vibration.json`` into ``--out``: for ``examples/translating_train.toml`` (a 4-5-6-7 rise and a cycloidal
return, 100.8 Hz train) and the slotting feed cam with a torsional train (2000 N m/rad), the median time (one core)
of the steady state's start (:func:`laws.response.steady_state`: one exponential a span and a 2 x 2 solve),
of the response at 720 cam angles (:func:`laws.response.grid_response`), of the elastic jump-speed search
(:func:`cams.dynamics.vibration.dynamic_jump_rpm`, 720 angles a speed) with the number of speeds it tried, and of
the event-driven integrator over 6 turns (:func:`cams.dynamics.vibration.simulate`) at a speed above the elastic
jump speed.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

from hardware import machine, median_time, one_thread_per_process, write_results  # noqa: E402

one_thread_per_process()  # one BLAS thread: before the first numpy import

import numpy as np  # noqa: E402


def _designs(tmp: Path):
    from cams.cam import Cam
    from cams.io.designfile import load_design

    feed = (
        (ROOT / "examples" / "slotting_feed_cam.toml")
        .read_text()
        .replace("journal_radius = 8.0", "journal_radius = 8.0\ntrain_stiffness = 2000.0\ndamping_ratio = 0.02")
    )
    p = tmp / "feed_train.toml"
    p.write_text(feed)
    return [
        ("translating_train", Cam(load_design(ROOT / "examples" / "translating_train.toml"))),
        ("slotting_feed_cam with a train", Cam(load_design(p))),
    ]


def _row(name: str, cam, repeats: int) -> dict:
    """One design's figures (see the module)."""
    from cams.dynamics import vibration as vib
    from laws.response import grid_response, spans, steady_state
    from laws.units import rpm_to_omega

    d, df = cam.design, cam.forces
    dyn = d.dynamics.dynamics.with_spring(df.spring)
    tm = vib.train_model(d, dyn)
    w = rpm_to_omega(d.rpm)
    tr = tm.train(w)
    steady_state(d.program, tr)  # warm the imports
    y0, t_ss = median_time(lambda: steady_state(d.program, tr), repeats)
    _, t_grid = median_time(lambda: grid_response(d.program, tr, y0, 720), repeats)
    calls = [0]
    inner, batch = vib._min_load, vib._losses

    def counted(*a, **k):
        calls[0] += 1
        return inner(*a, **k)

    def counted_batch(program, tm, rpms, samples):
        calls[0] += len(rpms)
        return batch(program, tm, rpms, samples)

    vib._min_load, vib._losses = counted, counted_batch
    try:
        jump, t_jump = median_time(
            lambda: vib.dynamic_jump_rpm(
                d.program, tm, start_rpm=0.05 * d.rpm, top_rpm=3 * max(d.rpm, df.jump.rpm), samples=720
            ),
            1,
        )
    finally:
        vib._min_load, vib._losses = inner, batch
    above = 1.05 * jump
    wa = rpm_to_omega(above)
    tra = tm.train(wa)
    ya = steady_state(d.program, tra)
    flight, t_sim = median_time(lambda: vib.simulate(d.program, tm, wa, (ya[0], ya[1] * tra.rho * wa)), 1)
    return {
        "design": name,
        "spans": len(spans(d.program)),
        "rpm": d.rpm,
        "natural_frequency_hz": tm.omega_n / (2 * np.pi),
        "steady_state_ms": 1e3 * t_ss,
        "response_720_ms": 1e3 * t_grid,
        "jump_search_s": t_jump,
        "jump_search_speeds": calls[0],
        "dynamic_jump_rpm": jump,
        "rigid_jump_rpm": df.jump.rpm,
        "flight_rpm": above,
        "flight_6_turns_s": t_sim,
        "flights_last_turn": len(flight.intervals),
    }


def run(repeats: int, tmp: Path) -> dict:
    rows = [_row(name, cam, repeats) for name, cam in _designs(tmp)]
    return {"machine": machine(), "repeats": repeats, "rows": rows}


def main(argv=None) -> int:
    import tempfile

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--out", default=str(ROOT / "benchmarks" / "results"))
    a = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        res = run(a.repeats, Path(tmp))
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    write_results(out / "vibration.json", res)
    for r in res["rows"]:
        print(
            f"{r['design']}: steady state {r['steady_state_ms']:.3g} ms, 720 angles {r['response_720_ms']:.3g} ms, "
            f"jump search {r['jump_search_s']:.3g} s ({r['jump_search_speeds']} speeds), "
            f"6 turns with flights {r['flight_6_turns_s']:.3g} s"
        )
    print(f"wrote {out / 'vibration.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
