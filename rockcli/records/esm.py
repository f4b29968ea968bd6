"""ESM / ITACA ASCII records (DYNA 1.2 header).

Layout (spec/records.md; ESM "ASCII format" of the Engineering Strong-Motion database,
https://esm-db.eu): ``KEY: value`` header lines (first keys ``EVENT_NAME:``, ``EVENT_ID:``), then
one value a line. The record is described by ``SAMPLING_INTERVAL_S``, ``NDATA`` and ``UNITS``
(``cm/s^2`` for accelerations). Keys contain ``/``, ``^`` and ``()``, so a line is split on its
first colon only; the header ends at the first numeric line, whatever its length.
"""

from __future__ import annotations

from rockcli.errors import InputError
from rockcli.records.kinds import RecordFormat
from rockcli.records.lines import (
    Origin,
    check_count,
    check_declared_pga,
    check_dt,
    is_number,
    parse_count,
    parse_number,
    read_tokens,
    split_lines,
    uniform_record,
)
from rockcli.records.record import Record
from rockcli.units import AccelUnit, parse_unit

FIRST_KEYS = ("EVENT_NAME", "EVENT_ID")
DT_KEY = "SAMPLING_INTERVAL_S"
COUNT_KEY = "NDATA"
UNITS_KEY = "UNITS"
DATA_TYPE_KEY = "DATA_TYPE"


#: The header's PGA, in cm/s² whatever UNITS says (signed: the peak sample's sign).
PGA_KEY = "PGA_CM/S^2"
#: Longest header value shown (event, station, component) [characters].
MAX_HEADER_CHARS = 200


def _is_numeric(line: str) -> bool:
    """True for a data line: one or more blank-separated tokens, the first a number.

    Only the first token decides (a damaged value further on is the reader's error, named
    by its line, not a header line).
    """
    tokens = line.split(maxsplit=1)
    return bool(tokens) and is_number(tokens[0])


def read_origin(header: dict[str, str]) -> Origin:
    """Event (name and date), station (``NETWORK.STATION_CODE``) and component (STREAM)."""
    event = " ".join(x for x in (header.get("EVENT_NAME"), header.get("EVENT_DATE_YYYYMMDD")) if x)
    station = ".".join(x for x in (header.get("NETWORK"), header.get("STATION_CODE")) if x)
    stream = header.get("STREAM", "")
    return Origin(event[:MAX_HEADER_CHARS], station[:MAX_HEADER_CHARS], stream[:MAX_HEADER_CHARS])


def looks_like_esm(lines: list[str]) -> bool:
    """True when the first non-blank line is ``EVENT_NAME:`` or ``EVENT_ID:``."""
    first = next((line for line in lines if line.strip()), "")
    return first.split(":", 1)[0].strip().upper() in FIRST_KEYS and ":" in first


def read_header(lines: list[str], *, file: str) -> tuple[dict[str, str], int]:
    """The ``KEY: value`` header (keys upper-case) and the index of the first data line."""
    header: dict[str, str] = {}
    for index, line in enumerate(lines):
        if _is_numeric(line):
            return header, index
        if not line.strip():
            continue
        if ":" not in line:
            raise InputError(
                "neither a 'KEY: value' header line nor a number",
                file=file,
                where=f"line {index + 1}",
                value=line.strip(),
                allowed="'KEY: value' in the header, then one number a line",
            )
        key, value = line.split(":", 1)
        header[key.strip().upper()] = value.strip()
    return header, len(lines)


def _header_value(header: dict[str, str], key: str, *, file: str) -> str:
    """A required header value; InputError naming the key when missing or empty."""
    value = header.get(key, "")
    if not value:
        raise InputError(
            "missing header value", file=file, where=key, value=None, allowed=f"'{key}: <value>'"
        )
    return value


def _check_acceleration(header: dict[str, str], *, file: str) -> None:
    """Only acceleration files are records here (DATA_TYPE, when present)."""
    data_type = header.get(DATA_TYPE_KEY, "ACCELERATION").upper()
    if data_type != "ACCELERATION":
        raise InputError(
            "not an acceleration record",
            file=file,
            where=DATA_TYPE_KEY,
            value=data_type,
            allowed="ACCELERATION",
        )


def parse_esm(text: str, *, name: str = "record", source: str = "<text>") -> Record:
    """Read the text of an ESM/ITACA ASCII file (DYNA 1.2 header) into a Record in g.

    Args:
        text: the whole file.
        name: label of the record (usually the file stem).
        source: the file as the user named it (used in every error).

    Raises:
        InputError: a missing or bad header value, an unknown unit, a token that is not a
            finite number, or a number of values different from NDATA.
    """
    lines = split_lines(text)
    header, start = read_header(lines, file=source)
    _check_acceleration(header, file=source)
    dt_text = _header_value(header, DT_KEY, file=source)
    dt = check_dt(parse_number(dt_text, file=source, where=DT_KEY), file=source, where=DT_KEY)
    count = parse_count(_header_value(header, COUNT_KEY, file=source), file=source, where=COUNT_KEY)
    unit = parse_unit(_header_value(header, UNITS_KEY, file=source), file=source, where=UNITS_KEY)
    values, tokens = read_tokens(lines[start:], first_line=start + 1, file=source)
    check_count(values, count, file=source, where=COUNT_KEY)
    if header.get(PGA_KEY):
        to_cm = unit.to_g / AccelUnit.CM_S2.to_g
        check_declared_pga(
            values, tokens, header[PGA_KEY], file=source, where=PGA_KEY, to_declared=to_cm
        )
    return uniform_record(
        values,
        dt=dt,
        unit=unit,
        fmt=RecordFormat.ESM,
        name=name,
        source=source,
        origin=read_origin(header),
    )
