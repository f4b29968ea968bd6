"""The output folder of `rock fragility STUDY.toml`: cases.csv, fragility.json, state.json.

cases.csv holds every run (one line per task and intensity, appended as each task completes,
sorted by task and intensity at the end); a failed task is one line with its error.
state.json names the study (a fingerprint of everything that decides its runs) and whether
it is complete. ``--resume`` reads the runs back and hands each task its own: only the runs
not on disk are computed, and the results are the same as an uninterrupted run's.

The folder is locked (rockcli.studies.sweep.lock) from the first look to the last write.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import math
import os
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rockcli.errors import InputError
from rockcli.fragility.run import TaskResult
from rockcli.fragility.study import FragilityPlan

CASES_FILE = "cases.csv"
STATE_FILE = "state.json"
RESULT_FILE = "fragility.json"
FIXED_COLUMNS = ("task", "point")
RUN_COLUMNS = ("record", "mechanism", "im", "scale", "max_theta_ratio", "overturned", "error")


def columns(plan: FragilityPlan) -> tuple[str, ...]:
    """The header of cases.csv: task, point, the axes, the run's columns."""
    return (*FIXED_COLUMNS, *(a.name for a in plan.study.axes), *RUN_COLUMNS)


def fingerprint(plan: FragilityPlan) -> str:
    """A hash of what decides the study's runs (not its file's name or place)."""
    study = plan.study
    facts = (
        study.base,
        [(a.name, a.paths, a.values) for a in study.axes],
        [(r.name, r.path, r.fmt, r.dt, r.units, r.scale, r.pga) for r in study.records],
        study.engine,
        study.ground,
        plan.mechanism,
        plan.measure,
        plan.period,
        [(s.name, s.level) for s in plan.states],
        plan.method,
        plan.scan,
        plan.levels,
    )
    return hashlib.sha256(repr(facts).encode("utf-8", "surrogateescape")).hexdigest()


@dataclass(frozen=True)
class Kept:
    """What an earlier run left: each task's runs, and the tasks that failed."""

    runs: dict[int, dict[float, float]]
    failed: dict[int, str]
    mechanisms: dict[int, str]


class Folder:
    """The study's output folder."""

    def __init__(self, out: str, plan: FragilityPlan) -> None:
        self.folder = Path(out)
        self.plan = plan
        self.header = columns(plan)
        self.cases = self.folder / CASES_FILE
        self.state = self.folder / STATE_FILE

    @contextmanager
    def lock(self) -> Iterator[None]:
        """The folder locked against another run into it (InputError when it is busy)."""
        from rockcli.studies.sweep.lock import FolderBusy, lock_folder, unlock_folder

        try:
            self.folder.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise self._unwritable(exc) from None
        try:
            fd = lock_folder(self.folder)
        except FolderBusy as exc:
            raise InputError(
                "another rock run is writing into this folder",
                where="--out",
                value=str(self.folder),
                allowed=f"another --out (process {exc.pid or '?'} holds it)",
            ) from None
        try:
            yield
        finally:
            unlock_folder(self.folder, fd)

    def check(self, *, resume: bool, overwrite: bool) -> Kept:
        """What to keep: nothing for a new folder or with overwrite; the runs on disk with
        resume (InputError: a folder of another study, or of this one without either)."""
        empty = Kept({}, {}, {})
        if not overwrite and not self.state.exists() and self.cases.exists():
            raise InputError("the folder holds a cases.csv of another run (no state.json)",
                             where="--out", value=str(self.folder),
                             allowed="another --out, or --force to start over in it")  # fmt: skip
        if overwrite or not self.state.exists():
            for path in (self.cases, self.state, self.folder / RESULT_FILE):
                path.unlink(missing_ok=True)
            return empty
        try:
            state = json.loads(self.state.read_text(encoding="utf-8"))
            same = state.get("study") == fingerprint(self.plan)
        except (OSError, ValueError, AttributeError):
            same = False
        if not same:
            raise InputError(
                "the folder holds another study's results",
                where="--out",
                value=str(self.folder),
                allowed="another --out, or --force to start over in it",
            )
        if not resume:
            raise InputError(
                "the folder holds this study's results already",
                where="--out",
                value=str(self.folder),
                allowed="--resume to continue it, --force to start over, or another --out",
            )
        return self.read()

    def start(self) -> None:
        """state.json (incomplete), and cases.csv with its header when it is new."""
        self._write_state(complete=False)
        if not self.cases.exists() or self.cases.stat().st_size == 0:
            self.cases.write_text(",".join(self.header) + "\n", encoding="utf-8")

    def append(self, result: TaskResult, labels: dict[str, Any]) -> None:
        """The task's new runs (or its error) appended to cases.csv."""
        with self.cases.open("a", encoding="utf-8", newline="") as f:
            f.write(task_lines(self.header, result, labels))
            f.flush()

    def read(self) -> Kept:
        """The runs of cases.csv by task (a last line cut short by an interruption is
        dropped, and cut from the file)."""
        runs: dict[int, dict[float, float]] = {}
        failed: dict[int, str] = {}
        mechanisms: dict[int, str] = {}
        for row in self._rows():
            task = int(row["task"])
            if row["mechanism"]:
                mechanisms[task] = row["mechanism"]
            if row["error"]:
                failed[task] = row["error"]
                continue
            value = math.inf if row["overturned"] == "true" else float(row["max_theta_ratio"])
            runs.setdefault(task, {})[float(row["im"])] = value
        return Kept(runs, failed, mechanisms)

    def _rows(self) -> Iterator[dict[str, str]]:
        if not self.cases.exists():
            return
        data = self.cases.read_bytes()
        whole = data[: data.rfind(b"\n") + 1]
        if len(whole) != len(data):
            with self.cases.open("r+b") as f:
                f.truncate(len(whole))
        reader = csv.DictReader(io.StringIO(whole.decode("utf-8")))
        if tuple(reader.fieldnames or ()) != self.header:
            raise InputError(
                "cases.csv is not this study's",
                file=str(self.cases),
                allowed="--force to start over",
            )
        for row in reader:
            if None in row.values() or None in row:
                raise InputError(
                    "a damaged line in cases.csv",
                    file=str(self.cases),
                    where=f"line {reader.line_num}",
                    allowed="--force to start over",
                )
            yield row

    def finish(self, document: dict[str, Any]) -> None:
        """cases.csv sorted by task and intensity, fragility.json, state.json complete."""
        lines = self.cases.read_text(encoding="utf-8").splitlines(keepends=True)
        body = sorted(lines[1:], key=_sort_key)
        _replace(self.cases, lines[0] + "".join(body))
        _replace(self.folder / RESULT_FILE, json.dumps(document, indent=1) + "\n")
        self._write_state(complete=True)

    def _write_state(self, *, complete: bool) -> None:
        state = {"study": fingerprint(self.plan), "complete": complete}
        _replace(self.state, json.dumps(state) + "\n")

    def _unwritable(self, exc: OSError) -> InputError:
        return InputError(
            f"cannot write the output folder: {exc.strerror or exc}",
            where="--out",
            value=str(self.folder),
            allowed="a writable folder",
        )


def _sort_key(line: str) -> tuple[int, float]:
    """A line of cases.csv by task, then intensity (an error line, with none, first)."""
    row = next(csv.reader([line]))
    im = row[-len(RUN_COLUMNS) + RUN_COLUMNS.index("im")]
    return int(row[0]), float(im) if im else -1.0


def _replace(path: Path, text: str) -> None:
    """Write text to path through a temporary file (a crash leaves the old file whole)."""
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def task_lines(header: Sequence[str], result: TaskResult, labels: dict[str, Any]) -> str:
    """The lines of cases.csv for a task's new runs, or its error line."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    base = {**labels, "task": result.id, "mechanism": result.mechanism or ""}
    if result.error is not None:
        writer.writerow([_cell({**base, "error": result.error}.get(k)) for k in header])
        return buffer.getvalue()
    for im in sorted(result.new):
        value = result.runs[im]
        scale = im / result.unit_im if result.unit_im else None
        over = math.isinf(value)
        row = {
            **base,
            "im": repr(im),
            "scale": scale,
            "overturned": "true" if over else "false",
            "max_theta_ratio": None if over else repr(value),
        }
        writer.writerow([_cell(row.get(k)) for k in header])
    return buffer.getvalue()


def _cell(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)
    return str(value)
