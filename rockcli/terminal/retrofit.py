"""The `rock retrofit` document (JSON, SI units) and its tables (kN, mm)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from rockcli.model.schema import Model
from rockcli.records.record import Record
from rockcli.studies.retrofit.candidates import RetrofitPlan
from rockcli.studies.retrofit.choose import failures
from rockcli.terminal.table import Column, Report, Table
from rockcli.version import __version__

SCHEMA = 1
#: What shook the block in the time history (record.input).
INPUTS = {
    "ground": "rocking input: the record itself, at the block's base",
    "floor": "rocking input: the record's floor motion at the block's height ([building])",
}
#: Newtons per kilonewton (the tables show kN, the JSON N).
N_PER_KN = 1000.0
#: What the max θ/α cell says for a block that overturns: its ratio is then the overturning
#: angle over α (π/2/α by default), a number that says nothing about the retrofit. The JSON
#: keeps the number and the "overturned" flag.
OVERTURNED = "overturned"


def retrofit_document(
    plan: RetrofitPlan,
    model: Model,
    record: Record,
    rows: Sequence[dict[str, Any]],
    chosen: dict[str, Any] | None,
    reason: str,
    *,
    ground: bool = False,
) -> dict[str, Any]:
    """The `rock retrofit --format json` document: every candidate, the choice and why, and
    the warnings on the model and the record (magnitudes that look like unit slips)."""
    from rockcli.analyses.floor import model_floor
    from rockcli.model.plausible import model_warnings

    floor = model_floor(model) is not None and not ground
    if rows and "input" in rows[0]:  # a wall's mechanism at height rocks on its floor
        floor = any(r["input"] == "floor" for r in rows)
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "model": {"name": model.name},
        "record": {
            "name": record.name,
            "pga_g": record.pga,
            "input": "floor" if floor else "ground",
        },
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
        "candidates": list(rows),
        "chosen": chosen,
        "reason": reason,
        "warnings": [*model_warnings(model), *record.warnings],
    }


COLUMNS = (
    Column("d", "d", "mm", "{:g}"),
    Column("K", "K", "kN/m", "{:.0f}"),
    Column("strength", "strength", "kN", "{:.4g}"),
    Column("code_zeta", "code ULS ζ", "", "{:.3f}", short="ζ"),
    Column("code_uls", "code ULS"),
    Column("max_ratio", "max θ/α", "", "{:.4f}"),
    Column("max_force", "peak force", "kN", "{:.4g}"),
    Column("utilisation", "utilisation", "", "{:.3f}", short="use"),
    Column("elongation", "elongation / can take", "mm", short="elong."),
    Column("overstrength", "γov·A·fy", "kN", "{:.4g}"),
    Column("ruptured", "ruptured", short="rupt."),
    Column("why", "result", align="left"),
)


def table_row(row: dict[str, Any]) -> dict[str, Any]:
    """One candidate in the table's units (mm, kN/m, kN); "overturned" for the max θ/α of
    a block that overturns."""
    passed = row["code_uls_passed"]
    return {
        **row,
        "d": row["diameter_mm"],
        "K": row["K"] / N_PER_KN,
        "strength": None if row["strength"] is None else row["strength"] / N_PER_KN,
        "code_uls": "not evaluated" if passed is None else ("pass" if passed else "fail"),
        "max_ratio": OVERTURNED if row["overturned"] else row["max_ratio"],
        "max_force": None if row["max_force"] is None else row["max_force"] / N_PER_KN,
        "elongation": elongation_text(row.get("ductility")),
        "overstrength": None if not row.get("anchor") else row["anchor"]["demand"] / N_PER_KN,
        "why": "; ".join(failures(row)) or "passes",
    }


def elongation_text(duct: dict[str, Any] | None) -> str | None:
    """ "106 / 345": the rod's largest elongation and what it can take [mm] (None: no steel)."""
    if not duct or duct["capacity"] is None:
        return None
    return f"{duct['demand'] * 1e3:.0f} / {duct['capacity'] * 1e3:.0f}"


def retrofit_report(doc: dict[str, Any]) -> Report:
    """The candidates' table, the rod and record as notes, the choice as the verdict."""
    rows = tuple(table_row(r) for r in doc["candidates"])
    rod = doc["rod"]
    where = (
        "the model's tie-rod"
        if rod["placed"] is None
        else f"a new rod at height {rod['placed']['height']:g} m, {rod['placed']['from_pivot']:g}"
        f" m from the pivot, {rod['placed']['length']:g} m long"
    )
    chosen = doc["chosen"]
    columns: tuple[Column, ...] = COLUMNS
    notes: tuple[str, ...] = ()
    names = list(dict.fromkeys(r["mechanism"] for r in doc["candidates"] if r.get("mechanism")))
    if len(names) > 1:  # a wall whose governing mechanism changes with the rod
        columns = (*COLUMNS[:-1], Column("mechanism", "governing mechanism", align="left"),
                   COLUMNS[-1])  # fmt: skip
    if names:
        notes = ("a wall: each diameter is checked by the code on the record's spectrum and "
                 "rocked for the governing mechanism of that check (a stronger rod can hand it "
                 "to another); no peak force where the rod is not on that mechanism (below its "
                 "hinge, or at a vertical flexure's held top)"
                 + (f"; governing: '{names[0]}'" if len(names) == 1 else ""),)  # fmt: skip
    verdict = (
        f"{doc['reason']} ({doc['count']} bar(s) of {doc['grade']})"
        if chosen is not None
        else doc["reason"]
    )
    return Report(
        title=f"rock retrofit — {doc['model']['name']} under {doc['record']['name']} "
        f"(PGA {doc['record']['pga_g']:.3f} g)",
        tables=(Table(f"'{rod['name']}': {where}", columns, rows),),
        notes=(
            f"{doc['count']} bar(s) of {doc['grade']} per diameter; code ULS ζ = capacity/"
            "demand on the record's spectrum; max θ/α, peak force and utilisation over both "
            "polarities; the rod's largest elongation against ε_u·L/γ_ε, and γov·A·fy, the force "
            "its anchorage must exceed (capacity design, NTC 2018 §7.5.1)",
            INPUTS[doc["record"]["input"]],
            *notes,
        ),
        warnings=tuple(doc["warnings"]),
        verdict=verdict,
    )
