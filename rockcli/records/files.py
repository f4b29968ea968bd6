"""The file edge of the records package: the only functions here that touch the disk.

:func:`read_record` reads a file and hands its text to :mod:`rockcli.records.parse`;
:func:`write_plain` writes the two-column plain text of :func:`rockcli.records.plain.format_plain`.
"""

from __future__ import annotations

from pathlib import Path

from rockcli import outfile, textfile
from rockcli.errors import InputError
from rockcli.records.kinds import RecordFormat
from rockcli.records.lines import check_record
from rockcli.records.parse import parse_text
from rockcli.records.plain import format_plain
from rockcli.records.record import Record
from rockcli.units import AccelUnit

#: Compound suffixes dropped from the file name to name the record.
_COMPOUND_SUFFIXES = (".cor.acc",)


def record_name(path: Path) -> str:
    """The record's label: the file name without its (compound) suffix."""
    lower = path.name.lower()
    for suffix in _COMPOUND_SUFFIXES:
        if lower.endswith(suffix) and len(lower) > len(suffix):
            return path.name[: -len(suffix)]
    return path.stem


def read_text(path: str | Path) -> str:
    """The text of a record file; InputError if unreadable, not a regular file or larger than
    :data:`rockcli.textfile.RECORD_LIMIT` (a 3 h, 200 Hz record; the module says why)."""
    return textfile.read_text(path, "record file", textfile.RECORD_LIMIT)


def read_record(
    path: str | Path,
    *,
    fmt: str | RecordFormat | None = None,
    dt: float | None = None,
    units: str | AccelUnit | None = None,
) -> Record:
    """Read a ground-motion record file into a Record in g.

    Args:
        path: the file (AT2, ESM ASCII, cor.acc or plain text; spec/records.md).
        fmt: force a format ("at2", "esm", "coracc", "plain"); None detects it.
        dt: time step [s] of a one-column plain file.
        units: acceleration unit of a plain file ("g", "m/s2", "cm/s2"; default g).

    Raises:
        InputError: the file cannot be read, its format is unknown, or its content is bad; the
            error names the file, the line or header key, the value and what is allowed.
    """
    source = str(path)
    text = read_text(path)
    return parse_text(
        text, fmt=fmt, name=record_name(Path(path)), source=source, dt=dt, units=units
    )


def check_to_write(record: Record, *, made_by: str | None = None) -> None:
    """Refuse a record that :func:`read_record` would refuse once written (InputError).

    The checks are the readers' own (:func:`rockcli.records.lines.check_record`): a writer
    never leaves a file that ``rock record info`` then refuses (NaN samples, |a| > 100 g,
    a single sample, dt = 1e308).

    Args:
        record: the record about to be written.
        made_by: the options or arguments that made the record (``--T1, --gamma``), named
            in the error as where it comes from.
    """
    try:
        check_record(record, file=None)
    except InputError as exc:
        at = f" at {exc.where}" if exc.where else ""
        raise InputError(
            f"the record it makes would not be a valid record: {exc.problem}{at}",
            where=made_by,
            value=exc.value,
            allowed=exc.allowed,
        ) from None


def write_plain(
    record: Record, path: str | Path, *, where: str | None = None, made_by: str | None = None
) -> None:
    """Write a record as two-column plain text that :func:`read_record` reads back.

    First checked as the readers check it (:func:`check_to_write`; nothing is written when it
    fails); then written atomically, without following a symlink at the target
    (:func:`rockcli.outfile.write_text`); the overwrite policy is the caller's
    (:func:`rockcli.outfile.check_writable`, first).
    """
    check_to_write(record, made_by=made_by)
    outfile.write_text(path, format_plain(record), where=where)
