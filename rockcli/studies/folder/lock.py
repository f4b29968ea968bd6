"""The lock of a study's output folder: one run at a time writes into it.

Two runs into the same folder (a CI job retried, a command started twice) would append to one
cases.csv and each mark it complete. The run holds an exclusive ``flock`` on
:data:`LOCK_FILE` in the folder from its first look at the folder to its summary; the file
holds the run's pid, which the run refused names. The kernel releases the lock when the
process ends, however it ends: a lock file left by a killed run does not block the next one.
The file is created without following a link (O_NOFOLLOW), and removed by the run that holds
it (a run that opened the file before it was removed sees it gone and takes a new one).
"""

from __future__ import annotations

import errno
import os
import stat
from contextlib import suppress
from pathlib import Path

try:
    import fcntl
except ImportError:  # not POSIX (Windows): no lock taken (docs/examples.md, "rock sweep")
    fcntl = None  # type: ignore[assignment]

#: The lock file's name in the output folder.
LOCK_FILE = "study.lock"
#: Times the lock is taken again when the file was replaced between opening and locking it.
LOCK_ATTEMPTS = 5
#: Bytes of the lock file read for the holder's pid.
PID_BYTES = 32
#: How the lock file is opened: created if absent, never through a link, never blocking (a
#: FIFO planted in its place), not inherited by the worker processes.
OPEN_FLAGS = os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0)


class FolderBusy(Exception):
    """Another process holds the lock; pid: the one its file names (None: not written yet)."""

    def __init__(self, pid: int | None) -> None:
        super().__init__(f"the output folder is in use (pid {pid})")
        self.pid = pid


class NotALockFile(Exception):
    """Something other than a regular file is at the lock file's name (a folder, a FIFO)."""


def lock_folder(folder: Path) -> int | None:
    """Take the folder's lock: the lock file's descriptor (None where there is no flock);
    FolderBusy when another process holds it."""
    return acquire(folder / LOCK_FILE) if fcntl is not None else None


def unlock_folder(folder: Path, fd: int | None) -> None:
    """Remove the lock file, then release the lock (in this order: a run waiting on the file
    finds it gone and takes a new one)."""
    if fd is None:
        return
    path = folder / LOCK_FILE
    with suppress(OSError):
        if still_there(path, fd):
            os.unlink(path)
    os.close(fd)


def acquire(path: Path) -> int:
    """The descriptor of the locked lock file, with this process's pid written in it."""
    for _ in range(LOCK_ATTEMPTS):
        fd = open_lock_file(path)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            pid = holder(fd)
            os.close(fd)
            raise FolderBusy(pid) from None
        if still_there(path, fd):
            mark = f"{os.getpid()}\n".encode()
            os.pwrite(fd, mark, 0)  # then cut: a reader never sees an empty file
            os.ftruncate(fd, len(mark))
            return fd
        os.close(fd)
    raise FolderBusy(None)


def open_lock_file(path: Path) -> int:
    """Open (create) the lock file; a link at its name is removed first, never followed."""
    try:
        fd = os.open(path, OPEN_FLAGS, 0o644)
    except OSError as exc:
        if exc.errno != errno.ELOOP:
            raise
        os.unlink(path)  # a symbolic link planted at the name
        fd = os.open(path, OPEN_FLAGS | os.O_EXCL, 0o644)
    if not stat.S_ISREG(os.fstat(fd).st_mode):
        os.close(fd)
        raise NotALockFile(str(path))
    return fd


def still_there(path: Path, fd: int) -> bool:
    """True when the path still names the file locked (its holder did not remove it)."""
    try:
        now = os.stat(path, follow_symlinks=False)
    except FileNotFoundError:
        return False
    mine = os.fstat(fd)
    return (now.st_dev, now.st_ino) == (mine.st_dev, mine.st_ino)


def holder(fd: int) -> int | None:
    """The pid written in a lock file (None when not written yet, or not a pid)."""
    words = os.pread(fd, PID_BYTES, 0).decode("ascii", "replace").split()
    return int(words[0]) if words and words[0].isascii() and words[0].isdigit() else None
