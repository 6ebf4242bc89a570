"""Output files: whole or not at all, never through a symbolic link unless forced."""

from __future__ import annotations

import os
import stat

import pytest

from ballscan.errors import BallscanError
from ballscan.outputs import OutputFileError, atomic_write_bytes, atomic_write_text, check_not_symlink


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
