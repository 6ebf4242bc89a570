"""Tests of ballscan.outputs: whole files or none, one writer per output, no writes through symlinks."""

from __future__ import annotations

import os
import stat
import subprocess
import sys

import pytest

from ballscan.errors import BallscanError
from ballscan.outputs import (
    TEMP_MARK,
    OutputFileError,
    OutputLock,
    atomic_path,
    atomic_write_bytes,
    atomic_write_text,
    check_not_symlink,
    remove_stale_temporaries,
)


def test_writes_a_new_file_and_leaves_no_temporary(tmp_path):
    p = tmp_path / "a.json"
    assert atomic_write_text(p, "{}\n") == p
    assert p.read_text() == "{}\n"
    assert sorted(os.listdir(tmp_path)) == ["a.json"]


def test_replaces_an_existing_file_keeping_its_mode(tmp_path):
    p = tmp_path / "a.csv"
    p.write_text("old, and longer than the new content\n")
    os.chmod(p, 0o640)
    atomic_write_bytes(p, b"new\n")
    assert p.read_bytes() == b"new\n"
    assert stat.S_IMODE(p.stat().st_mode) == 0o640


def test_a_new_file_gets_the_umask_mode(tmp_path):
    old = os.umask(0o027)
    try:
        p = atomic_write_text(tmp_path / "b.txt", "x")
    finally:
        os.umask(old)
    assert stat.S_IMODE(p.stat().st_mode) == 0o640


def test_a_symlink_is_refused_and_its_target_untouched(tmp_path):
    target = tmp_path / "precious.json"
    target.write_text("keep me")
    link = tmp_path / "out.truth.json"
    link.symlink_to(target)
    with pytest.raises(OutputFileError, match=r"out\.truth\.json: is a symbolic link") as info:
        atomic_write_text(link, "overwritten")
    assert isinstance(info.value, BallscanError)
    assert "\n" not in str(info.value)
    assert target.read_text() == "keep me"
    assert link.is_symlink()


def test_force_writes_the_links_target_and_keeps_the_link(tmp_path):
    target = tmp_path / "real.txt"
    target.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    assert atomic_write_text(link, "new", force=True) == target
    assert link.is_symlink() and target.read_text() == "new"


def test_a_dangling_link_is_refused_too(tmp_path):
    link = tmp_path / "dangling"
    link.symlink_to(tmp_path / "nowhere")
    with pytest.raises(OutputFileError):
        check_not_symlink(link)
    assert check_not_symlink(link, force=True) == tmp_path / "nowhere"


def test_a_missing_folder_is_one_line_naming_the_path(tmp_path):
    p = tmp_path / "no" / "such" / "dir.png"
    with pytest.raises(OutputFileError, match="dir.png: cannot write"):
        atomic_write_bytes(p, b"x")


def test_an_interrupted_write_leaves_the_old_file_and_no_temporary(tmp_path, monkeypatch):
    p = tmp_path / "a.txt"
    p.write_text("old")

    def fail(*_):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", fail)
    with pytest.raises(OutputFileError, match="No space left"):
        atomic_write_text(p, "new")
    assert p.read_text() == "old"
    assert sorted(os.listdir(tmp_path)) == ["a.txt"]



def test_atomic_write_replaces_whole_and_leaves_no_temporary(tmp_path):
    p = tmp_path / "a.json"
    atomic_write_text(p, "old")
    atomic_write_bytes(p, b"new")
    assert p.read_bytes() == b"new" and os.listdir(tmp_path) == ["a.json"]


def test_a_failed_write_keeps_the_old_file(tmp_path):
    p = tmp_path / "a.png"
    p.write_bytes(b"old")
    with pytest.raises(RuntimeError):
        with atomic_path(p) as tmp:
            assert tmp.suffix == ".png" and tmp.parent == tmp_path  # writers that go by the extension
            tmp.write_bytes(b"half")
            raise RuntimeError("crash")
    assert p.read_bytes() == b"old" and os.listdir(tmp_path) == ["a.png"]


def test_a_killed_writer_leaves_a_temporary_that_is_cleaned_up(tmp_path):
    code = f"from ballscan.outputs import atomic_path\nimport os\nwith atomic_path({str(tmp_path / 'x.txt')!r}) as t:\n    t.write_text('part')\n    os._exit(9)\n"
    assert subprocess.run([sys.executable, "-c", code]).returncode == 9
    left = [q for q in tmp_path.iterdir()]
    assert len(left) == 1 and TEMP_MARK in left[0].name and not (tmp_path / "x.txt").exists()
    assert remove_stale_temporaries(tmp_path) == left and list(tmp_path.iterdir()) == []


def test_symlinks_refused_unless_forced(tmp_path):
    target = tmp_path / "truth.json"
    target.write_text("keep")
    link = tmp_path / "link.json"
    link.symlink_to(target)
    with pytest.raises(BallscanError, match="link.json: is a symbolic link .* --force"):
        atomic_write_text(link, "x")
    with pytest.raises(BallscanError):
        check_not_symlink(link)
    assert target.read_text() == "keep"
    atomic_write_text(link, "forced", force=True)
    assert link.is_symlink() and target.read_text() == "forced"


def test_one_writer_per_output(tmp_path):
    lock = tmp_path / "out.csv.lock"
    with OutputLock(lock, "out.csv"):
        with pytest.raises(BallscanError, match=rf"out.csv: another ballscan run \(pid {os.getpid()}\) is writing it"):
            OutputLock(lock, "out.csv").acquire()
        other = subprocess.run([sys.executable, "-c", f"from ballscan.outputs import OutputLock; OutputLock({str(lock)!r}, 'out.csv').acquire()"], capture_output=True, text=True)
        assert other.returncode != 0 and "another ballscan run" in other.stderr
    OutputLock(lock, "out.csv").acquire().release()  # free again once released
