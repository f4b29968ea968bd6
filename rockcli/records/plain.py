"""Plain-text records: numbers only, one column (acceleration) or two (time, acceleration).

Layout (spec/records.md, table "What rock reads"): comment lines start with ``#``; values are
blank-separated; the unit is given by the caller (``--units``, default g) and a one-column file
needs the time step (``--dt``). The time column must increase strictly; a non-uniform step is
allowed and noted. :func:`format_plain` writes the two-column form back with exact floats.
"""

from __future__ import annotations

import numpy as np

from rockcli.errors import InputError
from rockcli.records.kinds import RecordFormat
from rockcli.records.lines import check_dt, parse_number, split_lines, uniform_record
from rockcli.records.record import Record
from rockcli.units import AccelUnit, parse_unit

COMMENT = "#"
#: Relative spread of the time steps below which a two-column record counts as uniform.
UNIFORM_RTOL = 1e-9

Row = tuple[int, list[float]]


def _is_data(line: str) -> bool:
    """A line that is neither blank nor a comment."""
    stripped = line.strip()
    return bool(stripped) and not stripped.startswith(COMMENT)


def looks_like_plain(lines: list[str]) -> bool:
    """True when the first data line holds only numbers."""
    first = next((line for line in lines if _is_data(line)), None)
    if first is None:
        return False
    try:
        [float(token) for token in first.split()]
    except ValueError:
        return False
    return True


def read_rows(lines: list[str], *, file: str) -> list[Row]:
    """(line number, numbers) of every data line, all with the same number (1 or 2) of columns."""
    rows = [
        (number, [parse_number(tok, file=file, where=f"line {number}") for tok in line.split()])
        for number, line in enumerate(lines, start=1)
        if _is_data(line)
    ]
    if not rows:
        raise InputError("no numbers in the file", file=file, allowed="one or two columns")
    _check_columns(rows, file=file)
    return rows


def _check_columns(rows: list[Row], *, file: str) -> None:
    """The first data line has 1 or 2 columns, and every other line as many."""
    first_line, first = rows[0]
    if len(first) > 2:
        raise InputError(
            f"{len(first)} columns",
            file=file,
            where=f"line {first_line}",
            value=len(first),
            allowed="1 column (acceleration) or 2 (time, acceleration)",
        )
    for number, values in rows:
        if len(values) != len(first):
            raise InputError(
                f"{len(values)} columns where the first data line has {len(first)}",
                file=file,
                where=f"line {number}",
                value=len(values),
                allowed=f"{len(first)} on every line",
            )


def _check_increasing(time: np.ndarray, rows: list[Row], *, file: str) -> None:
    """Time must increase strictly (spec/records.md, "Checks on every record")."""
    bad = np.flatnonzero(np.diff(time) <= 0.0)
    if bad.size:
        (_, before), (number, values) = rows[bad[0]], rows[bad[0] + 1]
        raise InputError(
            "time does not increase",
            file=file,
            where=f"line {number}",
            value=values[0],
            allowed=f"a time greater than {before[0]!r} s (the line before)",
        )


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


def _two_column_record(rows: list[Row], unit: AccelUnit, *, name: str, source: str) -> Record:
    """A Record from (t, a) rows: time strictly increasing, dt = median spacing."""
    if len(rows) < 2:
        raise InputError(
            "a two-column record needs at least 2 samples", file=source, value=len(rows)
        )
    table = np.array([values for _, values in rows], dtype=float)
    time, accel = table[:, 0], table[:, 1] * unit.to_g
    _check_increasing(time, rows, file=source)
    dt, notes = _time_step(time)
    return Record(
        name=name,
        source=source,
        format=str(RecordFormat.PLAIN),
        time=time,
        accel=accel,
        dt=dt,
        unit=str(unit),
        notes=notes,
    )


def _one_column_record(
    rows: list[Row], unit: AccelUnit, dt: float | None, *, name: str, source: str
) -> Record:
    """A Record from one value a line, sampled at t = i·dt."""
    if dt is None:
        raise InputError(
            "a one-column file needs the time step",
            file=source,
            where="dt",
            allowed="dt > 0 [s] (--dt)",
        )
    values = np.array([values[0] for _, values in rows], dtype=float)
    dt = check_dt(dt, file=source, where="dt")
    return uniform_record(
        values, dt=dt, unit=unit, fmt=RecordFormat.PLAIN, name=name, source=source
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
        units: unit of the acceleration column ("g", "m/s2", "cm/s2"); default g.

    Raises:
        InputError: a token that is not a finite number, ragged columns, time not strictly
            increasing, a missing or superfluous dt, an unknown unit.
    """
    unit = parse_unit(str(units or AccelUnit.G), file=source, where="units")
    rows = read_rows(split_lines(text), file=source)
    if len(rows[0][1]) == 1:
        return _one_column_record(rows, unit, dt, name=name, source=source)
    if dt is not None:
        raise InputError(
            "dt is given by the time column of a two-column file",
            file=source,
            where="dt",
            value=dt,
            allowed="no dt for a two-column file",
        )
    return _two_column_record(rows, unit, name=name, source=source)


def _one_line(text: str) -> str:
    """Text on a single line (for a ``#`` header entry)."""
    return " ".join(text.split())


def format_plain(record: Record) -> str:
    """The two-column plain text of a record: a ``#`` header, then ``t a`` [s, g] a line.

    Floats are written with ``repr`` (shortest exact form), so :func:`parse_plain` reads back
    exactly the same time and acceleration arrays.
    """
    header = [
        "# rock record: time [s], acceleration [g]",
        f"# name: {_one_line(record.name)}",
        f"# source: {_one_line(record.source)}",
        "# units: g",
        f"# dt: {record.dt!r}",
        f"# npts: {record.npts}",
        *(f"# note: {_one_line(note)}" for note in record.notes),
    ]
    body = (f"{float(t)!r} {float(a)!r}" for t, a in zip(record.time, record.accel, strict=True))
    return "\n".join([*header, *body]) + "\n"
