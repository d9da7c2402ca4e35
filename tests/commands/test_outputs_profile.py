"""``cams profile``: output paths checked together before solving; the files written all or none."""

import os
import shutil
from pathlib import Path

import pytest

from cams.cli import main
from cams.io.files import all_or_nothing, atomic_write, check_output_paths, ensure_folder
from laws.errors import InputError
from tests.conftest import EXAMPLES


@pytest.fixture
def design(tmp_path):
    p = tmp_path / "rf_copy.toml"
    shutil.copy(EXAMPLES / "rocker_force.toml", p)
    return p


def _names(folder):
    return sorted(os.listdir(folder))


def _run(capsys, *argv):
    rc = main(["profile", *map(str, argv)])
    cap = capsys.readouterr()
    return rc, cap.out, cap.err


def test_output_that_is_the_design_file_is_refused(design, capsys, monkeypatch):
    text = design.read_text()
    rc, out, err = _run(capsys, design, "--csv", design)
    assert rc == 2 and err.startswith("cams profile: error: --csv: ") and "input file" in err
    assert err.count("\n") == 1
    assert design.read_text() == text
    # the same file by another name: relative with .., or through a link
    monkeypatch.chdir(design.parent)
    rc, _, err = _run(capsys, design.name, "--svg", f"../{design.parent.name}/{design.name}")
    assert rc == 2 and "--svg" in err
    (design.parent / "link.toml").symlink_to(design)
    rc, _, err = _run(capsys, "link.toml", "--dxf", design.name)
    assert rc == 2 and "--dxf" in err
    assert design.read_text() == text


def test_two_outputs_to_one_file_are_refused(design, capsys):
    same = design.parent / "same.out"
    rc, out, err = _run(capsys, design, "--csv", same, "--svg", same)
    assert rc == 2 and "cams profile: error: --svg: " in err and "--csv" in err
    assert not same.exists() and out == ""
    rc, _, err = _run(capsys, design, "--csv", same, "--dxf", design.parent / "." / "same.out")
    assert rc == 2 and "--dxf" in err


@pytest.mark.parametrize("opt", ["--csv", "--dxf", "--svg"])
def test_empty_output_path_is_refused(design, capsys, opt):
    rc, out, err = _run(capsys, design, opt, "")
    assert rc == 2 and err.startswith(f"cams profile: error: {opt}: ") and "empty" in err
    assert out == ""


def test_flat_face_output_checks(tmp_path, capsys):
    flat = tmp_path / "flat.toml"
    shutil.copy(EXAMPLES / "rocker_flat.toml", flat)
    rc, _, err = _run(capsys, flat, "--csv", "")
    assert rc == 2 and "--csv" in err
    rc, _, err = _run(capsys, flat, "--csv", flat)
    assert rc == 2 and "--csv" in err and "input file" in err
    rc, _, err = _run(capsys, flat, "--csv", tmp_path / "a", "--svg", tmp_path / "a")
    assert rc == 2 and "--svg" in err
    assert _names(tmp_path) == ["flat.toml"]


def test_a_name_too_long_is_refused_before_solving(design, capsys):
    rc, _, err = _run(capsys, design, "--csv", design.parent / "ok.csv", "--dxf", design.parent / ("x" * 300 + ".dxf"))
    assert rc == 2 and err.startswith("cams profile: error: --dxf: ") and err.count("\n") == 1
    assert _names(design.parent) == ["rf_copy.toml"]


def test_a_failing_output_leaves_no_other_output(design, capsys, monkeypatch):
    """The DXF fails while written (disk full): the CSV, rendered first, must not remain, nor any temporary."""
    import cams.manufacture.dxf

    def full_disk(prof, path, **kw):
        def write(tmp):
            raise OSError(28, "No space left on device")
        return atomic_write(path, "--dxf", write)

    monkeypatch.setattr(cams.manufacture.dxf, "write_dxf", full_disk)
    folder = design.parent
    rc, out, err = _run(capsys, design, "--csv", folder / "ok.csv", "--dxf", folder / "x.dxf",
                        "--svg", folder / "ok.svg")
    assert rc == 2 and err.startswith("cams profile: error: --dxf: ") and "No space left" in err
    assert "wrote" not in out
    assert _names(folder) == ["rf_copy.toml"]


def test_all_outputs_are_written(design, capsys):
    folder = design.parent
    rc, out, _ = _run(capsys, design, "--csv", folder / "a.csv", "--dxf", folder / "a.dxf", "--svg", folder / "a.svg")
    assert rc == 0 and out.count("wrote") == 3
    assert _names(folder) == ["a.csv", "a.dxf", "a.svg", "rf_copy.toml"]
    assert (folder / "a.csv").read_text().startswith("phi_deg,")


def test_all_or_nothing_in_the_api(tmp_path):
    old = tmp_path / "old.txt"
    old.write_text("old")
    with pytest.raises(InputError, match="later"):
        with all_or_nothing():
            ensure_folder(tmp_path / "new" / "sub", "--out")
            atomic_write(old, "--out", lambda tmp: open(tmp, "w").close())
            atomic_write(tmp_path / "new" / "sub" / "b.txt", "--out", lambda tmp: open(tmp, "w").close())
            assert not (tmp_path / "new" / "sub" / "b.txt").exists()  # not before the end
            raise InputError("--out", "failed later")
    assert _names(tmp_path) == ["old.txt"] and old.read_text() == "old"  # the folders made are gone too
    with all_or_nothing():
        atomic_write(old, "--out", lambda tmp: open(tmp, "w").write("new"))
        with pytest.raises(InputError, match="twice"):
            atomic_write(tmp_path / "." / "old.txt", "--out", lambda tmp: None)
    assert old.read_text() == "new" and _names(tmp_path) == ["old.txt"]
    with pytest.raises(KeyboardInterrupt):
        with all_or_nothing():
            atomic_write(tmp_path / "c.txt", "--out", lambda tmp: None)
            raise KeyboardInterrupt
    assert _names(tmp_path) == ["old.txt"]


def test_a_failed_rename_puts_back_what_was_replaced(tmp_path, monkeypatch):
    a, b = tmp_path / "a.txt", tmp_path / "b.txt"
    a.write_text("old")
    real = os.replace

    def replace(src, dst):
        if Path(dst) == b:
            raise OSError(5, "Input/output error")
        return real(src, dst)

    monkeypatch.setattr(os, "replace", replace)
    with pytest.raises(InputError, match="^--b: .*Input/output error"):
        with all_or_nothing():
            atomic_write(a, "--a", lambda tmp: Path(tmp).write_text("new"))
            atomic_write(b, "--b", lambda tmp: Path(tmp).write_text("new"))
    assert _names(tmp_path) == ["a.txt"] and a.read_text() == "old"


def test_check_output_paths(tmp_path):
    a = tmp_path / "a.csv"
    assert check_output_paths([("--csv", a), ("--svg", None)]) == [a]
    with pytest.raises(InputError, match="^--svg: .*--csv"):
        check_output_paths([("--csv", a), ("--svg", str(a))])
    with pytest.raises(InputError, match="^FOO: .*empty"):
        check_output_paths([("FOO", "")])
    with pytest.raises(InputError, match="^--out: .*input file"):
        check_output_paths([("--out", a)], inputs=[("FILE", tmp_path / "x" / ".." / "a.csv")])
