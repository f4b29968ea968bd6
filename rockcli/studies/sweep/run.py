"""Run a study: expand and validate the cases, cut them in chunks, run the chunks on an
executor, write each chunk's rows as it completes, summarise.

Coded against :class:`concurrent.futures.Executor` (spec/engine.md, "Studies at scale"): the
main process (``--jobs 1``), a local process pool, or a dask cluster run the same chunks.
Chunks hold the cases of one record and about :data:`CHUNK_SECONDS` of work (fewer when the
study is small, so every worker gets several); at most a few chunks per worker are in flight,
so an error or an interruption stops the study soon, with every finished chunk on disk.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterable, Iterator, Mapping, MutableSequence, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from rockcli.errors import InputError
from rockcli.process import interrupted
from rockcli.studies.folder.folder import PartialWrite
from rockcli.studies.parallel.chunks import run_chunks
from rockcli.studies.parallel.executor import Lane
from rockcli.studies.sweep.batch import check_grid
from rockcli.studies.sweep.cases import Case, Cases, case_labels, expand
from rockcli.studies.sweep.output import Output, cell
from rockcli.studies.sweep.over_suite import suite_checks
from rockcli.studies.sweep.study import StudyPlan
from rockcli.studies.sweep.summary import split_axis
from rockcli.studies.sweep.worker import Chunk, ChunkLines, read_source, run_chunk_lines

#: Work per chunk aimed at [s]: long enough that pickling and scheduling (≈ 1 ms per task)
#: do not matter, short enough for a live progress bar and little lost work on interruption.
CHUNK_SECONDS = 1.0
#: Chunks per worker at least, when the study is small (load balance).
CHUNKS_PER_WORKER = 4
#: Estimated cost of a case, for the chunk size only [s]: the kinematic analysis (its
#: capacity curve with restrainers dominates), the rocking run per record sample (both
#: polarities). Measured on this machine: 1–2 ms and ≈ 20 ns per sample (benchmarks/sweep.py).
KINEMATIC_COST = 1.5e-3
ROCKING_COST = 2e-4
ROCKING_COST_PER_SAMPLE = 2e-8

Progress = Callable[[int, int], None]
#: Lowest measured speed factor used (a case timed much faster than estimated is a fluke of
#: the clock; chunks stay at most CHUNK_SECONDS / MIN_SPEED of estimated work).
MIN_SPEED = 0.25


class SweepInterrupted(KeyboardInterrupt):
    """Ctrl-C (or SIGTERM) during a study: how many cases are saved, and where."""

    def __init__(self, saved: int, total: int, out: str) -> None:
        super().__init__(f"{saved} of {total} cases saved")
        self.saved, self.total, self.out = saved, total, out


@dataclass(frozen=True)
class SweepResult:
    """The summary document and the output folder (the cases are in its cases.csv).

    Attributes:
        summary: the `rock sweep --format json` document.
        split: the axis to draw one panel per value of (the first non-geometric one).
        out: the output folder.
    """

    summary: dict[str, Any]
    split: str | None
    out: str


def case_cost(plan: StudyPlan, npts: int) -> float:
    """The estimated seconds of one case on a record of npts samples."""
    cost = KINEMATIC_COST if "kinematic" in plan.analyses else 0.0
    if "rocking" in plan.analyses:
        runs = 2 if plan.check_tolerance else 1  # the tolerance check runs each case again
        cost += runs * (ROCKING_COST + ROCKING_COST_PER_SAMPLE * npts)
    return cost


def make_chunks(
    plan: StudyPlan,
    ids: Sequence[int] | np.ndarray,
    npts: Sequence[int],
    workers: int,
    chunk_size: int | None = None,
    speed: float = 1.0,
) -> list[Chunk]:
    """The chunks of the cases to run (ids in ascending order): cases of one record together,
    ≈ CHUNK_SECONDS each, each chunk's ids a range where they follow each other.

    speed: measured time of a case over its estimate (:func:`measure`; the reference engine
    is ≈ 1000 times the estimate, which is the fast engine's).
    """
    ids = np.asarray(ids, dtype=np.int64)
    points = Cases(plan).points
    records = ids // points if plan.records else np.zeros(ids.size, dtype=np.int64)
    by_record = {(int(r) if plan.records else None): ids[records == r] for r in np.unique(records)}
    costs = {r: speed * case_cost(plan, npts[r] if r is not None else 0) for r in by_record}
    total = sum(costs[r] * len(c) for r, c in by_record.items())
    target = min(CHUNK_SECONDS, total / (CHUNKS_PER_WORKER * workers))
    chunks = []
    for record, group in by_record.items():
        size = chunk_size or max(1, math.floor(target / costs[record]) if costs[record] else 1)
        for start in range(0, len(group), size):
            part = group[start : start + size]
            first, last = int(part[0]), int(part[-1])
            span = range(first, last + 1) if last - first + 1 == part.size else tuple(part.tolist())
            chunks.append(Chunk(plan, record, span))
    return chunks


#: Cases of a batched study run and timed here first (one call of its kernel: the time of one
#: case alone would be mostly the call's own).
MEASURED_CASES = 64


def measure(plan: StudyPlan, todo: Sequence[Case], npts: Sequence[int]) -> tuple[ChunkLines, float]:
    """Run the first case to do here (a batched study: up to MEASURED_CASES of its record)
    and time it: its lines, and its time per case over the estimate (the chunks are then
    sized by measured time, so a slow engine or machine still gets chunks of about
    CHUNK_SECONDS, and Ctrl-C stops within about that). The kernels are loaded first, and a
    batched study's shared form made (rockcli.studies.sweep.batch), so neither is timed."""
    from rockcli.studies.parallel.setup import warm
    from rockcli.studies.sweep.batch import cached_form

    warm()
    first = todo[0]
    cases = [first]
    if cached_form(plan) is not None:
        cases += [c for c in todo[1:MEASURED_CASES] if c.record == first.record]
    start = time.perf_counter()
    lines = run_chunk_lines(Chunk(plan, first.record, tuple(c.id for c in cases)))
    elapsed = (time.perf_counter() - start) / len(cases)
    estimate = case_cost(plan, npts[first.record] if first.record is not None else 0)
    return lines, max(MIN_SPEED, elapsed / estimate) if estimate else 1.0


def record_facts(plan: StudyPlan) -> tuple[list[int], dict[str, dict[str, Any]]]:
    """Each record read once here (a bad file fails before any work): samples and facts (a
    suite: its records' samples, and its compatibility with its target)."""
    from rockcli.studies.sweep.over_suite import suite_facts

    npts, facts = [], {}
    for source in plan.records:
        if source.suite:
            count, facts[source.name] = suite_facts(source, plan.grid_file)
            npts.append(count)
            continue
        try:
            record = read_source(source)
        except InputError as exc:
            raise unquoted(exc) from None
        npts.append(record.npts)
        facts[source.name] = {
            "path": source.path,
            "pga_g": record.pga,
            "npts": record.npts,
            "duration_s": record.duration,
            "warnings": list(record.warnings),
        }
    return npts, facts


def unquoted(exc: InputError) -> InputError:
    """A record's error without the file's content when rock did not recognise the file: a
    study from an untrusted pull request must not make rock print what another file holds."""
    if "unrecognised" not in exc.problem:
        return exc
    return InputError(exc.problem, file=exc.file, where=exc.where, allowed=exc.allowed)


def run_sweep(
    plan: StudyPlan,
    out: str,
    lanes: MutableSequence[Lane],
    *,
    resume: bool = False,
    overwrite: bool = False,
    chunk_size: int | None = None,
    progress: Progress | None = None,
    run_facts: dict[str, Any] | None = None,
    started: float | None = None,
    parquet: bool = False,
) -> SweepResult:
    """Run every case of a study not already in the output folder; the summary.

    The output folder is locked from the first look at it to the summary (another run into
    it: InputError); the study is marked complete only when cases.csv holds every case once.

    Args:
        plan: the validated study. out: the output folder.
        lanes: where the chunks run: executors and how many chunks each takes at a time.
        resume: keep the cases an earlier run of the same study finished.
        overwrite: start over even if the folder holds another or an unfinished study.
        chunk_size: cases per chunk instead of the estimate.
        progress: called with (cases done, cases in all) after each chunk.
        run_facts: extra facts for the summary (jobs, scheduler).
        started: time.perf_counter() when the command started (the summary's wall time).
        parquet: also write the cases as cases.parquet (needs pyarrow).
    """
    start = time.perf_counter() if started is None else started
    cases = expand(plan)
    output = Output(out, plan, len(cases), lambda k: _label_cells(plan, cases[k]))
    with output.lock():
        kept = output.check(resume=resume, overwrite=overwrite)  # before any work
        checked = check_grid(plan, suite_checks(plan))
        npts, facts = record_facts(plan)
        output.start(kept)
        resumed = len(kept)
        runner = Runner(plan, cases, output, progress, kept)
        del kept
        runner.run(lanes, npts, chunk_size)
        run = {
            "out": str(output.folder),
            "computed_cases": len(cases) - resumed,
            "resumed_cases": resumed,
            **(run_facts or {}),
            "checked_up_front": checked,
            "wall_time_s": time.perf_counter() - start,
        }
        with runner.stopping():
            summary = conclude(plan, cases, output, facts, run, parquet)
        if summary["errors"] == summary["cases"]:
            raise nothing_succeeded(plan, output)
    return SweepResult(summary, split_axis(plan), str(output.folder))


class Runner:
    """The cases of a study not yet saved, run chunk by chunk, each chunk's rows appended as
    it completes; what is saved (a byte per case: memory stays flat)."""

    def __init__(
        self,
        plan: StudyPlan,
        cases: Sequence[Case],
        output: Output,
        progress: Progress | None,
        kept: Iterable[int] = (),
    ) -> None:
        """kept: the ids of the cases already in cases.csv (an earlier run's)."""
        self.plan, self.cases, self.output, self.progress = plan, cases, output, progress
        self.done = bytearray(len(cases))
        for k in kept:
            self.done[k] = 1
        self.saved = sum(self.done)

    def run(self, lanes: MutableSequence[Lane], npts: Sequence[int], size: int | None) -> None:
        """Every case not saved yet (SweepInterrupted on Ctrl-C, InputError when the folder
        cannot be written: each with the count of cases on disk)."""
        todo = np.flatnonzero(np.frombuffer(self.done, dtype=np.uint8) == 0)
        self.tell()
        with self.stopping():
            speed = 1.0
            if todo.size and size is None:
                first = [self.cases[int(k)] for k in todo[:MEASURED_CASES]]
                first_lines, speed = measure(self.plan, first, npts)
                self.save(first_lines)
                todo = todo[len(first_lines[0]) :]
            workers = sum(lane.workers for lane in lanes)
            chunks = make_chunks(self.plan, todo, npts, workers, size, speed)
            for chunk_rows in run_chunks(lanes, chunks, run_chunk_lines):
                self.save(chunk_rows)

    def save(self, done: ChunkLines | list[dict[str, Any]]) -> None:
        """Append a chunk's lines (or rows: the error rows of a chunk whose worker died) to
        cases.csv and count them saved."""
        try:
            if isinstance(done, tuple):
                ids = self.output.append_lines(*done)
            else:
                labels = (case_labels(self.plan, self.cases[r["case"]]) for r in done)
                ids = self.output.append([{**k, **r} for k, r in zip(labels, done, strict=True)])
        except PartialWrite as exc:
            self.mark(exc.ids)  # the lines that reached the disk before the error
            raise
        self.mark(ids)
        self.tell()

    def mark(self, ids: Iterable[int]) -> None:
        for k in ids:
            self.saved += not self.done[k]
            self.done[k] = 1

    def tell(self) -> None:
        if self.progress:
            self.progress(self.saved, len(self.cases))

    @contextmanager
    def stopping(self) -> Iterator[None]:
        """Errors of the block as :meth:`stopped` turns them."""
        try:
            yield
        except BaseException as exc:
            replaced = self.stopped(exc)
            if replaced is exc:
                raise
            raise replaced from None

    def stopped(self, exc: BaseException) -> BaseException:
        """The error to raise when the run stops: an interruption (Ctrl-C, and what it caused
        inside compiled code) or a write error, each saying how many cases are on disk;
        anything else as it came."""
        if interrupted(exc):
            return SweepInterrupted(self.saved, len(self.cases), str(self.output.folder))
        if isinstance(exc, OSError):  # a full disk, a folder turned read-only
            return InputError(
                f"cannot write the output folder: {exc.strerror or exc}; "
                f"{self.saved} of {len(self.cases)} cases saved",
                file=str(self.output.folder),
                where="--out",
                allowed="a writable folder with free space, then rerun with --resume",
            )
        return exc


def conclude(
    plan: StudyPlan,
    cases: Sequence[Case],
    output: Output,
    facts: Mapping[str, Mapping[str, Any]],
    run: Mapping[str, Any],
    parquet: bool,
) -> dict[str, Any]:
    """Sort cases.csv, write cases.parquet (when asked), the summary, and mark the study
    complete; the summary. The summary is made from cases.csv read back and checked
    (Output.checked_rows): a file this run did not write whole is never marked complete."""
    from rockcli.studies.sweep.output import PARQUET_FILE, write_parquet
    from rockcli.studies.sweep.summary import summarize

    try:
        output.finish()
        if parquet:
            write_parquet(output.cases_path, output.folder / PARQUET_FILE, output.header)
    except OSError as exc:
        raise InputError(
            f"cannot write the output folder: {exc.strerror or exc}; every case is in "
            f"{output.cases_path} (not sorted by case)",
            file=str(output.folder),
            where="--out",
            allowed="a writable folder with free space, then rerun with --resume",
        ) from None
    from rockcli.studies.sweep.output import result_kinds
    from rockcli.studies.sweep.summary import SUMMARY_COLUMNS, count_alike

    alike = count_alike(plan, output.checked_cells(SUMMARY_COLUMNS))
    summary = summarize(plan, alike, result_kinds(output.header), facts, run)
    output.write_summary(summary)
    return summary


def nothing_succeeded(plan: StudyPlan, output: Output) -> InputError:
    """The error of a study where every case failed: an input that gives no result at all is
    bad input (exit 2), not a study done; the first case's error, every case's in cases.csv
    (which, with summary.json, is written all the same)."""
    first = next(((k, row["error"]) for k, row in output.typed_rows() if row.get("error")), None)
    case, error = first if first is not None else (0, "")
    return InputError(
        f"no case of the study succeeded (each case's error is in {output.cases_path}); "
        f"case {case}: {error}",
        file=plan.file,
    )


def plot_rows(plan: StudyPlan, out: str) -> list[dict[str, Any]]:
    """Every case as the collapse map draws it (summary.case_rows), read back from the output
    folder's cases.csv (only a plot needs them all at once)."""
    from rockcli.studies.sweep.output import CASES_FILE, typed_rows
    from rockcli.studies.sweep.summary import case_rows

    return case_rows(plan, expand(plan), dict(typed_rows(Path(out) / CASES_FILE)))


def _label_cells(plan: StudyPlan, case: Case) -> list[str]:
    """The first cells of a case's row as written (its id, record and axis values)."""
    return [cell(v) for v in case_labels(plan, case).values()]
