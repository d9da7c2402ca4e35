"""The mechanism drawn at a cam angle: the cam turned, its follower in place, for each face.

The cam's profile and follower on one axes at cam angle ``phi`` (radians), in the follower's fixed frame (a roller)
or the flat face's report frame (:attr:`optimize.flat.FlatFaceSolution.centre`), lengths in mm. The face's
presenter (:mod:`cams.present.faces`) picks the drawing; the profile picture and the animation
(:mod:`cams.present.plots`) call it.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from cams.kinematics.flat import flat_parts
from cams.kinematics.inversion import smallest_cam_radius, to_fixed_frame

__all__ = ["draw_roller_mechanism", "draw_flat_mechanism", "add_polygon", "radii_label", "FACE_WIDTH_PT"]


def radii_label(R0: float, cam_radius: float | None) -> str:
    """The legend of the base circle: a roller's R0 (of its pitch curve) with the cam's own smallest radius
    ``cam_radius``; with ``cam_radius`` None, a flat face's R0 (the cam's own: a flat face has no pitch curve)."""
    if cam_radius is None:
        return f"base circle R0 = {R0:.3f} mm"
    return f"base circle R0 = {R0:.3f} mm (pitch curve)\ncam's smallest radius {cam_radius:.3f} mm"


def add_polygon(ax, points: np.ndarray, **style):
    """A filled polygon through ``points`` (shape (n, 2)), the axes' limits taken from its points at once;
    returns the polygon.

    ``ax.fill``/``add_patch`` walk every vertex of the path in Python to update the limits: slow for a
    profile of thousands of points.
    """
    from matplotlib.patches import Polygon

    poly = Polygon(points, closed=True, **style)
    ax.add_artist(poly)
    ax.update_datalim(points)
    ax.autoscale_view()
    return poly


def _cam_in_fixed_frame(profile, pts: np.ndarray, phi: float) -> np.ndarray:
    """A roller cam's profile points in the fixed frame at cam angle ``phi`` (its centre and sense)."""
    return to_fixed_frame(pts, profile.centre, profile.cam_sense, phi)


#: The flat face's stroke width (points): the stroke is drawn beside the face line, on the follower's side.
FACE_WIDTH_PT = 3.0


def draw_flat_mechanism(ax, cam, profile, phi: float):
    """A flat-faced follower's cam (turned to ``phi``) and its face, in the frame of ``FlatFaceSolution.centre``.

    The face's line (the artist's data) is the face itself, where the motion law puts it
    (:meth:`optimize.flat.FlatFaceSolution.face_line`); its stroke, and the stem's or arm's, is shifted by half
    its width (:data:`FACE_WIDTH_PT`) along the face's normal away from the cam, so that the stroke's edge on the
    cam's side is the face line: the drawn face touches the cam's outline and never covers it. The contact point
    is the exact one at ``phi`` (:func:`cams.kinematics.flat.flat_parts`' contact position along the face line).

    Returns ``move(phi)``, which turns the drawing to another cam angle (radians) by updating the moving
    artists' data in place (the cam, the face and its stem or arm, the contact point) and returns them.
    """
    from matplotlib.patches import Circle
    from matplotlib.transforms import ScaledTranslation

    d = cam.design
    sol = cam.solution
    prog = d.program
    centre = sol.centre
    lo, hi = sol.face_range
    margin = 0.1 * max(hi - lo, 1e-9)
    translating = d.follower.kind == "translating"
    contact_at = flat_parts(d, sol.R0)[1]  # the contact's position along the face, per phase

    def position(phi: float) -> float:
        """The contact's position along the face at cam angle ``phi`` (a phase joint: the later phase's)."""
        index, within = prog.locate(phi)
        i = int(index)
        u = min(max(float(within) / prog.phases[i].angle, 0.0), 1.0)  # a Program's phase angles are > 0
        return float(np.asarray(contact_at(i, np.array([u]))).reshape(-1)[0])

    def at(phi: float) -> dict[str, Any]:
        origin, direction = (v[0] for v in sol.face_line(np.array([phi])))
        normal = np.array([-direction[1], direction[0]])
        normal *= np.sign(normal @ (origin - centre))  # away from the cam: the face is p > 0 from its centre
        near = origin + (lo - margin) * direction
        return {"work": to_fixed_frame(profile.work, centre, d.cam_sense, phi),
                "face": origin + np.outer([lo - margin, hi + margin], direction),
                "contact": origin + position(phi) * direction,
                "normal": normal,
                "stem": (np.array([origin, origin + np.array([0.0, 0.6 * d.scale])]) if translating
                         else np.array([[0.0, 0.0], origin, near]))}

    def beside(normal: np.ndarray):
        """The data's transform shifted by half the face's stroke along ``normal`` (display units)."""
        half = 0.5 * FACE_WIDTH_PT / 72.0  # inches
        return ax.transData + ScaledTranslation(half * normal[0], half * normal[1], ax.figure.dpi_scale_trans)

    p = at(phi)
    cam_patch = add_polygon(ax, p["work"], fc="#e2e8f0", ec="#1a202c", lw=1.2, label="cam profile")
    ax.add_patch(Circle(centre, profile.R0, fill=False, color="#718096", lw=0.8, ls=":",
                        label=radii_label(profile.R0, None)))
    # the face and its stem or arm: one body, one legend entry
    body = "follower (flat face and stem)" if translating else "rocker (flat face and arm)"
    (face,) = ax.plot(p["face"][:, 0], p["face"][:, 1], color="#c53030", lw=FACE_WIDTH_PT, solid_capstyle="butt",
                      label=body, transform=beside(p["normal"]))
    (contact,) = ax.plot(*p["contact"], "o", color="#c53030", ms=3)
    if translating:
        (stem,) = ax.plot(p["stem"][:, 0], p["stem"][:, 1], color="#c53030", lw=FACE_WIDTH_PT, label=body,
                          transform=beside(p["normal"]))
        ax.axvline(0.0, color="k", lw=0.6, ls="-.")
    else:
        (stem,) = ax.plot(p["stem"][:, 0], p["stem"][:, 1], color="#c53030", lw=FACE_WIDTH_PT,
                          solid_capstyle="round", label=body, transform=beside(p["normal"]))
        ax.plot(0, 0, "ko", ms=5)
    # the face and stem are drawn a few points beside their data (``beside``), and matplotlib's autoscaling passes
    # over a line whose transform is not the data's: their data are taken into the view's limits here
    ax.update_datalim(np.concatenate([p["face"], p["stem"]]))
    ax.plot(*centre, "k+", ms=10)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3)
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")

    def move(phi: float) -> list:
        q = at(phi)
        cam_patch.set_xy(q["work"])
        face.set_data(q["face"][:, 0], q["face"][:, 1])
        contact.set_data([q["contact"][0]], [q["contact"][1]])
        stem.set_data(q["stem"][:, 0], q["stem"][:, 1])
        for a in (face, stem):
            a.set_transform(beside(q["normal"]))
        return [cam_patch, face, contact, stem]

    return move


def draw_roller_mechanism(ax, cam, profile, phi: float):
    """Cam (turned to ``phi``), follower and roller in the follower's fixed frame.

    Returns ``move(phi)``, which turns the drawing to another cam angle (radians) by updating the moving
    artists' data in place (the cam's profile, groove and pitch curve, the roller, the rocker or stem) and returns
    them.
    """
    from matplotlib.patches import Circle

    d = cam.design
    f = d.follower

    def at(phi: float) -> dict[str, Any]:
        A = f.position(d.program.evaluate(np.array([phi])).s)[0]
        return {"work": _cam_in_fixed_frame(profile, profile.work, phi),
                "pitch": _cam_in_fixed_frame(profile, profile.pitch, phi),
                "outer": None if profile.outer is None else _cam_in_fixed_frame(profile, profile.outer, phi),
                "A": A,
                "arm": (np.array([[0.0, 0.0], A]) if f.kind == "rocker"
                        else np.array([A, A + np.array([0.0, 0.6 * d.scale + 2 * profile.roller_radius])]))}

    p = at(phi)
    A = p["A"]
    cam_patch = add_polygon(ax, p["work"], fc="#e2e8f0", ec="#1a202c", lw=1.2, label="working profile")
    outer = None
    if p["outer"] is not None:
        (outer,) = ax.plot(p["outer"][:, 0], p["outer"][:, 1], color="#1a202c", lw=1.2, label="groove, outer wall")
    (pitch,) = ax.plot(p["pitch"][:, 0], p["pitch"][:, 1], color="#2b6cb0", lw=0.8, ls="--", label="pitch curve")
    ax.add_patch(Circle(profile.centre, profile.R0, fill=False, color="#718096", lw=0.8, ls=":",
                        label=radii_label(profile.R0, smallest_cam_radius(d, profile.centre)[0])))
    roller = None
    if profile.roller_radius > 0:
        roller = Circle(A, profile.roller_radius, fill=False, color="#c53030", lw=1.4)
        ax.add_patch(roller)
    (point,) = ax.plot(*A, "o", color="#c53030", ms=3)
    if f.kind == "rocker":
        (arm,) = ax.plot(p["arm"][:, 0], p["arm"][:, 1], color="#c53030", lw=2.5, solid_capstyle="round",
                         label="rocker")
        ax.plot(0, 0, "ko", ms=5)
    else:
        (arm,) = ax.plot(p["arm"][:, 0], p["arm"][:, 1], color="#c53030", lw=3, label="follower")
    ax.plot(*profile.centre, "k+", ms=10)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3)
    ax.set_xlabel("x, mm")
    ax.set_ylabel("y, mm")

    def move(phi: float) -> list:
        q = at(phi)
        cam_patch.set_xy(q["work"])
        pitch.set_data(q["pitch"][:, 0], q["pitch"][:, 1])
        moved = [cam_patch, pitch, point, arm]
        if outer is not None:
            outer.set_data(q["outer"][:, 0], q["outer"][:, 1])
            moved.append(outer)
        if roller is not None:
            roller.set_center(q["A"])
            moved.append(roller)
        point.set_data([q["A"][0]], [q["A"][1]])
        arm.set_data(q["arm"][:, 0], q["arm"][:, 1])
        return moved

    return move
