"""A record suite's reports: `rock suite check` (the records, the compatibility table, the
verdict) and the suite's time history (the records' max θ/α, the code's rule, the verdict).

The time history's JSON contract (issue 10): ``suite`` = {"n", "rule": "mean" | "worst",
"measure", "limit_ratio", "verdict", "overturned_records", "records": [{"name", "scale",
"pga_g", "max_ratio", "overturned"}], "compatibility": {"passed", "period_range": [a, b],
"min_ratio", "max_ratio"} or null}. Beside it, the tolerance check (rockcli.dynamics.tolerance)
of every record: ``sensitive`` (true when a record's result depends on the integration
tolerance, null when one's is not known) and ``sensitive_records`` (their names), each with its
warning in words.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from rockcli.studies.suite_run.assess import SuiteAssessment
from rockcli.studies.suite_run.compare import SuiteComparison
from rockcli.studies.suite_run.rule import SuiteMeasure
from rockcli.terminal.table import Column, Report, Table, key_value

#: What the code does with a suite of this size (NTC §3.2.3.6).
COUNT_TEXT = {
    "mean": "{n} records: 7 or more, the mean effect of the records may be used",
    "worst": "{n} records: 3 to 6, the worst effect of the records must be used (7 or more "
    "for the mean)",
}


def band_text(tolerance: list[float | None]) -> str:
    """The band as the user reads it: −10 %/+30 %, or −10 %/no upper bound; each bound to
    the digits it has (a file's −0.999 and 0.001 are −99.9 % and +0.1 %, not −100 % and
    +0 %, which would be no lower bound and no room above the target)."""
    lo, hi = tolerance
    lower = "no lower bound" if lo is None else percent(lo)
    upper = "no upper bound" if hi is None else percent(hi)
    return f"{lower} / {upper}"


def percent(fraction: float) -> str:
    """A fraction as a signed percentage to six significant digits, none of them trailing
    zeros: 0.3 is +30%, 0.001 is +0.1%."""
    return f"{fraction * 100.0:+g}%"


def verdict_line(numbers: dict[str, Any], doc: dict[str, Any]) -> str:
    """compatible or NOT, the worst ratio and its period."""
    word = "compatible" if numbers["passed"] else "NOT compatible"
    return (
        f"{word} over {doc['period_range'][0]:g}–{doc['period_range'][1]:g} s "
        f"(band {band_text(doc['tolerance'])}): worst mean/target "
        f"{numbers['worst_ratio']:.3f} at T = {numbers['worst_period']:.3g} s"
    )


def records_table(doc: dict[str, Any]) -> Table:
    """Per record: name, scale, PGA (of the scaled record; and of its floor motion at
    height)."""
    columns: tuple[Column, ...] = (
        Column("name", "record"),
        Column("scale", "scale", "-", "{:.4g}"),
        Column("pga_g", "PGA", "g", "{:.4g}"),
    )
    if doc.get("at_height"):
        columns += (Column("floor_pga_g", "floor PGA", "g", "{:.4g}"),)
    return Table("Records", columns, tuple(doc["records"]))


def compatibility_table(doc: dict[str, Any]) -> Table:
    """At every period of the grid: target, mean, ratio, within the band."""
    rows = tuple(
        {"T": T, "target": t, "mean": m, "ratio": r, "within": "yes" if w else "NO"}
        for T, t, m, r, w in zip(
            doc["periods"], doc["target"], doc["mean"], doc["ratio"], doc["within"], strict=True
        )
    )
    columns = (
        Column("T", "period", "s", "{:.3g}"),
        Column("target", "target Se", "g", "{:.4g}"),
        Column("mean", "mean Sa", "g", "{:.4g}"),
        Column("ratio", "mean/target", "-", "{:.3f}", short="ratio"),
        Column("within", "within band", short="within"),
    )
    return Table("Compatibility (5 % damping)", columns, rows)


def target_table(doc: dict[str, Any]) -> Table:
    """The target spectrum's parameters."""
    p = doc["target_parameters"]
    return key_value(
        "Target spectrum",
        [
            ("limit state", p["limit_state"], "", ""),
            ("edition", f"NTC {p['edition']}", "", ""),
            ("TR", p["TR"], "years", "{:.0f}"),
            ("ag", p["ag"], "g", "{:.4g}"),
            ("F0", p["F0"], "-", "{:.4g}"),
            ("TC*", p["Tc_star"], "s", "{:.4g}"),
            ("soil, topography", f"{p['soil']}, {p['topography']}", "", ""),
            ("S", p["S"], "-", "{:.4g}"),
            ("from", p["source"], "", ""),
            *height_rows(doc.get("at_height")),
        ],
    )


def height_rows(h: dict[str, Any] | None) -> list[tuple[str, Any, str, str]]:
    """The floor the target is moved to (--model at height)."""
    if not h:
        return []
    return [
        ("at height Z", h["Z"], "m", "{:g}"),
        ("building T1, ψ, γ, ξ", f"{h['T1']:.3g} s, {h['psi']:.3g}, {h['gamma']:.3g}, "
         f"{h['xi']:g}", "", ""),
        ("floor acceleration a_Z", h["a_z"], "g", "{:.4g}"),
        ("target", "floor spectrum S_eZ (Circ. 7/2019 §C7.2.3), 5 %", "", ""),
    ]  # fmt: skip


#: What the check compares at a block's height.
HEIGHT_NOTE = (
    "at height: each record's floor motion (ü_g + γ·ψ·ẍ₁ of the building's first mode, what "
    "the block rocks on in rock assess) against the code's floor spectrum at Z, both at 5 %"
)


def suite_report(doc: dict[str, Any]) -> Report:
    """The Report of a suite check document."""
    notes = [COUNT_TEXT[doc["count_rule"]].format(n=doc["count"])]
    if doc.get("at_height"):
        notes.append(HEIGHT_NOTE)
    verdict = verdict_line({"passed": doc["passed"], **doc}, doc)
    auto = doc.get("scale_auto")
    if auto is not None:
        notes.append(auto_line(auto, doc))
    return Report(
        title=f"rock suite check — {doc['suite']}",
        tables=(records_table(doc), target_table(doc), compatibility_table(doc)),
        notes=tuple(notes),
        verdict=verdict,
        warnings=tuple(doc.get("warnings", ())),
    )


def auto_line(auto: dict[str, Any], doc: dict[str, Any]) -> str:
    """--scale auto: the factor and the verdict with it, or why no factor passes."""
    if auto["factor"] is None:
        return (
            "--scale auto: the mean is zero at some period: no factor makes this suite compatible"
        )
    head = f"--scale auto: common factor {auto['factor']:.4g} (smallest ratio on the lower bound)"
    if not auto["feasible"]:
        return (
            f"{head}; with it the largest ratio is {auto['max_ratio']:.3f}, above the upper "
            "bound: no common factor makes this suite compatible"
        )
    return f"{head}; with it: {verdict_line(auto, doc)}"


# --- the suite in the time history -----------------------------------------------------

HISTORY_COLUMNS = (
    Column("name", "record", ""),
    Column("scale", "scale", "", "{:.4g}"),
    Column("pga_g", "PGA", "g", "{:.4f}"),
    Column("max_ratio", "max θ/α", "", "{:.4f}"),
    Column("overturned", "overturned", ""),
)


def history_document(
    measure: SuiteMeasure,
    rows: Sequence[Mapping[str, Any]],
    compatibility: Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """The ``suite`` section of assess/compare JSON with a suite."""
    return {
        "n": measure.n,
        "rule": measure.rule,
        "measure": measure.measure,
        "limit_ratio": measure.limit_ratio,
        "verdict": "passes" if measure.passed else "fails",
        "overturned_records": measure.overturned_records,
        "records": [
            {k: r[k] for k in ("name", "scale", "pga_g", "max_ratio", "overturned")} for r in rows
        ],
        "compatibility": None if compatibility is None else dict(compatibility),
    }


def history_records_table(doc: Mapping[str, Any]) -> Table:
    """One row per record: its scale, PGA, max θ/α over both polarities, overturned."""
    return Table("Records of the suite, both polarities", HISTORY_COLUMNS, tuple(doc["records"]))


def suite_tolerance_warnings(rows: Sequence[Mapping[str, Any]]) -> list[str]:
    """The tolerance check's warning of every record whose result depends on it, named."""
    from rockcli.terminal.tolerance import sensitive_warning

    found = []
    for row in rows:
        for run in row.get("tolerance", ()):
            text = sensitive_warning(run, run["rtol"])
            if text is not None:
                found.append(f"record {row['name']}, {text}")
    return found


def history_verdict(doc: Mapping[str, Any]) -> str:
    """The verdict line: the rule, the measure against its limit, the overturns, and whether
    the suite is compatible with its target spectrum."""
    how = "mean" if doc["rule"] == "mean" else "largest"
    line = (
        f"{doc['verdict']}: the {how} of max θ/α over {doc['n']} records is "
        f"{doc['measure']:.4f} against {doc['limit_ratio']:g} (NTC 2018 §7.3.5); "
        f"{doc['overturned_records']} of {doc['n']} overturn"
    )
    compat = doc.get("compatibility")
    if compat is not None and not compat["passed"]:
        line += " — the suite is not compatible with its target spectrum"
    return line


#: What shook the block, as the report says it.
INPUT_TEXT = {
    "ground": "each record itself, at the block's base",
    "floor": "each record's floor motion at the block's height (--ground: the record itself)",
}
#: The code's rule as the report says it.
RULE_TEXT = {"mean": "the mean over 7 or more records", "worst": "the worst of 3–6 records"}


def suite_assessment_document(sa: SuiteAssessment) -> dict[str, Any]:
    """The whole `rock assess MODEL --suite SUITE --format json` document."""
    from rockcli.version import __version__

    doc: dict[str, Any] = {
        "schema": 1,
        "rock_version": __version__,
        "model": {"name": sa.name, "kind": sa.kind},
        "suite_name": sa.suite,
        "input": sa.rows[0].get("input", "ground") if sa.rows else "ground",
        "suite": history_document(sa.measure, sa.rows, sa.compatibility),
        "warnings": list(sa.warnings),
    }
    names = list(dict.fromkeys(r["mechanism"] for r in sa.rows if r.get("mechanism")))
    if names:  # a wall: the mechanism rocked (one name; a list when records differ)
        doc["mechanism"] = names[0] if len(names) == 1 else names
    return with_tolerance_check(doc, sa.rows)


def with_tolerance_check(doc: dict[str, Any], rows: Sequence[Mapping[str, Any]]) -> dict[str, Any]:
    """The suite document with its records' tolerance check: ``sensitive`` (any record's),
    ``sensitive_records`` (their names) and the warning of each, after the others."""
    from rockcli.dynamics.tolerance import any_sensitive

    return {
        **doc,
        "sensitive": any_sensitive(r.get("sensitive") for r in rows),
        "sensitive_records": [r["name"] for r in rows if r.get("sensitive")],
        "warnings": [*doc["warnings"], *suite_tolerance_warnings(rows)],
    }


def suite_assessment_report(doc: dict[str, Any]) -> Report:
    """The terminal report of a model under a suite: the records, the rule, the verdict."""
    suite = doc["suite"]
    compat = suite["compatibility"]
    lo, hi = compat["period_range"]
    notes: tuple[str, ...] = (
        f"suite {doc['suite_name']!r}: mean spectrum / target from {compat['min_ratio']:.3f} to "
        f"{compat['max_ratio']:.3f} over {lo:g}–{hi:g} s: "
        + ("compatible" if compat["passed"] else "NOT compatible")
        + " (rock suite check gives the table)",
        f"rule: {RULE_TEXT[suite['rule']]} (NTC 2018 §7.3.5); an overturn counts at the "
        "overturning angle over α",
        f"input: {INPUT_TEXT[doc['input']]}",
    )
    if "mechanism" in doc:
        rocked = doc["mechanism"]
        names = rocked if isinstance(rocked, list) else [rocked]
        notes += ("mechanism rocked: " + ", ".join(f"'{n}'" for n in names)
                  + ("" if len(names) == 1 else " (the governing one of each record: "
                     "--mechanism NAME rocks one under all)"),)  # fmt: skip
    return Report(
        title=f"rock assess — {doc['model']['name']} under the suite {doc['suite_name']}",
        tables=(history_records_table(suite),),
        notes=notes,
        verdict=history_verdict(suite),
        warnings=tuple(doc["warnings"]),
    )


# --- the suite against the code check (rock compare --suite) ----------------------------

#: What the code check saw, as the report says it.
CODE_DEMAND_TEXT = {
    "target": "the suite's target spectrum",
    "suite-mean": "the suite's mean spectrum",
}


def suite_comparison_document(sc: SuiteComparison) -> dict[str, Any]:
    """The whole `rock compare MODEL --suite SUITE --format json` document: the suite
    section of assess --suite, the code check's document, the limit state both verdicts are
    of, the classification and what the code check saw."""
    from rockcli.terminal.kinematic import kinematic_document

    doc = suite_assessment_document(sc.assessment)
    passed = sc.kinematic.verdict()[sc.verdict_key]
    return {
        **doc,
        "kinematic": kinematic_document(sc.assessment.name, sc.kinematic),
        "limit_state": sc.limit_state,
        "collapse": {
            "code": None if passed is None else not passed,
            "code_verdict": sc.verdict_key,
            "rocking": not sc.assessment.measure.passed,
        },
        "classification": str(sc.classification),
        "code_demand": str(sc.code_demand),
        "notes": list(sc.notes),
    }


def suite_comparison_rows(doc: Mapping[str, Any]) -> tuple[dict[str, str], ...]:
    """The side-by-side rows: the limit state's verdict, its amplitude, the classification."""
    from rockcli.terminal.compare import code_cell, governing_check
    from rockcli.terminal.table import format_value

    kin, suite, col = doc["kinematic"], doc["suite"], doc["collapse"]
    states = (col["code_verdict"],)
    check = governing_check(kin, states)
    how = "mean" if suite["rule"] == "mean" else "largest"
    return (
        {
            "label": f"{doc['limit_state']} verdict",
            "code": code_cell(
                kin, states, None if col["code"] is None else not col["code"], ("passes", "fails")
            ),
            "rocking": f"{suite['verdict']}: {how} max θ/α {suite['measure']:.4f} vs "
            f"{suite['limit_ratio']:g}",
        },  # fmt: skip
        {
            "label": "amplitude",
            "code": "ζ = capacity/demand = "
            + format_value(check["ratio"] if check else None, "{:.3f}"),
            "rocking": f"{suite['overturned_records']} of {suite['n']} records overturn",
        },
        {"label": "classification", "code": doc["classification"], "rocking": ""},
    )


def suite_comparison_report(doc: dict[str, Any]) -> Report:
    """The terminal report of a model under a suite against the code check."""
    from rockcli.terminal.compare import COLUMNS
    from rockcli.terminal.kinematic import EDITION_TEXT, demand_line

    suite, kin = doc["suite"], doc["kinematic"]
    base = suite_assessment_report(doc)
    side = Table(
        f"{doc['model']['name']} under the suite {doc['suite_name']}, {doc['limit_state']}",
        COLUMNS,
        suite_comparison_rows(doc),
    )
    notes = (
        *base.notes,
        f"code: {EDITION_TEXT[kin['edition']]} on {CODE_DEMAND_TEXT[doc['code_demand']]}; both "
        f"sides judged at {doc['limit_state']} (the suite target's limit state)",
        "demand: " + "; ".join(demand_line(k, v) for k, v in kin["demand"].items()),
        *doc["notes"],
    )
    verdict = doc["classification"]
    if not suite["compatibility"]["passed"]:
        verdict += " — the suite is not compatible with its target spectrum"
    return Report(
        title=f"rock compare — {doc['model']['name']} under the suite {doc['suite_name']}",
        tables=(history_records_table(suite), side),
        notes=notes,
        verdict=verdict,
        warnings=tuple(doc["warnings"]),
    )
