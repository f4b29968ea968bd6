"""Reading a fragility data set a user already has (`rock fragility fit DATA.csv`).

A CSV file with a header row:

- MSA: columns ``im``, ``runs``, ``exceedances`` — at each intensity level, the runs made and
  how many reached the damage state;
- IDA: a column ``im`` — each record's intensity at which the damage state is first reached;
  and optionally a column ``censored`` (0 or 1, false or true): 1 for a record that did not
  reach the state up to ``im``, the highest intensity it was run at (right-censored there).

Other columns are ignored; blank lines and lines starting with ``#`` are skipped. Every bad
cell is an InputError naming the file, the line, the value and what is allowed.

Limits (docs/fragility.md, "Fitting a data set"): at most :data:`ROW_LIMIT` data rows; an
intensity finite, > 0 and at most :data:`IM_MAX` in the file's unit; runs and exceedances
whole numbers, 1 ≤ runs ≤ :data:`RUNS_MAX` and 0 ≤ exceedances ≤ runs. A row is one line (a
quoted cell does not run on to the next), and a line that is not a CSV row (e.g. a cell
longer than the csv module's 131 072 characters) is refused in one line too.
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
#: The most data rows a file may have: a hundred times an IDA's records (tens; FEMA P-695's
#: far-field set has 44) or an MSA's runs (5 to 20 stripes of tens of runs, one row a run
#: or a stripe). The fit and band of the largest file end within seconds and take about
#: 100 MB: 1–2 s, and up to 6 s for 10 000 IDA records nearly all censored, each at its own
#: intensity (the slowest: the band's bootstrap refits 1 000 resamples of them).
ROW_LIMIT = 10_000
#: The largest intensity, in the file's unit: above any PGA or Sa in g (a study's PGA is at
#: most 10 g) or in m/s², any PGV in cm/s, and 10 g in cm/s² (9 810).
IM_MAX = 1e4
#: The most runs at one MSA level (each a time history: a million is more than any study).
RUNS_MAX = 1_000_000
#: What an intensity may be.
IM_ALLOWED = f"a finite number > 0 and ≤ {IM_MAX:g} (the intensity measure, in its unit)"


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
    lines = _lines(text, path)
    if not lines:
        raise InputError("no header row", file=path, allowed=_header_allowed(method))
    header = [cell.strip() for cell in lines[0][1]]
    missing = [c for c in COLUMNS[method] if c not in header]
    if missing:
        raise InputError(f"no column {missing[0]!r}", file=path, where=f"line {lines[0][0]}",
                         value=",".join(header)[:80], allowed=_header_allowed(method))  # fmt: skip
    wanted = [*COLUMNS[method], *(["censored"] if method == "ida" and "censored" in header else [])]
    where = {c: header.index(c) for c in wanted}
    values: dict[str, list[float]] = {c: [] for c in wanted}
    for number, row in lines[1:]:
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
    for (number, _), n, z in zip(lines[1:], runs, exceed, strict=True):
        if z > n:
            raise InputError("more exceedances than runs", file=path, where=f"line {number}",
                             value=f"{z:g} of {n:g}",
                             allowed="0 to the runs of the level")  # fmt: skip
    return FragilityData(path, method, im, runs, exceed)


def _lines(text: str, path: str) -> list[tuple[int, list[str]]]:
    """The header and data rows of ``text``, each with its line number, one row a line
    (blank and ``#`` lines skipped); InputError for a line that is not a CSV row or for more
    than ROW_LIMIT data rows (read no further)."""
    rows: list[tuple[int, list[str]]] = []
    for k, line in enumerate(io.StringIO(text, newline=None), start=1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        if len(rows) > ROW_LIMIT:
            raise InputError(f"more than {ROW_LIMIT} data rows", file=path, where=f"line {k}",
                             allowed=f"at most {ROW_LIMIT} rows under the header")  # fmt: skip
        try:
            rows.append((k, next(csv.reader([line.rstrip("\n")]))))
        except csv.Error as exc:
            raise InputError(f"not a CSV row ({exc})", file=path, where=f"line {k}",
                             allowed="cells separated by commas, each up to 131 072 "
                             "characters") from None  # fmt: skip
    return rows


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
        f"a whole number from 1 to {RUNS_MAX:,}" if column == "runs" else
        f"a whole number from 0 to {RUNS_MAX:,}"
    )  # fmt: skip
    try:
        value = float(cell)
    except ValueError:
        value = math.nan
    ok = math.isfinite(value) and (0.0 < value <= IM_MAX if column == "im" else value >= 0.0)
    if whole:
        ok = ok and value == round(value) and (value >= 1.0 or column == "exceedances")
        ok = ok and value <= RUNS_MAX
    if not ok:
        raise InputError(f"column {column}: not a usable value", file=path,
                         where=f"line {line}", value=cell[:40], allowed=allowed)  # fmt: skip
    return value


def _header_allowed(method: str) -> str:
    return "a header row with the columns " + ", ".join(COLUMNS[method]) + f" ({method})"
