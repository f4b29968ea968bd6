"""`rock spectrum overturning`: the JSON document, the terminal Report and the CSV.

JSON (the contract): ``{"schema", "rock_version", "pulse" or "records", "x", "x_name",
"threshold", "threshold_name", "scan_step", …}``, full precision, null where nothing up to
the scan's end overturns (or a run decided nothing: ``notes`` says which).

- Pulses: ``pulse`` the kind, ``x`` the ratios ωp/p, ``threshold`` the lowest ap/a0 that
  overturns (a0 = g·tan α for a block, g·α linearized, the mechanism's uplift acceleration
  for a model), with ``below`` (the highest ap/a0 known to survive under it), ``period`` (Tp
  [s]) and ``runs`` per ratio.
- Records: ``records`` [{name, file, pga_g}], ``x`` the sizes (p [rad/s] or R [m]),
  ``threshold`` one list per record (the scale factor, ``threshold_name`` "scale"), with
  ``intensity`` (PGA·scale/(g tan α)) and ``runs`` in the same shape.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from typing import Any

from rockcli.studies.fragility.spectrum import Scan
from rockcli.terminal.table import Column, Report, Table, key_value
from rockcli.version import __version__

SCHEMA = 1
#: What the document says of the block rocked (the same at every point, but R in a size
#: spectrum; p too, there).
BLOCK_KEYS = ("p", "uplift_g", "e", "linearized")
#: What a scan can miss, said under every spectrum.
STEP_NOTE = (
    "the search scans up at a step of {step:g} (in units of the uplift acceleration) and "
    "bisects to {tolerance:g} inside the first step that overturns: a window of overturning "
    "narrower than the step can be missed (a smaller --scan-step sees more)"
)
SIZE_NOTE = (
    "the threshold against ωp/p does not depend on the block's size: in τ = p·t the "
    "equation of motion holds only α, e, ωp/p and ap/a0"
)


def scan_document(scan: Scan) -> dict[str, float]:
    return {"first": scan.first, "step": scan.step, "last": scan.last, "tolerance": scan.tolerance}


def pulse_document(
    kind: str,
    ratios: Sequence[float],
    rows: Sequence[dict[str, Any]],
    scan: Scan,
    subject: dict[str, Any],
    threshold_name: str,
) -> dict[str, Any]:
    """The pulse spectrum's document (``subject``: the block or model rocked)."""
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "pulse": kind,
        "x": list(ratios),
        "x_name": "omega_p/p",
        "threshold": [row["threshold"] for row in rows],
        "threshold_name": threshold_name,
        "scan_step": scan.step,
        "scan": scan_document(scan),
        "below": [row["below"] for row in rows],
        "period": [row["period"] for row in rows],
        "runs": [row["runs"] for row in rows],
        "subject": {**subject, **{k: rows[0][k] for k in BLOCK_KEYS}, "R": rows[0]["R"]},
        "notes": pulse_notes(ratios, rows, scan),
    }


def pulse_notes(ratios: Sequence[float], rows: Sequence[dict[str, Any]], scan: Scan) -> list[str]:
    """A note for each ratio without a threshold: none up to the scan's end, or undecided."""
    notes = []
    for ratio, row in zip(ratios, rows, strict=True):
        if row["undecided"]:
            notes.append(
                f"ωp/p = {ratio:g}: no threshold, a run decided nothing ({row['undecided']})"
            )
        elif row["threshold"] is None:
            notes.append(f"ωp/p = {ratio:g}: no overturn up to {scan.last:g} (--scan-to)")
        if row["unsettled"]:
            notes.append(
                f"ωp/p = {ratio:g}: {row['unsettled']} runs still moving at the end "
                f"of the tail, taken as survivals (a block vibrating on its "
                "restrainers)"
            )
    return notes


def records_document(
    records: Sequence[dict[str, Any]],
    size_name: str,
    sizes: Sequence[float],
    rows: Sequence[Sequence[dict[str, Any]]],
    scan: Scan,
    subject: dict[str, Any],
) -> dict[str, Any]:
    """The record spectrum's document: ``rows[i][j]`` the row of record i at size j."""
    notes = []
    for rec, per_record in zip(records, rows, strict=True):
        for size, row in zip(sizes, per_record, strict=True):
            where = f"{rec['name']}, {size_name} = {size:g}"
            if row["undecided"]:
                notes.append(f"{where}: no threshold, a run decided nothing ({row['undecided']})")
            elif row["scale"] is None:
                notes.append(f"{where}: no overturn up to PGA·scale = {scan.last:g}·a0 (--scan-to)")
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "records": list(records),
        "x": list(sizes),
        "x_name": size_name,
        "threshold": [[row["scale"] for row in per] for per in rows],
        "threshold_name": "scale",
        "scan_step": scan.step,
        "scan": scan_document(scan),
        "intensity": [[row["threshold"] for row in per] for per in rows],
        "below": [[row["scale_below"] for row in per] for per in rows],
        "runs": [[row["runs"] for row in per] for per in rows],
        "subject": {**subject, **{k: rows[0][0][k] for k in BLOCK_KEYS if k != "p"}},
        "notes": notes,
    }


PULSE_COLUMNS = (
    Column("x", "ωp/p", fmt="{:.4g}"),
    Column("period", "Tp", "s", fmt="{:.4g}"),
    Column("threshold", "lowest overturning ap/a0", fmt="{:.4f}", short="ap/a0"),
    Column("below", "highest surviving below it", fmt="{:.4f}", short="below"),
    Column("runs", "runs", fmt="{}"),
)
RECORD_COLUMNS = (
    Column("name", "record"),
    Column("x", "size", fmt="{:.4g}"),
    Column("scale", "lowest overturning scale", fmt="{:.4f}", short="scale"),
    Column("intensity", "PGA·scale/a0", fmt="{:.4f}", short="PGA·s/a0"),
    Column("runs", "runs", fmt="{}"),
)


def overturning_report(doc: dict[str, Any]) -> Report:
    """The Report of either spectrum: what rocks, the spectrum, its notes."""
    scan = doc["scan"]
    step = STEP_NOTE.format(step=scan["step"], tolerance=scan["tolerance"])
    subject = key_value("Rocked", _subject_items(doc))
    if "pulse" in doc:
        rows = tuple(
            {"x": x, "period": t, "threshold": v, "below": b, "runs": n}
            for x, t, v, b, n in zip(
                doc["x"], doc["period"], doc["threshold"], doc["below"], doc["runs"], strict=True
            )
        )
        table = Table(
            f"Overturning spectrum, {doc['pulse']} pulse: a0 = {_a0(doc)}", PULSE_COLUMNS, rows
        )
        extra = (SIZE_NOTE,) if doc["subject"].get("kind") == "block" else ()
        return Report(
            title=f"rock spectrum overturning — {doc['pulse']} pulse",
            tables=(subject, table),
            notes=(*extra, step, *doc["notes"]),
        )
    return Report(
        title="rock spectrum overturning — records",
        tables=(
            subject,
            Table(
                f"Overturning scale of each record, size {_size_label(doc)}",
                _record_columns(doc),
                _record_rows(doc),
            ),
        ),
        notes=(
            f"a0 = {doc['subject']['uplift_g']:.4g} g, the uplift acceleration: "
            "PGA·scale/a0 is the scaled record's peak in units of a0",
            step,
            *doc["notes"],
        ),
    )


def _a0(doc: dict[str, Any]) -> str:
    a0 = doc["subject"]["uplift_g"]
    return f"{a0:.4g} g, the uplift acceleration ({doc['threshold_name']} in the JSON)"


#: The unit of each size a record spectrum runs over.
SIZE_UNITS = {"p": "rad/s", "R": "m", "T1": "s"}


def _size_label(doc: dict[str, Any]) -> str:
    return f"{doc['x_name']} [{SIZE_UNITS[doc['x_name']]}]"


def _record_columns(doc: dict[str, Any]) -> tuple[Column, ...]:
    size = Column("x", doc["x_name"], SIZE_UNITS[doc["x_name"]], fmt="{:.4g}")
    return (RECORD_COLUMNS[0], size, *RECORD_COLUMNS[2:])


def _record_rows(doc: dict[str, Any]) -> tuple[dict[str, Any], ...]:
    return tuple(
        {
            "name": rec["name"],
            "x": x,
            "scale": doc["threshold"][i][j],
            "intensity": doc["intensity"][i][j],
            "runs": doc["runs"][i][j],
        }
        for i, rec in enumerate(doc["records"])
        for j, x in enumerate(doc["x"])
    )


def _subject_items(doc: dict[str, Any]) -> list[tuple[str, Any, str, str]]:
    s = doc["subject"]
    items: list[tuple[str, Any, str, str]] = []
    if s.get("model"):
        items.append(("model", s["model"], "", ""))
    if s.get("mechanism"):
        items.append(("mechanism", s["mechanism"], "", ""))
    if s.get("alpha") is not None:
        items.append(("slenderness α", s["alpha"], "rad", "{:.4g}"))
    items.append(("restitution e", s["e"], "", "{:.4g}"))
    if "pulse" in doc:
        items.append(("p", s["p"], "rad/s", "{:.4g}"))
        items.append(("R", s["R"], "m", "{:.4g}"))
    items.append(("linearized", bool(s.get("linearized")), "", ""))
    items.append(("uplift acceleration a0", s["uplift_g"], "g", "{:.4g}"))
    if s.get("floor"):
        items.append(("input", "the floor motion at the block's height", "", ""))
    return items


def overturning_csv(doc: dict[str, Any]) -> str:
    """CSV: pulses a row per ratio; records a row per record and size; full precision."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    if "pulse" in doc:
        writer.writerow(["omega_p/p", "period_s", "threshold", "below", "runs"])
        for i, x in enumerate(doc["x"]):
            writer.writerow(
                [
                    _cell(x),
                    _cell(doc["period"][i]),
                    _cell(doc["threshold"][i]),
                    _cell(doc["below"][i]),
                    doc["runs"][i],
                ]
            )
        return out.getvalue()
    writer.writerow(["record", doc["x_name"], "scale", "intensity", "runs"])
    for i, rec in enumerate(doc["records"]):
        for j, x in enumerate(doc["x"]):
            writer.writerow(
                [
                    rec["name"],
                    _cell(x),
                    _cell(doc["threshold"][i][j]),
                    _cell(doc["intensity"][i][j]),
                    doc["runs"][i][j],
                ]
            )
    return out.getvalue()


def _cell(value: float | None) -> str:
    return "" if value is None else repr(value)
