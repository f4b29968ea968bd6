"""The one overwrite policy and atomic write of every output file (rockcli.outfile)."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from rockcli.errors import InputError
from rockcli.outfile import check_writable, is_stdout, write_bytes, write_text


def test_dash_is_stdout_and_always_allowed():
    assert is_stdout("-")
    check_writable("-", force=False)


def test_existing_file_needs_force(tmp_path: Path):
    path = tmp_path / "out.txt"
    path.write_text("old")
    with pytest.raises(InputError, match="file exists.*--force"):
        check_writable(path, force=False, where="-o")
    check_writable(path, force=True)


def test_missing_folder_and_folder_in_place_are_refused(tmp_path: Path):
    with pytest.raises(InputError, match="folder does not exist"):
        check_writable(tmp_path / "nope" / "out.txt", force=False)
    with pytest.raises(InputError, match="is a folder"):
        check_writable(tmp_path, force=True)


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into read-only folders")
def test_read_only_folder_is_refused(tmp_path: Path):
    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o500)
    try:
        with pytest.raises(InputError, match="not writable"):
            check_writable(folder / "out.txt", force=False)
    finally:
        folder.chmod(0o700)


def test_symlink_at_the_target_is_replaced_not_followed(tmp_path: Path):
    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    link = tmp_path / "out.txt"
    link.symlink_to(victim)
    with pytest.raises(InputError, match="file exists"):
        check_writable(link, force=False)
    write_text(link, "result")
    assert victim.read_text() == "precious"
    assert not link.is_symlink() and link.read_text() == "result"


def test_write_leaves_no_temporary_file(tmp_path: Path):
    write_text(tmp_path / "a.txt", "x")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt"]


def test_a_written_file_has_a_new_files_mode(tmp_path: Path):
    # The atomic write goes through mkstemp (mode 0600): the result must be readable as any
    # new file is (0666 less the umask), not private to its owner.
    old = os.umask(0o022)
    try:
        out = tmp_path / "plot.png"
        write_bytes(out, b"x")
        assert stat.S_IMODE(out.stat().st_mode) == 0o644
        os.umask(0o077)
        write_bytes(out, b"y")
        assert stat.S_IMODE(out.stat().st_mode) == 0o600
    finally:
        os.umask(old)
