"""The `rock sweep` summary as tables: the paper's Fig. 8 counts and the inconsistencies.

Built from the summary document only (rockcli.studies.sweep.summary), rendered by the one
generic renderer (:mod:`rockcli.terminal.table`).
"""

from __future__ import annotations

import unicodedata
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from rockcli.terminal.table import Column, Report, Table

COUNT_COLUMNS = (
    Column("cases", "cases", "", "{:d}"),
    Column("code_collapses", "code", "", "{:d}"),
    Column("rocking_collapses", "rocking", "", "{:d}"),
    Column("code_conservative", "code cons.", "", "{:d}"),
    Column("code_unconservative", "code uncons.", "", "{:d}", short="uncons."),
    Column("undetermined", "undetermined", "", "{:d}", short="undet."),
    Column("errors", "errors", "", "{:d}"),
    Column("sensitive_cases", "tol.-sensitive", "", "{:d}"),
)


def _cell(row: dict[str, Any], analyses: Sequence[str]) -> str:
    """A pivot cell: code / rocking collapses (and code-conservative cases), as run, and the
    cases without a verdict (``+n ?``): never shown as if they were zero collapses."""
    if len(analyses) == 1:
        key = "code_collapses" if analyses[0] == "kinematic" else "rocking_collapses"
        text = str(row[key])
    else:
        text = f"{row['code_collapses']} / {row['rocking_collapses']} ({row['code_conservative']})"
    unknown = row.get("undetermined") or 0
    return f"{text} +{unknown} ?" if unknown else text


def pivot(
    title: str, rows: list[dict[str, Any]], key: str, label: str, analyses: Sequence[str]
) -> Table:
    """Rows by `key`, one column per α, cells from :func:`_cell` (paper Fig. 8)."""
    alphas = sorted({r["alpha"] for r in rows}, key=lambda a: (a is None, a or 0.0))
    names = list(dict.fromkeys(r[key] for r in rows))
    cells: dict[Any, dict[str, Any]] = {n: {"name": n} for n in names}
    for r in rows:
        cells[r[key]][f"a{alphas.index(r['alpha'])}"] = _cell(r, analyses)
    cols = (
        Column("name", label, align="left"),
        *(
            Column(f"a{i}", "α unknown" if a is None else f"α = {a:.4g}", "rad")
            for i, a in enumerate(alphas)
        ),
    )
    return Table(title, cols, tuple(cells[n] for n in names))


def totals_table(doc: dict[str, Any]) -> Table:
    """Per record and in all: PGA, cases and the counts (of the analyses that ran)."""
    rows = [{"name": r["record"] or "(code demand)", **r} for r in doc["records"]]
    counts = tuple(c for c in COUNT_COLUMNS if doc.get(c.key) is not None)
    rows.append({"name": "all", **{c.key: doc[c.key] for c in counts}})
    cols = (Column("name", "record"), Column("pga_g", "PGA", "g", "{:.3f}"), *counts)
    return Table("Totals: collapses and inconsistencies", cols, tuple(rows))


def inconsistency_table(doc: dict[str, Any]) -> Table:
    """The paper's inconsistency count and share (§3.3: 14/26 = 54 %) and the opposite."""
    rows = (
        {
            "label": "code collapses, rocking survives (code conservative)",
            "count": doc["code_conservative"],
            "of": f"of {doc['code_collapses']} code collapses",
            "share": _percent(doc["inconsistency_share"]),
        },
        {
            "label": "rocking collapses, code passes (code unconservative)",
            "count": doc["code_unconservative"],
            "of": f"of {doc['rocking_collapses']} rocking collapses",
            "share": _percent(doc["unconservative_share"]),
        },
    )
    cols = (
        Column("label", ""),
        Column("count", "cases", "", "{:d}"),
        Column("of", "", align="left"),
        Column("share", "share"),
    )
    return Table("Inconsistencies (paper §3.3)", cols, rows)


def _percent(value: float | None) -> str | None:
    return None if value is None else f"{100 * value:.0f} %"


def printable(value: Any) -> Any:
    """Every text inside value with its control characters escaped (``\\x1b``), so that a
    name from a study or a record cannot drive the terminal (colours, cursor, title)."""
    if isinstance(value, str):
        return "".join(
            ch.encode("unicode_escape").decode("ascii")
            if unicodedata.category(ch) in ("Cc", "Cf") and ch != " "
            else ch
            for ch in value
        )
    if isinstance(value, dict):
        return {printable(k): printable(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return type(value)(printable(v) for v in value)
    return value


def sweep_report(doc: dict[str, Any]) -> Report:
    """The terminal report of a study summary (names with control characters escaped)."""
    doc = printable(doc)
    analyses = doc["analyses"]
    both = len(analyses) == 2
    what = "code / rocking collapses (code conservative)" if both else f"{analyses[0]} collapses"
    tables = [
        pivot(
            f"Per record and α: {what}",
            doc["by_record_alpha"],
            "record",
            "record",
            analyses,
        ),
    ]
    for name, rows in doc["by_axis_alpha"].items():
        tables.append(pivot(f"Per {name} and α: {what}", rows, name, name, analyses))
    tables.append(totals_table(doc))
    if both:
        tables.append(inconsistency_table(doc))
    notes = [
        *(
            [
                f"undetermined (+n ? in the tables): {doc['undetermined']} cases where a verdict"
                " was not reached (the code's non-linear check without d0* — positive global"
                " stiffness, no limit —, an undecided rocking run, or a failed case); not"
                " counted as collapses nor as survivals"
            ]
            if doc["undetermined"]
            else []
        ),
        *(
            [
                f"errors: {doc['errors']} cases failed; their message is in the error column of"
                f" {doc['out']}/cases.csv"
            ]
            if doc.get("errors")
            else []
        ),
        sensitive_note(doc),
        f"{doc['cases']} cases ({doc['computed_cases']} run now, {doc['resumed_cases']} from an "
        f"earlier run) in {doc['wall_time_s']:.2f} s; every case in {doc['out']}/cases.csv",
        *(suite_note(r) for r in doc["records"] if r.get("suite_records")),
        check_note(doc),
        *(
            f"record {s['name']} skipped: {s['path']} is absent"
            + (f" (get it from {s['source']})" if s["source"] else "")
            for s in doc["skipped_records"]
        ),
    ]
    return Report(
        title=f"rock sweep — {doc['name']}",
        tables=tuple(tables),
        notes=tuple(n for n in notes if n),
        warnings=tuple(doc.get("warnings", ())),
    )


def sensitive_note(doc: dict[str, Any]) -> str | None:
    """What the tolerance check found (--check-tolerance), in words."""
    count = doc.get("sensitive_cases")
    if count is None:
        return None
    from rockcli.dynamics.tolerance import SENSITIVE_CHANGE, TIGHT_FACTOR

    return (
        f"tolerance check: each rocking case again at its tolerances over {TIGHT_FACTOR:g}; "
        f"{count} of {doc['cases']} cases tolerance-sensitive (max θ/α moved by more than "
        f"{100 * SENSITIVE_CHANGE:g} % or the overturning verdict changed: read their values "
        "as uncertain by that much; the sensitive column of cases.csv names them)"
    )


def check_note(doc: dict[str, Any]) -> str | None:
    """Say when not every model of the grid was validated before the study ran."""
    points = 1
    for axis in doc["axes"]:
        points *= len(axis["values"])
    checked = doc.get("checked_up_front")
    if checked is None or checked >= points:
        return None
    return (
        f"{checked} of the grid's {points} models were validated before the study ran (every "
        "value of every axis); the others as they ran: a case that is not a valid model is a "
        "row with its error"
    )


#: How a suite case's rocking verdict is reached (rockcli.studies.sweep.over_suite).
SUITE_RULE_TEXT = {
    "mean": "the mean of max θ/α over its records",
    "worst": "the largest max θ/α of its records",
}


def suite_note(row: dict[str, Any]) -> str:
    """What a suite entry of the study is: its records, the rule, its compatibility."""
    compatible = "compatible" if row["compatible"] else "NOT compatible"
    return (
        f"{row['record']}: a suite of {row['suite_records']} records (each case counts once): "
        f"rocking by {SUITE_RULE_TEXT[row['rule']]} against the model's {row['limit_state']} "
        f"limit, the code at {row['limit_state']} on its target; mean spectrum / target "
        f"{row['min_ratio']:.3f}–{row['max_ratio']:.3f}: {compatible}"
    )


@contextmanager
def progress_bar(
    show: bool | None, what: str = "cases"
) -> Iterator[Callable[[int, int], None] | None]:
    """A rich progress bar on stderr, as a callback (done, total); None when off.

    show: True, False, or None for "when stderr is a terminal". what: what it counts.
    """
    from rich.console import Console
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    console = Console(stderr=True)
    if not (console.is_terminal if show is None else show):
        yield None
        return
    columns = (BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TimeRemainingColumn())
    with Progress(what, *columns, console=console, transient=False) as bar:
        task = bar.add_task(what, total=None)

        def update(done: int, total: int) -> None:
            bar.update(task, completed=done, total=total)

        yield update
