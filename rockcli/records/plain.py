"""Plain-text records: numbers only, one column (acceleration) or two (time, acceleration).

Layout (spec/records.md, table "What rock reads"): comment lines start with ``#``; values are
blank-separated; the unit is declared by a ``# units: m/s2`` comment line before the data, or
given by the caller (``--units``; the two must agree), else g is assumed; a one-column file
needs the time step (``--dt``). The time column must increase strictly; a non-uniform step is
allowed and noted. :func:`format_plain` writes the two-column form back with exact floats, its
unit (``# units: g``) and its warnings (``# warning:``, read back as warnings).
"""

from __future__ import annotations

import re
from dataclasses import replace
from decimal import Decimal
from typing import NamedTuple

import numpy as np

from rockcli.errors import InputError
from rockcli.records.kinds import RecordFormat
from rockcli.records.lines import (
    check_dt,
    check_last_number,
    check_time_axis,
    finish_record,
    is_number,
    number_shape,
    parse_count,
    parse_number,
    split_lines,
    uniform_record,
)
from rockcli.records.record import Record
from rockcli.units import AccelUnit, parse_unit

COMMENT = "#"
#: Relative spread of the time steps below which a two-column record counts as uniform.
UNIFORM_RTOL = 1e-9
#: The sample count in a comment line (``# npts: 1201``, written by ``rock record convert``).
_NPTS_COMMENT = re.compile(r"#\s*npts\s*:\s*(\S+)\s*", re.IGNORECASE | re.ASCII)
#: The unit in a comment line (``# units: m/s2``; ``unit``, ``=`` and any case accepted).
_UNITS_COMMENT = re.compile(r"#\s*units?\s*[:=]\s*(.*?)\s*", re.IGNORECASE | re.ASCII)
#: A warning in a comment line (``# warning: ...``, written by ``rock record convert``).
WARNING_COMMENT = "# warning:"
#: Longest comment line searched for ``# npts:`` or ``# units:`` [characters] (keeps the
#: patterns linear).
MAX_COMMENT_CHARS = 200
#: Digits of time written by :func:`format_plain` beyond those of dt, never more than this.
MAX_TIME_DECIMALS = 17


class Row(NamedTuple):
    """One data line: its number in the file, its numbers and their tokens."""

    number: int
    values: list[float]
    tokens: list[str]


def _is_data(line: str) -> bool:
    """A line that is neither blank nor a comment."""
    stripped = line.strip()
    return bool(stripped) and not stripped.startswith(COMMENT)


def looks_like_plain(lines: list[str]) -> bool:
    """True when the first data line holds only numbers (of the strict grammar)."""
    first = next((line for line in lines if _is_data(line)), None)
    return first is not None and all(is_number(token) for token in first.split())


def _row(number: int, line: str, *, file: str) -> Row:
    tokens = line.split()
    values = [parse_number(token, file=file, where=f"line {number}") for token in tokens]
    return Row(number, values, tokens)


def read_rows(lines: list[str], *, file: str) -> list[Row]:
    """(line number, numbers, tokens) of every data line, all with 1 or 2 columns alike.

    The last number is checked for a cut (:func:`rockcli.records.lines.check_last_number`,
    column by column: a time column and an acceleration column print differently).
    """
    rows = [_row(number, line, file=file) for number, line in enumerate(lines, 1) if _is_data(line)]
    if not rows:
        raise InputError("no numbers in the file", file=file, allowed="one or two columns")
    _check_columns(rows, file=file)
    column = [row.tokens[-1] for row in rows]
    check_last_number(
        [number_shape(token) for token in column],
        unterminated=_is_data(lines[-1]),
        file=file,
        where=f"line {rows[-1].number}",
        token=column[-1],
    )
    return rows


def declared_count(lines: list[str], *, file: str) -> int | None:
    """The ``# npts: N`` of the comment lines before the data, if any."""
    for number, line in enumerate(lines, start=1):
        if _is_data(line):
            return None
        found = _NPTS_COMMENT.fullmatch(line.strip()[:MAX_COMMENT_CHARS])
        if found:
            return parse_count(found.group(1), file=file, where=f"line {number} (# npts)")
    return None


def _header(lines: list[str]) -> list[tuple[int, str]]:
    """(line number, stripped text) of the comment lines before the first data line."""
    found = []
    for number, line in enumerate(lines, start=1):
        if _is_data(line):
            break
        if line.strip():
            found.append((number, line.strip()))
    return found


class DeclaredUnit(NamedTuple):
    """The unit a ``# units:`` line declares, where, and as written."""

    unit: AccelUnit
    where: str
    token: str


def declared_unit(lines: list[str], *, file: str) -> DeclaredUnit | None:
    """The unit of the ``# units:`` lines before the data, if any (they must agree).

    The spelling is that of ``--units`` (:func:`rockcli.units.parse_unit`: g, m/s2, m/s^2,
    m/s², cm/s2, cm/s^2, gal…, any case); an unknown unit is an error naming the line.
    """
    declared: DeclaredUnit | None = None
    for number, text in _header(lines):
        found = _UNITS_COMMENT.fullmatch(text[:MAX_COMMENT_CHARS])
        if found is None:
            continue
        where = f"line {number} (# units)"
        unit = DeclaredUnit(
            parse_unit(found.group(1), file=file, where=where), where, found.group(1)
        )
        if declared is not None and unit.unit is not declared.unit:
            raise InputError(
                f"a second '# units:' line contradicts the {declared.where}",
                file=file,
                where=where,
                value=unit.token,
                allowed=f"one unit for the file ({declared.token}, as the first line says)",
            )
        declared = declared or unit
    return declared


def record_unit(
    option: str | AccelUnit | None, declared: DeclaredUnit | None, *, file: str
) -> tuple[AccelUnit, bool]:
    """(the unit to read the values in, whether it was declared) from --units and the file.

    A ``# units:`` line and ``--units`` must agree (a contradiction is an error naming both:
    which of them is the slip cannot be told); without either, g is assumed (not declared).
    """
    given = parse_unit(str(option), file=file, where="units") if option else None
    if declared is None:
        return (given or AccelUnit.G), given is not None
    if given is not None and given is not declared.unit:
        raise InputError(
            f"--units {given} contradicts the file's '# units: {declared.token}' line",
            file=file,
            where=declared.where,
            value=str(option),
            allowed=f"no --units (the file declares {declared.unit}), or --units {declared.unit}",
        )
    return declared.unit, True


def header_warnings(lines: list[str]) -> tuple[str, ...]:
    """The ``# warning:`` lines before the data (a file rock wrote keeps its warnings)."""
    size = len(WARNING_COMMENT)
    return tuple(
        text[size:].strip()
        for _, text in _header(lines)
        if text[:size].lower() == WARNING_COMMENT and text[size:].strip()
    )


def _check_declared(rows: list[Row], declared: int | None, *, file: str) -> None:
    """A file that declares ``# npts:`` must hold that many samples (a cut file does not)."""
    if declared is not None and len(rows) != declared:
        raise InputError(
            f"{len(rows)} samples read but the header declares {declared} (a cut file?)",
            file=file,
            where="# npts",
            value=len(rows),
            allowed=f"exactly {declared} samples",
        )


def _check_columns(rows: list[Row], *, file: str) -> None:
    """The first data line has 1 or 2 columns, and every other line as many."""
    first = rows[0]
    if len(first.values) > 2:
        raise InputError(
            f"{len(first.values)} columns",
            file=file,
            where=f"line {first.number}",
            value=len(first.values),
            allowed="1 column (acceleration) or 2 (time, acceleration)",
        )
    for row in rows:
        if len(row.values) != len(first.values):
            raise InputError(
                f"{len(row.values)} columns where the first data line has {len(first.values)}",
                file=file,
                where=f"line {row.number}",
                value=len(row.values),
                allowed=f"{len(first.values)} on every line",
            )


def _check_increasing(time: np.ndarray, rows: list[Row], *, file: str) -> None:
    """Time must increase strictly (spec/records.md, "Checks on every record")."""
    bad = np.flatnonzero(np.diff(time) <= 0.0)
    if bad.size:
        before, row = rows[bad[0]], rows[bad[0] + 1]
        raise InputError(
            "time does not increase",
            file=file,
            where=f"line {row.number}",
            value=row.values[0],
            allowed=f"a time greater than {before.values[0]!r} s (the line before)",
        )


def _rezeroed(rows: list[Row], *, file: str) -> tuple[np.ndarray, tuple[str, ...]]:
    """The time column re-zeroed at its first value, subtracted exactly (in decimal).

    A record with absolute times (Unix epoch, t ≈ 1.7e9 s) keeps only ~2e-7 s of float
    resolution: the 1 ms steps of a 1 kHz record would come out uneven, and every check that
    compares a step to a tolerance would depend on the absolute time. Subtracting the first
    time in decimal, before the conversion to float, gives the steps exactly as printed.
    """
    first = rows[0].tokens[0]
    time = np.array([row.values[0] for row in rows], dtype=float)
    with np.errstate(over="ignore", invalid="ignore"):
        _check_increasing(time, rows, file=file)
    if time[0] == 0.0:
        return time, ()
    start = Decimal(first)
    shifted = np.array([float(Decimal(row.tokens[0]) - start) for row in rows], dtype=float)
    return shifted, (f"time re-zeroed: the file's time starts at {first} s",)


def _time_step(time: np.ndarray) -> tuple[float, tuple[str, ...]]:
    """dt [s] of a time column, and a note when the spacing is not uniform.

    Uniform (every step within UNIFORM_RTOL of the mean): dt = span/(n − 1), which is not
    disturbed by the rounding of each difference. Otherwise dt is the median step, noted.
    """
    steps = np.diff(time)
    mean = float((time[-1] - time[0]) / steps.size)
    if np.allclose(steps, mean, rtol=UNIFORM_RTOL, atol=0.0):
        return mean, ()
    dt = float(np.median(steps))
    note = (
        f"non-uniform time step: dt = {dt:g} s is the median spacing "
        f"(min {steps.min():g} s, max {steps.max():g} s)"
    )
    return dt, (note,)


def _two_column_record(
    rows: list[Row], unit: AccelUnit, *, declared: bool, name: str, source: str
) -> Record:
    """A Record from (t, a) rows: time strictly increasing and re-zeroed, dt = median spacing."""
    if len(rows) < 2:
        raise InputError(
            "a two-column record needs at least 2 samples", file=source, value=len(rows)
        )
    time, notes = _rezeroed(rows, file=source)
    check_time_axis(time, file=source)
    accel = np.array([row.values[1] for row in rows], dtype=float) * unit.to_g
    dt, step_notes = _time_step(time)
    check_dt(dt, file=source, where="time column")
    return finish_record(
        Record(
            name=name,
            source=source,
            format=str(RecordFormat.PLAIN),
            time=time,
            accel=accel,
            dt=dt,
            unit=str(unit),
            notes=(*notes, *step_notes),
            unit_declared=declared,
        )
    )


def _one_column_record(
    rows: list[Row], unit: AccelUnit, dt: float | None, *, declared: bool, name: str, source: str
) -> Record:
    """A Record from one value a line, sampled at t = i·dt."""
    if dt is None:
        raise InputError(
            "a one-column file needs the time step",
            file=source,
            where="dt",
            allowed="dt > 0 [s] (--dt)",
        )
    values = np.array([row.values[0] for row in rows], dtype=float)
    dt = check_dt(dt, file=source, where="dt")
    return uniform_record(
        values,
        dt=dt,
        unit=unit,
        fmt=RecordFormat.PLAIN,
        name=name,
        source=source,
        unit_declared=declared,
    )


def parse_plain(
    text: str,
    *,
    name: str = "record",
    source: str = "<text>",
    dt: float | None = None,
    units: str | AccelUnit | None = None,
) -> Record:
    """Read a plain-text record (one or two columns) into a Record in g.

    Args:
        text: the whole file.
        name: label of the record (usually the file stem).
        source: the file as the user named it (used in every error).
        dt: time step [s]; required for one column, refused for two (the time column rules).
        units: unit of the acceleration column ("g", "m/s2", "cm/s2"); None: the file's
            ``# units:`` line, else g (assumed, not declared: a PGA above 1 g warns).

    Raises:
        InputError: a token that is not a finite number, ragged columns, time not strictly
            increasing, a missing or superfluous dt, an unknown unit, ``units`` that
            contradicts the file's ``# units:`` line, a count different from the ``# npts:``
            comment, a last number that may be cut.
    """
    lines = split_lines(text)
    unit, declared = record_unit(units, declared_unit(lines, file=source), file=source)
    rows = read_rows(lines, file=source)
    _check_declared(rows, declared_count(lines, file=source), file=source)
    if len(rows[0].values) == 1:
        record = _one_column_record(rows, unit, dt, declared=declared, name=name, source=source)
    elif dt is not None:
        raise InputError(
            "dt is given by the time column of a two-column file",
            file=source,
            where="dt",
            value=dt,
            allowed="no dt for a two-column file",
        )
    else:
        record = _two_column_record(rows, unit, declared=declared, name=name, source=source)
    carried = header_warnings(lines)
    if not carried:
        return record
    return replace(record, warnings=tuple(dict.fromkeys((*carried, *record.warnings))))


def _one_line(text: str) -> str:
    """Text on a single line (for a ``#`` header entry)."""
    return " ".join(text.split())


def time_decimals(dt: float) -> int:
    """Decimals that write every multiple of dt exactly as dt's shortest form has them."""
    exponent = Decimal(repr(float(dt))).as_tuple().exponent
    return min(max(0, -int(exponent)), MAX_TIME_DECIMALS) if isinstance(exponent, int) else 0


def time_strings(record: Record) -> list[str]:
    """The times as written: i·dt with dt's decimals when uniform from 0, else exact repr.

    ``0.1*3`` is 0.30000000000000004 in floats; written with dt's decimals it is ``0.3``,
    which reads back as the double nearest to 0.3. A non-uniform time column keeps ``repr``.
    """
    if record.time[0] != 0.0 or not record.uniform:
        return [repr(float(t)) for t in record.time]
    digits = time_decimals(record.dt)
    return [f"{i * record.dt:.{digits}f}" for i in range(record.npts)]


def format_plain(record: Record) -> str:
    """The two-column plain text of a record: a ``#`` header, then ``t a`` [s, g] a line.

    Accelerations are written with ``repr`` (shortest exact form), so :func:`parse_plain`
    reads them back bit for bit; times as :func:`time_strings` writes them.
    """
    header = [
        "# rock record: time [s], acceleration [g]",
        f"# name: {_one_line(record.name)}",
        f"# source: {_one_line(record.source)}",
        "# units: g",
        f"# dt: {record.dt!r}",
        f"# npts: {record.npts}",
        *(f"# note: {_one_line(note)}" for note in record.notes),
        *(f"# warning: {_one_line(warning)}" for warning in record.warnings),
    ]
    times = time_strings(record)
    body = (f"{t} {float(a)!r}" for t, a in zip(times, record.accel, strict=True))
    return "\n".join([*header, *body]) + "\n"
