"""ITACA/ESD ``cor.acc`` records: ten header lines, then fixed-width 5E14.7 fields in m/s².

Layout (spec/records.md, table "What rock reads"; the L'Aquila AQV file of gmpe-smtk's test
data): ``label : value`` header lines (``Time Increment (s)``, ``Number of Data``, …) filling the
first ten lines, the last a title (``Accelaration time series in m/s/s``); then five
14-character fields a line. Negative numbers touch their neighbours (``-4.07E-09-4.09E-09``),
so lines are sliced by width, never split on blanks.
"""

from __future__ import annotations

from functools import partial

from rockcli.errors import InputError
from rockcli.records.kinds import RecordFormat
from rockcli.records.lines import (
    check_count,
    check_dt,
    fixed_fields,
    parse_count,
    parse_number,
    read_values,
    split_lines,
    uniform_record,
)
from rockcli.records.record import Record
from rockcli.units import AccelUnit

HEADER_LINES = 10
FIELD_WIDTH = 14
DT_LABEL = "time increment (s)"
COUNT_LABEL = "number of data"
#: spec/records.md: cor.acc values are in m/s².
UNIT = AccelUnit.M_S2


def read_header(lines: list[str]) -> dict[str, str]:
    """``label : value`` pairs of the first ten lines (labels lower-case; split on 1st colon)."""
    pairs = (line.split(":", 1) for line in lines[:HEADER_LINES] if ":" in line)
    return {label.strip().lower(): value.strip() for label, value in pairs}


def looks_like_coracc(lines: list[str]) -> bool:
    """True when the header names the time increment and the number of data."""
    header = read_header(lines)
    return DT_LABEL in header and COUNT_LABEL in header


def _header_value(header: dict[str, str], label: str, *, file: str) -> str:
    """A required header value; InputError naming the label when missing or empty."""
    value = header.get(label, "")
    if not value:
        raise InputError(
            "missing header value",
            file=file,
            where=label.capitalize(),
            value=None,
            allowed=f"'{label.capitalize()} : <value>' in the first {HEADER_LINES} lines",
        )
    return value


def parse_coracc(text: str, *, name: str = "record", source: str = "<text>") -> Record:
    """Read the text of an ITACA/ESD ``cor.acc`` file into a Record in g.

    Args:
        text: the whole file.
        name: label of the record (usually the file stem).
        source: the file as the user named it (used in every error).

    Raises:
        InputError: a missing or bad header value, a field that is not a finite number, or a
            number of values different from ``Number of Data``.
    """
    lines = split_lines(text)
    header = read_header(lines)
    dt_where, count_where = DT_LABEL.capitalize(), COUNT_LABEL.capitalize()
    dt_text = _header_value(header, DT_LABEL, file=source)
    dt = check_dt(parse_number(dt_text, file=source, where=dt_where), file=source, where=dt_where)
    count_text = _header_value(header, COUNT_LABEL, file=source)
    count = parse_count(count_text, file=source, where=count_where)
    split = partial(fixed_fields, width=FIELD_WIDTH)
    values = read_values(
        lines[HEADER_LINES:], first_line=HEADER_LINES + 1, file=source, split=split
    )
    check_count(values, count, file=source, where=count_where)
    return uniform_record(
        values, dt=dt, unit=UNIT, fmt=RecordFormat.CORACC, name=name, source=source
    )
