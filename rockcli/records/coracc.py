"""ITACA/ESD ``cor.acc`` records: ten header lines, then fixed-width 5E14.7 fields in m/s².

Layout (spec/records.md, table "What rock reads"; the L'Aquila AQV file of gmpe-smtk's test
data): ``label : value`` header lines (``Time Increment (s)``, ``Number of Data``, …) filling the
first ten lines, the last a title (``Accelaration time series in m/s/s``); then five
14-character fields a line. Negative numbers touch their neighbours (``-4.07E-09-4.09E-09``),
so lines are sliced by width, never split on blanks.
"""

from __future__ import annotations

import re
from functools import partial

from rockcli.errors import InputError
from rockcli.records.kinds import RecordFormat
from rockcli.records.lines import (
    Origin,
    check_count,
    check_declared_pga,
    check_dt,
    fixed_fields,
    parse_count,
    parse_number,
    read_tokens,
    split_lines,
    uniform_record,
)
from rockcli.records.record import Record
from rockcli.units import AccelUnit

HEADER_LINES = 10
FIELD_WIDTH = 14
DT_LABEL = "time increment (s)"
COUNT_LABEL = "number of data"
PGA_LABEL = "pga"
#: spec/records.md: cor.acc values are in m/s² (used when the header names no unit).
UNIT = AccelUnit.M_S2
#: A unit of acceleration written in a header: ``m/s/s``, ``cm/s^2``, ``cm/s2``, ``m/s**2``.
#: The line is bounded (MAX_HEADER_CHARS) so the pattern stays linear.
_ACCEL_UNIT = re.compile(r"\b(cm|m)\s*/\s*s(?:\s*/\s*s|\s*\^\s*2|2|²|\*\*2)", re.IGNORECASE)
_GAL = re.compile(r"\bgal\b", re.IGNORECASE)
UNITS = {"m": AccelUnit.M_S2, "cm": AccelUnit.CM_S2}
MAX_HEADER_CHARS = 200
#: Header labels that name the record: event, station, component (in Origin's order).
ORIGIN_LABELS = ("event date & time", "station code / name", "orientation")


def read_header(lines: list[str]) -> dict[str, str]:
    """``label : value`` pairs of the first ten lines (labels lower-case; split on 1st colon)."""
    pairs = (line.split(":", 1) for line in lines[:HEADER_LINES] if ":" in line)
    return {label.strip().lower(): value.strip() for label, value in pairs}


def units_named(text: str) -> set[AccelUnit]:
    """The acceleration units a header line names (``m/s/s``, ``cm/s^2``, ``gal``)."""
    head = text[:MAX_HEADER_CHARS]
    found = {UNITS[match.group(1).lower()] for match in _ACCEL_UNIT.finditer(head)}
    return found | ({AccelUnit.CM_S2} if _GAL.search(head) else set())


def header_unit(lines: list[str], *, file: str) -> tuple[AccelUnit, tuple[str, ...]]:
    """The unit of the data, from the header's labels and title (m/s² when none is named).

    The ITACA title says ``Accelaration time series in m/s/s``; a file whose title or labels
    say cm/s/s is read in cm/s² (noted), and one that names both is refused.
    """
    named: set[AccelUnit] = set()
    for line in lines[:HEADER_LINES]:
        # A "Label : value" line names its unit in the label; free text (a station called
        # "Gal", a processing note "1 gal = 1 cm/s2") is not a unit declaration.
        label, colon, _ = line.partition(":")
        named |= units_named(label if colon else line)
    if len(named) > 1:
        raise InputError(
            "the header names two acceleration units",
            file=file,
            where=f"lines 1-{HEADER_LINES}",
            value=", ".join(sorted(named)),
            allowed="one unit (m/s/s or cm/s/s) in the labels and the title",
        )
    if named == {AccelUnit.CM_S2}:
        return AccelUnit.CM_S2, ("values read in cm/s² as the header states",)
    return UNIT, ()


def _pga_entry(header: dict[str, str]) -> tuple[str, str] | None:
    """(label, value) of the header's PGA line, if any."""
    for label, value in header.items():
        if label.startswith(PGA_LABEL) and value:
            return label, value
    return None


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
    unit, notes = header_unit(lines, file=source)
    split = partial(fixed_fields, width=FIELD_WIDTH)
    values, tokens = read_tokens(
        lines[HEADER_LINES:], first_line=HEADER_LINES + 1, file=source, split=split
    )
    check_count(values, count, file=source, where=count_where)
    pga = _pga_entry(header)
    if pga is not None:
        check_declared_pga(values, tokens, pga[1], file=source, where=pga[0].capitalize())
    origin = Origin(*(header.get(label, "")[:MAX_HEADER_CHARS] for label in ORIGIN_LABELS))
    return uniform_record(
        values,
        dt=dt,
        unit=unit,
        fmt=RecordFormat.CORACC,
        name=name,
        source=source,
        notes=notes,
        origin=origin,
    )
