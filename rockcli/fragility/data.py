"""Reading a fragility data set a user already has (`rock fragility fit DATA.csv`).

A CSV file with a header row:

- MSA: columns ``im``, ``runs``, ``exceedances`` — at each intensity level, the runs made and
  how many reached the damage state;
- IDA: a column ``im`` — each record's intensity at which the damage state is first reached;
  and optionally a column ``censored`` (0 or 1, false or true): 1 for a record that did not
  reach the state up to ``im``, the highest intensity it was run at (right-censored there).

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
#: The words of the censored column.
FLAGS = {"0": 0.0, "1": 1.0, "false": 0.0, "true": 1.0}
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
    #: IDA: True for a right-censored record (its im is the highest intensity run).
    censored: np.ndarray | None = None


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
    wanted = [*COLUMNS[method], *(["censored"] if method == "ida" and "censored" in header else [])]
    where = {c: header.index(c) for c in wanted}
    values: dict[str, list[float]] = {c: [] for c in wanted}
    for (number, _), row in zip(lines[1:], rows[1:], strict=True):
        for column, index in where.items():
            cell = row[index].strip() if index < len(row) else ""
            values[column].append(_number(cell, column, path, number))
    if len(values["im"]) < 2:
        raise InputError("fewer than two data rows", file=path,
                         allowed="two or more rows under the header")  # fmt: skip
    im = np.array(values["im"])
    if method == "ida":
        censored = np.array(values["censored"], dtype=bool) if "censored" in values else None
        return FragilityData(path, method, im, censored=censored)
    runs, exceed = np.array(values["runs"]), np.array(values["exceedances"])
    for k, (n, z) in enumerate(zip(runs, exceed, strict=True)):
        if z > n:
            raise InputError("more exceedances than runs", file=path,
                             where=f"line {lines[k + 1][0]}", value=f"{z:g} of {n:g}",
                             allowed="0 to the runs of the level")  # fmt: skip
    return FragilityData(path, method, im, runs, exceed)


def _number(cell: str, column: str, path: str, line: int) -> float:
    """A cell as a number of its column's kind (InputError naming the line otherwise)."""
    if column == "censored":
        flag = FLAGS.get(cell.lower())
        if flag is None:
            raise InputError("column censored: not a usable value", file=path,
                             where=f"line {line}", value=cell[:40],
                             allowed="0 or 1 (false or true)")  # fmt: skip
        return flag
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
