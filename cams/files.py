"""Writing files whole or not at all, and checking output paths first.

Every file the project writes goes through :func:`atomic_write`: the content is
written to a temporary file in the same folder and then renamed over the
target, so a failure leaves no partial file.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Callable

from laws.errors import InputError

__all__ = ["atomic_write", "check_output_path", "ensure_folder", "read_toml"]


def read_toml(path: str | os.PathLike) -> dict:
    """Parse a TOML file; raise :class:`InputError` (field ``FILE``) if unreadable or invalid."""
    import tomllib

    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except OSError as e:
        raise InputError("FILE", f"cannot read {str(p)!r}: {e.strerror or e}") from None
    except UnicodeDecodeError:
        raise InputError("FILE", f"{str(p)!r} is not UTF-8 text") from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise InputError("FILE", f"{p}: not valid TOML: {e}") from None


def _umask() -> int:
    m = os.umask(0)
    os.umask(m)
    return m


def ensure_folder(path: str | os.PathLike, field: str) -> Path:
    """Create folder ``path`` (and parents) or raise :class:`InputError` naming ``field``."""
    p = Path(path)
    try:
        p.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise InputError(field, f"cannot create {str(p)!r}: {e.strerror or e}") from None
    return p


def check_output_path(path: str | os.PathLike, field: str) -> Path:
    """Raise :class:`InputError` unless ``path`` can be created (its folder exists, it is no folder).

    Parameters
    ----------
    path : path-like
    field : str
        Name of the option for the message (e.g. ``"--csv"``).
    """
    p = Path(path)
    folder = p.parent if str(p.parent) else Path(".")
    if not folder.is_dir():
        raise InputError(field, f"cannot write {str(p)!r}: folder {str(folder)!r} does not exist")
    if p.is_dir():
        raise InputError(field, f"cannot write {str(p)!r}: it is a folder")
    if not os.access(folder, os.W_OK):
        raise InputError(field, f"cannot write {str(p)!r}: folder {str(folder)!r} is not writable")
    return p


def atomic_write(path: str | os.PathLike, field: str, write: Callable[[str], None]) -> Path:
    """Call ``write(tmp)`` for a temporary file next to ``path``, then move it to ``path``.

    Parameters
    ----------
    path : path-like
        The file to create or replace.
    field : str
        Name of the option for error messages (e.g. ``"--csv"``).
    write : callable
        Writes the whole content to the temporary file name it is given.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    InputError
        The folder does not exist or the file cannot be written; no file is
        left behind.
    """
    p = Path(path)
    folder = p.parent if str(p.parent) else Path(".")
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=f".{p.name}.", suffix=".tmp")
    except OSError as e:
        raise InputError(field, f"cannot write {str(p)!r}: {e.strerror or e}") from None
    os.close(fd)
    try:
        write(tmp)
        os.chmod(tmp, 0o666 & ~_umask())  # mkstemp makes 0600; give the usual permissions
        os.replace(tmp, p)
    except OSError as e:
        raise InputError(field, f"cannot write {str(p)!r}: {e.strerror or e}") from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
    return p
