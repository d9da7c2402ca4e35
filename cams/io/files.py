"""Reading TOML input files; writing files whole or not at all, and checking output paths first.

Design and machine files are read by :func:`read_toml` and their tables
checked with :func:`toml_table`, :func:`toml_number` and :func:`check_keys`,
so that both name the offending field the same way.

Every file the project writes goes through :func:`atomic_write`: the content is
written to a temporary file in the same folder and then renamed over the
target, so a failure leaves no partial file. A command writing several files
does so inside :func:`all_or_nothing`: every file is rendered to its temporary
first and they are all renamed into place only when every one succeeded, so a
failure leaves none of them. :func:`check_output_paths` checks all the output
options of a command at once, before any computation.

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
import math
import os
import re
import stat
import sys
import tempfile
from collections.abc import Callable, Collection, Iterable, Iterator
from pathlib import Path

from laws.errors import InputError, show_value

__all__ = ["atomic_write", "all_or_nothing", "check_output_path", "check_output_paths", "ensure_folder", "read_toml",
           "check_document", "toml_table", "toml_number", "toml_integer", "check_keys", "MAX_NUMBER", "MAX_DEPTH",
           "output_kind", "writes_stdout", "STDOUT"]

#: The output name for standard output.
STDOUT = "-"

#: The largest size of a number in a design or machine file (integers included): far beyond any quantity a
#: cam or a machine has (lengths are further limited to 1e9 mm), and small enough that sums and products of a
#: few such numbers stay finite and integers stay exact in floating point.
MAX_NUMBER = 1e15
#: The deepest nesting of tables and arrays a file may have (the files use 3 at most: a machine file's
#: ``forces.friction.A``).
MAX_DEPTH = 16


def read_toml(path: str | os.PathLike) -> dict:
    """Parse a TOML file.

    Its numbers and nesting are checked by the loaders that build on it
    (:func:`check_document`), so that the API's dicts get the same checks.

    Parameters
    ----------
    path : path-like
        The file, UTF-8 text; a leading byte-order mark is accepted.

    Returns
    -------
    dict
        The parsed document (tables as dicts, arrays of tables as lists).

    Raises
    ------
    InputError
        Field ``FILE``: the file cannot be read, is not UTF-8, is not valid
        TOML or nests too deeply for the parser.
    """
    import tomllib

    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8-sig")  # -sig: a byte-order mark some editors write is not content
    except OSError as e:
        raise InputError("FILE", f"cannot read {str(p)!r}: {e.strerror or e}") from None
    except UnicodeDecodeError:
        raise InputError("FILE", f"{str(p)!r} is not UTF-8 text") from None
    try:
        d = tomllib.loads(text)
    except tomllib.TOMLDecodeError as e:
        raise InputError("FILE", f"{p}: not valid TOML: {e}") from None
    except RecursionError:
        raise InputError("FILE", f"{p}: arrays or tables nested too deeply (at most {MAX_DEPTH} levels)") from None
    return d


def check_document(d: dict) -> None:
    """Refuse an empty document, and what no key of a design or machine file allows, wherever it is.

    A non-finite float (TOML's ``nan``, ``inf``), a number larger than
    :data:`MAX_NUMBER` in size (a 100-bit integer, ``1e300``) and nesting
    deeper than :data:`MAX_DEPTH` levels. The walk is iterative, so a deep
    document cannot exhaust Python's stack. Types and ranges of each key are
    checked by the loaders (:func:`toml_number`).

    Parameters
    ----------
    d : dict
        A parsed document (or a dict built like one, for the API).

    Raises
    ------
    InputError
        Naming the value's dotted path, e.g. ``motion[2].angle``; ``FILE`` for
        an empty document or too deep a nesting.
    """
    if not d:
        raise InputError("FILE", "the file is empty (no table, no key); see examples/ for complete files")
    stack: list[tuple[str, object, int]] = [("", d, 0)]
    while stack:
        path, v, depth = stack.pop()
        if isinstance(v, dict):
            items = [(f"{path}.{k}" if path else str(k), x) for k, x in v.items()]
        elif isinstance(v, (list, tuple)):
            items = [(f"{path}[{i}]", x) for i, x in enumerate(v)]
        else:
            _finite(path, v)
            continue
        if depth >= MAX_DEPTH:
            raise InputError(path or "FILE", f"arrays or tables nested too deeply (at most {MAX_DEPTH} levels)")
        stack += [(q, x, depth + 1) for q, x in reversed(items)]


def _finite(field: str, v: object) -> None:
    """Refuse ``v`` if it is a number that is not finite or larger than :data:`MAX_NUMBER` in size."""
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        return
    if isinstance(v, float) and not math.isfinite(v):
        raise InputError(field, f"must be a finite number, got {v!r}")
    if abs(v) > MAX_NUMBER:
        raise InputError(field, f"{show_value(v)} is too large: numbers in a file are at most {MAX_NUMBER:g} in size")


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
        raise InputError(key, f"must be a table ([{key}]), got {_kind(t)}")
    return t


def _kind(v: object) -> str:
    """What a TOML value is, for messages: ``an array``, ``the string 'x'``, ``the number 3``."""
    if isinstance(v, dict):
        return "a table"
    if isinstance(v, list):
        return "an array"
    if isinstance(v, bool):
        return f"the boolean {str(v).lower()}"
    if isinstance(v, str):
        return f"the string {v!r}"
    if isinstance(v, (int, float)):
        return f"the number {v!r}"
    return f"a {type(v).__name__} value"


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
        A required entry is missing, or the value is not a finite number of
        size at most :data:`MAX_NUMBER` (booleans, strings, arrays and tables
        are refused).
    """
    if key not in table:
        if required and default is None:
            raise InputError(field, "is required")
        return default
    v = table[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise InputError(field, f"must be a number, got {_kind(v)}")
    _finite(field, v)
    return float(v)


def toml_integer(table: dict, key: str, field: str, *, default: int, lo: int, hi: int) -> int:
    """The whole number ``table[key]`` within ``[lo, hi]``, ``default`` when absent.

    Parameters
    ----------
    table : dict
        A parsed TOML table.
    key : str
        The entry.
    field : str
        Name of the entry in error messages, e.g. ``"solve.samples"``.
    default : int
        Returned when ``key`` is absent.
    lo, hi : int
        The allowed range, both included.

    Returns
    -------
    int

    Raises
    ------
    InputError
        The value is not an integer (``2.0`` and ``true`` are refused) or
        lies outside ``[lo, hi]``; the message gives the range.
    """
    v = table.get(key, default)
    if isinstance(v, bool) or not isinstance(v, int) or not lo <= v <= hi:
        shown = show_value(v) if isinstance(v, int) and not isinstance(v, bool) else _kind(v)
        raise InputError(field, f"must be an integer from {lo} to {hi}, got {shown}")
    return v


def check_keys(table: dict, allowed: Collection[str], field: str) -> None:
    """Refuse entries of ``table`` outside ``allowed``: the one unknown-key check of the files.

    Parameters
    ----------
    table : dict
        A parsed TOML table.
    allowed : set or sequence of str
        Its allowed keys: a set is listed sorted in the message, a sequence
        (a table's documented order, e.g. the ``[dynamics]`` keys) as given.
    field : str
        Name of the table in the error message.

    Raises
    ------
    InputError
        Unknown keys; the message lists them sorted, then the allowed ones.
    """
    unknown = set(table) - set(allowed)
    if unknown:
        shown = sorted(allowed) if isinstance(allowed, (set, frozenset)) else list(allowed)
        raise InputError(field, f"unknown key(s) {', '.join(sorted(unknown))}; allowed: {', '.join(shown)}")


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


def output_kind(path: str | os.PathLike) -> tuple[str, Path | int]:
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
    kind, where = output_kind(path)
    if kind == "descriptor":
        return where == 1
    if kind == "stream":
        try:
            return os.path.samestat(os.stat(where), os.fstat(1))
        except OSError:
            return False
    return False


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
        kind, where = output_kind(path)
    except OSError as e:  # a name too long, a loop of links ...
        raise InputError(field, f"cannot write {str(p)!r}: {e.strerror or e}") from None
    if kind == "descriptor":
        try:
            os.fstat(where)
        except OSError:
            raise InputError(field, f"cannot write {str(p)!r}: descriptor {where} is not open") from None
        return p
    if kind == "folder":
        raise InputError(field, f"cannot write {str(p)!r}: it is a folder")
    if kind == "refused":
        raise InputError(field, f"cannot write {str(p)!r}: it is {where}; give a regular file, a character device, "
                         f"a FIFO or - (standard output)")
    if kind == "stream":
        if not os.access(p, os.W_OK):
            raise InputError(field, f"cannot write {str(p)!r}: permission denied")
        return p
    folder = _folder(where)
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
    kind, where = output_kind(path)
    try:
        if kind == "descriptor":
            if where in (1, 2):  # what Python buffered for that stream goes first
                (sys.stdout if where == 1 else sys.stderr).flush()
            _write_all(where, tmp)
            return
        fd = os.open(where, os.O_WRONLY | getattr(os, "O_NOCTTY", 0))  # never created nor truncated
        try:
            if stat.S_ISREG(os.fstat(fd).st_mode):  # replaced by a file since it was checked: not overwritten
                raise InputError(field, f"cannot write {str(path)!r}: it changed from a device or FIFO to a file "
                                 "while the command ran")
            _write_all(fd, tmp)
        finally:
            os.close(fd)
    except OSError as e:
        raise InputError(field, f"cannot write {str(path)!r}: {e.strerror or e}") from None


def atomic_write(path: str | os.PathLike, field: str, write: Callable[[str], None], *, suffix: str = ".tmp") -> Path:
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
        Writes the whole content to the temporary file name it is given.
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
    kind, where = output_kind(path)
    target = where if kind == "file" else None
    folder = _folder(target) if target is not None else None  # a stream's temporary goes to the system's folder
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
