"""Outputs that are links or special files: written through, streamed, or refused; never a false "wrote".

A symbolic link is followed (its target replaced, the link kept); a FIFO, a character device and standard
output receive the content; a device that refuses the data (``/dev/full``) is an error naming the option.
"""

import os
import shutil
import stat
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest

from cams.cli import main
from cams.io.files import all_or_nothing, atomic_write, check_output_path
from laws.errors import InputError
from tests.conftest import EXAMPLES

ROOT = Path(__file__).resolve().parents[2]
DESIGN = EXAMPLES / "rocker_force.toml"


def _device(tmp_path, name: str, minor: int) -> Path:
    """A character device of the memory driver (3 null, 7 full): a node of our own in ``tmp_path`` when this
    process may make one (as root, so that a faulty writer replaces only that node), else the system's."""
    if os.geteuid() == 0:
        node = tmp_path / name
        try:
            os.mknod(node, 0o666 | stat.S_IFCHR, os.makedev(1, minor))
            return node
        except OSError:
            pass
        pytest.skip("as root without mknod: the system's device could be replaced by a faulty writer")
    return Path("/dev") / name


def _guard_descriptor(name: str) -> None:
    """Only a writer that streams to ``name`` may be pointed at it (a faulty one run as root replaces it)."""
    from cams.io.files import output_kind

    assert output_kind(name)[0] == "descriptor"


def _reference_csv(tmp_path, capsys) -> str:
    """The CSV of the design written to a plain new file (the reference the other targets must receive)."""
    ref = tmp_path / "reference.csv"
    assert main(["profile", str(DESIGN), "--csv", str(ref)]) == 0
    capsys.readouterr()
    return ref.read_text()


def test_symlink_output_replaces_the_target_and_keeps_the_link(tmp_path, capsys):
    expected = _reference_csv(tmp_path, capsys)
    target = tmp_path / "real.csv"
    target.write_text("old\n")
    link = tmp_path / "link.csv"
    link.symlink_to(target)
    rc = main(["profile", str(DESIGN), "--csv", str(link)])
    out = capsys.readouterr().out
    assert rc == 0 and f"wrote {link}" in out
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert target.read_text() == expected
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.csv", "real.csv", "reference.csv"]  # no temporary


def test_dangling_symlink_creates_its_target(tmp_path, capsys):
    expected = _reference_csv(tmp_path, capsys)
    sub = tmp_path / "sub"
    sub.mkdir()
    link = tmp_path / "link.csv"
    link.symlink_to(sub / "new.csv")
    assert main(["profile", str(DESIGN), "--csv", str(link)]) == 0
    capsys.readouterr()
    assert link.is_symlink() and (sub / "new.csv").read_text() == expected
    # a dangling link into a folder that does not exist: refused before anything is computed, naming the option
    bad = tmp_path / "bad.csv"
    bad.symlink_to(tmp_path / "nowhere" / "x.csv")
    rc = main(["profile", str(DESIGN), "--csv", str(bad)])
    err = capsys.readouterr().err
    assert rc == 2 and err.startswith("cams profile: error: --csv: ") and "does not exist" in err
    assert err.count("\n") == 1 and bad.is_symlink()


def test_replaced_file_keeps_its_permissions(tmp_path):
    p = tmp_path / "keep.txt"
    p.write_text("old")
    os.chmod(p, 0o640)
    atomic_write(p, "--out", lambda tmp: Path(tmp).write_text("new"))
    assert p.read_text() == "new" and stat.S_IMODE(os.stat(p).st_mode) == 0o640


def test_fifo_receives_the_content(tmp_path, capsys):
    expected = _reference_csv(tmp_path, capsys)
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_text()))
    reader.start()
    rc = main(["profile", str(DESIGN), "--csv", str(fifo)])
    reader.join(timeout=60)
    assert rc == 0 and not reader.is_alive()
    assert got == [expected]
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)  # still the FIFO, not replaced by a file
    assert f"wrote {fifo}" in capsys.readouterr().out


def test_dev_full_is_an_error_not_a_success(tmp_path, capsys):
    full = _device(tmp_path, "full", 7)
    before = os.stat(full)
    rc = main(["profile", str(DESIGN), "--csv", str(full)])
    cap = capsys.readouterr()
    assert rc == 2 and "wrote" not in cap.out
    assert cap.err.startswith(f"cams profile: error: --csv: cannot write '{full}': ") and cap.err.count("\n") == 1
    assert "space" in cap.err.lower()
    after = os.stat(full)
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev  # the device is still the device
    # the API: the same error, inside a transaction too
    with pytest.raises(InputError, match="^--svg: cannot write '.*full'"):
        with all_or_nothing():
            atomic_write(full, "--svg", lambda tmp: Path(tmp).write_text("x" * 10))


def test_dev_null_is_written_to_without_being_replaced(tmp_path):
    null = _device(tmp_path, "null", 3)
    before = os.stat(null)
    atomic_write(null, "--csv", lambda tmp: Path(tmp).write_text("data\n"))
    after = os.stat(null)
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev


def _cli(*argv, cwd=None):
    return subprocess.run([sys.executable, "-m", "cams.cli", *map(str, argv)], capture_output=True, cwd=cwd or ROOT)


@pytest.mark.parametrize("name", ["-", "/dev/stdout"])
def test_standard_output_gets_the_csv_and_the_summary_goes_to_stderr(tmp_path, capsys, name):
    _guard_descriptor(name)
    expected = _reference_csv(tmp_path, capsys)
    r = _cli("profile", DESIGN, "--csv", name)
    assert r.returncode == 0, r.stderr
    assert r.stdout.decode() == expected  # the CSV alone: the summary does not mix in
    assert b"points at tolerance" in r.stderr and f"wrote {name}".encode() in r.stderr
    if name == "-":
        assert b"wrote - (standard output)" in r.stderr
    assert not (ROOT / "-").exists()


@pytest.mark.parametrize("opt, head", [("--svg", b"<?xml"), ("--dxf", b"  0\nSECTION")])
def test_dash_streams_svg_and_dxf(opt, head):
    _guard_descriptor("-")
    r = _cli("profile", DESIGN, opt, "-")
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith(head)


def test_dev_stdout_redirected_to_a_file_is_written_in_place(tmp_path):
    """``--csv /dev/stdout > file``: the shell's file receives the CSV (not replaced behind the shell's back)."""
    _guard_descriptor("/dev/stdout")
    out = tmp_path / "redirected.csv"
    with open(out, "wb") as fh:
        r = subprocess.run([sys.executable, "-m", "cams.cli", "profile", str(DESIGN), "--csv", "/dev/stdout"],
                           stdout=fh, stderr=subprocess.PIPE, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    data = np.loadtxt(out, delimiter=",", skiprows=1)
    assert data.shape[1] == 5 and len(data) > 100


def test_two_standard_outputs_are_refused(tmp_path, capsys):
    rc = main(["profile", str(DESIGN), "--csv", "-", "--svg", "-"])
    err = capsys.readouterr().err
    assert rc == 2 and "--svg" in err and "--csv" in err


def test_output_kinds():
    from cams.io.files import output_kind

    assert output_kind("-") == ("descriptor", 1)
    assert output_kind("/dev/stdout") == ("descriptor", 1)
    assert output_kind("/dev/fd/2") == ("descriptor", 2)
    assert output_kind("/dev/null")[0] == "stream"
    assert check_output_path("-", "--csv") == Path("-")


def test_socket_is_refused(tmp_path):
    import socket

    path = tmp_path / "s.sock"
    s = socket.socket(socket.AF_UNIX)
    try:
        s.bind(str(path))
        with pytest.raises(InputError, match="^--csv: .*socket"):
            check_output_path(path, "--csv")
    finally:
        s.close()


def test_sweep_output_through_a_link(tmp_path, capsys):
    target = tmp_path / "t.csv"
    link = tmp_path / "l.csv"
    link.symlink_to(target)
    shutil.copy(DESIGN, tmp_path / "d.toml")
    rc = main(["sweep", str(tmp_path / "d.toml"), "--vary", "follower.arm=120,125", "--out", str(link),
               "--jobs", "1", "--quiet"])
    capsys.readouterr()
    assert rc == 0 and link.is_symlink() and target.read_text().startswith("index,file,follower.arm,")


def test_new_to_standard_output_prints_the_template_only(tmp_path):
    _guard_descriptor("-")
    r = _cli("new", "rocker", "--out", "-")
    assert r.returncode == 0, r.stderr
    text = r.stdout.decode()
    assert text.startswith("#") and text.rstrip().splitlines()[-1] != "-"  # no "-" printed after the file
    # to a FIFO: streamed, not "exists; use --force"
    fifo = tmp_path / "t.toml"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_text()))
    reader.start()
    assert main(["new", "rocker", "--out", str(fifo)]) == 0
    reader.join(timeout=60)
    assert got == [text]


@pytest.mark.parametrize("args", [["solve", str(DESIGN), "--json"], ["laws", "--json"], ["solve", str(DESIGN)]])
def test_full_standard_output_is_an_error_naming_it(args):
    """Standard output on a full device (``cams solve --json > /dev/full``): exit 2 and one line naming standard
    output (before: ``cams solve: error: : No space left on device``, an empty name)."""
    with open("/dev/full", "w") as out:
        r = subprocess.run([sys.executable, "-m", "cams.cli", *args], stdout=out, stderr=subprocess.PIPE,
                           text=True, cwd=ROOT, timeout=120)
    err = r.stderr.strip()
    assert r.returncode == 2 and len(err.splitlines()) == 1, err
    assert "standard output: No space left on device" in err and ": :" not in err
