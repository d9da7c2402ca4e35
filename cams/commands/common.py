"""Exit codes and small helpers shared by the subcommands."""

__all__ = ["EXIT_OK", "EXIT_CHECK_FAILED", "EXIT_BAD_INPUT", "is_flat", "refuse_method"]

EXIT_OK, EXIT_CHECK_FAILED, EXIT_BAD_INPUT = 0, 1, 2
#: Exit code after Ctrl-C (128 + SIGINT), as shells report it.
EXIT_INTERRUPTED = 130


def is_flat(design) -> bool:
    """True for a flat-faced follower's design (:class:`cams.model.design.FlatFaceDesign`)."""
    return getattr(design, "face", "roller") == "flat"


def refuse_method(method) -> None:
    """``--method`` chooses a zone solver: a flat face has none (its size follows from convexity)."""
    if method is not None:
        from laws.errors import InputError

        raise InputError("--method", "does not apply to a flat-faced follower: its base radius follows from "
                         "convexity directly")
