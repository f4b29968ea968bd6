"""The output folder of `rock fragility STUDY.toml`: cases.csv, fragility.json, state.json.

cases.csv holds every run (one line per task and intensity, appended as each task completes,
sorted by task and intensity at the end); a failed task is one line with its error.
state.json names the study (a fingerprint of the contents of everything that decides its runs)
and whether it is complete. ``--resume`` reads the runs back, each line checked, and hands
each task its own: only the runs not on disk are computed, and the results are the same as an
uninterrupted run's.

The folder is the one machinery of study folders (rockcli.studies.folder.folder.StudyFolder,
as `rock sweep`'s): checked and locked before any work, written without following links,
resumed by content (a folder copied or moved resumes; a record edited since does not).
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from rockcli.studies.folder.folder import StudyFolder, digest_of, record_identities
from rockcli.studies.fragility.run import Task, TaskResult, task_labels
from rockcli.studies.fragility.study import FragilityPlan
from rockcli.version import __version__

STATE_FILE = "state.json"
RESULT_FILE = "fragility.json"
FIXED_COLUMNS = ("task", "point")
RUN_COLUMNS = ("record", "mechanism", "im", "scale", "max_theta_ratio", "overturned", "error")


def columns(plan: FragilityPlan) -> tuple[str, ...]:
    """The header of cases.csv: task, point, the axes, the run's columns."""
    return (*FIXED_COLUMNS, *(a.name for a in plan.study.axes), *RUN_COLUMNS)


def fingerprint(plan: FragilityPlan) -> str:
    """A hash of what decides the study's runs: rock's version, the model's content, the axes,
    each record by its bytes (not its path: a folder moved or copied resumes), the options."""
    study = plan.study
    records = record_identities(study.records)
    facts = {
        "rock": __version__,
        "base": study.base,
        "axes": [(a.name, a.texts, a.values) for a in study.axes],
        "records": records,
        "engine": study.engine,
        "ground": study.ground,
        "mechanism": plan.mechanism,
        "measure": plan.measure,
        "period": plan.period,
        "states": [(s.name, repr(s.level)) for s in plan.states],
        "method": plan.method,
        "scan": [repr(x) for x in plan.scan or ()],
        "levels": [repr(x) for x in plan.levels],
    }
    return digest_of(facts)


@dataclass(frozen=True)
class Kept:
    """What an earlier run left: each task's runs, and the tasks that failed."""

    runs: dict[int, dict[float, float]]
    failed: dict[int, str]
    mechanisms: dict[int, str]


class Folder(StudyFolder):
    """The study's output folder."""

    def __init__(self, out: str, plan: FragilityPlan, todo: Sequence[Task]) -> None:
        """todo: every task of the study (the rows read back are checked against them)."""
        super().__init__(
            out,
            command="rock fragility",
            state_file=STATE_FILE,
            header=columns(plan),
            fingerprint=fingerprint(plan),
            row_problem=self._row_problem,
        )
        self.plan = plan
        self.labels = [_label_cells(self.header, t.id, task_labels(plan, t)) for t in todo]
        self._seen: set[tuple[str, str]] = set()
        self._kept: list[list[str]] = []

    def check(self, *, resume: bool, overwrite: bool) -> Kept:
        """What to keep: nothing for a new folder or with overwrite; the runs on disk with
        resume (InputError: a folder of another study, or an unfinished run of this one
        without --resume or --force; a damaged cases.csv)."""
        if not self.keeps(resume=resume, overwrite=overwrite):
            return Kept({}, {}, {})
        return self.read()

    def start(self) -> None:
        """state.json (incomplete), and cases.csv with its header and the lines kept (written
        whole: a full disk leaves the old file, never an empty one)."""
        self.write_state(complete=False, study=self.plan.file)
        tasks = len({row[0] for row in self._kept})
        self.rewrite(self._kept, saved=f"{tasks} of {len(self.labels)} tasks saved")

    def append(self, result: TaskResult, labels: dict[str, Any]) -> None:
        """The task's new runs (or its error) appended to cases.csv (PartialWrite when the disk
        fills part-way)."""
        text = task_lines(self.header, result, labels)
        lines = [line.encode("utf-8") for line in text.splitlines(keepends=True)]
        self.append_bytes([result.id] * len(lines), lines)

    def read(self) -> Kept:
        """The runs of cases.csv by task, every line checked (a last line cut short by an
        interruption is dropped)."""
        runs: dict[int, dict[float, float]] = {}
        failed: dict[int, str] = {}
        mechanisms: dict[int, str] = {}
        self._kept = self._checked_lines()
        for cells in self._kept:
            row = dict(zip(self.header, cells, strict=True))
            task = int(row["task"])
            if row["mechanism"]:
                mechanisms[task] = row["mechanism"]
            if row["error"]:
                failed[task] = row["error"]
                continue
            value = math.inf if row["overturned"] == "true" else float(row["max_theta_ratio"])
            runs.setdefault(task, {})[float(row["im"])] = value
        return Kept(runs, failed, mechanisms)

    def _checked_lines(self) -> list[list[str]]:
        """The lines of cases.csv, each checked (:meth:`_row_problem`)."""
        self._seen = set()
        return self.read_lines()

    def _row_problem(self, cells: Sequence[str]) -> str | None:
        """What is wrong with a line of cases.csv read back, or None: a task of this study with
        its own point, axis values and record; an error line, or a run at a finite intensity
        > 0 with its response; no task's intensity (or error) twice."""
        row = dict(zip(self.header, cells, strict=True))
        task = row["task"]
        if not (task.isascii() and task.isdigit() and int(task) < len(self.labels)):
            return f"not a task of this study (0 to {len(self.labels) - 1})"
        if list(cells[: len(self.labels[int(task)])]) != self.labels[int(task)]:
            return "the point, axis values or record are not those of its task"
        problem = _error_problem(row) if row["error"] else _run_problem(row)
        if problem is None:
            key = (task, row["im"])
            if key in self._seen:
                return f"task {task} at intensity {row['im'] or '(its error)'} twice"
            self._seen.add(key)
        return problem

    def finish(self, document: dict[str, Any]) -> None:
        """cases.csv sorted by task and intensity, fragility.json, state.json complete."""
        import json

        rows = sorted(self._checked_lines(), key=self._sort_key)
        self.rewrite(rows)
        self.write_file(RESULT_FILE, json.dumps(document, indent=1) + "\n")
        self.write_state(complete=True, study=self.plan.file)

    def _sort_key(self, row: Sequence[str]) -> tuple[int, float]:
        """A row by task, then intensity (an error line, with none, first)."""
        im = row[self.header.index("im")]
        return int(row[0]), float(im) if im else -1.0


def _label_cells(header: Sequence[str], task: int, labels: dict[str, Any]) -> list[str]:
    """A task's first cells as written: its id, point, axis values and record."""
    cells = {**labels, "task": task}
    return [_cell(cells.get(k)) for k in header[: header.index("record") + 1]]


def _error_problem(row: dict[str, str]) -> str | None:
    if any(row[k] for k in ("im", "scale", "max_theta_ratio", "overturned")):
        return "an error line with a run's values"
    return None


def _run_problem(row: dict[str, str]) -> str | None:
    im = _finite(row["im"])
    if im is None or im <= 0.0:
        return f"intensity {row['im']!r} is not a finite number > 0"
    if row["overturned"] not in ("true", "false"):
        return f"overturned {row['overturned']!r} is not true or false"
    if row["scale"] and _finite(row["scale"]) is None:
        return f"scale {row['scale']!r} is not a finite number"
    ratio = row["max_theta_ratio"]
    if row["overturned"] == "true":
        return "an overturned run with a max θ/α" if ratio else None
    value = _finite(ratio)
    if value is None or value < 0.0:
        return f"max_theta_ratio {ratio!r} is not a finite number ≥ 0"
    return None


def _finite(text: str) -> float | None:
    """The finite number a cell holds, or None."""
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


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
