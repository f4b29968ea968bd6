"""Reading a file at the edge: only regular files, below a size limit, one decoding rule.

Every file rock reads on the user's behalf (a model, a study, a suite, a case file, a record,
the hazard grid) goes through :func:`read_limited`. Two things a path can name would
otherwise hang or exhaust the machine: a FIFO (a named pipe: opening it waits for a writer,
forever) and an endless or huge file (``/dev/zero``, a sparse file of terabytes: read whole,
it fills the memory). So a path is opened only when it names a regular file — checked by
``stat`` before opening, so that no device is ever opened, and again by ``fstat`` on the
descriptor, which is opened with ``O_NONBLOCK`` (a FIFO swapped in between the two cannot
block the open) — and at most ``limit + 1`` bytes are read, whatever the file claims its size
is (``/proc`` files say 0).

The limits, by kind of file (docs/conventions.md, Records, "Files"):

- :data:`TOML_LIMIT` (1 MiB) for the TOML files (model, study, suite, case file): a model
  file is 1–5 kB, the largest case file of the bundled casebook 10 kB; a file a hundred
  times larger than any of them is not one a person wrote.
- :data:`RECORD_LIMIT` (64 MiB) for a record: real accelerograms are 20 kB to 2 MB (PEER AT2,
  ESM ASCII, ITACA cor.acc); 64 MiB holds a 3-hour record at 200 Hz (2.16 million samples) in
  one column at full double precision (about 24 bytes a sample, 52 MB). Reading text costs
  memory: a record file takes about 22 times its size while it is parsed, 1.4 GB at the limit.
- :data:`GRID_LIMIT` (16 MiB) for the NTC hazard grid: the official Allegato B table is
  1.7 MB; ten times that leaves room for a reformatted copy, not for a file that is not it.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from rockcli.errors import InputError

#: Largest TOML input (model, study, suite, case file) [bytes]; the module docstring says why.
TOML_LIMIT = 1 << 20
#: Largest record file [bytes]: a 3 h, 200 Hz record in one column at full precision.
RECORD_LIMIT = 64 << 20
#: Largest hazard grid file [bytes]: ten times the official Allegato B table (1.7 MB).
GRID_LIMIT = 16 << 20

#: What each kind of file that is not a regular file is called in a message.
_KINDS = (
    (stat.S_ISDIR, "a folder"),
    (stat.S_ISFIFO, "a named pipe"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
)


def read_text(path: str | Path, what: str, limit: int) -> str:
    """The text of a file (UTF-8, or Latin-1 for older headers); InputError if unreadable,
    not a regular file or larger than ``limit`` bytes.

    Args:
        path: the file, named in the error as given.
        what: what the file is, for the message ("record file", "hazard grid file").
        limit: the largest size accepted [bytes] (:data:`RECORD_LIMIT`, :data:`GRID_LIMIT`).
    """
    try:
        data = read_limited(path, what, limit)
    except (OSError, ValueError) as exc:
        raise InputError(
            f"cannot read the {what}",
            file=str(path),
            value=reason(exc),
            allowed="an existing, readable file",
        ) from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def reason(exc: OSError | ValueError) -> str:
    """Why the system refused a path, in its words ("No such file or directory", "embedded
    null byte")."""
    return exc.strerror if isinstance(exc, OSError) and exc.strerror else str(exc)


def read_limited(path: str | Path, what: str, limit: int) -> bytes:
    """The bytes of a regular file of at most ``limit`` bytes.

    Raises:
        InputError: not a regular file (a folder, a FIFO, a device), or larger than the limit.
        OSError, ValueError: the system refuses the path (absent, no permission, a NUL
            character); the caller words it.
    """
    fd = open_regular(path, what)
    with os.fdopen(fd, "rb") as handle:
        check_size(os.fstat(fd).st_size, path, what, limit)
        data = handle.read(limit + 1)
    if len(data) > limit:  # a file that grew, or one whose size the system does not know
        raise too_large(f"more than {limit:,}", path, what, limit)
    return data


def open_regular(path: str | Path, what: str) -> int:
    """A read-only descriptor on a regular file (the caller closes it); InputError for any
    other kind of file. ``stat`` first, so that no FIFO or device is ever opened; then
    ``O_NONBLOCK`` and ``fstat`` on the descriptor, so that one swapped in meanwhile is
    refused instead of blocking the open (the flag is cleared before reading)."""
    check_regular(os.stat(path).st_mode, path, what)
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
    fd = os.open(path, flags | getattr(os, "O_CLOEXEC", 0))
    try:
        check_regular(os.fstat(fd).st_mode, path, what)
        if hasattr(os, "set_blocking"):
            os.set_blocking(fd, True)
    except BaseException:
        os.close(fd)
        raise
    return fd


def check_regular(mode: int, path: str | Path, what: str) -> None:
    """InputError unless ``mode`` is a regular file's, naming what the path is instead."""
    if stat.S_ISREG(mode):
        return
    raise InputError(
        f"not a regular file ({file_kind(mode)})",
        file=str(path),
        allowed=f"a regular file as the {what} (not a folder, pipe or device)",
    )


def file_kind(mode: int) -> str:
    """What a file that is not a regular file is ("a folder", "a named pipe"…)."""
    return next((name for test, name in _KINDS if test(mode)), "not a file")


def check_size(size: int, path: str | Path, what: str, limit: int) -> None:
    """InputError when a file's size is above the limit."""
    if size > limit:
        raise too_large(f"{size:,}", path, what, limit)


def too_large(size: str, path: str | Path, what: str, limit: int) -> InputError:
    """The error of a file above its limit: its size and the limit, in bytes."""
    return InputError(
        f"too large ({size} bytes; the limit is {limit:,})",
        file=str(path),
        allowed=f"a {what} of at most {limit >> 20} MiB",
    )
