"""The previous release's import paths still work for one release, warn, and give the same objects."""

import importlib
import subprocess
import sys

import pytest

from cams._moved import MOVED, new_name

OLD_MODULES = sorted(set(MOVED) - {"cams.profile", "cams.checks", "cams.machine"})


def test_every_old_module_path_forwards_to_the_new_module():
    """In a fresh interpreter, where each path is imported for the first time: the old path warns,
    naming the new one, and its public names are the new module's."""
    code = """
import sys, warnings, importlib
from cams._moved import MOVED
bad = []
for old in sys.argv[1:]:
    warnings.simplefilter("error", DeprecationWarning)
    try:
        importlib.import_module(old)
    except DeprecationWarning as w:
        if MOVED[old][0] not in str(w):
            bad.append(f"{old}: {w}")
    else:
        bad.append(f"{old}: no warning")
    warnings.simplefilter("ignore", DeprecationWarning)
    module = importlib.import_module(old)
    new = importlib.import_module(MOVED[old][0])
    names = [n for n in dir(new) if not n.startswith("_")]
    if not names or not all(getattr(module, n) is getattr(new, n) for n in names):
        bad.append(f"{old}: names differ")
print(len(sys.argv) - 1, bad)
"""
    r = subprocess.run([sys.executable, "-c", code, *OLD_MODULES], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.split(" ", 1) == [str(len(OLD_MODULES)), "[]\n"], r.stdout


def test_a_moved_package_s_submodules_follow_it():
    assert new_name("cams.linkage.machines") == "cams.machine.linkage.machines"
    assert new_name("cams.designfile") == "cams.io.designfile"  # not taken for cams.design + "file"
    assert new_name("cams.model.design") is None


@pytest.mark.parametrize(("package", "name", "home"), [("cams.profile", "build_profile", "cams.profile.roller"),
                                                       ("cams.checks", "check_profile", "cams.checks.profile"),
                                                       ("cams.checks", "check_design", "cams.solve"),
                                                       ("cams.machine", "design_machine", "cams.machine.design")])
def test_an_old_module_that_became_a_package_forwards_its_names(package, name, home):
    with pytest.warns(DeprecationWarning, match=home):
        got = getattr(importlib.import_module(package), name)
    assert got is getattr(importlib.import_module(home), name)
    with pytest.raises(AttributeError):
        importlib.import_module(package).no_such_name


def test_a_module_split_by_stage_forwards_each_name_to_its_home():
    code = """
import warnings
warnings.simplefilter("ignore", DeprecationWarning)
from cams.flatface import size_flat_face, flat_face_profile, check_flat_face, FlatRocker
import optimize.flat, cams.profile.flat, cams.checks.flat, cams.model.follower
assert size_flat_face is optimize.flat.size_flat_face and flat_face_profile is cams.profile.flat.flat_face_profile
assert check_flat_face is cams.checks.flat.check_flat_face and FlatRocker is cams.model.follower.FlatRocker
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr


def test_the_old_files_module_forwards_the_reading_and_the_writing_names():
    """``cams.files`` was split: output in cams.io.files, reading and checking the document in cams.io.document."""
    code = """
import warnings
warnings.simplefilter("ignore", DeprecationWarning)
from cams.files import atomic_write, read_toml, check_keys, toml_number, MAX_NUMBER
import cams.io.files, cams.io.document
assert atomic_write is cams.io.files.atomic_write and read_toml is cams.io.document.read_toml
assert check_keys is cams.io.document.check_keys and toml_number is cams.io.document.toml_number
assert MAX_NUMBER == cams.io.document.MAX_NUMBER
"""
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
