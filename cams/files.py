"""Reading TOML input files; writing files whole or not at all, and checking output paths first.

Design and machine files are read by :func:`read_toml` and their tables
checked with :func:`toml_table`, :func:`toml_number` and :func:`check_keys`,
so that both name the offending field the same way.

Every file the project writes goes through :func:`atomic_write`: the content is
written to a temporary file in the same folder and then renamed over the
target, so a failure leaves no partial file.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Callable

import numpy as np

from laws.errors import InputError

__all__ = ["atomic_write", "check_output_path", "ensure_folder", "read_toml", "toml_table", "toml_number", "check_keys"]


def read_toml(path: str | os.PathLike) -> dict:
    """Parse a TOML file.

    Parameters
    ----------
    path : path-like
        The file, UTF-8 text.

    Returns
    -------
    dict
        The parsed document (tables as dicts, arrays of tables as lists).

    Raises
    ------
    InputError
        Field ``FILE``: the file cannot be read, is not UTF-8 or is not valid
        TOML.
    """
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


def toml_table(d: dict, key: str) -> dict:
    """The table ``d[key]`` of a parsed TOML document, ``{}`` when absent.

    Parameters
    ----------
    d : dict
        A parsed document or table.
    key : str
        The table's name, also the field named in errors.

    Returns
    -------
    dict
        The table (not a copy).

    Raises
    ------
    InputError
        ``d[key]`` is not a table.
    """
    t = d.get(key, {})
    if not isinstance(t, dict):
        raise InputError(key, "must be a table")
    return t


def toml_number(table: dict, key: str, field: str, *, default=None, required: bool = True) -> float | None:
    """The number ``table[key]`` as a float, in the file's own unit (no conversion).

    Parameters
    ----------
    table : dict
        A parsed TOML table.
    key : str
        The entry.
    field : str
        Name of the entry in error messages, e.g. ``"follower.arm"``.
    default : float or None, optional
        Returned when ``key`` is absent; a default other than None makes the
        entry optional.
    required : bool, optional
        With ``default`` None, whether an absent entry is an error (else None
        is returned).

    Returns
    -------
    float or None
        The value, ``default`` when absent.

    Raises
    ------
    InputError
        A required entry is missing, or the value is not a finite number
        (booleans are refused).
    """
    if key not in table:
        if required and default is None:
            raise InputError(field, "is required")
        return default
    v = table[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not np.isfinite(v):
        raise InputError(field, f"must be a number, got {v!r}")
    return float(v)


def check_keys(table: dict, allowed: set, field: str) -> None:
    """Refuse entries of ``table`` outside ``allowed``.

    Parameters
    ----------
    table : dict
        A parsed TOML table.
    allowed : set of str
        Its allowed keys.
    field : str
        Name of the table in the error message.

    Raises
    ------
    InputError
        Unknown keys; the message lists them and the allowed ones, sorted.
    """
    unknown = set(table) - allowed
    if unknown:
        raise InputError(field, f"unknown key(s) {', '.join(sorted(unknown))}; allowed: {', '.join(sorted(allowed))}")


def _folder(p: Path) -> Path:
    """The folder a file ``p`` is written in."""
    return p.parent if str(p.parent) else Path(".")


def _umask() -> int:
    m = os.umask(0)
    os.umask(m)
    return m


def ensure_folder(path: str | os.PathLike, field: str) -> Path:
    """Create folder ``path`` (and parents) or raise :class:`InputError` naming ``field``.

    Parameters
    ----------
    path : path-like
        The folder; an existing one is fine.
    field : str
        Name of the option for the message (e.g. ``"--out"``).

    Returns
    -------
    Path
        ``path``.
    """
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
        The file to be written.
    field : str
        Name of the option for the message (e.g. ``"--csv"``).

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    InputError
        The folder does not exist or is not writable, or ``path`` is a folder.
    """
    p = Path(path)
    folder = _folder(p)
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
    folder = _folder(p)
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
