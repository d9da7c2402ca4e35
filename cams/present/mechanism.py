"""The mechanism drawn at a cam angle: the cam turned, its follower in place, for each face.

The cam's profile and follower on one axes at cam angle ``phi`` (radians), in the follower's fixed frame (a roller)
or the flat face's report frame (:attr:`optimize.flat.FlatFaceSolution.centre`), lengths in mm. The face's
presenter (:mod:`cams.present.faces`) picks the drawing; the profile picture and the animation
(:mod:`cams.present.plots`) call it.
"""

from __future__ import annotations

import numpy as np

from cams.kinematics.inversion import smallest_cam_radius, to_fixed_frame
from laws.units import TWO_PI

__all__ = ["draw_roller_mechanism", "draw_flat_mechanism", "add_polygon", "radii_label"]


def radii_label(R0: float, cam_radius: float | None) -> str:
    """The legend of the base circle: a roller's R0 (of its pitch curve) with the cam's own smallest radius
    ``cam_radius``; with ``cam_radius`` None, a flat face's R0 (the cam's own: a flat face has no pitch curve)."""
    if cam_radius is None:
        return f"base circle R0 = {R0:.3f} mm"
    return f"base circle R0 = {R0:.3f} mm (pitch curve)\ncam's smallest radius {cam_radius:.3f} mm"


def add_polygon(ax, points: np.ndarray, **style) -> None:
    """A filled polygon through ``points`` (shape (n, 2)), the axes' limits taken from its points at once.

    ``ax.fill``/``add_patch`` walk every vertex of the path in Python to update the limits: slow for a
    profile of thousands of points, drawn at every frame of an animation.
    """
    from matplotlib.patches import Polygon

    ax.add_artist(Polygon(points, closed=True, **style))
    ax.update_datalim(points)
    ax.autoscale_view()

def _cam_in_fixed_frame(profile, pts: np.ndarray, phi: float) -> np.ndarray:
    """A roller cam's profile points in the fixed frame at cam angle ``phi`` (its centre and sense)."""
    return to_fixed_frame(pts, profile.centre, profile.cam_sense, phi)


def draw_flat_mechanism(ax, cam, profile, phi: float):
    """A flat-faced follower's cam (turned to ``phi``) and its face, in the frame of ``FlatFaceSolution.centre``."""
    from matplotlib.patches import Circle

    d = cam.design
    sol = cam.solution
    centre = sol.centre
    work = to_fixed_frame(profile.work, centre, d.cam_sense, phi)
    add_polygon(ax, work, fc="#e2e8f0", ec="#1a202c", lw=1.2, label="cam profile")
    ax.add_patch(Circle(centre, profile.R0, fill=False, color="#718096", lw=0.8, ls=":",
                        label=radii_label(profile.R0, None)))
    origin, direction = (v[0] for v in sol.face_line(np.array([phi])))
    lo, hi = sol.face_range
    margin = 0.1 * max(hi - lo, 1e-9)
    ends = origin + np.outer([lo - margin, hi + margin], direction)
    # the face and its stem or arm: one body, one legend entry
    body = "follower (flat face and stem)" if d.follower.kind == "translating" else "rocker (flat face and arm)"
    ax.plot(ends[:, 0], ends[:, 1], color="#c53030", lw=3, solid_capstyle="butt", label=body)
    k = int(np.argmin(np.abs((profile.phi - phi + np.pi) % TWO_PI - np.pi)))
    contact = to_fixed_frame(profile.work[k:k + 1], centre, d.cam_sense, profile.phi[k])[0]
    ax.plot(*contact, "o", color="#c53030", ms=3)
    if d.follower.kind == "translating":
        top = origin + np.array([0.0, 0.6 * d.scale])
        ax.plot([origin[0], top[0]], [origin[1], top[1]], color="#c53030", lw=3, label=body)
        ax.axvline(0.0, color="k", lw=0.6, ls="-.")
    else:
        near = origin + (lo - margin) * direction
        ax.plot([0, origin[0], near[0]], [0, origin[1], near[1]], color="#c53030", lw=3,
                solid_capstyle="round", label=body)
        ax.plot(0, 0, "ko", ms=5)
    ax.plot(*centre, "k+", ms=10)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3)
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")


def draw_roller_mechanism(ax, cam, profile, phi: float):
    """Cam (turned to ``phi``), follower and roller in the follower's fixed frame."""
    from matplotlib.patches import Circle

    d = cam.design
    f = d.follower
    work = _cam_in_fixed_frame(profile, profile.work, phi)
    pitch = _cam_in_fixed_frame(profile, profile.pitch, phi)
    add_polygon(ax, work, fc="#e2e8f0", ec="#1a202c", lw=1.2, label="working profile")
    if profile.outer is not None:
        outer = _cam_in_fixed_frame(profile, profile.outer, phi)
        ax.plot(outer[:, 0], outer[:, 1], color="#1a202c", lw=1.2, label="groove, outer wall")
    ax.plot(pitch[:, 0], pitch[:, 1], color="#2b6cb0", lw=0.8, ls="--", label="pitch curve")
    ax.add_patch(Circle(profile.centre, profile.R0, fill=False, color="#718096", lw=0.8, ls=":",
                        label=radii_label(profile.R0, smallest_cam_radius(d, profile.centre)[0])))
    m = d.program.evaluate(np.array([phi]))
    A = f.position(m.s)[0]
    if profile.roller_radius > 0:
        ax.add_patch(Circle(A, profile.roller_radius, fill=False, color="#c53030", lw=1.4))
    ax.plot(*A, "o", color="#c53030", ms=3)
    if f.kind == "rocker":
        ax.plot([0, A[0]], [0, A[1]], color="#c53030", lw=2.5, solid_capstyle="round", label="rocker")
        ax.plot(0, 0, "ko", ms=5)
    else:
        top = A + np.array([0.0, 0.6 * d.scale + 2 * profile.roller_radius])
        ax.plot([A[0], top[0]], [A[1], top[1]], color="#c53030", lw=3, label="follower")
    ax.plot(*profile.centre, "k+", ms=10)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3)
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")
