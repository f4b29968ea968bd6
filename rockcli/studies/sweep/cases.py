"""The cases of a study: records × the product of the axes, each a validated model.

Case ids are the position in that product, records outermost and the axes in the order of
the file (the first axis outermost), so a study file and its records give the same ids on
every run and every machine: results are keyed by them, whatever order they complete in.
Every case is the base model's table with the axis values set, validated by
:func:`rockcli.model.load.validate_model` (never ``model_copy(update=…)``, which does not
validate: spec/style.md, principle 2).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, overload

from rockcli.errors import InputError
from rockcli.model.schema import Model
from rockcli.studies.sweep.paths import with_values
from rockcli.studies.sweep.study import StudyPlan, relative_to_study


@dataclass(frozen=True)
class Case:
    """One case: its id, the record (index into the plan's records) and each axis' index."""

    id: int
    record: int | None
    indices: tuple[int, ...]


def axis_points(plan: StudyPlan) -> list[tuple[int, ...]]:
    """The product of the axes' value indices, first axis outermost."""
    return list(itertools.product(*(range(len(a.values)) for a in plan.axes)))


class Cases(Sequence[Case]):
    """Every case of a study by id (records outermost, then the axes, the first outermost;
    no record: the kinematic check on the model's own code demand), each made when it is
    asked for: a study of 10⁶ cases holds no list of them."""

    def __init__(self, plan: StudyPlan) -> None:
        self.sizes = [len(a.values) for a in plan.axes]
        self.points = math.prod(self.sizes)
        self.records = len(plan.records)

    def __len__(self) -> int:
        return (self.records or 1) * self.points

    @overload
    def __getitem__(self, k: int) -> Case: ...

    @overload
    def __getitem__(self, k: slice) -> list[Case]: ...

    def __getitem__(self, k: int | slice) -> Case | list[Case]:
        if isinstance(k, slice):
            return [self[i] for i in range(*k.indices(len(self)))]
        n = len(self)
        if k < 0:
            k += n
        if not 0 <= k < n:
            raise IndexError(k)
        record, point = divmod(k, self.points)
        indices = []
        for size in reversed(self.sizes):
            point, index = divmod(point, size)
            indices.append(index)
        return Case(k, record if self.records else None, tuple(reversed(indices)))


def expand(plan: StudyPlan) -> Cases:
    """Every case of the study, by id (:class:`Cases`)."""
    return Cases(plan)


def case_label(plan: StudyPlan, case: Case) -> str:
    """``case 12 (R = 1.5, alpha = 0.05, record ELC180)``: how errors name a case."""
    parts = [f"{a.name} = {a.label(i)}" for a, i in zip(plan.axes, case.indices, strict=True)]
    if case.record is not None:
        parts.append(f"record {plan.records[case.record].name}")
    return f"case {case.id}" + (f" ({', '.join(parts)})" if parts else "")


def case_labels(plan: StudyPlan, case: Case) -> dict[str, Any]:
    """The case's id, record and axis values: the first columns of its row."""
    return {
        "case": case.id,
        "record": plan.records[case.record].name if case.record is not None else None,
        **{a.name: a.label(i) for a, i in zip(plan.axes, case.indices, strict=True)},
    }


def case_error(plan: StudyPlan, case: Case, exc: InputError) -> InputError:
    """A case's bad input as one line naming the study file and the case's axis values."""
    inner = ": ".join(x for x in (exc.where, exc.problem) if x)
    if exc.file and exc.file != plan.base_file:
        inner = f"{relative_to_study(plan.file, exc.file)}: {inner}"
    return InputError(
        inner, file=plan.file, where=case_label(plan, case), value=exc.value, allowed=exc.allowed
    )


def case_table(plan: StudyPlan, case: Case) -> dict[str, Any]:
    """The model table of a case: the base with the axis values set."""
    return with_values(plan.base, plan.axes, case.indices)


def build_model(plan: StudyPlan, case: Case) -> Model:
    """The validated model of a case; InputError naming the case otherwise."""
    from rockcli.model.load import validate_model

    try:
        return validate_model(case_table(plan, case), file=plan.base_file)
    except InputError as exc:
        raise case_error(plan, case, exc) from None


#: Grid points whose models are all validated before any work. A larger grid has a covering
#: subset validated up front (every value of every axis at least once, and the corner of the
#: last values); the workers validate every case as they run it, and a case that is not a
#: valid model is then a row with its error (validating 10⁶ models first took 3 minutes).
CHECK_ALL_UP_TO = 20_000


def check_cases(plan: StudyPlan, check: Callable[[Model], None] | None = None) -> int:
    """Validate the models of the grid's points (the record does not change the model) so that
    a bad case stops the study before any work: every point up to CHECK_ALL_UP_TO, else a
    covering subset (:func:`covering_points`). The error names the case of the first record
    (its id is the point's index) by its axis values. check: what else each model must allow
    (InputError otherwise; rockcli.studies.sweep.over_suite.suite_checks). Returns how many points
    were checked."""
    sizes = [len(a.values) for a in plan.axes]
    total = math.prod(sizes)
    points = axis_points(plan) if total <= CHECK_ALL_UP_TO else covering_points(sizes)
    for point in points:
        model = build_model(plan, Case(point_id(point, sizes), None, tuple(point)))
        if check is not None:
            check(model)
    return len(points)


def covering_points(sizes: list[int]) -> list[tuple[int, ...]]:
    """Every value of every axis at least once (the others at their first value), and the
    point of every axis at its last value."""
    points = {tuple(sizes[k] - 1 for k in range(len(sizes)))}
    for k, size in enumerate(sizes):
        for v in range(size):
            points.add(tuple(v if j == k else 0 for j in range(len(sizes))))
    return sorted(points)


def point_id(point: tuple[int, ...] | list[int], sizes: list[int]) -> int:
    """The point's place in the product of the axes (first axis outermost)."""
    index = 0
    for v, size in zip(point, sizes, strict=True):
        index = index * size + v
    return index
