"""Run a fragility study: one task per grid point and record, on the sweep's executors.

A task prepares the model's rocked block under its record once (rockcli.studies.fragility.response)
and runs the record scaled to each intensity the method asks for:

- IDA: the hunt-and-fill search of each damage state's first exceedance
  (rockcli.studies.fragility.search), over the study's scan of intensities;
- MSA: each of the study's intensity levels.

Every intensity measure is linear in the record's scale (PGA, PGV and Sa are linear in the
accelerations; the dimensionless ones divide them by constants of the block), so the record
reaches the intensity x at the scale x / IM(record at scale 1). The measure is the ground
motion's, also for a block at height (the earthquake's intensity, as a hazard curve gives it;
docs/fragility.md).

A task is given the runs already on disk (``known``, from an earlier run of the same study) and
computes only the others; the search over them is deterministic, so the main process finds
the same exceedances from the runs alone (:func:`exceedances`).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rockcli.errors import InputError
from rockcli.studies.fragility.search import Exceedance, first_exceedances
from rockcli.studies.fragility.study import FragilityPlan, Measure

if TYPE_CHECKING:
    from rockcli.records.record import Record
    from rockcli.studies.fragility.response import ScaledRun


@dataclass(frozen=True)
class Task:
    """One grid point under one record (picklable: sent to a worker).

    Attributes:
        id: the task's index (records outermost, then the grid's points).
        point: the grid point's index. indices: each axis' value index.
        record: the record's index in the study's records.
        known: responses already on disk, by intensity.
    """

    plan: FragilityPlan
    id: int
    point: int
    indices: tuple[int, ...]
    record: int
    known: Mapping[float, float] = field(default_factory=dict)

    @property
    def cases(self) -> tuple[Task]:
        """The task as one case (rockcli.studies.parallel.chunks: a chunk's cases)."""
        return (self,)


@dataclass(frozen=True)
class TaskResult:
    """What a task found.

    Attributes:
        id: the task's id. mechanism: the rocked mechanism's name (None: a block).
        unit_im: the record's intensity at scale 1 (None when the task failed before).
        runs: max θ/α (inf: overturned) by intensity, every run of the task.
        new: the intensities run by this task (not on disk before).
        error: why the task failed (one line), or None.
    """

    id: int
    mechanism: str | None
    unit_im: float | None
    runs: dict[float, float]
    new: tuple[float, ...] = ()
    error: str | None = None


def tasks(
    plan: FragilityPlan, known: Mapping[int, Mapping[float, float]] | None = None
) -> list[Task]:
    """Every task of the study, records outermost (ids as in cases.csv)."""
    from rockcli.studies.sweep.cases import axis_points

    points = axis_points(plan.study)
    known = known or {}
    out = []
    for r in range(len(plan.study.records)):
        for p, indices in enumerate(points):
            k = r * len(points) + p
            out.append(Task(plan, k, p, indices, r, known.get(k, {})))
    return out


def run_task(task: Task) -> TaskResult:
    """The task's runs; a failure is the result's error (the study goes on)."""
    from rockcli.studies.fragility.spectrum import UndecidedRun
    from rockcli.studies.sweep.worker import one_line

    runs: dict[float, float] = dict(task.known)
    mechanism = unit = None
    try:
        rocker, record = prepared(task)
        mechanism = rocker.mechanism
        unit = unit_intensity(task.plan, rocker, record)
        respond(task.plan, cached(runs, lambda im: rocker.response(im / unit)))
    except (InputError, UndecidedRun) as exc:
        return TaskResult(task.id, mechanism, unit, runs, _new(task, runs), one_line(str(exc)))
    except Exception as exc:  # noqa: BLE001 - any failure of one task is that task's row
        text = f"internal error (please report): {type(exc).__name__}: {exc}"
        return TaskResult(task.id, mechanism, unit, runs, _new(task, runs), one_line(text))
    return TaskResult(task.id, mechanism, unit, runs, _new(task, runs))


def cached(runs: dict[float, float], run: Callable[[float], float]) -> Callable[[float], float]:
    """``run`` computed once per intensity, kept in ``runs`` (which may hold some already)."""

    def response(im: float) -> float:
        if im not in runs:
            runs[im] = run(im)
        return runs[im]

    return response


def _new(task: Task, runs: Mapping[float, float]) -> tuple[float, ...]:
    return tuple(im for im in runs if im not in task.known)


def prepared(task: Task) -> tuple[ScaledRun, Record]:
    """The task's model, its rocked block and the record (InputError naming the case)."""
    from rockcli.studies.fragility.response import prepare
    from rockcli.studies.sweep.cases import Case, build_model, case_error
    from rockcli.studies.sweep.worker import read_source

    study = task.plan.study
    case = Case(task.id, task.record, task.indices)
    model = build_model(study, case)
    record = read_source(study.records[task.record])
    try:
        rocker = prepare(
            model,
            record,
            mechanism=task.plan.mechanism,
            ground=study.ground,
            engine=study.engine,
            file=study.base_file,
        )
    except InputError as exc:
        raise case_error(study, case, exc) from None
    return rocker, record


def unit_intensity(plan: FragilityPlan, rocker: ScaledRun, record: Record) -> float:
    """The record's intensity at scale 1 (of the ground motion: module docstring).

    Raises:
        InputError: the record cannot give it (zero, or not finite).
    """
    from rockcli.studies.fragility import intensity

    block = rocker.block
    g = block.g
    measure = Measure(plan.measure)
    try:
        if measure in (Measure.PGA, Measure.PGA_RATIO):
            value = intensity.pga(record.accel)
        elif measure in (Measure.PGV, Measure.PGV_RATIO):
            value = intensity.pgv(record.time, record.accel, g)
        else:
            period = 2.0 * math.pi / block.p if plan.period == "mechanism" else plan.period
            assert isinstance(period, float)
            value = intensity.sa(record.time, record.accel, period, g)
        if measure == Measure.PGA_RATIO:
            value = intensity.pga_ratio(value, block.uplift_acceleration)
        elif measure == Measure.PGV_RATIO:
            value = intensity.pgv_ratio(value, block.p, block.uplift_acceleration, g)
    except ValueError as exc:
        raise InputError(
            str(exc), where=f"record {record.name}", allowed="a record with finite samples"
        ) from None
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(
            f"the record gives no {plan.measure_label}",
            where=f"record {record.name}",
            value=value,
            allowed="a record whose intensity measure is finite and > 0",
        )
    return value


def respond(plan: FragilityPlan, response: Callable[[float], float]) -> None:
    """Run the method's intensities through ``response`` (max θ/α by intensity): IDA's
    search, or MSA's levels."""
    if plan.method == "msa":
        for level in plan.levels:
            response(level)
    else:
        ida_search(plan, response)


def ida_search(plan: FragilityPlan, response: Callable[[float], float]) -> list[Exceedance]:
    """IDA: each damage state's first exceedance by ``response``, over the study's scan."""
    assert plan.scan is not None
    first, step, last, tolerance = plan.scan
    levels = [s.level for s in plan.states]
    found, _ = first_exceedances(
        response, levels, first=first, step=step, last=last, tolerance=tolerance
    )
    return found


def exceedances(plan: FragilityPlan, runs: Mapping[float, float]) -> list[Exceedance]:
    """IDA: each state's first exceedance, found again from the task's runs alone.

    Raises:
        KeyError: a run the search needs is not among them (an incomplete task).
    """
    return ida_search(plan, lambda im: runs[im])


def stripe_counts(
    plan: FragilityPlan, results: Sequence[TaskResult], level: float
) -> tuple[list[int], list[int]]:
    """MSA: at each intensity level, the records run and those whose response reaches the
    damage state's level (failed tasks left out)."""
    runs, hits = [], []
    for x in plan.levels:
        values = [r.runs[x] for r in results if r.error is None and x in r.runs]
        runs.append(len(values))
        hits.append(sum(v >= level for v in values))
    return runs, hits


def task_labels(plan: FragilityPlan, task: Task) -> dict[str, Any]:
    """The first cells of a task's lines: its point, axis values and record."""
    study = plan.study
    return {
        "point": task.point,
        **{a.name: a.label(i) for a, i in zip(study.axes, task.indices, strict=True)},
        "record": study.records[task.record].name,
    }
