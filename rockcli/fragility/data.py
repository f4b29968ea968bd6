"""Reading a fragility data set a user already has (`rock fragility fit DATA.csv`).

A CSV file with a header row:

- MSA: columns ``im``, ``runs``, ``exceedances`` — at each intensity level, the runs made and
  how many reached the damage state;
- IDA: a column ``im`` — each record's intensity at which the damage state is first reached.

Other columns are ignored; blank lines and lines starting with ``#`` are skipped. Every bad
cell is an InputError naming the file, the line, the value and what is allowed.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass

import numpy as np

from rockcli.errors import InputError
from rockcli.textfile import TOML_LIMIT, read_text

#: Columns each method needs.
COLUMNS = {"msa": ("im", "runs", "exceedances"), "ida": ("im",)}
#: What an intensity may be.
IM_ALLOWED = "a finite number > 0 (the intensity measure, in its unit)"


@dataclass(frozen=True)
class FragilityData:
    """A data set: the intensities, and for MSA the runs and exceedances at each."""

    file: str
    method: str
    im: np.ndarray
    runs: np.ndarray | None = None
    exceedances: np.ndarray | None = None


def read_data(path: str, method: str) -> FragilityData:
    """The data set of a CSV file for ``method`` ("msa" or "ida"); InputError otherwise."""
    text = read_text(path, "fragility data file", TOML_LIMIT)
    lines = [(k + 1, line) for k, line in enumerate(text.splitlines())
             if line.strip() and not line.lstrip().startswith("#")]  # fmt: skip
    if not lines:
        raise InputError("no header row", file=path, allowed=_header_allowed(method))
    rows = list(csv.reader(io.StringIO("\n".join(line for _, line in lines))))
    header = [cell.strip() for cell in rows[0]]
    missing = [c for c in COLUMNS[method] if c not in header]
    if missing:
        raise InputError(f"no column {missing[0]!r}", file=path, where=f"line {lines[0][0]}",
                         value=",".join(header), allowed=_header_allowed(method))  # fmt: skip
    where = {c: header.index(c) for c in COLUMNS[method]}
    values: dict[str, list[float]] = {c: [] for c in COLUMNS[method]}
    for (number, _), row in zip(lines[1:], rows[1:], strict=True):
        for column, index in where.items():
            cell = row[index].strip() if index < len(row) else ""
            values[column].append(_number(cell, column, path, number))
    if len(values["im"]) < 2:
        raise InputError("fewer than two data rows", file=path,
                         allowed="two or more rows under the header")  # fmt: skip
    im = np.array(values["im"])
    if method == "ida":
        return FragilityData(path, method, im)
    runs, exceed = np.array(values["runs"]), np.array(values["exceedances"])
    for k, (n, z) in enumerate(zip(runs, exceed, strict=True)):
        if z > n:
            raise InputError("more exceedances than runs", file=path,
                             where=f"line {lines[k + 1][0]}", value=f"{z:g} of {n:g}",
                             allowed="0 to the runs of the level")  # fmt: skip
    return FragilityData(path, method, im, runs, exceed)


def _number(cell: str, column: str, path: str, line: int) -> float:
    """A cell as a number of its column's kind (InputError naming the line otherwise)."""
    whole = column in ("runs", "exceedances")
    allowed = (
        IM_ALLOWED if column == "im" else
        "a whole number ≥ 1" if column == "runs" else "a whole number ≥ 0"
    )  # fmt: skip
    try:
        value = float(cell)
    except ValueError:
        value = math.nan
    ok = math.isfinite(value) and (value > 0.0 if column == "im" else value >= 0.0)
    if whole:
        ok = ok and value == round(value) and (value >= 1.0 or column == "exceedances")
    if not ok:
        raise InputError(f"column {column}: not a usable value", file=path,
                         where=f"line {line}", value=cell[:40], allowed=allowed)  # fmt: skip
    return value


def _header_allowed(method: str) -> str:
    return "a header row with the columns " + ", ".join(COLUMNS[method]) + f" ({method})"
