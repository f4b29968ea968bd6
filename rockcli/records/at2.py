"""PEER AT2 records: old PEER, NGA-West1, NGA-West2 and the Pacific Engineering variant.

Layout (spec/records.md, table "What rock reads", and the PEER strong-motion database files):
four header lines; line 3 states the units (``UNITS OF G``); line 4 declares NPTS and DT in one
of several layouts; then the accelerations in g, blank-separated, normally five a line, with no
time column (t = i·DT). The El Centro "Peknold" file (``ELC_NS_Peknold_8F10.5.txt``) has the
same four-line header, with line 3 ``The units are (g)`` and eight F10.5 values a line: it is
read as AT2 too.
"""

from __future__ import annotations

import re

from rockcli.errors import InputError
from rockcli.records.kinds import RecordFormat
from rockcli.records.lines import (
    Origin,
    check_count,
    check_dt,
    is_number,
    parse_count,
    parse_number,
    read_values,
    split_lines,
    uniform_record,
)
from rockcli.records.record import Record
from rockcli.units import AccelUnit

HEADER_LINES = 4
NPTS_LINE = 4
UNITS_LINE = 3
EVENT_LINE = 2

#: Longest header line searched [characters]: real line 4s are under 100; the bound keeps
#: every header pattern linear in the file, whatever a damaged line holds.
MAX_HEADER_CHARS = 200

_NUM = r"[-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eEdD][-+]?\d+)?"
#: ``NPTS= 4000, DT= .01000 SEC``, ``DT= .0100 SEC, NPTS= 4096``, ``NPTS 4096 DT .0100``…
_NPTS_KEY = re.compile(rf"\bNPTS\s*[=:]?\s*({_NUM})", re.IGNORECASE | re.ASCII)
_DT_KEY = re.compile(rf"\bDT\s*[=:]?\s*({_NUM})(?:\s*([A-Z]+))?", re.IGNORECASE | re.ASCII)
#: NGA-West1: ``4096    0.0100    NPTS, DT`` (values first, labels after).
_VALUES_FIRST = re.compile(
    rf"^\s*({_NUM})\s*,?\s+({_NUM})\s+(NPTS|DT)\s*,?\s*(NPTS|DT)\b", re.IGNORECASE | re.ASCII
)
#: Two bare numbers and nothing else: ``  1201    0.0050``.
_BARE_PAIR = re.compile(rf"\s*({_NUM})\s*,?\s+({_NUM})\s*", re.ASCII)
_WHOLE = re.compile(r"\d+", re.ASCII)
#: Line 3: ``... IN UNITS OF G`` (PEER) or ``The units are (g)`` (Peknold).
_UNITS_OF_G = re.compile(r"\bUNITS\s+(?:OF|ARE|IN)\s*\(?\s*G\s*\)?(?![A-Z/])", re.IGNORECASE)
#: Line 1 of the PEER and Pacific Engineering files, whose line 2 is "event, station, comp".
_PEER_TITLE = re.compile(r"^\s*(?:PEER|PACIFIC ENGINEERING)", re.IGNORECASE)

#: Words after the DT value: seconds, or milliseconds (converted).
SECOND_WORDS = frozenset({"S", "SEC", "SECS", "SECOND", "SECONDS"})
MILLISECOND_WORDS = frozenset({"MS", "MSEC", "MSECS", "MILLISECOND", "MILLISECONDS"})
#: Words that may follow DT's value without being its unit (other keys of line 4).
OTHER_KEYS = frozenset({"NPTS"})
MS_TO_S = 1e-3
#: A bare DT is accepted only below this [s] (NPTS is then the whole number before it).
BARE_DT_LIMIT = 1.0

LINE4_ALLOWED = "NPTS and DT, e.g. 'NPTS=  4000, DT= .01000 SEC' or '4096  0.0100  NPTS, DT'"


def _head(line: str) -> str:
    """The part of a header line that is searched (MAX_HEADER_CHARS)."""
    return line[:MAX_HEADER_CHARS]


def find_npts_dt(line: str) -> tuple[str, str, str] | None:
    """NPTS, DT and DT's unit word of an AT2 line 4 (keyed layouts); None if absent."""
    head = _head(line)
    npts, dt = _NPTS_KEY.search(head), _DT_KEY.search(head)
    if npts and dt:
        return npts.group(1), dt.group(1), (dt.group(2) or "").upper()
    first = _VALUES_FIRST.search(head)
    if first and first.group(3).upper() != first.group(4).upper():
        by_label = {first.group(3).upper(): first.group(1), first.group(4).upper(): first.group(2)}
        return by_label["NPTS"], by_label["DT"], ""
    return None


def _bare_pair(line: str) -> tuple[str, str] | None:
    """The two tokens of a line 4 that holds two bare numbers and nothing else."""
    found = _BARE_PAIR.fullmatch(_head(line)) if len(line) <= MAX_HEADER_CHARS else None
    return (found.group(1), found.group(2)) if found else None


def _units_line_ok(lines: list[str]) -> bool:
    line = lines[UNITS_LINE - 1] if len(lines) >= UNITS_LINE else ""
    return _UNITS_OF_G.search(_head(line)) is not None


def looks_like_at2(lines: list[str]) -> bool:
    """True when line 4 declares NPTS and DT (spec/records.md: "line 4 holds NPTS and DT").

    A ``#`` line 4 is a comment of a plain-text file, never an AT2 header. Two bare numbers
    on line 4 count only under an AT2 units line that is not a ``#`` comment (a plain file's
    fourth row is two numbers, and its comments may well say "units of g").
    """
    line = lines[NPTS_LINE - 1] if len(lines) >= NPTS_LINE else ""
    if line.lstrip().startswith("#"):
        return False
    if find_npts_dt(line) is not None:
        return True
    commented = any(head.lstrip().startswith("#") for head in lines[: NPTS_LINE - 1])
    return _bare_pair(line) is not None and not commented and _units_line_ok(lines)


def _check_units_line(lines: list[str], *, file: str) -> None:
    """Line 3 must say the values are in g (``UNITS OF G``)."""
    if not _units_line_ok(lines):
        line = lines[UNITS_LINE - 1] if len(lines) >= UNITS_LINE else ""
        raise InputError(
            "an AT2 file must hold accelerations in g",
            file=file,
            where=f"line {UNITS_LINE}",
            value=_head(line.strip()),
            allowed="a line 3 with 'UNITS OF G'",
        )


def _unambiguous_bare(tokens: tuple[str, str], *, file: str, where: str) -> tuple[str, str, str]:
    """NPTS and DT from two bare numbers: a whole number, then a time step below 1 s."""
    npts, dt = tokens
    if _WHOLE.fullmatch(npts) and is_number(dt) and 0.0 < float(dt) < BARE_DT_LIMIT:
        return npts, dt, ""
    raise InputError(
        "line 4 holds two numbers without NPTS and DT labels, and they are ambiguous",
        file=file,
        where=where,
        value=f"{npts} {dt}",
        allowed="a whole NPTS then a DT below 1 s ('1201  0.0050'), or " + LINE4_ALLOWED,
    )


def _dt_seconds(dt: float, word: str, *, file: str, where: str) -> tuple[float, tuple[str, ...]]:
    """DT in seconds from its value and the word after it (SEC, MSEC…); notes of a conversion."""
    if not word or word in SECOND_WORDS or word in OTHER_KEYS:
        return dt, ()
    if word in MILLISECOND_WORDS:
        return dt * MS_TO_S, (f"DT declared as {dt:g} {word.lower()}: read as {dt * MS_TO_S:g} s",)
    raise InputError(
        "unknown unit of DT",
        file=file,
        where=where,
        value=word,
        allowed="SEC (seconds) or MSEC (milliseconds)",
    )


def _read_npts_dt(lines: list[str], *, file: str) -> tuple[int, float, tuple[str, ...]]:
    """NPTS, DT [s] from line 4, and the notes of a DT unit conversion."""
    where = f"line {NPTS_LINE}"
    line = lines[NPTS_LINE - 1] if len(lines) >= NPTS_LINE else ""
    tokens = find_npts_dt(line)
    if tokens is None:
        bare = _bare_pair(line)
        if bare is not None:
            tokens = _unambiguous_bare(bare, file=file, where=where)
    if tokens is None:
        raise InputError(
            "no NPTS and DT in the AT2 header",
            file=file,
            where=where,
            value=_head(line.strip()),
            allowed=LINE4_ALLOWED,
        )
    npts = parse_count(tokens[0], file=file, where=f"{where} (NPTS)")
    dt_token = tokens[1].upper().replace("D", "E")  # Fortran D exponent
    dt = parse_number(dt_token, file=file, where=f"{where} (DT)")
    dt, notes = _dt_seconds(dt, tokens[2], file=file, where=f"{where} (DT unit)")
    return npts, check_dt(dt, file=file, where=f"{where} (DT)"), notes


def read_origin(lines: list[str]) -> Origin:
    """Event, station and component of a PEER line 2 (``EVENT, DATE, STATION, COMP``).

    PEER and Pacific Engineering files (line 1 says so) write line 2 as comma-separated
    fields ending with the station and the component (``180 (USGS STATION 117)``: the
    component is its first word). Other files (the Peknold text) have free text: nothing.
    """
    if len(lines) < EVENT_LINE or not _PEER_TITLE.match(_head(lines[0])):
        return Origin()
    parts = [part.strip() for part in _head(lines[EVENT_LINE - 1]).split(",")]
    if len(parts) < 3 or not parts[-1]:
        return Origin()
    return Origin(", ".join(parts[:-2]), parts[-2], parts[-1].split()[0])


def parse_at2(text: str, *, name: str = "record", source: str = "<text>") -> Record:
    """Read the text of a PEER AT2 file into a Record in g.

    Args:
        text: the whole file.
        name: label of the record (usually the file stem).
        source: the file as the user named it (used in every error).

    Raises:
        InputError: bad header, a token that is not a finite number, or a number of values
            different from NPTS (spec/records.md, "Checks on every record").
    """
    lines = split_lines(text)
    _check_units_line(lines, file=source)
    npts, dt, notes = _read_npts_dt(lines, file=source)
    values = read_values(lines[HEADER_LINES:], first_line=HEADER_LINES + 1, file=source)
    check_count(values, npts, file=source, where=f"line {NPTS_LINE} (NPTS)")
    return uniform_record(
        values,
        dt=dt,
        unit=AccelUnit.G,
        fmt=RecordFormat.AT2,
        name=name,
        source=source,
        notes=notes,
        origin=read_origin(lines),
    )
