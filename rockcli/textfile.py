"""Reading a text file at the edge: one error for an unreadable file, one decoding rule."""

from __future__ import annotations

from pathlib import Path

from rockcli.errors import InputError


def read_text(path: str | Path, what: str) -> str:
    """The text of a file (UTF-8, or Latin-1 for older headers); InputError if unreadable.

    Args:
        path: the file, named in the error as given.
        what: what the file is, for the message ("record file", "hazard grid file").
    """
    try:
        data = Path(path).read_bytes()
    except OSError as exc:
        raise InputError(
            f"cannot read the {what}",
            file=str(path),
            value=exc.strerror,
            allowed="an existing, readable file",
        ) from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return data.decode("latin-1")
