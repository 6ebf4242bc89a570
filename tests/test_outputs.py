"""Tests of ballscan.outputs: whole files or none, one writer per output, no writes through symlinks."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from ballscan.errors import BallscanError
from ballscan.outputs import TEMP_MARK, OutputLock, atomic_path, atomic_write_bytes, atomic_write_text, check_not_symlink, remove_stale_temporaries


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
