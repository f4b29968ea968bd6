"""The `rock compare` report: the two verdicts side by side."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from rockcli.notes import Note
from rockcli.records.record import Record
from rockcli.terminal.assess import strength_caveat
from rockcli.terminal.kinematic import EDITION_TEXT, ULTIMATE_FIX, actions_table, demand_line
from rockcli.terminal.table import Column, Report, Table, format_value
from rockcli.terminal.tolerance import compare_rows as tolerance_rows
from rockcli.terminal.tolerance import verdict_caveat
from rockcli.version import __version__

if TYPE_CHECKING:
    from rockcli.analyses.compare import ComparisonOutput

SCHEMA = 1
#: The warning and the verdict's tail when the code check did not see the record
#: (`--code-demand model`).
DIFFERENT_EARTHQUAKES = Note(
    "different_earthquakes",
    "the code check used the model's spectrum, not the record: the two sides see different "
    "earthquakes",
)


def _negate(value: bool | None) -> bool | None:
    return None if value is None else not value


def comparison_document(
    kin: dict[str, Any], roc: dict[str, Any], classification: str, code_demand: str = "record"
) -> dict[str, Any]:
    """Both documents, the activation and collapse rows, the classification and the code
    check's demand (``"record"``: the record on both sides; ``"model"``: the model's
    spectrum)."""
    code_collapse = _negate(kin["verdict"]["ULS"])
    rocking_collapse = None if roc["verdict"] == "undecided" else roc["verdict"] == "overturns"
    uplifts = [r["t_uplift"] for r in roc["runs"] if r["t_uplift"] is not None]
    overturns = [r["t_overturn"] for r in roc["runs"] if r["t_overturn"] is not None]
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "kinematic": kin,
        "rocking": roc,
        "activation": {
            "code": _negate(kin["verdict"]["DLS"]),
            "rocking": bool(uplifts),
            "t_uplift": min(uplifts) if uplifts else None,
        },
        "collapse": {
            "code": code_collapse,
            "rocking": rocking_collapse,
            "t_overturn": min(overturns) if overturns else None,
        },
        "classification": classification,
        "code_demand": code_demand,
    }


def comparison_output_document(out: ComparisonOutput, record: Record) -> dict[str, Any]:
    """The `rock compare --format json` document of a comparison's results."""
    from rockcli.terminal.assess import assessment_output_document
    from rockcli.terminal.kinematic import kinematic_document

    kin = kinematic_document(out.rocking.name, out.kinematic, out.rocking.warnings)
    roc = assessment_output_document(out.rocking, record)
    doc = comparison_document(kin, roc, str(out.classification), str(out.code_demand))
    doc["classification_note"] = out.classification_note
    if out.mechanisms:
        doc["mechanisms"] = [mechanism_comparison(m) for m in out.mechanisms]
        doc["governing"] = out.kinematic.governing
    return doc


def mechanism_comparison(m: Any) -> dict[str, Any]:
    """One mechanism of the catalogue under the record: its code verdicts, its rocking and
    their classification (rocking and classification null, and ``not_rocked`` the reason,
    for one the time history cannot rock)."""
    rocking = None
    if m.rocking is not None:
        rocking = {"verdict": str(m.rocking.verdict), "max_ratio": m.rocking.max_ratio}
    return {
        "name": m.name,
        "type": m.type,
        "classification": None if m.classification is None else str(m.classification),
        "code": m.code.verdict(),
        "rocking": rocking,
        "not_rocked": m.not_rocked,
        "classification_note": m.classification_note,
    }


MECHANISM_COLUMNS = (
    Column("name", "mechanism", align="left"),
    Column("code_uls", "code ULS", align="left"),
    Column("max_ratio", "max θ/α", "", "{:.3f}"),
    Column("rocking", "rocking", align="left"),
    Column("classification", "classification", align="left"),
)


def mechanisms_table(doc: dict[str, Any]) -> Table:
    """The classification of every mechanism of the catalogue, the governing one first."""
    rows = tuple(
        {
            "name": m["name"],
            "code_uls": _yes_no(m["code"].get("ULS"), "satisfied", "NOT satisfied"),
            "max_ratio": None if m["rocking"] is None else m["rocking"]["max_ratio"],
            "rocking": "not rocked" if m["rocking"] is None else m["rocking"]["verdict"],
            "classification": m["classification"] or "—",
        }
        for m in doc["mechanisms"]
    )
    return Table("Every mechanism (governing first)", MECHANISM_COLUMNS, rows)


COLUMNS = (
    Column("label", ""),
    Column("code", "code (NTC kinematic)", align="left"),
    Column("rocking", "rocking (time history)", align="left"),
)


def _yes_no(value: bool | None, yes: str, no: str) -> str:
    return "not evaluated" if value is None else (yes if value else no)


def governing_check(kin: dict[str, Any], states: tuple[str, ...]) -> dict[str, Any] | None:
    """The check that decides the verdict: among the deciding checks (the non-linear ones
    when the analysis has them, else the linear ones; codecheck.result.deciding), the
    evaluated one with the smallest capacity/demand ratio."""
    mine = [c for c in kin["checks"] if c["limit_state"] in states]
    nonlinear = [c for c in mine if c["method"] == "nonlinear"]
    checks = [c for c in (nonlinear or mine) if c["ratio"] is not None]
    return min(checks, key=lambda c: c["ratio"]) if checks else None


def code_cell(
    kin: dict[str, Any], states: tuple[str, ...], verdict: bool | None, what: tuple[str, str]
) -> str:
    check = governing_check(kin, states)
    text = _yes_no(verdict, what[0], what[1])
    if check is None:
        return text
    return (
        f"{text} ({check['method']} {check['location']}: demand "
        f"{format_value(check['demand'], '{:.4g}')} vs capacity "
        f"{format_value(check['capacity'], '{:.4g}')} {check['unit']})"
    )


def comparison_rows(doc: dict[str, Any]) -> tuple[dict[str, str], ...]:
    """The side-by-side rows: activation, collapse, amplitude, restrainers, classification."""
    kin, roc = doc["kinematic"], doc["rocking"]
    act, col = doc["activation"], doc["collapse"]
    uplift = act["t_uplift"]
    over = col["t_overturn"]
    uls = governing_check(kin, ("ULS", "SLV", "SLC"))
    rows = [
        {
            "label": "activation",
            "code": code_cell(kin, ("DLS", "SLD"), act["code"], ("activates", "stays at rest")),
            "rocking": f"uplifts at {uplift:.3f} s" if uplift is not None else "stays at rest",
        },
        {
            "label": "collapse",
            "code": code_cell(kin, ("ULS", "SLV", "SLC"), col["code"], ("collapses", "survives"))
            + ("" if col["code"] is not None else f"; {ULTIMATE_FIX}"),
            "rocking": _yes_no(col["rocking"], "overturns", "survives")
            + (f" at {over:.3f} s" if over is not None else ""),
        },
        {
            "label": "amplitude",
            "code": "ζ = capacity/demand = "
            + format_value(uls["ratio"] if uls else None, "{:.3f}"),
            "rocking": "overturned"
            if any(r["overturned"] for r in roc["runs"])
            else f"max θ/α = {roc['max_ratio']:.4f}",
        },
    ]
    for run in roc["runs"]:
        for p in run["restrainers"]:
            rows.append(
                {
                    "label": f"{p['name']} ({run['polarity']:+d})",
                    "code": "—",
                    "rocking": f"{1e3 * p['max_displacement']:.2f} mm, "
                    f"{p['max_force'] / 1e3:.2f} kN" + member_events(p),
                }
            )
    rows += tolerance_rows(roc)
    rows.append({"label": "classification", "code": doc["classification"], "rocking": ""})
    return tuple(rows)


def member_events(p: dict[str, Any]) -> str:
    """ ", yielded", ", lost at t s" for a run's restrainer row (empty when it stayed elastic)."""
    text = ", yielded" if p.get("yielded") else ""
    if p.get("t_rupture") is not None:
        text += f", lost at {p['t_rupture']:.3f} s"
    return text


def comparison_report(doc: dict[str, Any]) -> Report:
    """The terminal report of a comparison document."""
    kin, roc = doc["kinematic"], doc["rocking"]
    rec = roc["record"]
    table = Table(
        f"{kin['model']['name']} under {rec['name']} (PGA {rec['pga_g']:.3f} g)",
        COLUMNS,
        comparison_rows(doc),
    )
    notes: tuple[str, ...] = (
        f"code: {EDITION_TEXT[kin['edition']]}, Ts/T_SLV as in `rock kinematic`; demand: "
        + "; ".join(demand_line(k, v) for k, v in kin["demand"].items()),
        f"rocking: both polarities, engine {roc['engine']['name']}; input: "
        + roc["record"].get("input_note", "the record itself, at the block's base"),
    )
    actions = kin.get("restrainer_actions", [])
    catalogue = (mechanisms_table(doc),) if doc.get("mechanisms") else ()
    if doc.get("mechanisms"):
        shown = [n for n in kin.get("notes", ()) if n.startswith("the comparison shows")]
        notes = (*notes, f"governing mechanism: {doc['governing']}; the first table shows "
                 f"'{kin.get('mechanism')}'", *shown)  # fmt: skip
        notes += tuple(f"'{m['name']}' is not rocked: {m['not_rocked']}"
                       for m in doc["mechanisms"] if m.get("not_rocked"))  # fmt: skip
    return Report(
        title="rock compare",
        tables=(table, *((actions_table(actions),) if actions else ()), *catalogue),
        notes=notes,
        verdict=comparison_verdict(doc),
        warnings=tuple(
            w for w in doc.get("warnings", comparison_warnings(doc)) if w != DIFFERENT_EARTHQUAKES
        ),
    )


def comparison_verdict(doc: dict[str, Any]) -> str:
    """The verdict line: the classification, whether the two sides saw one earthquake, and
    whether a restrainer of the time history went beyond its strength (then not valid)."""
    line = str(doc["classification"])
    if doc.get("code_demand") == "model":
        line += f" — {DIFFERENT_EARTHQUAKES}"
    rocking = doc["rocking"]
    return line + strength_caveat(rocking.get("restrainer_checks", ())) + verdict_caveat(rocking)


def comparison_warnings(doc: dict[str, Any]) -> list[str]:
    """The warnings of both analyses, each once, in order (the document's ``"warnings"``),
    first whether the two sides saw different earthquakes."""
    both = [*doc["kinematic"].get("warnings", ()), *doc["rocking"].get("warnings", ())]
    if doc.get("code_demand") == "model":
        both.insert(0, DIFFERENT_EARTHQUAKES)
    return list(dict.fromkeys(both + undecided_warnings(doc)))


def undecided_warnings(doc: dict[str, Any]) -> list[str]:
    """Why a classification is undetermined though the runs ended (the engines, or the
    tolerance check, disagree on the verdict): the comparison's, then each other
    mechanism's."""
    shown = doc["kinematic"].get("mechanism")
    out = [f"{doc['classification_note']}"] if doc.get("classification_note") else []
    return out + [
        f"'{m['name']}': {m['classification_note']}"
        for m in doc.get("mechanisms", ())
        if m.get("classification_note") and m["name"] != shown
    ]
