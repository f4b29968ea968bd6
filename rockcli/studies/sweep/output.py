"""The output folder of a study: ``cases.csv`` written chunk by chunk, a state file, resume.

``cases.csv`` holds one row per case (the rocking columns are the envelope of both
polarities). Rows are appended as each chunk completes, so an interrupted study keeps every
finished chunk; ``--resume`` reads them back (dropping a half-written last line), skips those
cases and appends the rest. When the study completes, the file is rewritten sorted by case id,
so its content does not depend on the order the chunks completed in. ``sweep.json`` holds the
study's fingerprint (the study, the base model, the records, the rock version) so that a
resume never mixes the results of two different studies. One run at a time writes into the
folder (:meth:`Output.lock`, rockcli.studies.sweep.lock), and no file of it is written
through a link planted at its name (:data:`FOLDER_FILES`).
"""

from __future__ import annotations

import csv
import functools
import json
import math
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any, NoReturn

from rockcli.errors import InputError, install_hint
from rockcli.outfile import replacing
from rockcli.studies.folder.folder import (
    CASES_FILE,
    StudyFolder,
    csv_text,
    digest_of,
    file_digest,
    record_identities,
)
from rockcli.studies.folder.lock import LOCK_FILE
from rockcli.studies.sweep.study import StudyPlan
from rockcli.version import __version__

PARQUET_FILE = "cases.parquet"
#: What --output parquet needs, and how to get it.
PARQUET_EXTRA = f"{install_hint('parquet')} (pyarrow)"
STATE_FILE = "sweep.json"
SUMMARY_FILE = "summary.json"
#: Every name a study gives a file in its output folder. Each is written through a new
#: temporary file beside it (rockcli.outfile.replacing: mkstemp, then a rename that replaces
#: a link rather than follows it); cases.csv is appended to with O_NOFOLLOW; the lock file is
#: opened with O_NOFOLLOW (rockcli.studies.folder: the one machinery of study folders).
FOLDER_FILES = (CASES_FILE, PARQUET_FILE, STATE_FILE, SUMMARY_FILE, LOCK_FILE)
STATE_SCHEMA = 1

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
    "input": str,
    "utilisation": float,
    "code_dls": str,
    "code_uls": str,
    "uls_ratio": float,
    "a0_star": float,
    "Ts": float,
    "classification": str,
    "limit_state": str,
    "code_state": str,
    "suite_rule": str,
    "suite_records": int,
    "suite_overturned": int,
    "error": str,
}


#: Result columns of a study run with --check-tolerance, after RESULT_COLUMNS (a study without
#: it writes the header it always did, so its cases.csv resumes as before).
TOLERANCE_COLUMNS: dict[str, type] = {"sensitive": bool}


#: Result columns of a study whose base model is a wall with its mechanism catalogue, after
#: the others: the mechanism each case rocks and checks (a study of a block writes the header
#: it always did).
MECHANISM_COLUMNS: dict[str, type] = {"mechanism": str}

#: Result columns of a study whose base model has a ``[base]`` table (or an axis on it),
#: after the others: whether the case's mechanism slides on its base before it lifts
#: (rockcli.analyses.sliding; empty for a mechanism not at the base).
SLIDING_COLUMNS: dict[str, type] = {"slides": bool}


def has_sliding_column(plan: StudyPlan) -> bool:
    """True when the study's base model has a ``[base]`` table or an axis sets one."""
    return "base" in plan.base or any(
        path[0] == "base" for axis in plan.axes for path in axis.paths
    )


def has_mechanism_column(plan: StudyPlan) -> bool:
    """True when the study's base model is a wall of storeys or lists mechanisms (its cases
    name the mechanism they rock and check; a block file's study keeps its header)."""
    geometry = plan.base.get("geometry")
    storeys = isinstance(geometry, dict) and "storeys" in geometry
    return storeys or bool(plan.base.get("mechanisms"))


def columns(plan: StudyPlan) -> list[str]:
    """The header of cases.csv."""
    extra = {
        **(TOLERANCE_COLUMNS if plan.check_tolerance else {}),
        **(MECHANISM_COLUMNS if has_mechanism_column(plan) else {}),
        **(SLIDING_COLUMNS if has_sliding_column(plan) else {}),
    }
    return ["case", "record", *(a.name for a in plan.axes), *RESULT_COLUMNS, *extra]


def result_kinds(header: Sequence[str]) -> dict[str, type]:
    """The result columns of a header and their types (RESULT_COLUMNS, and the tolerance
    check's and the mechanism's when the header has them)."""
    optional = {**TOLERANCE_COLUMNS, **MECHANISM_COLUMNS, **SLIDING_COLUMNS}
    extra = {k: v for k, v in optional.items() if k in header}
    return {**RESULT_COLUMNS, **extra}


#: First characters that make a spreadsheet read a cell as a formula (OWASP, CSV injection).
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")


def cell(value: Any) -> str:
    """One CSV cell: floats at full precision (repr), booleans true/false, None empty, text
    escaped against formulas (:func:`escape`)."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, str):
        return escape(value)
    return str(value)


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def escape(text: str) -> str:
    """Text that a spreadsheet would run as a formula (it starts with = + - @, a tab or a
    carriage return, after any leading quotes) prefixed with a single quote; numbers such as
    -0.5 stay numbers (OWASP, CSV injection)."""
    if text.lstrip("'").startswith(FORMULA_STARTS) and not _is_number(text):
        return "'" + text
    return text


def unescape(text: str) -> str:
    """The text :func:`escape` was given."""
    if text.startswith("'") and text.lstrip("'").startswith(FORMULA_STARTS):
        return text[1:]
    return text


def parse_cell(text: str, kind: type) -> Any:
    """A result cell back to its value (None when empty; ValueError when not of its kind)."""
    if text == "":
        return None
    if kind is bool:
        if text not in ("true", "false"):
            raise ValueError(text)
        return text == "true"
    if kind is float:
        value = float(text)
        if not math.isfinite(value):
            raise ValueError(text)
        return value
    return kind(text)


def row_lines(header: Sequence[str], rows: Iterable[Mapping[str, Any]]) -> list[bytes]:
    """Each row's line of cases.csv (its cells in the header's order, :func:`cell`)."""
    return [csv_text([[cell(row.get(c)) for c in header]]).encode("utf-8") for row in rows]


@functools.lru_cache(maxsize=4096)
def csv_field(text: str) -> str:
    """A cell as csv.writer writes it inside a row (quoted when it holds a comma, a quote or
    a line break), so that fields joined by commas are the writer's line."""
    return csv_text([[text, ""]])[:-2]


def column_lines(
    header: Sequence[str], n: int, columns: Mapping[str, Sequence[str]]
) -> list[bytes]:
    """The lines of n rows given as columns of written fields (:func:`csv_field` of each
    :func:`cell`; a column of the header that is missing is empty): the bytes that
    :func:`row_lines` writes for the same cells."""
    empty = [""] * n
    ordered = [columns.get(c, empty) for c in header]
    return [(",".join(fields) + "\n").encode("utf-8") for fields in zip(*ordered, strict=True)]


def fingerprint(plan: StudyPlan) -> str:
    """A hash of what decides the results: rock's version, the study, base model, records
    (each by its bytes, not its name or size)."""
    records = record_identities(plan.records)
    data = {
        "rock": __version__,
        "analyses": plan.analyses,
        "engine": plan.engine,
        "code_demand": plan.code_demand,
        "ground": plan.ground,
        "grid": file_digest(plan.grid_file) if plan.grid_file else None,
        "axes": [(a.name, a.texts, a.values) for a in plan.axes],
        "base": plan.base,
        "records": records,
    }
    if plan.check_tolerance:  # only then: a study without it keeps its fingerprint
        data["check_tolerance"] = True
    return digest_of(data)


class Output(StudyFolder):
    """The output folder of one study run (rockcli.studies.folder.folder: checked, locked,
    written without following links, resumed by the content of its inputs)."""

    def __init__(
        self,
        folder: str,
        plan: StudyPlan,
        n_cases: int,
        label_of: Callable[[int], Sequence[str]] | None = None,
    ) -> None:
        """label_of: a case id's first cells (case, record, axis values) as written, to check
        the rows kept on --resume against."""
        super().__init__(
            folder,
            command="rock sweep",
            state_file=STATE_FILE,
            header=columns(plan),
            fingerprint=fingerprint(plan),
            row_problem=self._row_problem,
        )
        self.label_of = label_of
        self.n_cases = n_cases
        self.file = str(plan.file)
        # The blocks of rows in cases.csv, in the order written: (first id, last id, byte
        # offset, byte length); None once a block is not in ascending order.
        self._blocks: list[tuple[int, int, int, int]] | None = []

    def check(self, *, resume: bool, overwrite: bool) -> dict[int, dict[str, str]]:
        """Before any work: the folder can be written and may be used; the rows kept from an
        earlier run (by case id) when resuming."""
        return self.read_rows() if self.keeps(resume=resume, overwrite=overwrite) else {}

    def start(self, kept: Mapping[int, Mapping[str, str]]) -> None:
        """Mark the study unfinished and rewrite cases.csv with the rows kept."""
        self._write_state(complete=False)
        self._rewrite(kept)
        header = len(csv_text([self.header]).encode("utf-8"))
        size = self.cases_path.stat().st_size
        self._blocks = [(min(kept), max(kept), header, size - header)] if kept else []

    def _write_state(self, *, complete: bool) -> None:
        self.write_state(
            complete=complete, schema=STATE_SCHEMA, study=self.file, cases=self.n_cases
        )

    def read_rows(self) -> dict[int, dict[str, str]]:
        """The rows of cases.csv by case id (StudyFolder.read_lines, each row checked by
        :meth:`_row_problem`; a case's first row kept)."""
        kept: dict[int, dict[str, str]] = {}
        for row in self.read_lines():
            kept.setdefault(int(row[0]), dict(zip(self.header, row, strict=True)))
        return kept

    def _row_problem(self, row: Sequence[str]) -> str | None:
        """What is wrong with a row of cases.csv, or None."""
        if not (row[0].isascii() and row[0].isdigit() and int(row[0]) < self.n_cases):
            return f"not a case id of this study (0 to {self.n_cases - 1})"
        expected = self.label_of(int(row[0])) if self.label_of is not None else None
        if expected is not None and list(row[: len(expected)]) != list(expected):
            return "the record or axis values are not those of its case"
        cells = dict(zip(self.header, row, strict=True))
        for name, kind in result_kinds(self.header).items():
            try:
                parse_cell(unescape(cells[name]), kind)
            except ValueError:
                return f"column {name} is not a {kind.__name__}"
        return None

    def _rewrite(self, rows: Mapping[int, Mapping[str, str]]) -> None:
        """cases.csv with the header and the given rows sorted by case id (atomically)."""
        saved = f"{len(rows)} of {self.n_cases} cases saved"
        self.rewrite(([rows[k][c] for c in self.header] for k in sorted(rows)), saved=saved)

    def append(self, rows: Iterable[Mapping[str, Any]]) -> list[int]:
        """Append the rows of a completed chunk; returns their case ids (append_lines)."""
        rows = list(rows)
        return self.append_lines([int(r["case"]) for r in rows], row_lines(self.header, rows))

    def append_lines(self, ids: list[int], lines: Sequence[bytes]) -> list[int]:
        """Append the lines of a completed chunk's cases (ids: each line's case); returns the
        ids (StudyFolder.append_bytes: PartialWrite when the disk fills part-way)."""
        offset = self.append_bytes(ids, lines)
        if ids and self._blocks is not None:
            if all(a < b for a, b in zip(ids, ids[1:], strict=False)):
                self._blocks.append((ids[0], ids[-1], offset, sum(map(len, lines))))
            else:
                self._blocks = None
        return ids

    def finish(self) -> None:
        """Sort cases.csv by case id, streaming: the blocks written are each in order and
        (in a study run from start to end) cover disjoint ranges of ids, so they are copied in
        the order of their first id; otherwise (a resumed study) the rows are sorted in
        memory."""
        blocks = sorted(self._blocks or [])
        if self._blocks is None or any(
            a[1] >= b[0] for a, b in zip(blocks, blocks[1:], strict=False)
        ):
            self._rewrite(self.read_rows())
            return
        if all(a[2] < b[2] for a, b in zip(blocks, blocks[1:], strict=False)):
            return  # written in order already
        with open(self.cases_path, "rb") as src, replacing(self.cases_path) as dst:
            dst.write(csv_text([self.header]).encode("utf-8"))
            for _, _, offset, length in blocks:
                src.seek(offset)
                dst.write(src.read(length))

    def write_summary(self, summary: dict[str, Any]) -> None:
        """Write summary.json and mark the study complete."""
        self.write_file(SUMMARY_FILE, json.dumps(summary, indent=2, allow_nan=False))
        self._write_state(complete=True)

    def typed_rows(self) -> Iterator[tuple[int, dict[str, Any]]]:
        """Each case id and its result cells as values (:func:`typed_rows`)."""
        return typed_rows(self.cases_path)

    def checked_rows(self) -> Iterator[tuple[int, dict[str, Any]]]:
        """:meth:`typed_rows` of the finished (sorted) cases.csv, checked on the way
        (:meth:`checked_cells`)."""
        kinds = result_kinds(self.header)
        names = tuple(kinds)
        for k, cells in self.checked_cells(names):
            yield k, typed(dict(zip(names, cells, strict=True)), kinds)

    def checked_cells(self, names: Sequence[str]) -> Iterator[tuple[int, tuple[str, ...]]]:
        """Each case id of the finished (sorted) cases.csv and its cells of the named columns
        as written (those the header lacks: empty), checked on the way: this study's header,
        then every case once, in order, each row whole. Anything else (another program wrote
        to the file meanwhile) is an InputError before the study is marked complete."""
        expected = 0
        width = len(self.header)
        where = [self.header.index(n) if n in self.header else width for n in names]
        try:
            with open(self.cases_path, encoding="utf-8", newline="") as fh:
                reader = csv.reader(fh)
                if next(reader, None) != self.header:
                    self._changed("its header is not this study's columns")
                for row in reader:
                    if len(row) != width:
                        raise ValueError(f"{len(row)} cells")
                    k = int(row[0])
                    if k != expected:
                        self._changed(f"line {expected + 2} is case {k}, not case {expected}")
                    expected += 1
                    row.append("")
                    yield expected - 1, tuple(row[i] for i in where)
        except (OSError, UnicodeDecodeError, ValueError, csv.Error) as exc:
            self._changed(f"line {expected + 2} cannot be read ({exc.__class__.__name__})")
        if expected != self.n_cases:
            self._changed(f"it holds {expected} of the {self.n_cases} cases")

    def _changed(self, problem: str) -> NoReturn:
        raise InputError(
            f"{CASES_FILE} changed during the run: {problem}; the study is not marked complete",
            file=str(self.cases_path),
            allowed="one rock sweep at a time in a folder no other program writes to; "
            "rerun with --resume",
        )


def typed_rows(path: Path) -> Iterator[tuple[int, dict[str, Any]]]:
    """Each case id and its result cells as values, read from a cases.csv one row at a time."""
    with open(path, encoding="utf-8", newline="") as fh:
        reader = csv.reader(fh)
        header = next(reader, None)
        if header is None:
            return
        kinds = result_kinds(header)
        for row in reader:
            yield int(row[0]), typed(dict(zip(header, row, strict=True)), kinds)


def typed(row: Mapping[str, str], kinds: Mapping[str, type] = RESULT_COLUMNS) -> dict[str, Any]:
    """The result cells of a row as values (floats, booleans, text, None); ``kinds``: the
    result columns and their types (:func:`result_kinds` of the file's header)."""
    return {k: parse_cell(unescape(row[k]), kind) for k, kind in kinds.items()}


def parquet_available() -> bool:
    """True when pyarrow can be imported (the parquet extra)."""
    import importlib.util

    return importlib.util.find_spec("pyarrow") is not None


#: Arrow types of the result columns (RESULT_COLUMNS' Python types).
_ARROW_TYPES = {float: "float64", bool: "bool", str: "string", int: "int64"}


def write_parquet(csv_path: Path, parquet_path: Path, header: Sequence[str]) -> None:
    """cases.csv as Parquet, streamed block by block (memory flat): the case id and the
    result columns typed (RESULT_COLUMNS; empty cells null), the record and axis columns as
    Arrow infers them, and text cells without the quote that guards them in the CSV against
    spreadsheet formulas (:func:`escape`)."""
    import pyarrow as pa
    import pyarrow.compute as pc
    import pyarrow.csv as pacsv
    import pyarrow.parquet as pq

    types = {"case": pa.int64(), "record": pa.string()}
    kinds = result_kinds(header)
    types |= {k: pa.type_for_alias(_ARROW_TYPES[v]) for k, v in kinds.items()}
    convert = pacsv.ConvertOptions(
        column_types=types,
        true_values=["true"],
        false_values=["false"],
        null_values=[""],
        strings_can_be_null=True,
    )
    read = pacsv.ReadOptions(block_size=1 << 20)  # 1 MB: the peak memory stays flat
    reader = pacsv.open_csv(str(csv_path), read_options=read, convert_options=convert)
    guarded = r"^'+[=+\-@\t\r]"
    with replacing(parquet_path) as fh, pq.ParquetWriter(fh, reader.schema) as writer:
        for batch in reader:
            columns = []
            for field, column in zip(batch.schema, batch.columns, strict=True):
                if pa.types.is_string(field.type):
                    strip = pc.match_substring_regex(column, guarded)
                    column = pc.if_else(strip, pc.utf8_slice_codeunits(column, 1), column)
                columns.append(column)
            writer.write_batch(pa.RecordBatch.from_arrays(columns, schema=batch.schema))
