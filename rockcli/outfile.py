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
from contextlib import suppress
from pathlib import Path

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


def write_bytes(path: str | Path, data: bytes, *, where: str | None = None) -> None:
    """Write ``data`` to ``path`` atomically (temporary file + rename; symlinks not followed)."""
    target = Path(path)
    folder = target.parent
    tmp_name = None
    try:
        fd, tmp_name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
        os.fchmod(fd, new_file_mode())  # mkstemp makes it 0600: give it a new file's mode
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.replace(tmp_name, target)
        tmp_name = None
    except OSError as exc:
        raise InputError(
            "cannot write the file",
            file=str(path),
            where=where,
            value=exc.strerror or str(exc),
            allowed="a writable path with free space",
        ) from None
    finally:
        if tmp_name is not None:
            with suppress(OSError):
                os.unlink(tmp_name)


def write_text(path: str | Path, text: str, *, where: str | None = None) -> None:
    """Write UTF-8 ``text`` to ``path`` atomically (see :func:`write_bytes`)."""
    write_bytes(path, text.encode("utf-8"), where=where)
