"""``cams plot``: pictures of a design as PNG and SVG."""

from __future__ import annotations

import argparse
import sys
from functools import partial
from pathlib import Path

from cams.commands.common import EXIT_CHECK_FAILED, EXIT_OK, add_drawing_jobs, check_jobs
from cams.commands.progress import Progress, progress, wanted
from cams.present.faces import FlatPresenter, RollerPresenter
from laws.errors import InputError

__all__ = ["register", "run", "PICTURES", "FLAT_PICTURES"]

#: Picture names in the order they are written; each needs only what it draws (the faces' presenters say which
#: they draw, :attr:`cams.present.faces.Presenter.pictures`).
PICTURES = tuple(RollerPresenter.pictures)
#: A flat-faced follower's pictures: no zone; the radius of curvature with the contact's travel instead.
FLAT_PICTURES = tuple(FlatPresenter.pictures)
#: Every picture name ``--only`` takes ("optimized": a design with an [optimize] table, drawn for it by default).
NAMES = ("motion", "zone", "pressure", "curvature", "profile", "forces", "contact", "vibration", "optimized")

def draw(cam, which: tuple[str, ...], out: Path, *, title: str = "", bar: Progress | None = None,
         jobs: int | None = None, turn: bool = False) -> list[Path]:
    """Draw the pictures ``which`` of ``cam`` (a :class:`cams.cam.Cam`) into ``out``, and with ``turn`` one turn of
    the cam as an animated GIF (:func:`cams.present.plots.animate_profile`, ``NAME_turn.gif``).

    ``title`` (:meth:`cams.assess.Assessment.title`) marks every picture of a failing cam; ``bar`` counts one
    step a picture (and a turn's frames, when the turn is drawn here). The pictures and the turn are drawn side by
    side by up to ``jobs`` processes (None: one per core; :func:`cams.present.forked.forked_map`), each from the
    cam solved here; the files are written here, in that order.
    """
    from cams.present import plots
    from cams.present.faces import presenter
    from cams.present.forked import forked_map, workers

    bar = bar or Progress()
    names = [name for name in (*presenter(cam).pictures, "optimized") if name in which]
    forked = workers(jobs, len(names) + turn) > 1

    def render(name: str) -> dict[str, bytes]:
        if name == "optimized":
            from cams.present.motion_plots import plot_motion_design

            fig = plot_motion_design(cam)
        else:
            fig = plots.picture(presenter(cam).pictures[name], cam)
        return plots.rendered(plots.mark_failing(fig, title))

    def animate() -> dict[str, bytes]:
        import tempfile

        done = len(names)
        # frames are counted when drawn here: a forked process's bar is not the one on the terminal
        frames = None if forked else (lambda k, n: bar.to(done + k, done + n))
        with tempfile.TemporaryDirectory(prefix="cams-turn-") as tmp:
            return {"gif": plots.animate_profile(cam, Path(tmp) / "turn.gif", title=title,
                                                 progress=frames).read_bytes()}

    plots.prepare()
    tasks = [partial(render, name) for name in names] + ([animate] if turn else [])
    effort = [plots.EFFORT.get(presenter(cam).pictures.get(name, ""), 10) for name in names] + [20] * turn
    if tasks:
        bar.stage(f"drawing {len(names)} picture{'' if len(names) == 1 else 's'}" + (" and one turn" * turn))
    # a step a picture, and the turn's when it was drawn elsewhere (here, its frames count it)
    files = forked_map(tasks, jobs=jobs, effort=effort,
                       done=lambda k: bar.advance() if k < len(names) or forked else None,
                       note=lambda words: bar.note(f"cams plot: note: {words}"))
    stem = out / _slug(cam.design.name)
    written: list[Path] = []
    for name, drawn in zip([*names, *(["turn"] * turn)], files, strict=True):
        written += plots.write_rendered(drawn, f"{stem}_{name}")
    return written


def _slug(name: str) -> str:
    s = "".join(c if c.isalnum() else "_" for c in name.lower())
    s = "_".join(w for w in s.split("_") if w)
    return s or "cam"


def _only(spec: str | None) -> tuple[str, ...] | None:
    """The pictures ``--only`` asks for (None: all); an empty or unknown entry is refused."""
    if spec is None:
        return None
    which = tuple(w.strip() for w in spec.split(","))
    for w in which:
        if not w:
            raise InputError("--only", f"{spec!r} has an empty entry; give a comma-separated list of pictures among "
                             f"{', '.join(NAMES)}")
        if w not in NAMES:
            raise InputError("--only", f"{w!r} is not a picture, must be among {', '.join(NAMES)}")
    return tuple(dict.fromkeys(which))


def run(args) -> int:
    from cams.cam import Cam
    from cams.io.files import all_or_nothing, ensure_folder

    check_jobs(args.jobs)
    which = _only(args.only)
    from cams.present.faces import presenter
    from cams.present.plots import NEEDS, missing

    cam = Cam.from_file(args.file)
    designed = cam.given.optimize is not None
    if which is None:  # everything that applies: no note for what the user did not ask for
        which = tuple(w for w in (*presenter(cam).pictures, *(("optimized",) if designed else ()))
                      if missing(w, cam) is None)
    elif (asked := next((w for w in which if w in NEEDS and missing(w, cam) is not None), None)) is not None:
        raise InputError("--only", f"{asked}: {missing(asked, cam)}")
    elif "optimized" in which and not designed:
        which = tuple(w for w in which if w != "optimized")
        print("cams plot: note: optimized: the design has no [optimize] table, no motion was designed; skipped",
              file=sys.stderr)
    no_profile = cam.face.no_profile(cam.design)
    if no_profile is not None and "profile" in which:
        which = tuple(w for w in which if w != "profile")
        print(f"cams plot: note: profile: {no_profile} to draw; skipped", file=sys.stderr)
    skipped = presenter(cam).skipped
    for w in which:
        if w in skipped:
            print(f"cams plot: note: {w}: {skipped[w]}", file=sys.stderr)
    if args.animate and no_profile is not None:
        print(f"cams plot: note: --animate: {no_profile} to turn; skipped", file=sys.stderr)
    turn = args.animate and no_profile is None
    # the pictures (and a turn's frames) counted on a terminal's stderr: the designed law's take seconds each
    with progress(wanted(args), "solving the cam", total=len(which) + turn, unit="step") as bar:
        # one rule for every command (cams.assess): a failing cam's pictures are drawn, titled as failing, exit 1;
        # the motion diagrams alone need no solution, so they alone assess nothing
        a = None if set(which) <= {"motion"} and not args.animate else cam.assessment
        # every picture is drawn to a temporary file; they are moved into place together only when all succeeded,
        # so a failure (a design that cannot be solved for the zone ...) leaves none of them behind
        with all_or_nothing():
            out = ensure_folder(args.out, "--out")
            written = draw(cam, which, out, title="" if a is None else a.title(), bar=bar, jobs=args.jobs,
                           turn=turn)
    for p in written:
        print(p)
    if a is not None and not a.usable:
        from cams.present.text import print_assessment, verified_words

        print(verified_words(a.to_dict()))
        print_assessment(a.to_dict(), indent="")
        return EXIT_CHECK_FAILED
    return EXIT_OK


def register(sub) -> None:
    """Add the ``plot`` subcommand."""
    q = sub.add_parser(
        "plot",
        help="pictures: zone, motion diagrams, pressure angle, profile, forces (PNG and SVG)",
        description="Draw the pictures of a design file; only what is asked for is computed. A flat-faced "
                    "follower has no zone (skipped with a note) and a curvature picture instead: the radius of "
                    "curvature against its limit and the contact's travel on the face. A cam that fails a check "
                    "(not verified or not buildable) is drawn with the pictures titled as failing, exit code 1.",
        epilog="example: cams plot examples/rocker_force.toml --out pictures --only zone,motion",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    q.add_argument("file", help="design file (TOML)")
    q.add_argument("--out", default=".", help="output folder (default: current)")
    q.add_argument("--only", help=f"comma-separated subset of {','.join(PICTURES)} (flat face: "
                   f"{','.join(FLAT_PICTURES)}); forces needs a [dynamics] table (contact force, spring and load, "
                   "camshaft torque); contact needs a [contact] table (p0 and the film along the cycle); a design "
                   "with [optimize] adds optimized (the designed laws, pressure "
                   "angles and cam beside the original ones)")
    q.add_argument("--animate", action="store_true", help="also write one turn of the cam as an animated GIF")
    add_drawing_jobs(q)
    q.add_argument("--quiet", action="store_true", help="no progress (drawn on a terminal's stderr when the work "
                   "runs past about two seconds)")
    q.set_defaults(func=run)
