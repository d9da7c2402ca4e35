"""Exit codes and small helpers shared by the subcommands."""

from laws.errors import InputError

__all__ = ["EXIT_OK", "EXIT_CHECK_FAILED", "EXIT_BAD_INPUT", "face_cam", "check_jobs", "add_drawing_jobs"]

EXIT_OK, EXIT_CHECK_FAILED, EXIT_BAD_INPUT = 0, 1, 2
#: Exit code after Ctrl-C (128 + SIGINT), as shells report it.
EXIT_INTERRUPTED = 130


def face_cam(design, args):
    """The :class:`cams.cam.Cam` of ``design`` with the command's ``--method`` (refused where the face takes none)
    and ``--tolerance`` (where the command has it)."""
    from cams.cam import Cam

    cam = Cam(design, method=args.method, tolerance=getattr(args, "tolerance", None))  # nothing solved yet
    cam.face.check_method(args.method, "--method")
    return cam


def check_jobs(jobs: int | None) -> None:
    """Refuse a ``--jobs`` below 1 (None: the default, one per core)."""
    if jobs is not None and jobs < 1:
        raise InputError("--jobs", f"must be an integer >= 1 (processes), got {jobs}")


def add_drawing_jobs(parser) -> None:
    """The ``--jobs N`` of a command that draws pictures side by side (:mod:`cams.present.forked`); checked by
    :func:`check_jobs`."""
    parser.add_argument("--jobs", type=int, metavar="N", help="processes drawing the pictures side by side, >= 1 "
                        "(default: one per core, at most one per picture; 1 draws them in this process, one after "
                        "another)")
