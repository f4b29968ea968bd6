"""Which reader a record's text needs, and the dispatch to it (all on text, no files).

spec/records.md: "detect the format from the content, allow ``--format`` to force it". The
recognisers are tried from the most specific header to the least: ESM (``EVENT_NAME:`` first),
cor.acc (``Time Increment (s)`` and ``Number of Data`` in the first ten lines), AT2 (NPTS and DT
on line 4), plain text (the first data line is numbers only).
"""

from __future__ import annotations

from collections.abc import Callable

from rockcli.errors import InputError
from rockcli.records.at2 import looks_like_at2, parse_at2
from rockcli.records.coracc import looks_like_coracc, parse_coracc
from rockcli.records.esm import looks_like_esm, parse_esm
from rockcli.records.kinds import FILE_FORMATS, RecordFormat
from rockcli.records.lines import split_lines
from rockcli.records.plain import looks_like_plain, parse_plain
from rockcli.records.record import Record
from rockcli.units import AccelUnit

FORMATS_ALLOWED = ", ".join(FILE_FORMATS)
#: The formats rock recognises, as a user knows them.
RECOGNISED = (
    "PEER AT2 (NPTS and DT on line 4), ESM ASCII (EVENT_NAME: first), ITACA cor.acc, or plain "
    "text (one or two columns of numbers)"
)

#: Recognisers in the order they are tried (most specific header first).
_RECOGNISERS: tuple[tuple[RecordFormat, Callable[[list[str]], bool]], ...] = (
    (RecordFormat.ESM, looks_like_esm),
    (RecordFormat.CORACC, looks_like_coracc),
    (RecordFormat.AT2, looks_like_at2),
    (RecordFormat.PLAIN, looks_like_plain),
)

_HEADER_READERS: dict[RecordFormat, Callable[..., Record]] = {
    RecordFormat.AT2: parse_at2,
    RecordFormat.ESM: parse_esm,
    RecordFormat.CORACC: parse_coracc,
}


def parse_format(text: str | RecordFormat, *, where: str = "format") -> RecordFormat:
    """A file format name ("at2", "esm", "coracc", "plain"); InputError if unknown."""
    name = str(text).strip().lower()
    if name not in FILE_FORMATS:
        raise InputError(
            "unknown record format", where=where, value=str(text), allowed=FORMATS_ALLOWED
        )
    return RecordFormat(name)


def detect_format(text: str, *, source: str = "<text>") -> RecordFormat:
    """The format of a record's text, from its content.

    Raises:
        InputError: when no reader recognises the text.
    """
    lines = split_lines(text)
    for fmt, recognises in _RECOGNISERS:
        if recognises(lines):
            return fmt
    # The file's content is never quoted: a suite or a study may name any file of the
    # machine (/etc/passwd, a key), and its first line would end up in a log.
    raise InputError(
        "unrecognised record format (no header of a known format, and not numbers)",
        file=source,
        allowed=f"{RECOGNISED}; or force one with --as ({FORMATS_ALLOWED})",
    )


def _refuse_overrides(fmt: RecordFormat, dt: float | None, units: object, *, source: str) -> None:
    """dt and units are declared by AT2, ESM and cor.acc headers: an override is an error."""
    for where, value in (("dt", dt), ("units", units)):
        if value is not None:
            raise InputError(
                f"{where} is declared in the file's own header ({fmt} format)",
                file=source,
                where=where,
                value=value,
                allowed=f"{where} only for plain-text files",
            )


def parse_text(
    text: str,
    *,
    fmt: str | RecordFormat | None = None,
    name: str = "record",
    source: str = "<text>",
    dt: float | None = None,
    units: str | AccelUnit | None = None,
) -> Record:
    """Parse the text of a record file in a detected or forced format.

    Args:
        text: the whole file.
        fmt: force a format ("at2", "esm", "coracc", "plain"); None detects it.
        name: label of the record (usually the file stem).
        source: the file as the user named it (used in every error).
        dt: time step [s] of a one-column plain file.
        units: acceleration unit of a plain file ("g", "m/s2", "cm/s2"; default g).

    Raises:
        InputError: an unknown or unrecognised format, or any error of the reader.
    """
    chosen = detect_format(text, source=source) if fmt is None else parse_format(fmt)
    if chosen is RecordFormat.PLAIN:
        return parse_plain(text, name=name, source=source, dt=dt, units=units)
    _refuse_overrides(chosen, dt, units, source=source)
    return _HEADER_READERS[chosen](text, name=name, source=source)
