"""The `rock retrofit` document (JSON, SI units) and its tables (kN, mm)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from rockcli.model.schema import Model
from rockcli.records.record import Record
from rockcli.studies.retrofit.candidates import RetrofitPlan
from rockcli.terminal.table import Column, Report, Table
from rockcli.version import __version__

SCHEMA = 1
#: What shook the block in the time history (record.input).
INPUTS = {
    "ground": "rocking input: the record itself, at the block's base",
    "floor": "rocking input: the record's floor motion at the block's height ([building])",
}
#: What each mechanism's code check reads (the document's code_demand).
CODE_DEMANDS = {"record": "the record's spectrum", "model": "the model's own code spectra"}
#: Newtons per kilonewton (the tables show kN, the JSON N).
N_PER_KN = 1000.0
#: What the max θ/α cell says for a block that overturns: its ratio is then the overturning
#: angle over α (π/2/α by default), a number that says nothing about the retrofit. The JSON
#: keeps the number and the "overturned" flag.
OVERTURNED = "overturned"


def retrofit_document(
    plan: RetrofitPlan,
    model: Model,
    record: Record | None,
    rows: Sequence[dict[str, Any]],
    chosen: dict[str, Any] | None,
    reason: str,
    *,
    ground: bool = False,
    code_demand: str = "record",
) -> dict[str, Any]:
    """The `rock retrofit --format json` document: every candidate, the choice and why, and
    the warnings on the model and the record (magnitudes that look like unit slips); without a
    record (the code check alone) ``record`` is null."""
    from rockcli.analyses.floor import model_floor
    from rockcli.model.plausible import model_warnings
    from rockcli.studies.retrofit.choose import others

    floor = model_floor(model) is not None and not ground
    if rows and "input" in rows[0]:  # a wall's mechanism at height rocks on its floor
        floor = any(r["input"] == "floor" for r in rows)
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "model": {"name": model.name},
        "record": None
        if record is None
        else {"name": record.name, "pga_g": record.pga, "input": "floor" if floor else "ground"},
        "rod": {
            "name": plan.name,
            "placed": None
            if plan.placement is None
            else {
                "height": plan.placement.height,
                "from_pivot": plan.placement.from_pivot,
                "length": plan.placement.length,
            },
        },
        "grade": plan.grade,
        "count": plan.count,
        "code_demand": code_demand,
        "candidates": list(rows),
        "chosen": chosen,
        "reason": reason,
        "another_intervention": others(chosen or (rows[-1] if rows else {})),
        "warnings": [*model_warnings(model), *(() if record is None else record.warnings)],
    }


#: One row per diameter (80 columns): the rod, how many of the mechanisms it restrains it
#: makes safe, the worst of its checks over them, and the outcome.
COLUMNS = (
    Column("d", "d", "mm", "{:g}"),
    Column("strength", "strength", "kN", "{:.4g}"),
    Column("safe", "safe / restrained", short="safe"),
    Column("max_ratio", "max θ/α", "", "{:.4f}"),
    Column("max_force", "peak force", "kN", "{:.4g}"),
    Column("utilisation", "use", "", "{:.3f}"),
    Column("why", "result", align="left"),
)
#: One row per diameter and mechanism (--details).
DETAIL_COLUMNS = (
    Column("d", "d", "mm", "{:g}"),
    Column("K", "K", "kN/m", "{:.0f}"),
    Column("name", "mechanism", align="left"),
    Column("restrained", "restrained", short="rod"),
    Column("code_zeta", "code ULS ζ", "", "{:.3f}", short="ζ"),
    Column("max_ratio", "max θ/α", "", "{:.4f}"),
    Column("utilisation", "utilisation", "", "{:.3f}", short="use"),
    Column("elongation", "elongation / can take", "mm", short="elong."),
    Column("status", "status", align="left"),
)

#: The same without a record: the code check alone (no time history, no force, no θ/α).
CODE_COLUMNS = tuple(c for c in COLUMNS if c.key not in ("max_ratio", "max_force", "utilisation"))
CODE_DETAIL_COLUMNS = tuple(
    c for c in DETAIL_COLUMNS if c.key not in ("max_ratio", "utilisation", "elongation")
)


def table_row(row: dict[str, Any]) -> dict[str, Any]:
    """One diameter in the table's units (mm, kN/m, kN): the rod, the mechanisms it restrains
    and makes safe, its peak force and utilisation over them, the outcome."""
    from rockcli.studies.retrofit.choose import FAILS, SAFE, candidate_failures

    mechanisms = row.get("mechanisms") or [row]
    restrained = [m for m in mechanisms if m.get("restrained", True)]
    held = [m for m in mechanisms if m.get("on_mechanism", True)]  # the rod's force acts on
    forces = [m["max_force"] for m in held if m.get("max_force") is not None]
    uses = [m["utilisation"] for m in held if m.get("utilisation") is not None]
    failing = [f"'{m['name']}'" for m in mechanisms if m.get("status") == FAILS]
    if len(mechanisms) == 1:  # a block (or a synthetic row): why, in short
        failing = short_failures(mechanisms[0]) if candidate_failures(row) else []
    rocked = [m for m in held if m.get("max_ratio") is not None]
    return {
        "d": row["diameter_mm"],
        "K": row["K"] / N_PER_KN,
        "strength": None if row["strength"] is None else row["strength"] / N_PER_KN,
        "safe": f"{sum(m.get('status', SAFE) == SAFE for m in restrained)} / {len(restrained)}",
        "max_force": max(forces) / N_PER_KN if forces else None,
        "utilisation": max(uses) if uses else None,
        "max_ratio": OVERTURNED
        if any(m["overturned"] for m in rocked)
        else max((m["max_ratio"] for m in rocked), default=None),
        "why": outcome(failing, single=len(mechanisms) == 1),
    }


def short_failures(m: dict[str, Any]) -> list[str]:
    """A mechanism's failures in a few words each (the table's cell; the JSON and --details
    say them in full)."""
    duct, anchor = m.get("ductility") or {}, m.get("anchor") or {}
    use = m.get("utilisation")
    said = [
        (m["code_uls_passed"] is None, "code ULS not evaluated"),
        (m["code_uls_passed"] is False,
         f"code ζ {m['code_zeta']:.3f}" if m.get("code_zeta") is not None else "code fails"),
        (m["overturned"], "overturns"),
        (not m["overturned"] and m.get("rocking") not in ("survives", None), "undecided"),
        (m["ruptured"], "rod ruptures"),
        (use is not None and use > 1.0 + 1e-9, f"use {use or 0:.2f}"),
        (duct.get("passed") is False, "stretches"),
        (anchor.get("passed") is False, "anchor"),
    ]  # fmt: skip
    return [text for cond, text in said if cond]


def outcome(failing: list[str], single: bool) -> str:
    """A diameter's result: "passes", a block's reasons, or the mechanisms that fail."""
    if not failing:
        return "passes"
    return "; ".join(failing) if single else "fails: " + ", ".join(failing)


def detail_rows(row: dict[str, Any]) -> list[dict[str, Any]]:
    """Every mechanism of one diameter, in the details' units."""
    from rockcli.studies.retrofit.choose import failures

    out = []
    for m in row.get("mechanisms") or [row]:
        failing = failures(m)
        status = m.get("status") or ("safe" if not failing else "fails")
        out.append({
            "d": row["diameter_mm"],
            "K": row["K"] / N_PER_KN,
            "name": m.get("name") or m.get("mechanism") or "block",
            "restrained": m.get("restrained", True),
            "code_zeta": m["code_zeta"],
            "max_ratio": OVERTURNED if m["overturned"] else m["max_ratio"],
            "utilisation": m["utilisation"],
            "elongation": elongation_text(m.get("ductility")),
            "status": status if not failing or status == "safe"
            else f"{status}: {'; '.join(failing)}",
        })  # fmt: skip
    return out


def elongation_text(duct: dict[str, Any] | None) -> str | None:
    """ "106 / 345": the rod's largest elongation and what it can take [mm] (None: no steel)."""
    if not duct or duct["capacity"] is None:
        return None
    return f"{duct['demand'] * 1e3:.0f} / {duct['capacity'] * 1e3:.0f}"


def retrofit_report(doc: dict[str, Any], details: bool = False) -> Report:
    """A row per diameter (the mechanisms it makes safe of those it restrains, the rod's
    worst checks, the outcome), with ``details`` a row per diameter and mechanism; the rod,
    the record and the mechanisms needing another intervention as notes; the choice."""
    from rockcli.studies.retrofit.choose import others

    rows = tuple(table_row(r) for r in doc["candidates"])
    rod = doc["rod"]
    where = (
        "the model's tie-rod"
        if rod["placed"] is None
        else f"a new rod at height {rod['placed']['height']:g} m, {rod['placed']['from_pivot']:g}"
        f" m from the pivot, {rod['placed']['length']:g} m long"
    )
    chosen = doc["chosen"]
    record = doc["record"]
    columns = COLUMNS if record is not None else CODE_COLUMNS
    tables = [Table(f"'{rod['name']}': {where}", columns, rows)]
    if details:
        each = tuple(d for r in doc["candidates"] for d in detail_rows(r))
        shown = DETAIL_COLUMNS if record is not None else CODE_DETAIL_COLUMNS
        tables.append(Table("each mechanism with each diameter", shown, each))
    demand = CODE_DEMANDS[doc.get("code_demand", "record")]
    if record is None:
        notes = [f"{doc['count']} bar(s) of {doc['grade']} per diameter; the code check alone "
                 f"(no --record, no time history): each mechanism's code ULS on {demand}, the "
                 "rod acting as the code check takes it (a tie-rod: its design strength), its "
                 "anchor checked (γov·A·fy, NTC 2018 §7.5.1); restrained: on it, and not slack "
                 "on the side its code check governs"]  # fmt: skip
    else:
        notes = [
            f"{doc['count']} bar(s) of {doc['grade']} per diameter; each mechanism's code ULS "
            f"on {demand}; the time history (both polarities) of each mechanism the rod is "
            "on; peak force and utilisation: the largest over the mechanisms the rod is on; "
            "restrained: on it, and not slack on the side its code check governs; the rod's "
            "elongation against ε_u·L/γ_ε, and γov·A·fy, the force its anchorage must exceed "
            "(capacity design, NTC 2018 §7.5.1)",
            INPUTS[record["input"]],
        ]
    shown_row = chosen or (doc["candidates"][-1] if doc["candidates"] else {})
    names = others(shown_row)
    if names:
        notes.append("need another intervention (the rod is not on them, or goes slack on the "
                     "side they fail on): " + ", ".join(f"'{n}'" for n in names))  # fmt: skip
    if not details and any(r.get("mechanisms") for r in doc["candidates"]):
        notes.append("--details: a row per diameter and mechanism (--format json: every column)")
    verdict = (
        f"{doc['reason']} ({doc['count']} bar(s) of {doc['grade']})"
        if chosen is not None
        else doc["reason"]
    )
    title = f"rock retrofit — {doc['model']['name']} " + (
        f"on {demand} (no record)" if record is None
        else f"under {record['name']} (PGA {record['pga_g']:.3f} g)"
    )  # fmt: skip
    return Report(
        title=title,
        tables=tuple(tables),
        notes=tuple(notes),
        warnings=tuple(doc["warnings"]),
        verdict=verdict,
    )
