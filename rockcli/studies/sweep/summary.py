"""The summary of a study: the paper's counts of collapses and inconsistencies.

Paper §3.3 (Fig. 8): collapses per record and slenderness α, by the code (non-linear ULS
check not satisfied) and by the rocking analysis (overturning in either polarity); an
*inconsistency* is a case the code says collapses and the rocking analysis says survives
(14 of the 26 code collapses, 54 %), the opposite case is counted too (never met in the
paper). §4.4 (Fig. 17) breaks the counts down by the restrainer stiffness K: any axis that
does not set the geometry gets its own table by value and α.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Hashable, Iterable, Mapping, Sequence
from typing import Any

from rockcli.studies.sweep.cases import Case
from rockcli.studies.sweep.study import StudyPlan
from rockcli.version import __version__

SCHEMA = 1
#: Digits α is rounded to when grouping cases by slenderness (α from thickness and height is
#: computed, so equal slenderness may differ in the last bits).
ALPHA_DIGITS = 10


def code_collapse(row: Mapping[str, Any]) -> bool | None:
    """The code's collapse verdict: its ULS check not satisfied (None: not evaluated); for a
    suite case, its check of the suite target's limit state (``code_state``)."""
    verdict = row.get("code_state") if row.get("limit_state") else row.get("code_uls")
    return None if verdict is None else verdict == "fail"


#: The rocking verdicts that are a collapse: a record overturns the block, or a suite's
#: measure reaches its limit (rockcli.studies.sweep.over_suite).
COLLAPSES = ("overturns", "fails")


def rocking_collapse(row: Mapping[str, Any]) -> bool | None:
    """The rocking verdict: overturning in either polarity, or a suite that fails the code's
    rule (None: not run or undecided)."""
    verdict = row.get("rocking")
    return None if verdict in (None, "undecided") else verdict in COLLAPSES


#: The counts that need each analysis (None in the summary when it did not run).
NEEDS = {
    "code_collapses": {"kinematic"},
    "rocking_collapses": {"rocking"},
    "code_conservative": {"kinematic", "rocking"},
    "code_unconservative": {"kinematic", "rocking"},
    "consistent_safe": {"kinematic", "rocking"},
    "consistent_unsafe": {"kinematic", "rocking"},
}


def undetermined(row: Mapping[str, Any], analyses: Iterable[str]) -> bool:
    """True when an analysis that ran gave no verdict: a failed case (its ``error``), the
    code's check not evaluated, or an undecided rocking run (step or event limit). Such a
    case is neither a collapse nor a survival: the summary counts it apart."""
    ran = set(analyses)
    return bool(
        row.get("error")
        or ("kinematic" in ran and code_collapse(row) is None)
        or ("rocking" in ran and row.get("rocking") == "undecided")
    )


#: The counts of a set of cases.
COUNT_KEYS = (
    "cases",
    "code_collapses",
    "rocking_collapses",
    "code_conservative",
    "code_unconservative",
    "consistent_safe",
    "consistent_unsafe",
    "undetermined",
    "errors",
    "sensitive_cases",
)


class Counts:
    """The counts of a set of cases, one case at a time (a study's summary streams its rows:
    no per-case object is kept)."""

    def __init__(self, analyses: Iterable[str]) -> None:
        self.ran = set(analyses)
        self.counts = dict.fromkeys(COUNT_KEYS, 0)
        self.checked = False  # a row carried the tolerance check's column

    def add(self, row: Mapping[str, Any], times: int = 1) -> None:
        """Count one case (or ``times`` cases alike)."""
        out = self.counts
        out["cases"] += times
        out["code_collapses"] += times * (code_collapse(row) is True)
        out["rocking_collapses"] += times * (rocking_collapse(row) is True)
        kind = row.get("classification")
        if kind is not None and kind != "undetermined":
            out[kind.replace("-", "_")] += times
        out["undetermined"] += times * undetermined(row, self.ran)
        out["errors"] += times * bool(row.get("error"))
        if "sensitive" in row:  # --check-tolerance (output.TOLERANCE_COLUMNS)
            self.checked = True
            out["sensitive_cases"] += times * (row["sensitive"] is True)

    def result(self) -> dict[str, int | None]:
        """The counts (None: the analyses behind a count did not run; sensitive_cases: the
        study was not run with --check-tolerance)."""
        return {
            k: v
            if NEEDS.get(k, set()) <= self.ran and (k != "sensitive_cases" or self.checked)
            else None
            for k, v in self.counts.items()
        }


def tally(rows: Iterable[Mapping[str, Any]], analyses: Iterable[str]) -> dict[str, int | None]:
    """The counts of a set of cases (None: the analyses behind a count did not run)."""
    counts = Counts(analyses)
    for row in rows:
        counts.add(row)
    return counts.result()


def share(part: int | None, whole: int | None) -> float | None:
    """part/whole, None when either is unknown or whole is 0."""
    return part / whole if part is not None and whole else None


def grouped(
    rows: Sequence[Mapping[str, Any]],
    key: Callable[[Mapping[str, Any]], tuple[Hashable, ...]],
    analyses: Iterable[str],
) -> list[tuple[tuple[Hashable, ...], dict[str, int | None]]]:
    """The tally of each group, groups in order of their key."""
    groups: dict[tuple[Hashable, ...], list[Mapping[str, Any]]] = {}
    for row in rows:
        groups.setdefault(key(row), []).append(row)
    return [(k, tally(groups[k], analyses)) for k in sorted(groups, key=sort_key)]


def sort_key(key: tuple[Hashable, ...]) -> tuple[tuple[int, Any], ...]:
    """An order for group keys whatever their parts: numbers, then text, then None (an axis
    may mix numbers and text; a failed case may have no α)."""
    out: list[tuple[int, Any]] = []
    for part in key:
        if isinstance(part, int | float) and not isinstance(part, bool):
            out.append((0, part))
        elif part is None:
            out.append((2, ""))
        else:
            out.append((1, str(part)))
    return tuple(out)


#: The result columns the summary reads (output.RESULT_COLUMNS, output.TOLERANCE_COLUMNS).
SUMMARY_COLUMNS = (
    "block_alpha",
    "error",
    "code_uls",
    "code_state",
    "limit_state",
    "rocking",
    "classification",
    "sensitive",
    "suite_records",
)

#: Cases alike for the summary: (record index, the indices of the axes that get their own
#: table, the SUMMARY_COLUMNS' cells as written).
Alike = tuple[int, tuple[int, ...], tuple[str, ...]]


def split_axes(plan: StudyPlan) -> list[int]:
    """The axes that do not set the geometry (each gets its own table by value and α)."""
    return [i for i, a in enumerate(plan.axes) if any(p[0] != "geometry" for p in a.paths)]


def count_alike(plan: StudyPlan, cells: Iterable[tuple[int, tuple[str, ...]]]) -> dict[Alike, int]:
    """How many cases are alike for the summary (:data:`Alike`), from each case id and its
    SUMMARY_COLUMNS' cells (output.Output.checked_cells): one dictionary entry per kind of
    case, not per case, so a study of 10⁶ cases is summarised in seconds."""
    sizes = [len(a.values) for a in plan.axes]
    points = math.prod(sizes)
    strides = [math.prod(sizes[i + 1 :]) for i in range(len(sizes))]
    split = [(strides[i], sizes[i]) for i in split_axes(plan)]
    counts: dict[Alike, int] = {}
    for k, row in cells:
        record, point = divmod(k, points)
        key = (record, tuple(point // stride % size for stride, size in split), row)
        counts[key] = counts.get(key, 0) + 1
    return counts


def summarize(
    plan: StudyPlan,
    alike: Mapping[Alike, int],
    kinds: Mapping[str, type],
    records: Mapping[str, Mapping[str, Any]],
    run: Mapping[str, Any],
) -> dict[str, Any]:
    """The summary document (`rock sweep --format json`, schema 1), from the counts of the
    cases alike (:func:`count_alike`; memory: the groups' counts, not the cases).

    Args:
        plan: the study. alike: how many cases of each kind (:data:`Alike`).
        kinds: the result columns of cases.csv and their types (output.result_kinds): a
            column the file does not have is not in a case's row.
        records: per record name, its pga_g, npts, duration_s, path, warnings.
        run: facts of this run (out, wall_time_s, computed, resumed, jobs, scheduler).
    """
    analyses = plan.analyses
    total = Counts(analyses)
    by_record: dict[tuple[Hashable, ...], Counts] = {}
    by_record_alpha: dict[tuple[Hashable, ...], Counts] = {}
    split = split_axes(plan)
    by_axis: dict[int, dict[tuple[Hashable, ...], Counts]] = {i: {} for i in split}
    runs = 0
    for (record_index, split_index, cells), n in alike.items():
        row = _row(plan, cells, kinds)
        total.add(row, n)
        runs += n * 2 * (row.get("suite_records") or 1)
        name = plan.records[record_index].name if plan.records else None
        record = (record_index if plan.records else -1, name)
        _group(by_record, record, analyses).add(row, n)
        _group(by_record_alpha, (*record, row["_alpha"]), analyses).add(row, n)
        for i, index in zip(split, split_index, strict=True):
            key = (index, plan.axes[i].label(index), row["_alpha"])
            _group(by_axis[i], key, analyses).add(row, n)
    counts = total.result()
    records_rows = [
        {"record": k[1], **(records.get(str(k[1])) or {}), **c.result()}
        for k, c in _sorted(by_record)
    ]
    alpha_rows = [
        {"record": k[1], "alpha": k[2], **c.result()} for k, c in _sorted(by_record_alpha)
    ]
    axis_rows = {
        plan.axes[i].name: [
            {plan.axes[i].name: k[1], "alpha": k[2], **c.result()} for k, c in _sorted(by_axis[i])
        ]
        for i in split
    }
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "study": plan.file,
        "name": plan.name,
        "analyses": list(analyses),
        **counts,
        "runs": runs if "rocking" in analyses else 0,
        "check_tolerance": plan.check_tolerance,
        "inconsistency_share": share(counts["code_conservative"], counts["code_collapses"]),
        "unconservative_share": share(counts["code_unconservative"], counts["rocking_collapses"]),
        "axes": [
            {
                "name": a.name,
                "paths": list(a.texts),
                "values": [a.label(i) for i in range(len(a.values))],
            }
            for a in plan.axes
        ],
        "records": records_rows,
        "skipped_records": [
            {"name": s.name, "path": s.path, "source": s.source} for s in plan.skipped
        ],
        "by_record_alpha": alpha_rows,
        "by_axis_alpha": axis_rows,
        **run,
        "warnings": [
            f"record {name}: {warning}"
            for name, fact in records.items()
            for warning in fact.get("warnings", ())
        ],
    }


def _group(
    groups: dict[tuple[Hashable, ...], Counts], key: tuple[Hashable, ...], analyses: Iterable[str]
) -> Counts:
    found = groups.get(key)
    if found is None:
        found = groups[key] = Counts(analyses)
    return found


def _sorted(
    groups: dict[tuple[Hashable, ...], Counts],
) -> list[tuple[tuple[Hashable, ...], Counts]]:
    return [(k, groups[k]) for k in sorted(groups, key=sort_key)]


def _row(plan: StudyPlan, cells: Sequence[str], kinds: Mapping[str, type]) -> dict[str, Any]:
    """The SUMMARY_COLUMNS of a kind of case as values (those of cases.csv's columns), with
    its α rounded for grouping."""
    from rockcli.studies.sweep.output import parse_cell, unescape

    row = {
        name: parse_cell(unescape(text), kinds[name])
        for name, text in zip(SUMMARY_COLUMNS, cells, strict=True)
        if name in kinds
    }
    alpha = row.get("block_alpha")
    row["_alpha"] = round(alpha, ALPHA_DIGITS) if alpha is not None else None
    return row


def case_rows(
    plan: StudyPlan, cases: Sequence[Case], results: Mapping[int, Mapping[str, Any]]
) -> list[dict[str, Any]]:
    """Every case as the collapse map draws it (rockcli.plots.plot_sweep): the block's
    R and α, the record, the two collapse verdicts, and the axis values by axis name."""
    rows = []
    for case in cases:
        result = results[case.id]
        rows.append(
            {
                **{a.name: a.label(i) for a, i in zip(plan.axes, case.indices, strict=True)},
                "R": result.get("block_R"),
                "alpha": result.get("block_alpha"),
                "record": plan.records[case.record].name if case.record is not None else "",
                "code_collapse": code_collapse(result),
                "rocking_collapse": rocking_collapse(result),
                "classification": result.get("classification"),
                "error": result.get("error"),
            }
        )
    return rows


def split_axis(plan: StudyPlan) -> str | None:
    """The first axis that does not set the geometry (the stiffness K of §4.4), if any."""
    return next((a.name for a in plan.axes if any(p[0] != "geometry" for p in a.paths)), None)
