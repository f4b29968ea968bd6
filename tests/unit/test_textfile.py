"""The file edge (rockcli.textfile): regular files only, never more than the limit read.

The special files that hung or exhausted the machine on main are tested through the command
line, in a child process under limits (tests/cli/test_special_files.py); here the pieces, in
process, on files that cannot hang: a size the system does not know (/proc), the exact limit,
a FIFO swapped in between ``stat`` and ``open``, a NUL in a path, and random contents.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rockcli.errors import InputError
from rockcli.model.load import read_toml
from rockcli.textfile import read_limited, read_text

#: Seconds a refusal may take in process before the test unblocks it and fails.
BLOCK_TIMEOUT = 5.0


def test_a_file_at_the_limit_reads_and_one_byte_more_is_too_large(tmp_path: Path) -> None:
    path = tmp_path / "r.txt"
    path.write_bytes(b"x" * 100)
    assert read_limited(path, "record file", 100) == b"x" * 100
    with pytest.raises(InputError) as info:
        read_limited(path, "record file", 99)
    assert info.value.problem == "too large (100 bytes; the limit is 99)"
    assert info.value.file == str(path)


@pytest.mark.skipif(not Path("/proc/self/status").is_file(), reason="needs Linux /proc")
def test_a_file_whose_size_is_unknown_is_read_to_the_limit_only() -> None:
    # /proc files report st_size 0 whatever they hold: only the bytes read can tell.
    assert os.stat("/proc/self/status").st_size == 0
    with pytest.raises(InputError) as info:
        read_limited("/proc/self/status", "record file", 16)
    assert info.value.problem == "too large (more than 16 bytes; the limit is 16)"


def test_a_folder_is_not_a_regular_file(tmp_path: Path) -> None:
    with pytest.raises(InputError) as info:
        read_text(tmp_path, "record file", 100)
    assert info.value.problem == "not a regular file (a folder)"


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs POSIX FIFOs")
def test_a_fifo_swapped_in_after_stat_is_refused_without_blocking(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """stat says "regular file" (the race: the file is replaced by a FIFO before the open);
    the open must not wait for a writer (O_NONBLOCK) and fstat must refuse it."""
    regular, fifo = tmp_path / "r.txt", tmp_path / "pipe.txt"
    regular.write_text("0 0\n", encoding="utf-8")
    os.mkfifo(fifo)
    real_stat = os.stat
    monkeypatch.setattr(os, "stat", lambda path, *a, **k: real_stat(regular))
    outcome: list[BaseException | None] = []

    def read() -> None:
        try:
            read_limited(fifo, "record file", 100)
            outcome.append(None)
        except BaseException as exc:  # handed to the test's thread
            outcome.append(exc)

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    reader.join(BLOCK_TIMEOUT)
    if reader.is_alive():  # blocked in open(): release it with a writer, then fail
        os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        reader.join(BLOCK_TIMEOUT)
        pytest.fail("the FIFO's open blocked")
    (exc,) = outcome
    assert isinstance(exc, InputError) and exc.problem == "not a regular file (a named pipe)"


def test_a_nul_in_a_path_is_an_input_error(tmp_path: Path) -> None:
    # On main the suite loader's record path with a NUL exited 3 (ValueError).
    with pytest.raises(InputError) as info:
        read_text(tmp_path / "a\x00b.txt", "record file", 100)
    assert info.value.problem == "cannot read the record file"
    assert info.value.value == "embedded null byte"
    with pytest.raises(InputError) as info:
        read_toml(str(tmp_path / "a\x00b.toml"))
    assert info.value.problem == "cannot read the file: embedded null byte"


@settings(
    max_examples=100, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(data=st.binary(max_size=64), limit=st.integers(0, 80))
def test_random_contents_read_whole_or_too_large(tmp_path: Path, data: bytes, limit: int) -> None:
    path = tmp_path / "f.bin"
    path.write_bytes(data)
    try:
        assert read_limited(path, "record file", limit) == data
        assert len(data) <= limit
    except InputError as exc:
        assert len(data) > limit
        assert exc.problem == f"too large ({len(data):,} bytes; the limit is {limit:,})"
    text = None
    try:
        text = read_text(path, "record file", limit)
    except InputError:
        assert len(data) > limit
    if text is not None:  # UTF-8 (a BOM dropped) or Latin-1: never a decoding error
        assert len(text) <= len(data)
