"""Writing files whole or not at all, and checking output paths first.

Every file the project writes goes through :func:`atomic_write`: the content is
written to a temporary file in the same folder and then renamed over the
target, so a failure leaves no partial file. A command writing several files
does so inside :func:`all_or_nothing`: every file is rendered to its temporary
first and they are all renamed into place only when every one succeeded, so a
failure leaves none of them. :func:`check_output_paths` checks all the output
options of a command at once, before any computation. (Reading the input
files is :mod:`cams.io.document`.)

What an output path names decides how it is written (:func:`output_kind`):

* a regular file, or a name not yet taken: whole or nothing, by rename; a
  symbolic link is followed, so the file it points to is replaced and the
  link kept (a dangling link creates its target);
* ``-`` (standard output), ``/dev/stdout``, ``/dev/stderr``, ``/dev/fd/N``:
  the content is streamed to that open descriptor;
* a character device (``/dev/null``, a terminal) or a FIFO: the content is
  streamed into it (a FIFO waits for its reader); a write error there (no
  space left on ``/dev/full``, a closed pipe) is an :class:`InputError`, never
  a success;
* a block device or a socket: refused.
"""

from __future__ import annotations

import contextlib
import contextvars
import os
import re
import stat
import sys
import tempfile
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import Literal, TypeAlias

from laws.errors import InputError

__all__ = ["atomic_write", "all_or_nothing", "check_suffix", "check_output_path", "check_output_paths",
           "ensure_folder", "output_kind", "writes_stdout", "STDOUT"]

#: The output name for standard output.
STDOUT = "-"

#: What :func:`output_kind` returns: how an output name is written and where (the kind says which type it is).
OutputKind: TypeAlias = (tuple[Literal["descriptor"], int] | tuple[Literal["file", "folder", "stream"], Path]
                         | tuple[Literal["refused"], str])


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

    Raises
    ------
    InputError
        Naming ``field``: the path is empty, the folder cannot be created or
        is not writable.
    """
    p = Path(path)
    if not str(path).strip():
        raise InputError(field, "must name a folder, got an empty path")
    missing = []  # the folders this call creates, deepest first
    q = p
    while not q.exists() and q != q.parent:
        missing.append(q)
        q = q.parent
    try:
        p.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise InputError(field, f"cannot create {str(p)!r}: {e.strerror or e}") from None
    if not os.access(p, os.W_OK | os.X_OK):  # an existing read-only folder: say so now, naming the option
        raise InputError(field, f"cannot write into {str(p)!r}: the folder is not writable")
    t = _PENDING.get()
    if t is not None:
        t.folders += missing
    return p


#: Names of open descriptors: the content is written to descriptor N itself (shared offset, no new open).
_FD_NAMES = re.compile(r"^/(?:dev/fd|proc/self/fd)/(\d+)$")
_STD_NAMES = {"/dev/stdin": 0, "/dev/stdout": 1, "/dev/stderr": 2}


def _descriptor(path: str) -> int | None:
    """The descriptor number an output name stands for (``-`` is 1), else None."""
    if path == STDOUT:
        return 1
    if path in _STD_NAMES:
        return _STD_NAMES[path]
    m = _FD_NAMES.match(path)
    return int(m.group(1)) if m else None


def output_kind(path: str | os.PathLike) -> OutputKind:
    """How an output name is written, and where.

    Parameters
    ----------
    path : path-like
        An output name; ``-`` is standard output.

    Returns
    -------
    (kind, where)
        ``("descriptor", n)``: stream to open descriptor ``n`` (``-``,
        ``/dev/stdout``, ``/dev/fd/N``); ``("stream", path)``: stream to a
        character device or FIFO (opened for writing, never created nor
        replaced); ``("file", target)``: whole or nothing by rename, ``target``
        the regular file ``path`` names once symbolic links are followed;
        ``("refused", why)`` for a block device or a socket; ``("folder",
        path)`` for a folder.
    """
    s = str(path)
    fd = _descriptor(s)
    if fd is not None:
        return "descriptor", fd
    p = Path(s)
    try:
        mode = os.stat(p).st_mode  # follows links
    except FileNotFoundError:
        mode = None  # not there yet (or a dangling link): a new file at the link's target
    if mode is None or stat.S_ISREG(mode):
        return "file", Path(os.path.realpath(p))
    if stat.S_ISDIR(mode):
        return "folder", p
    if stat.S_ISCHR(mode) or stat.S_ISFIFO(mode):
        return "stream", p
    what = "a block device" if stat.S_ISBLK(mode) else "a socket" if stat.S_ISSOCK(mode) else "a special file"
    return "refused", what


def writes_stdout(path: str | os.PathLike | None) -> bool:
    """Whether output ``path`` goes to standard output (``-``, ``/dev/stdout`` or what descriptor 1 is)."""
    if path is None:
        return False
    out = output_kind(path)
    if out[0] == "descriptor":
        return out[1] == 1
    if out[0] == "stream":
        try:
            return os.path.samestat(os.stat(out[1]), os.fstat(1))
        except OSError:
            return False
    return False


#: The names of the kinds of file the commands read or write: an output whose name ends in one of them holds
#: that kind (an SVG written as ``cam.png`` would be opened as a picture it is not).
KNOWN_SUFFIXES = (".csv", ".dxf", ".svg", ".png", ".pdf", ".gif", ".html", ".htm", ".json", ".toml", ".parquet",
                  ".pq", ".typ")


def check_suffix(path: str | os.PathLike | None, field: str, allowed: tuple[str, ...], what: str) -> None:
    """Refuse an output named as another kind of file than it holds: ``path``'s extension, when it is one of
    :data:`KNOWN_SUFFIXES`, must be one of ``allowed`` (any other name, or none, is the user's choice).

    Raises
    ------
    InputError
        Naming ``field``: ``--svg cam.png``, ``--out table.svg``...
    """
    if path is None:
        return
    suffix = Path(path).suffix.lower()
    if suffix in KNOWN_SUFFIXES and suffix not in allowed:
        raise InputError(field, f"{str(path)!r}: writes {what}, not a {suffix} file: give it a {allowed[0]} name")


def check_output_path(path: str | os.PathLike, field: str) -> Path:
    """Raise :class:`InputError` unless ``path`` can be written (see :func:`output_kind`).

    Parameters
    ----------
    path : path-like
        The file to be written; ``-`` is standard output.
    field : str
        Name of the option for the message (e.g. ``"--csv"``).

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    InputError
        ``path`` is empty; it is a folder, a block device or a socket; the
        folder of the file it names (after links) does not exist or is not
        writable; a device or FIFO is not writable.
    """
    if not str(path).strip():
        raise InputError(field, "must name a file, got an empty path")
    p = Path(path)
    try:
        out = output_kind(path)
    except OSError as e:  # a name too long, a loop of links ...
        raise InputError(field, f"cannot write {str(p)!r}: {e.strerror or e}") from None
    if out[0] == "descriptor":
        try:
            os.fstat(out[1])
        except OSError:
            raise InputError(field, f"cannot write {str(p)!r}: descriptor {out[1]} is not open") from None
        return p
    if out[0] == "folder":
        raise InputError(field, f"cannot write {str(p)!r}: it is a folder")
    if out[0] == "refused":
        raise InputError(field, f"cannot write {str(p)!r}: it is {out[1]}; give a regular file, a character device, "
                         f"a FIFO or - (standard output)")
    if out[0] == "stream":
        if not os.access(p, os.W_OK):
            raise InputError(field, f"cannot write {str(p)!r}: permission denied")
        return p
    folder = _folder(out[1])
    if not folder.is_dir():
        raise InputError(field, f"cannot write {str(p)!r}: folder {str(folder)!r} does not exist")
    if not os.access(folder, os.W_OK):
        raise InputError(field, f"cannot write {str(p)!r}: folder {str(folder)!r} is not writable")
    return p


def _same_file(a: Path, b: Path) -> bool:
    """Whether paths ``a`` and ``b`` name the same file (resolved; the same inode when both exist)."""
    try:
        if a.exists() and b.exists():
            return os.path.samefile(a, b)
    except OSError:
        pass
    return os.path.normcase(str(a.resolve())) == os.path.normcase(str(b.resolve()))


def check_output_paths(outputs: Iterable[tuple[str, str | os.PathLike | None]], *,
                       inputs: Iterable[tuple[str, str | os.PathLike]] = ()) -> list[Path]:
    """Check all the output files of one command together, before anything is computed.

    Each output goes through :func:`check_output_path`; besides, no output may
    be one of the input files, and no two outputs may be the same file (after
    resolving links and ``..``).

    Parameters
    ----------
    outputs : iterable of (field, path)
        The option naming each output (e.g. ``"--csv"``) and its path; a None
        path (option not given) is skipped, an empty one refused.
    inputs : iterable of (field, path)
        The files the command reads (e.g. ``("FILE", "cam.toml")``).

    Returns
    -------
    list of Path
        The output paths given, in order.

    Raises
    ------
    InputError
        Naming the option of the first output that is refused.
    """
    ins = [(f, Path(p)) for f, p in inputs]
    seen: list[tuple[str, Path]] = []
    for field, path in outputs:
        if path is None:
            continue
        p = check_output_path(path, field)
        for f, q in ins:
            if _same_file(p, q):
                raise InputError(field, f"cannot write {str(p)!r}: it is the input file {f}; give another file name")
        for f, q in seen:
            if _same_file(p, q):
                raise InputError(field, f"cannot write {str(p)!r}: it is also the {f} output; give each output its "
                                 "own file")
        seen.append((field, p))
    return [p for _, p in seen]


class _Transaction:
    """The temporaries written inside :func:`all_or_nothing`, and the folders it created."""

    def __init__(self):
        self.files: list[tuple[str, Path, str]] = []  # (temporary, target, field): renamed into place
        self.streams: list[tuple[str, str | os.PathLike, str]] = []  # (temporary, output name, field): streamed
        self.folders: list[Path] = []

    def add(self, tmp: str, target: Path, field: str) -> None:
        for _, q, _f in self.files:
            if _same_file(target, q):
                raise InputError(field, f"cannot write {str(target)!r}: it is written twice by one command")
        self.files.append((tmp, target, field))

    def add_stream(self, tmp: str, path: str | os.PathLike, field: str) -> None:
        self.streams.append((tmp, path, field))

    def discard(self) -> None:
        for tmp, _, _ in self.files + self.streams:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
        self.files = []
        self.streams = []
        for f in self.folders:  # deepest first; only empty ones go
            with contextlib.suppress(OSError):
                f.rmdir()
        self.folders = []

    def commit(self) -> None:
        """Stream to the special files first (what fails most), then rename every temporary into place.

        When one rename fails, what the others replaced is put back; what a
        device or pipe received cannot be taken back.
        """
        for _, target, field in self.files:  # what would fail, before anything moves
            if target.is_dir():
                raise InputError(field, f"cannot write {str(target)!r}: it is a folder")
        for tmp, path, field in self.streams:
            _stream(tmp, path, field)
        done: list[tuple[Path, str | None, bool]] = []  # (target, hard link to the file it replaced, existed)
        try:
            for tmp, target, field in self.files:
                backup = None
                existed = target.exists()
                if existed:
                    backup = f"{tmp}.old"
                    try:
                        os.link(target, backup)
                    except OSError:
                        backup = None  # no hard links here: that file cannot be put back
                try:
                    os.replace(tmp, target)
                except OSError as e:
                    if backup is not None:
                        os.unlink(backup)
                    raise InputError(field, f"cannot write {str(target)!r}: {e.strerror or e}") from None
                done.append((target, backup, existed))
        except BaseException:
            for target, backup, existed in reversed(done):
                with contextlib.suppress(OSError):
                    if backup is not None:
                        os.replace(backup, target)
                    elif not existed:
                        os.unlink(target)
            raise
        for _, backup, _ in done:
            if backup is not None:
                with contextlib.suppress(OSError):
                    os.unlink(backup)
        self.files = []
        self.folders = []


_PENDING: contextvars.ContextVar[_Transaction | None] = contextvars.ContextVar("cams_files_pending", default=None)


@contextlib.contextmanager
def all_or_nothing() -> Iterator[None]:
    """Make the files written in the block (by :func:`atomic_write`) appear together or not at all.

    Inside the block :func:`atomic_write` writes each file whole to a
    temporary next to its target and keeps it; when the block ends normally
    the outputs that are devices, FIFOs or standard output receive their
    content, then the temporaries are renamed into place, one after the other.
    When the block raises (any exception, Ctrl-C included) the temporaries are
    removed, and so are the folders :func:`ensure_folder` created in the block
    if they are still empty: no file of the block is left. A block inside
    another one joins it.
    """
    if _PENDING.get() is not None:
        yield
        return
    t = _Transaction()
    token = _PENDING.set(t)
    try:
        yield
    except BaseException:
        _PENDING.reset(token)
        t.discard()
        raise
    _PENDING.reset(token)
    try:
        t.commit()
    finally:
        t.discard()  # what a failed rename left


def _write_all(fd: int, tmp: str) -> None:
    """Copy the file ``tmp`` to open descriptor ``fd`` (every byte, or ``OSError``)."""
    with open(tmp, "rb") as src:
        while chunk := src.read(1 << 16):
            view = memoryview(chunk)
            while view:
                n = os.write(fd, view)
                view = view[n:]


def _stream(tmp: str, path: str | os.PathLike, field: str) -> None:
    """Send the content of ``tmp`` to the descriptor, device or FIFO ``path`` names.

    Raises
    ------
    InputError
        Naming ``field``: the target cannot be opened, did not take every byte
        (no space left, a closed pipe) or failed when closed.
    """
    out = output_kind(path)
    try:
        if out[0] == "descriptor":
            if out[1] in (1, 2):  # what Python buffered for that stream goes first
                (sys.stdout if out[1] == 1 else sys.stderr).flush()
            _write_all(out[1], tmp)
            return
        if out[0] == "refused":  # became a block device or a socket since it was checked
            raise InputError(field, f"cannot write {str(path)!r}: it is {out[1]}")
        fd = os.open(out[1], os.O_WRONLY | getattr(os, "O_NOCTTY", 0))  # never created nor truncated
        try:
            if stat.S_ISREG(os.fstat(fd).st_mode):  # replaced by a file since it was checked: not overwritten
                raise InputError(field, f"cannot write {str(path)!r}: it changed from a device or FIFO to a file "
                                 "while the command ran")
            _write_all(fd, tmp)
        finally:
            os.close(fd)
    except OSError as e:
        raise InputError(field, f"cannot write {str(path)!r}: {e.strerror or e}") from None


def atomic_write(path: str | os.PathLike, field: str, write: Callable[[str], object], *,
                 suffix: str = ".tmp") -> Path:
    """Call ``write(tmp)`` for a temporary file, then move it to ``path`` (or stream it there).

    A regular file (or a new name) is replaced by rename: whole or nothing. A
    symbolic link is followed: the file it points to is replaced and the link
    kept. Standard output (``-``, ``/dev/stdout``), a character device or a
    FIFO receives the content written to the temporary (see
    :func:`output_kind`). Inside :func:`all_or_nothing` the move waits for the
    end of the block.

    Parameters
    ----------
    path : path-like
        The file to create or replace; ``-`` for standard output.
    field : str
        Name of the option for error messages (e.g. ``"--csv"``).
    write : callable
        Writes the whole content to the temporary file name it is given
        (what it returns is not used).
    suffix : str, optional
        End of the temporary file's name, for writers that choose the format
        from it (e.g. ``".gif"``).

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    InputError
        The folder does not exist, the file cannot be written or the device or
        pipe did not take the whole content; no file is left behind.
    """
    p = check_output_path(path, field)
    out = output_kind(path)
    target = out[1] if out[0] == "file" else None
    folder = _folder(target) if target is not None else None  # a stream's temporary goes to the system's folder
    tmp: str | None  # None once a transaction owns the temporary
    try:
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=f".{p.name or 'out'}.", suffix=suffix)
    except OSError as e:
        raise InputError(field, f"cannot write {str(p)!r}: {e.strerror or e}") from None
    os.close(fd)
    pending = _PENDING.get()
    try:
        write(tmp)
        if target is not None:
            try:  # a replaced file keeps its permissions; a new one gets the usual ones (mkstemp makes 0600)
                mode = stat.S_IMODE(os.stat(target).st_mode)
            except OSError:
                mode = 0o666 & ~_umask()
            os.chmod(tmp, mode)
        if pending is not None:
            if target is not None:
                pending.add(tmp, target, field)
            else:
                pending.add_stream(tmp, path, field)
            tmp = None  # the transaction owns it now
        elif target is not None:
            os.replace(tmp, target)
        else:
            _stream(tmp, path, field)
    except OSError as e:
        raise InputError(field, f"cannot write {str(p)!r}: {e.strerror or e}") from None
    finally:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
    return p
