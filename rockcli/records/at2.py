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
    check_count,
    check_dt,
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

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eEdD][-+]?\d+)?"
#: ``NPTS= 4000, DT= .01000 SEC``, ``DT= .0100 SEC, NPTS= 4096``, ``NPTS 4096 DT .0100``…
_NPTS_KEY = re.compile(rf"\bNPTS\s*[=:]?\s*({_NUM})", re.IGNORECASE)
_DT_KEY = re.compile(rf"\bDT\s*[=:]?\s*({_NUM})", re.IGNORECASE)
#: NGA-West1: ``4096    0.0100    NPTS, DT`` (values first, labels after).
_VALUES_FIRST = re.compile(
    rf"^\s*({_NUM})\s*,?\s+({_NUM})\s+(NPTS|DT)\s*,?\s*(NPTS|DT)\b", re.IGNORECASE
)
#: Line 3: ``... IN UNITS OF G`` (PEER) or ``The units are (g)`` (Peknold).
_UNITS_OF_G = re.compile(r"\bUNITS\s+(?:OF|ARE|IN)\s*\(?\s*G\s*\)?(?![A-Z/])", re.IGNORECASE)

LINE4_ALLOWED = "NPTS and DT, e.g. 'NPTS=  4000, DT= .01000 SEC' or '4096  0.0100  NPTS, DT'"


def find_npts_dt(line: str) -> tuple[str, str] | None:
    """The NPTS and DT tokens of an AT2 line 4, in any of its layouts; None if absent."""
    npts, dt = _NPTS_KEY.search(line), _DT_KEY.search(line)
    if npts and dt:
        return npts.group(1), dt.group(1)
    first = _VALUES_FIRST.search(line)
    if first and first.group(3).upper() != first.group(4).upper():
        by_label = {first.group(3).upper(): first.group(1), first.group(4).upper(): first.group(2)}
        return by_label["NPTS"], by_label["DT"]
    return None


def looks_like_at2(lines: list[str]) -> bool:
    """True when line 4 declares NPTS and DT (spec/records.md: "line 4 holds NPTS and DT").

    A ``#`` line 4 is a comment of a plain-text file, never an AT2 header.
    """
    line = lines[NPTS_LINE - 1] if len(lines) >= NPTS_LINE else ""
    return not line.lstrip().startswith("#") and find_npts_dt(line) is not None


def _check_units_line(lines: list[str], *, file: str) -> None:
    """Line 3 must say the values are in g (``UNITS OF G``)."""
    line = lines[UNITS_LINE - 1] if len(lines) >= UNITS_LINE else ""
    if not _UNITS_OF_G.search(line):
        raise InputError(
            "an AT2 file must hold accelerations in g",
            file=file,
            where=f"line {UNITS_LINE}",
            value=line.strip(),
            allowed="a line 3 with 'UNITS OF G'",
        )


def _read_npts_dt(lines: list[str], *, file: str) -> tuple[int, float]:
    """NPTS and DT [s] from line 4."""
    where = f"line {NPTS_LINE}"
    line = lines[NPTS_LINE - 1] if len(lines) >= NPTS_LINE else ""
    tokens = find_npts_dt(line)
    if tokens is None:
        raise InputError(
            "no NPTS and DT in the AT2 header",
            file=file,
            where=where,
            value=line.strip(),
            allowed=LINE4_ALLOWED,
        )
    npts = parse_count(tokens[0], file=file, where=f"{where} (NPTS)")
    dt_token = tokens[1].upper().replace("D", "E")  # Fortran D exponent
    dt = parse_number(dt_token, file=file, where=f"{where} (DT)")
    return npts, check_dt(dt, file=file, where=f"{where} (DT)")


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
    npts, dt = _read_npts_dt(lines, file=source)
    values = read_values(lines[HEADER_LINES:], first_line=HEADER_LINES + 1, file=source)
    check_count(values, npts, file=source, where=f"line {NPTS_LINE} (NPTS)")
    return uniform_record(
        values, dt=dt, unit=AccelUnit.G, fmt=RecordFormat.AT2, name=name, source=source
    )
