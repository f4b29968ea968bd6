"""Run a fragility study on the sweep's executors (local processes or a dask cluster).

The tasks (rockcli.studies.fragility.run) go to the lanes as chunks of one task each
(rockcli.studies.parallel.chunks); each task's runs are appended to cases.csv as it completes,
so Ctrl-C keeps every finished task, and ``--resume`` hands each task the runs already on
disk. The document is made from every task's runs once all are done.
"""

from __future__ import annotations

import time
from collections.abc import Callable, MutableSequence
from dataclasses import dataclass
from typing import Any

from rockcli.errors import InputError
from rockcli.studies.fragility.output import Folder, Kept
from rockcli.studies.fragility.run import Task, TaskResult, run_task, task_labels, tasks
from rockcli.studies.fragility.study import FragilityPlan
from rockcli.studies.parallel.executor import Lane

Progress = Callable[[int, int], None]


class FragilityInterrupted(KeyboardInterrupt):
    """Ctrl-C (or SIGTERM) during the study: the tasks saved, and where."""

    def __init__(self, saved: int, total: int, out: str) -> None:
        super().__init__(f"{saved} of {total} records saved")
        self.saved, self.total, self.out = saved, total, out


@dataclass(frozen=True)
class FragilityResult:
    """The document and the output folder."""

    document: dict[str, Any]
    out: str


def run_fragility(
    plan: FragilityPlan,
    out: str,
    lanes: MutableSequence[Lane],
    *,
    resume: bool = False,
    overwrite: bool = False,
    progress: Progress | None = None,
    run_facts: dict[str, Any] | None = None,
    started: float | None = None,
) -> FragilityResult:
    """Every task of the study, the runs on disk kept with ``resume``; the document."""
    from rockcli.process import interrupted
    from rockcli.studies.fragility.results import document
    from rockcli.studies.parallel.chunks import run_chunks
    from rockcli.studies.parallel.setup import warm

    start = time.perf_counter() if started is None else started
    folder = Folder(out, plan, tasks(plan))
    with folder.lock():
        kept = folder.check(resume=resume, overwrite=overwrite)
        read_records(plan)  # a bad record file fails here, before any work
        todo = tasks(plan, kept.runs)
        folder.start()
        results = failed_results(todo, kept)
        resumed = sum(len(r) for r in kept.runs.values())
        pending = [t for t in todo if t.id not in results]
        tell = progress or (lambda done, total: None)
        tell(len(results), len(todo))
        warm()
        computed = 0
        try:
            for found in run_chunks(lanes, pending, run_task):
                for result in _results(found):
                    folder.append(result, task_labels(plan, todo[result.id]))
                    results[result.id] = result
                    computed += len(result.new)
                tell(len(results), len(todo))
        except BaseException as exc:
            if interrupted(exc):
                raise FragilityInterrupted(len(results), len(todo), out) from None
            if isinstance(exc, OSError):  # a full disk, a folder turned read-only
                saved = f"{len(results)} of {len(todo)} tasks saved"
                raise folder.unwritable(exc.strerror or str(exc), saved) from None
            raise
        wall = time.perf_counter() - start
        run = {
            "out": out,
            **(run_facts or {}),
            "tasks": len(todo),
            "computed_runs": computed,
            "resumed_runs": resumed,
            "wall_time_s": wall,
            "runs_per_s": computed / wall if wall > 0 else None,
        }
        doc = document(plan, todo, results, run)
        folder.finish(doc)
        if all(r.error is not None for r in results.values()):
            raise nothing_succeeded(plan, todo, results, folder)
    return FragilityResult(doc, out)


def read_records(plan: FragilityPlan) -> None:
    """Read every record of the study once (InputError for the first bad file, as a sweep's
    reader gives it: rockcli.studies.sweep.run.unquoted)."""
    from rockcli.studies.sweep.run import unquoted
    from rockcli.studies.sweep.worker import read_source

    for source in plan.study.records:
        try:
            read_source(source)
        except InputError as exc:
            raise unquoted(exc) from None


def nothing_succeeded(
    plan: FragilityPlan, todo: list[Task], results: dict[int, TaskResult], folder: Folder
) -> InputError:
    """The error of a study whose every record failed: bad input (exit 2), the first
    record's error (every one's is in cases.csv, written all the same)."""
    first = results[todo[0].id]
    name = plan.study.records[todo[0].record].name
    return InputError(
        f"no record of the study gave a result (each one's error is in {folder.cases_path}); "
        f"record {name}: {first.error}",
        file=plan.file,
    )


def failed_results(todo: list[Task], kept: Kept) -> dict[int, TaskResult]:
    """The tasks an earlier run found failing (not run again, as a sweep's failed cases)."""
    return {
        t.id: TaskResult(t.id, kept.mechanisms.get(t.id), None, {}, (), kept.failed[t.id])
        for t in todo
        if t.id in kept.failed
    }


def _results(found: Any) -> list[TaskResult]:
    """A chunk's result, or the error rows of a chunk whose worker died, as TaskResults."""
    if isinstance(found, TaskResult):
        return [found]
    return [TaskResult(row["case"], None, None, {}, (), row["error"]) for row in found]
