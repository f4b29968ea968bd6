"""Writing output files at the edge: one overwrite policy, checked before any work, atomically.

Every command that writes a file (a record, a history CSV, a plot, a template, a study's
tables) goes through here, so that they all behave alike:

- the path is checked *before* the analysis runs (an existing file without ``--force``, a
  folder in its place, a missing or unwritable parent folder: InputError, exit 2);
- ``-`` means standard output (for text outputs that allow it);
- the content goes to a temporary file in the target's folder, then ``os.replace`` puts it in
  place: a reader never sees half a file, and a symlink planted at the target is replaced, not
  followed (a study file from an untrusted pull request cannot make rock write elsewhere).
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import BinaryIO

from rockcli.errors import InputError

#: The path that means standard output.
STDOUT = "-"


def is_stdout(path: str | Path | None) -> bool:
    """True when the user asked for standard output (``-o -``)."""
    return path is not None and str(path) == STDOUT


def check_writable(path: str | Path, *, force: bool, where: str | None = None) -> None:
    """Refuse, before any work, a path that cannot or may not be written.

    Args:
        path: the output file as the user gave it (``-`` passes: standard output).
        force: overwrite an existing file.
        where: the option that named it (``--history``), for the error line.
    """
    if is_stdout(path):
        return
    target = Path(path)
    if target.is_dir():
        raise InputError("is a folder", file=str(path), where=where, allowed="a file path")
    if (target.exists() or target.is_symlink()) and not force:
        raise InputError(
            "file exists", file=str(path), where=where, allowed="another path, or --force"
        )
    parent = target.parent  # Path("out.txt").parent is Path(".")
    if not parent.is_dir():
        raise InputError(
            "the folder does not exist",
            file=str(path),
            where=where,
            value=str(parent),
            allowed="a path in an existing folder",
        )
    if not os.access(parent, os.W_OK | os.X_OK):
        raise InputError(
            "the folder is not writable",
            file=str(path),
            where=where,
            value=str(parent),
            allowed="a path in a writable folder",
        )


def new_file_mode() -> int:
    """The mode open() gives a new file: 0o666 less the process's umask."""
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


#: The suffix of the temporary files beside an output (``.NAME.XXXXXXXX.tmp``).
TEMP_SUFFIX = ".tmp"


def temp_beside(target: str | Path) -> tuple[int, str]:
    """A new, empty file in the target's folder to write the target's content to, then
    rename onto it: (its descriptor, its path).

    mkstemp creates it with O_CREAT|O_EXCL under a random name (``.NAME.XXXXXXXX.tmp``), so a
    link planted in the folder is never opened; it gets a new file's mode (mkstemp's is 0600).
    """
    target = Path(target)
    fd, name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=TEMP_SUFFIX, dir=target.parent)
    try:
        os.fchmod(fd, new_file_mode())
    except OSError:
        os.close(fd)
        os.unlink(name)
        raise
    return fd, name


def is_temp_of(name: str, target: str) -> bool:
    """True when the file name is one :func:`temp_beside` gives for the target's name."""
    prefix = f".{target}."
    return name.startswith(prefix) and name.endswith(TEMP_SUFFIX) and len(name) > len(prefix)


@contextmanager
def replacing(target: str | Path) -> Iterator[BinaryIO]:
    """A binary file (:func:`temp_beside`) for the target's new content: it replaces the
    target (``os.replace``: a link at the target is replaced, not followed) when the block
    ends, and is removed when the block raises (OSError as it came)."""
    fd, tmp_name = temp_beside(target)
    try:
        with os.fdopen(fd, "wb") as fh:
            yield fh
        os.replace(tmp_name, target)
    except BaseException:
        with suppress(OSError):
            os.unlink(tmp_name)
        raise


def write_bytes(path: str | Path, data: bytes, *, where: str | None = None) -> None:
    """Write ``data`` to ``path`` atomically (temporary file + rename; symlinks not followed)."""
    try:
        with replacing(path) as fh:
            fh.write(data)
    except OSError as exc:
        raise InputError(
            "cannot write the file",
            file=str(path),
            where=where,
            value=exc.strerror or str(exc),
            allowed="a writable path with free space",
        ) from None


def write_text(path: str | Path, text: str, *, where: str | None = None) -> None:
    """Write UTF-8 ``text`` to ``path`` atomically (see :func:`write_bytes`)."""
    write_bytes(path, text.encode("utf-8"), where=where)
