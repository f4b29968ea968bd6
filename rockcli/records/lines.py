"""Reading numbers out of record text, with errors that name the file, the line and the token.

Shared by every reader (spec/records.md, "Checks on every record"): line ends of any kind,
tokens that are not numbers, NaN/inf, the declared count, dt > 0. Nothing is truncated.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable

import numpy as np

from rockcli.errors import InputError
from rockcli.records.record import Record
from rockcli.units import AccelUnit

#: A function that cuts one data line into number tokens.
Splitter = Callable[[str], list[str]]

#: What a value in a data line may look like (shown in errors).
NUMBER_ALLOWED = "a finite decimal number such as -.6403182E-02"

#: Time tolerance, as a fraction of dt, for an edge (window, pulse end) that falls on a sample.
EDGE_TOL = 1e-9


def check_positive(value: float, *, where: str, unit: str) -> float:
    """Return value if it is finite and > 0; InputError naming the argument otherwise."""
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(
            "must be greater than 0", where=where, value=value, allowed=f"a number > 0 {unit}"
        )
    return value


def split_lines(text: str) -> list[str]:
    """Split text into lines for LF, CRLF, CR CR LF and lone-CR line ends.

    spec/records.md: "line ends may be LF, CRLF or even ``\\r\\r\\n``" (NORTHR_ARL360_CRCRLF.AT2);
    a plain ``splitlines`` would turn each CR CR LF into two lines and shift every line number.
    """
    text = text.replace("\r\r\n", "\n").replace("\r\n", "\n").replace("\r", "\n")
    return text.split("\n")


def parse_number(token: str, *, file: str, where: str) -> float:
    """One finite float from a token; InputError naming where it is otherwise."""
    try:
        value = float(token)
    except ValueError:
        raise InputError(
            "not a number", file=file, where=where, value=token, allowed=NUMBER_ALLOWED
        ) from None
    if not math.isfinite(value):
        raise InputError(
            "not a finite number", file=file, where=where, value=token, allowed=NUMBER_ALLOWED
        )
    return value


def parse_count(token: str, *, file: str, where: str) -> int:
    """A declared number of samples: an integer ≥ 1."""
    try:
        count = int(token.strip())
    except ValueError:
        count = 0
    if count < 1:
        raise InputError(
            "the number of samples must be a whole number ≥ 1",
            file=file,
            where=where,
            value=token.strip(),
            allowed="an integer ≥ 1",
        )
    return count


def check_dt(dt: float, *, file: str | None, where: str | None) -> float:
    """Return dt if it is a finite number > 0 [s]; InputError otherwise."""
    if not (math.isfinite(dt) and dt > 0.0):
        raise InputError(
            "the time step must be greater than 0",
            file=file,
            where=where,
            value=dt,
            allowed="dt > 0 [s]",
        )
    return dt


def fixed_fields(line: str, width: int) -> list[str]:
    """Cut a line into fields of ``width`` characters (trailing blanks ignored).

    Fixed-width files let negative numbers touch (``-3.99E-09-4.00E-09``, spec/records.md,
    cor.acc), so such lines are sliced, never split on blanks.
    """
    body = line.rstrip()
    return [body[i : i + width].strip() for i in range(0, len(body), width)]


def read_values(
    lines: Iterable[str], *, first_line: int, file: str, split: Splitter = str.split
) -> np.ndarray:
    """Every number in the data lines, in order; blank lines are skipped.

    Args:
        lines: the data lines (after the header).
        first_line: the 1-based number of the first of them in the file (for errors).
        file: the file name, for errors.
        split: cuts a line into tokens (blank-separated by default).
    """
    values: list[float] = []
    for number, line in enumerate(lines, start=first_line):
        where = f"line {number}"
        values.extend(parse_number(token, file=file, where=where) for token in split(line))
    return np.asarray(values, dtype=float)


def check_count(values: np.ndarray, declared: int, *, file: str, where: str) -> None:
    """The number of values read must equal the declared count (spec/records.md, "Checks")."""
    if values.size != declared:
        raise InputError(
            f"{values.size} values read but the header declares {declared}",
            file=file,
            where=where,
            value=values.size,
            allowed=f"exactly {declared} values",
        )


def uniform_record(
    values: np.ndarray,
    *,
    dt: float,
    unit: AccelUnit,
    fmt: str,
    name: str,
    source: str,
    notes: tuple[str, ...] = (),
) -> Record:
    """A Record sampled at t = i·dt, with values converted from ``unit`` to g."""
    return Record(
        name=name,
        source=source,
        format=str(fmt),
        time=np.arange(values.size) * dt,
        accel=values * unit.to_g,
        dt=dt,
        unit=str(unit),
        notes=notes,
    )
