"""A machine's results in words for the terminal (from ``MachineResult.to_dict`` and the forces' ``to_dict``).

Angles in degrees, lengths in mm, forces in N, torques in N m: the reports' units.
"""

from __future__ import annotations

import math

__all__ = ["print_machine", "print_forces"]


def _iv(iv) -> str:
    if iv[1] > 360 + 1e-9:
        return f"{iv[0]:.3f} .. {iv[1] - 360:.3f} deg (through position 1)"
    return f"{iv[0]:.3f} .. {iv[1]:.3f} deg"


def print_machine(rep: dict) -> None:
    """Readable summary of a machine report (as from ``MachineResult.to_dict``)."""
    from cams.present.text import print_assessment, print_summary

    u = rep["units"]
    lk = rep["linkage"]
    print(f"{rep['name']}: {lk['type']} linkage")
    syn = rep["synthesis"]
    if syn is not None:
        course = f"K = {syn['time_ratio']:g}, H = {syn['stroke']:g} {u}, L = {syn['centre_distance']:g} {u}"
        if syn.get("rod_ratio") is not None:
            course += f", rod ratio = {syn['rod_ratio']:g}"
        print(f"  synthesis from {course}: swing theta = {syn['swing_deg']:.4f} deg")
    lengths = ", ".join(f"{k} = {v:.4f} {u}" for k, v in lk.items()
                        if isinstance(v, float) and not k.endswith("_deg") and k != "rpm")
    print(f"  lengths: {lengths}")
    a = rep["analysis"]
    print(
        f"  stroke {a['stroke']:.4f} {u}, time ratio K = {a['time_ratio']:.6f}, dead positions at "
        f"{a['dead_positions_deg'][0]:.3f} and {a['dead_positions_deg'][1]:.3f} deg (frame), "
        f"min transmission angle {a['min_transmission_deg']:.3f} deg at {a['min_transmission_at_deg']:.3f} deg"
    )
    w = rep["windows"]
    print(f"  cycle angle from position 1 (end of the working stroke, frame {w['origin_frame_deg']:.3f} deg), "
          f"crank {w['crank_rotation']}:")
    print(f"    return {_iv(w['return'])}, working {_iv(w['working'])}")
    print(f"    cutting {_iv(w['cutting'])}, out of work {_iv(w['out_of_work'])}, {w['out_of_work_span']:.3f} deg")
    t = rep["timing"]
    dr = rep["drive"]
    drive = "same shaft" if dr["teeth"] is None else f"gears {dr['teeth'][0]}/{dr['teeth'][1]} ({dr['sense']} sense)"
    print(f"  cam: {drive}, ratio {t['ratio']:g}; program starts at cycle angle {t['mount_deg']:.3f} deg "
          f"(crank at {t['mount_frame_deg']:.3f} deg frame)")
    for r in t["rises_deg"]:
        print(f"    rise over crank {_iv(r)}")
    print(f"    free margins {t['margins_deg'][0]:.3f} / {t['margins_deg'][1]:.3f} deg (asked {t['margin_deg']:.3f}); "
          f"largest feasible rise {t['largest_rise_deg']:.3f} deg of cam")
    if t["key_angle_deg"] is not None:
        print(f"    key angle crank -> cam start radius {t['key_angle_deg']:.3f} deg")
    print(f"  feeding overlaps cutting: {'YES' if rep['overlap'] else 'no'}")
    for n in rep.get("notes", []):
        print(f"  note: {n}")
    print_summary(rep["cam"])
    print_assessment(rep)  # the feed cam by the rule every command shares (cams.assess)


def print_forces(rep: dict, *, follower: str = "rocker") -> None:
    """Readable summary of a forces report (as from ``MachineForces.to_dict``).

    ``follower`` (the cam's follower kind) gives the spring's units
    (:func:`cams.words.spring_text`).
    """

    from cams.dynamics.jump import jump_text
    from cams.words import deg, force, spring_words, torque_words

    lk = rep.get("linkage")
    if lk is not None:
        mb = lk["balancing_moment"]
        passes = {1: "no friction from the reactions", 2: "two-stage friction"}.get(
            lk["passes"], f"{lk['passes']} friction passes")
        print(f"  forces at {lk['rpm']:.4g} rpm ({passes}); angles: {lk['angle_reference']}:")
        print(f"    balancing moment: max |M_b| = {mb['max_abs']:.4g} N m at {mb['at_deg']:.1f} deg, "
              f"mean {mb['mean']:.4g} N m; "
              f"Zhukovsky's lever agrees within {mb['virtual_work_max_difference']:.2g} N m")
        for name, p in lk["pairs"].items():
            print(f"    pair {name:8s} ({p['kind']:9s}): max {p['max']:.5g} N at {p['at_deg']:.1f} deg, "
                  f"mean {p['mean']:.5g} N")
        if lk["friction_power_mean_W"]:
            parts = ", ".join(f"{k} {v:.3g} W" for k, v in lk["friction_power_mean_W"].items())
            print(f"    friction losses: mean {lk['friction_power_total_mean_W']:.4g} W ({parts}); "
                  f"drive power mean {lk['drive_power_mean_W']:.4g} W")
        else:
            print(f"    drive power mean {lk['drive_power_mean_W']:.4g} W")
    fw = rep.get("flywheel")
    # the flywheel's curves are over the same angle as the linkage's (fw["angle_reference"])
    if fw is not None:
        print(f"  flywheel for delta = {fw['delta']:g}: driving moment {fw['driving_moment']:.4g} N m, excess work "
              f"{fw['excess_work']:.4g} J, J_F = {fw['flywheel_inertia']:.4g} kg m^2; omega {fw['omega_min']:.4g} .. "
              f"{fw['omega_max']:.4g} rad/s")
    cam = rep.get("cam")
    if cam is not None:
        sp = cam["spring"]

        def at(key):
            where = f"cam angle {deg(cam[key + '_deg'])}"
            cyc = cam.get(key + "_cycle_deg")
            if cyc:
                where += f" = cycle angle {', '.join(deg(c) for c in cyc)}"
            return where

        def torques(c: dict, where) -> str:
            return "; ".join(torque_words(c[f"max_{k}_torque"], c[f"max_{k}_torque_at_deg"], k,
                                          where=where(f"max_{k}_torque_at")) for k in ("driving", "braking"))

        print(f"  cam forces at {cam['rpm']:.6g} rpm: spring {spring_words(sp, follower)}; "
              f"max contact force {force(cam['max_contact_force'])} at {at('max_contact_at')}")
        if sp.get("note"):
            print(f"    note: {sp['note']}")
        print(f"    camshaft: {torques(cam, at)}")
        bi = cam.get("between_impacts")
        if bi:
            print(f"    between the rigid impacts: max contact force {force(bi['max_contact_force'])}, camshaft "
                  f"{torques(bi, lambda key: deg(bi[key + '_deg']))}, jump speed {jump_text(bi['jump_rpm'])}")
        if cam["jump_rpm"] is None or not math.isfinite(cam["jump_rpm"]):
            jump = jump_text(None)
        elif cam.get("jump_at_impact"):
            jump = f"0 rpm: the follower leaves the cam at any speed at its velocity drop (at {at('jump_at')})"
        else:
            jump = f"{jump_text(cam['jump_rpm'])} (at {at('jump_at')})"
        print(f"    jump speed {jump}; jamming limit {deg(cam['jamming_limit_deg'])}; contact lost: "
              f"{'YES' if cam['contact_lost'] else 'no'}; jammed: {'YES' if cam['jammed'] else 'no'}")
    for n in rep.get("notes", []):
        print(f"  note: {n}")
