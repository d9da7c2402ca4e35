"""The elastic follower train's picture: the response against the rigid motion and the dynamic contact force.

Read through the face's pipeline (:attr:`cams.cam.Cam.vibration`, a :class:`cams.dynamics.vibration.Vibration`).
"""

from __future__ import annotations

import numpy as np

__all__ = ["no_vibration", "plot_vibration"]


def no_vibration(cam) -> str | None:
    """Why ``cam`` has no vibration to draw, or None when it has (:func:`plot_vibration`)."""
    spec = cam.design.dynamics
    if spec is None or spec.dynamics.train_stiffness is None:
        return ("the design has no follower train ([dynamics] train_stiffness, with cam.rpm); add one to draw its "
                "vibration")
    if cam.vibration is None:
        return f"no vibration to draw: {cam.forces_note or 'no forces at the cam'}"
    return None


def plot_vibration(cam):
    """Three panes over one turn at the design's speed, cam angle from the timing datum (deg) on the abscissa.

    The output's displacement against the rigid motion (mm, or deg for a rocker) with their difference on a
    second axis (µm, or millidegrees); the output's acceleration against the rigid one (m/s², rad/s²); the dynamic
    contact force against the rigid one (N), with the event-driven one where contact is lost.

    Raises
    ------
    ValueError
        ``cam`` has no vibration (:func:`no_vibration` says why).
    """
    from cams.present.plots import _figure, _title, legend_once

    why = no_vibration(cam)
    if why is not None:
        raise ValueError(why)
    v = cam.vibration
    d = cam.design
    rocker = d.follower.kind == "rocker"
    to = np.degrees if rocker else (lambda a: np.asarray(a))
    unit, acc_unit, acc_scale = ("deg", "rad/s²", 1.0) if rocker else ("mm", "m/s²", 1e-3)
    x = np.degrees(v.phi)
    fig = _figure(h=8.0)
    ax_s, ax_a, ax_n = fig.subplots(3, 1, sharex=True)
    ax_s.plot(x, to(v.s), color="0.45", lw=1.2, ls="--", label="rigid motion")
    ax_s.plot(x, to(v.q), color="#2b6cb0", lw=1.2, label="output (elastic train, steady state)")
    ax_e = ax_s.twinx()
    diff = (to(v.q) - to(v.s)) * 1e3
    ax_e.plot(x, diff, color="#c05621", lw=0.9, label="output − rigid")
    ax_e.set_ylabel(f"output − rigid, {'mdeg' if rocker else 'µm'}")
    ax_s.set_ylabel(f"displacement, {unit}")
    ax_a.plot(x, v.d2s * acc_scale, color="0.45", lw=1.2, ls="--", label="rigid acceleration")
    ax_a.plot(x, v.d2q * acc_scale, color="#2b6cb0", lw=1.0, label="output's acceleration")
    ax_a.set_ylabel(f"acceleration, {acc_unit}")
    df = cam.forces
    if df is not None:
        ax_n.plot(x, np.where(np.isfinite(df.forces.contact), df.forces.contact, np.nan), color="0.45", lw=1.2,
                  ls="--", label="rigid contact force")
    ax_n.plot(x, np.where(np.isfinite(v.contact), v.contact, np.nan), color="#2b6cb0", lw=1.2,
              label="dynamic contact force (contact assumed)")
    if v.flight is not None:
        amp = v.contact / np.where(v.load != 0, v.load, np.nan)
        o = np.argsort(np.degrees(v.flight.phi))
        ax_n.plot(np.degrees(v.flight.phi)[o], (v.flight.load * amp)[o], color="#c53030", lw=1.0,
                  label="with separation (event-driven)")
    if v.contact_lost_at is not None:
        ax_n.axvline(np.degrees(v.contact_lost_at), color="#c53030", lw=1.0, ls=":", label="contact lost")
    ax_n.axhline(0.0, color="0.3", lw=0.6)
    ax_n.set_ylabel("contact force, N")
    ax_n.set_xlabel("cam angle φ from the timing datum, deg")
    for ax in (ax_s, ax_a, ax_n):
        for s in d.program.starts:
            ax.axvline(np.degrees(s), color="0.6", lw=0.6, ls=":")
        ax.grid(True, lw=0.3)
        ax.set_xlim(0, 360)
        legend_once(ax, fontsize=7, loc="best")
    legend_once(ax_e, fontsize=7, loc="lower right")
    _title(ax_s, f"{d.name}: follower train at {v.rpm:.4g} rpm, natural frequency {v.natural_frequency:.4g} Hz")
    return fig
