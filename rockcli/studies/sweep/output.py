"""The output folder of a study: ``cases.csv`` written chunk by chunk, a state file, resume.

``cases.csv`` holds one row per case (the rocking columns are the envelope of both
polarities). Rows are appended as each chunk completes, so an interrupted study keeps every
finished chunk; ``--resume`` reads them back (dropping a half-written last line), skips those
cases and appends the rest. When the study completes, the file is rewritten sorted by case id,
so its content does not depend on the order the chunks completed in. ``sweep.json`` holds the
study's fingerprint (the study, the base model, the records, the rock version) so that a
resume never mixes the results of two different studies.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import math
import os
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict
from pathlib import Path
from typing import Any

from rockcli import __version__
from rockcli.errors import InputError
from rockcli.studies.sweep.study import StudyPlan

CASES_FILE = "cases.csv"
STATE_FILE = "sweep.json"
SUMMARY_FILE = "summary.json"
STATE_SCHEMA = 1
#: Bytes read at a time when hashing a record file.
HASH_BLOCK = 1 << 20

#: Result columns and their types, after the case id, the record and the axis columns.
RESULT_COLUMNS: dict[str, type] = {
    "block_R": float,
    "block_alpha": float,
    "max_ratio": float,
    "max_ratio_pos": float,
    "max_ratio_neg": float,
    "overturned": bool,
    "t_overturn": float,
    "rocking": str,
    "code_dls": str,
    "code_uls": str,
    "uls_ratio": float,
    "a0_star": float,
    "Ts": float,
    "classification": str,
    "error": str,
}


def columns(plan: StudyPlan) -> list[str]:
    """The header of cases.csv."""
    return ["case", "record", *(a.name for a in plan.axes), *RESULT_COLUMNS]


def cell(value: Any) -> str:
    """One CSV cell: floats at full precision (repr), booleans true/false, None empty."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return str(value)


def parse_cell(text: str, kind: type) -> Any:
    """A result cell back to its value (None when empty)."""
    if text == "":
        return None
    if kind is bool:
        return text == "true"
    return kind(text)


def csv_lines(rows: Iterable[Sequence[str]]) -> str:
    """CSV text of rows of cells (\\n line ends)."""
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(rows)
    return buffer.getvalue()


def file_digest(path: str) -> str:
    """The sha256 of a file's bytes (a record edited at the same size changes it)."""
    digest = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(HASH_BLOCK), b""):
            digest.update(block)
    return digest.hexdigest()


def fingerprint(plan: StudyPlan) -> str:
    """A hash of what decides the results: rock's version, the study, base model, records
    (each by its bytes, not its name or size)."""
    records = [
        {**asdict(r), "path": Path(r.path).name, "sha256": file_digest(r.path)}
        for r in plan.records
    ]
    data = {
        "rock": __version__,
        "analyses": plan.analyses,
        "engine": plan.engine,
        "record_demand": plan.record_demand,
        "axes": [(a.name, a.texts, a.values) for a in plan.axes],
        "base": plan.base,
        "records": records,
    }
    text = json.dumps(data, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


class Output:
    """The output folder of one study run."""

    def __init__(self, folder: str, plan: StudyPlan, n_cases: int) -> None:
        self.folder = Path(folder)
        self.header = columns(plan)
        self.fingerprint = fingerprint(plan)
        self.n_cases = n_cases
        self.file = str(plan.file)

    @property
    def cases_path(self) -> Path:
        return self.folder / CASES_FILE

    def _state(self) -> dict[str, Any] | None:
        try:
            return dict(json.loads((self.folder / STATE_FILE).read_text(encoding="utf-8")))
        except (OSError, ValueError):
            return None

    def start(self, *, resume: bool, overwrite: bool) -> dict[int, dict[str, str]]:
        """Prepare the folder; the rows kept from an earlier run (by case id) when resuming."""
        state = self._state() if self.cases_path.exists() else None
        same = state is not None and state.get("fingerprint") == self.fingerprint
        if not overwrite:
            self._check_reuse(state, same, resume)
        kept = self.read_rows() if resume and same and not overwrite else {}
        self._write_state(complete=False)
        self._rewrite(kept)
        return kept

    def _check_reuse(self, state: dict[str, Any] | None, same: bool, resume: bool) -> None:
        """Refuse to replace what the folder holds unless it is this study, complete."""
        if state is None:
            if self.cases_path.exists():
                self._refuse("holds a cases.csv that rock did not write", "--overwrite")
            return
        if not same:
            self._refuse(
                "holds the results of another study (or the base model, the records or rock "
                "changed since)",
                "--overwrite to start over, or another --out",
            )
        if not resume and not state.get("complete"):
            self._refuse(
                "holds an unfinished run of this study",
                "--resume to continue it, or --overwrite to start over",
            )

    def _refuse(self, problem: str, allowed: str) -> None:
        raise InputError(
            f"the output folder {problem}", file=str(self.folder), where="--out", allowed=allowed
        )

    def _write_state(self, *, complete: bool) -> None:
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            state = {
                "schema": STATE_SCHEMA,
                "study": self.file,
                "fingerprint": self.fingerprint,
                "cases": self.n_cases,
                "columns": self.header,
                "complete": complete,
            }
            (self.folder / STATE_FILE).write_text(json.dumps(state, indent=2), encoding="utf-8")
        except OSError as exc:
            raise InputError(
                f"cannot write the output folder: {exc.strerror or exc}",
                file=str(self.folder),
                where="--out",
                allowed="a writable folder",
            ) from None

    def read_rows(self) -> dict[int, dict[str, str]]:
        """The complete rows of cases.csv by case id (a half-written last line is dropped)."""
        try:
            text = self.cases_path.read_text(encoding="utf-8")
        except OSError:
            return {}
        lines = text.splitlines(keepends=True)
        if lines and not lines[-1].endswith("\n"):
            lines.pop()  # interrupted in the middle of a line
        rows = list(csv.reader(lines))
        if not rows or rows[0] != self.header:
            return {}
        kept: dict[int, dict[str, str]] = {}
        for row in rows[1:]:
            if len(row) == len(self.header) and row[0].isdigit():
                case = int(row[0])
                if case < self.n_cases:
                    kept.setdefault(case, dict(zip(self.header, row, strict=True)))
        return kept

    def _rewrite(self, rows: Mapping[int, Mapping[str, str]]) -> None:
        """cases.csv with the header and the given rows sorted by case id (atomically)."""
        body = [self.header, *([rows[k][c] for c in self.header] for k in sorted(rows))]
        tmp = self.cases_path.with_suffix(".csv.tmp")
        tmp.write_text(csv_lines(body), encoding="utf-8")
        os.replace(tmp, self.cases_path)

    def append(self, rows: Iterable[Mapping[str, Any]]) -> list[dict[str, str]]:
        """Append the rows of a completed chunk; returns them as written (text cells)."""
        written = [{c: cell(row.get(c)) for c in self.header} for row in rows]
        with self.cases_path.open("a", encoding="utf-8") as out:
            out.write(csv_lines([[r[c] for c in self.header] for r in written]))
            out.flush()
        return written

    def finish(self, rows: Mapping[int, Mapping[str, str]], summary: dict[str, Any]) -> None:
        """Sort cases.csv by case id, write summary.json and mark the study complete."""
        self._rewrite(rows)
        (self.folder / SUMMARY_FILE).write_text(
            json.dumps(summary, indent=2, allow_nan=False), encoding="utf-8"
        )
        self._write_state(complete=True)


def typed(row: Mapping[str, str]) -> dict[str, Any]:
    """The result cells of a row as values (floats, booleans, text, None)."""
    return {k: parse_cell(row[k], kind) for k, kind in RESULT_COLUMNS.items()}
