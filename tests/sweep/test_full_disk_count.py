"""Issue 34, finding F18: on a full disk, the count of rows said saved is the number of whole
lines that reached cases.csv, wherever the disk fills (mid-line, at a line's end, at the
first byte), never one short or one over."""

from __future__ import annotations

import errno
import os
from pathlib import Path

import pytest

from rockcli.studies.folder import folder as study_folder
from rockcli.studies.folder.folder import PartialWrite, write_all

LINES = [f"{k},row {k}\n".encode() for k in range(6)]


@pytest.mark.parametrize("room", [0, 1, 7, 8, 9, 23, 24, 40, 200])
def test_the_rows_said_saved_are_the_whole_lines_on_disk(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, room: int
) -> None:
    """A disk with ``room`` bytes left: os.write writes what fits (a short write), then
    fails with ENOSPC, as a filling file system does."""
    real_write = os.write
    left = [room]

    def filling(fd: int, data: bytes) -> int:
        if left[0] == 0:
            raise OSError(errno.ENOSPC, "No space left on device")
        n = real_write(fd, bytes(data[: left[0]]))
        left[0] -= n
        return n

    monkeypatch.setattr(study_folder.os, "write", filling)
    path = tmp_path / "cases.csv"
    fd = os.open(path, os.O_WRONLY | os.O_CREAT)
    ids = list(range(len(LINES)))
    data = b"".join(LINES)
    try:
        write_all(fd, data, lambda n: ids[: study_folder.whole_lines(LINES, n)])
        saved = ids
    except PartialWrite as exc:
        saved = exc.ids
    finally:
        os.close(fd)
    on_disk = path.read_bytes()
    whole = on_disk.count(b"\n")
    assert on_disk == data[: min(room, len(data))]
    assert len(saved) == whole
