"""The face's words and pictures: one :class:`Presenter` per follower face, chosen once.

The pipelines (:mod:`cams.faces`) hold what a face computes; this module holds what the texts and pictures of
each face show (its summary, the kinds of picture it draws, its report's tables, how its mechanism is drawn).
:func:`presenter` picks the face's presenter from the cam's pipeline (:attr:`cams.cam.Cam.face`) by its name, the
one place above the pipelines that does; the commands, pictures and report call the presenter without asking which
face it is. It sits at the bottom of :mod:`cams.present`: it names the pictures by kind
(:data:`cams.present.plots.PICTURES`) and imports only the modules below it (text, tables, mechanism).
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from collections.abc import Callable
from typing import Any, ClassVar

import numpy as np

__all__ = ["Presenter", "RollerPresenter", "FlatPresenter", "presenter", "presenter_of_face"]


class Presenter(ABC):
    """What the texts and pictures show of one face's cam (lengths mm, angles as each function states)."""

    #: Why a picture ``cams plot`` knows is not drawn for this face (picture name: reason).
    skipped: ClassVar[dict[str, str]] = {}
    #: True when the motion design's picture has a pressure-angle panel (a face with a pressure-angle limit).
    pressure_panel: ClassVar[bool] = True

    @abstractmethod
    def print_summary(self, rep: dict) -> None:
        """Print the readable summary of a solve report (:meth:`cams.faces.result.SolveResult.to_dict`)."""

    #: The pictures ``cams plot`` draws of the face's cam, in order (the names ``--only`` takes), each with the
    #: kind of picture (:data:`cams.present.plots.PICTURES`) drawn under it; ``forces`` only for a cam with
    #: forces (a ``[dynamics]`` table, force closure and a speed: :func:`cams.present.plots.no_forces`).
    pictures: ClassVar[dict[str, str]]
    #: The report's pictures: (title, picture kind), in order, before the motion design's.
    report_pictures: ClassVar[tuple[tuple[str, str], ...]]

    @abstractmethod
    def report_sections(self, cam) -> list[tuple[str, list[tuple[str, str]]]]:
        """The report's tables (:func:`cams.present.report.report_sections`)."""


    @abstractmethod
    def draw_mechanism(self, ax, cam, profile, phi: float) -> Callable[[float], list]:
        """The cam turned to cam angle ``phi`` (rad) with its follower, on the axes ``ax``; returns ``move(phi)``,
        which turns the drawing to another cam angle by updating its moving artists in place (and returns them)."""

    @abstractmethod
    def animation_extent(self, cam, profile) -> tuple[np.ndarray, float, np.ndarray]:
        """``(cam centre, reach, follower points)``: what an animation's view must hold at every cam angle."""

    @abstractmethod
    def outline(self, design, size) -> tuple[np.ndarray, np.ndarray | None, float]:
        """``(working profile, pitch curve or None, R0)`` of ``design``'s cam of ``size`` (cam frame, mm)."""

    @abstractmethod
    def reference_size(self, ref: dict) -> Any:
        """The original cam's size from the motion design's ``reference`` (what :meth:`outline` takes)."""

    @abstractmethod
    def size_of(self, solution) -> Any:
        """A solution's size as :meth:`outline` takes it."""

    @abstractmethod
    def profile_report(self, cam, prof, bore: float, given: float | None) -> dict:
        """``cams profile``'s summary of the exported profile ``prof`` (lengths mm), after ``name``."""

    @abstractmethod
    def profile_line(self, rep: dict, bore: float, f: str) -> str:
        """``cams profile``'s line of text for :meth:`profile_report`'s ``rep`` (``f``: the lengths' format)."""

    @abstractmethod
    def explorer(self, design, solution) -> dict:
        """What the explorer page (``cams explore``) lets the user move, and the face's data it draws with.

        ``solution``: the sized cam (:class:`cams.faces.result.SolveResult`), or None where none exists (no
        feasible zone). JSON-ready, lengths in the design's unit, angles in radians: ``mode`` (``"centre"``: a
        point dragged in the follower's fixed frame; ``"size"``: R0 and, for a rocker, L), ``follower``,
        ``limits`` and ``start`` (the sized cam's movable values, or None).
        """


class RollerPresenter(Presenter):
    """A roller (or knife-edge) follower's cam in words and pictures."""

    skipped: ClassVar[dict[str, str]] = {
        "curvature": "drawn for flat-faced followers only (a roller cam's curvature is checked by cams check); "
                     "skipped"}

    def print_summary(self, rep: dict) -> None:
        from cams.present.text import print_summary

        print_summary(rep)

    pictures: ClassVar[dict[str, str]] = {"motion": "motion", "zone": "zone", "pressure": "pressure",
                                          "profile": "profile", "forces": "forces", "contact": "contact",
                                          "vibration": "vibration"}
    report_pictures: ClassVar[tuple[tuple[str, str], ...]] = (
        ("Allowable-centre zone", "zone"), ("Motion diagrams", "motion"), ("Pressure angle", "pressure"),
        ("Cam profile", "profile"), ("Forces at the cam", "forces"), ("Contact stress and film", "contact"),
        ("Follower train: vibration and dynamic contact force", "vibration"))

    def report_sections(self, cam):
        from cams.present.tables import roller_sections

        return roller_sections(cam)

    def draw_mechanism(self, ax, cam, profile, phi: float) -> Callable[[float], list]:
        from cams.present.mechanism import draw_roller_mechanism

        return draw_roller_mechanism(ax, cam, profile, phi)

    def animation_extent(self, cam, profile):
        d = cam.design
        r = profile.roller_radius
        reach = max(float(np.max(np.linalg.norm(c, axis=1))) + (r if c is profile.pitch else 0.0)
                    for c in (profile.work, profile.pitch, profile.outer) if c is not None)
        A = d.follower.position(np.linspace(0.0, d.program.lift, 33))
        pts = [A - r, A + r, d.follower.pivot[None]]
        if d.follower.kind != "rocker":
            pts.append(A + np.array([0.0, 0.6 * d.scale + 2 * r]))
        return profile.centre, reach, np.concatenate(pts)

    def outline(self, design, size):
        from cams.kinematics.inversion import pitch_curve  # the kernel's pitch curve, as the profile's

        pg = pitch_curve(design, size, np.linspace(0.0, 2 * np.pi, 1441))
        R0 = float(np.linalg.norm(size - design.follower.position(0.0)))
        r = design.follower.roller_radius
        return (pg.offset(-r) if r > 0 else pg.point), pg.point, R0

    def reference_size(self, ref: dict):
        return np.array([ref["centre"]["x"], ref["centre"]["y"]])

    def size_of(self, solution):
        return solution.centre

    def profile_report(self, cam, prof, bore, given):
        from cams.kinematics.inversion import smallest_cam_radius

        sol = cam.solution
        return {"points": len(prof), "tolerance": prof.tolerance, "R0": prof.R0,
                "centre": {"x": float(sol.centre[0]), "y": float(sol.centre[1])},
                "roller_radius": prof.roller_radius, "min_work_radius": prof.min_work_radius, "bore_radius": bore,
                "bore_suggested": given is None,
                "smallest_cam_radius": smallest_cam_radius(cam.design, sol.centre)[0],
                "largest_roller_radius": cam.checks.largest_roller_radius, "groove": prof.groove}

    def profile_line(self, rep: dict, bore: float, f: str) -> str:
        from cams.present.text import no_working_profile
        from cams.words import bore_text

        broken = no_working_profile(rep)
        head = (f"{rep['name']}: {rep['points']} points at tolerance {rep['tolerance']:g} mm, "
                f"R0 = {rep['R0']:{f}} mm (pitch curve), ")
        if broken is None:
            return f"{head}cam's smallest radius {rep['smallest_cam_radius']:{f}} mm, " \
                   f"{bore_text(bore, rep['bore_suggested'])}"
        bore_words = "no bore suggested" if rep["bore_suggested"] else bore_text(bore, False)
        return f"{head}{broken}; {bore_words}"

    def explorer(self, design, solution) -> dict:
        """The cam centre is dragged in the follower's fixed frame (``[cam] centre``'s); the zone is drawn."""
        from cams.present.explore_data import roller_zone

        f = design.follower
        lim = design.limits
        rocker = f.kind == "rocker"
        start = None
        if solution is not None:
            start = {"centre": [float(v) for v in solution.centre], "R0": float(solution.R0),
                     "L": None if solution.L is None else float(solution.L),
                     "offset": None if solution.offset is None else float(solution.offset)}
        binding = () if solution is None else solution.detail.binding
        return {
            "mode": "centre",
            "follower": {"kind": f.kind, "arm": float(f.arm) if rocker else None,
                         "sense": int(f.sense) if rocker else None, "roller_radius": float(f.roller_radius),
                         "A0": [float(v) for v in f.position(0.0)], "pivot": [float(v) for v in f.pivot],
                         "scale": float(design.scale)},
            "cam_sense": int(design.cam_sense),
            "limits": {"closure": lim.closure, "pressure_angle": float(lim.pressure_angle),
                       "return_limit": float(lim.return_limit) if lim.closure == "form" else None,
                       "safety_factor": float(lim.safety_factor),
                       "constrained": [[int(i), float(g)] for i, g in design.constrained_phases()]},
            "start": start,
            "zone": roller_zone(design, None if start is None else solution.centre, binding),
        }


class FlatPresenter(Presenter):
    """A flat-faced follower's cam in words and pictures (no zone; the curvature with the face's travel)."""

    skipped: ClassVar[dict[str, str]] = {
        "zone": "the allowable-centre zone does not apply to a flat-faced follower (its size is set by convexity, "
                "not by a pressure-angle limit); skipped"}
    pressure_panel: ClassVar[bool] = False

    def print_summary(self, rep: dict) -> None:
        from cams.present.text import print_flat_summary

        print_flat_summary(rep)

    pictures: ClassVar[dict[str, str]] = {"motion": "motion", "pressure": "flat_pressure",
                                          "curvature": "curvature", "profile": "profile", "forces": "forces",
                                          "contact": "contact", "vibration": "vibration"}
    report_pictures: ClassVar[tuple[tuple[str, str], ...]] = (
        ("Motion diagrams", "motion"), ("Pressure angle", "flat_pressure"),
        ("Radius of curvature and contact on the face", "curvature"), ("Cam profile", "profile"),
        ("Forces at the cam", "forces"), ("Contact stress and film", "contact"),
        ("Follower train: vibration and dynamic contact force", "vibration"))

    def report_sections(self, cam):
        from cams.present.tables import flat_sections

        return flat_sections(cam)

    def draw_mechanism(self, ax, cam, profile, phi: float) -> Callable[[float], list]:
        from cams.present.mechanism import draw_flat_mechanism

        return draw_flat_mechanism(ax, cam, profile, phi)

    def animation_extent(self, cam, profile):
        d, sol = cam.design, cam.solution
        reach = float(np.max(np.linalg.norm(profile.work, axis=1)))
        phis = np.linspace(0, 2 * np.pi, 145)
        o, t = sol.face_line(phis)
        lo_f, hi_f = sol.face_range
        margin = 0.1 * max(hi_f - lo_f, 1e-9)
        follower = np.concatenate([o + (lo_f - margin) * t, o + (hi_f + margin) * t,
                                   o + np.array([0.0, 0.6 * d.scale]), np.zeros((1, 2))])
        return sol.centre, reach, follower

    def outline(self, design, size):
        from cams.profile.flat import flat_face_profile

        return flat_face_profile(design, float(size)).point, None, float(size)

    def reference_size(self, ref: dict):
        return ref["R0"]

    def size_of(self, solution):
        return solution.R0

    def profile_report(self, cam, prof, bore, given):
        sol = cam.solution
        return {"face": "flat", "points": len(prof), "tolerance": prof.tolerance, "R0": prof.R0,
                "centre": {"x": float(sol.centre[0]), "y": float(sol.centre[1])},
                "min_work_radius": prof.min_work_radius, "min_rho": sol.min_rho, "min_radius": cam.design.min_radius,
                "bore_radius": bore, "bore_suggested": given is None, "columns": "phi_deg,work_x,work_y"}

    def profile_line(self, rep: dict, bore: float, f: str) -> str:
        from cams.words import bore_text

        return (f"{rep['name']}: {rep['points']} points at tolerance {rep['tolerance']:g} mm, "
                f"R0 = {rep['R0']:{f}} mm, profile radius >= {rep['min_work_radius']:{f}} mm, "
                f"radius of curvature >= {rep['min_rho']:{f}} mm, {bore_text(bore, rep['bore_suggested'])}")

    def explorer(self, design, solution) -> dict:
        """The base radius R0 is moved (``[cam] base_radius``) and, for a rocker, the centre distance L
        (``follower.centre_distance``); the face's distance from the pivot (``face_offset``) or its axis offset
        stay the file's."""
        f = design.follower
        rocker = f.kind == "rocker"
        start = None
        if solution is not None:
            start = {"R0": float(solution.R0), "L": float(f.centre_distance) if rocker else None,
                     "offset": None if rocker else float(f.offset)}
        return {
            "mode": "size",
            "follower": {"kind": f.kind, "sense": int(f.sense) if rocker else None,
                         "L": float(f.centre_distance) if rocker else None,
                         "face_offset": float(f.face_offset) if rocker else None,
                         "offset": None if rocker else float(f.offset), "scale": float(design.scale)},
            "cam_sense": int(design.cam_sense),
            "limits": {"min_radius": float(design.min_radius)},
            "start": start,
        }


_PRESENTERS: dict[str, Presenter] = {"roller": RollerPresenter(), "flat": FlatPresenter()}


def presenter_of_face(name: str) -> Presenter:
    """The presenter of the face called ``name`` (:attr:`cams.faces.base.Face.name`)."""
    return _PRESENTERS[name]


def presenter(cam) -> Presenter:
    """The presenter of ``cam``'s face (a :class:`cams.cam.Cam`)."""
    return presenter_of_face(cam.face.name)
