"""`rock record spectrum`: the JSON document, the terminal Report and the CSV of the spectra.

JSON (a fixed contract, read by scripts): ``{"records": [{"name", "damping", "periods",
"Sa_g", "Sd_m"}]}``, one entry per file in the order given, full precision. CSV: one row per
period, header ``period_s,<name>_Sa_g,<name>_Sd_m,…``.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from typing import Any

import numpy as np

from rockcli.records.record import Record
from rockcli.terminal.table import Column, Report, Table

#: A terminal table shows at most this many records (period + 2 columns each: 7 columns fit
#: in 100 characters); more records: JSON or CSV.
MAX_TABLE_RECORDS = 3

#: What every spectrum table says about its numbers.
DEFINITION = (
    "Sa = ω²·Sd (pseudo-acceleration, ω = 2π/T), Sd the peak relative displacement of a linear "
    "oscillator at rest at the first sample, including its free vibration after the record"
)


def unique_names(records: Sequence[Record]) -> list[str]:
    """The records' names, a repeated one suffixed #2, #3 … (CSV columns must differ)."""
    names: list[str] = []
    for rec in records:
        name, n = rec.name, 1
        while name in names:
            n += 1
            name = f"{rec.name}#{n}"
        names.append(name)
    return names


def spectrum_document(
    names: Sequence[str],
    damping: float,
    periods: np.ndarray,
    spectra: Sequence[tuple[np.ndarray, np.ndarray]],
) -> dict[str, Any]:
    """The JSON document: per record its name, damping (fraction), periods [s], Sa [g], Sd [m]."""
    return {
        "records": [
            {
                "name": name,
                "damping": damping,
                "periods": periods.tolist(),
                "Sa_g": Sa.tolist(),
                "Sd_m": Sd.tolist(),
            }
            for name, (Sa, Sd) in zip(names, spectra, strict=True)
        ]
    }


def spectrum_csv(doc: dict[str, Any]) -> str:
    """The CSV text: ``period_s`` then ``<name>_Sa_g,<name>_Sd_m`` per record, full precision."""
    records = doc["records"]
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["period_s", *(f"{r['name']}_{k}" for r in records for k in ("Sa_g", "Sd_m"))])
    for i, period in enumerate(records[0]["periods"]):
        writer.writerow([repr(period), *(repr(r[k][i]) for r in records for k in ("Sa_g", "Sd_m"))])
    return out.getvalue()


def spectrum_tables(doc: dict[str, Any]) -> tuple[Table, Table]:
    """Sa [g], then Sd [m]: the period, then a column per record (at most MAX_TABLE_RECORDS)."""
    records = doc["records"]
    damping = f"damping {records[0]['damping']:.4g} of critical"
    return (
        _quantity_table(f"Pseudo-acceleration Sa [g], {damping}", records, "Sa_g"),
        _quantity_table(f"Displacement Sd [m], {damping}", records, "Sd_m"),
    )


def _quantity_table(title: str, records: list[dict[str, Any]], key: str) -> Table:
    columns = (Column("T", "T", "s"), *(Column(str(i), r["name"]) for i, r in enumerate(records)))
    rows = tuple(
        {"T": T, **{str(i): rec[key][j] for i, rec in enumerate(records)}}
        for j, T in enumerate(records[0]["periods"])
    )
    return Table(title, columns, rows)


def spectrum_report(doc: dict[str, Any], records: Sequence[Record]) -> Report:
    """The Report: the table, the definition of Sa and Sd, each record's PGA, notes, warnings."""
    names = [rec["name"] for rec in doc["records"]]
    named = len(names) > 1
    return Report(
        title=f"rock record spectrum — {', '.join(names)}",
        tables=spectrum_tables(doc),
        notes=(
            DEFINITION,
            *(
                line
                for n, r in zip(names, records, strict=True)
                for line in (_short_period_note(n, r, doc["records"][0]["damping"]), *r.notes)
            ),
        ),
        warnings=tuple(
            f"{n}: {w}" if named else w
            for n, r in zip(names, records, strict=True)
            for w in r.warnings
        ),
    )


def _short_period_note(name: str, rec: Record, damping: float) -> str:
    """What Sa tends to as T → 0: the PGA, or the overshoot of a record starting off zero."""
    from rockcli.codecheck.response import rigid_limit

    limit = rigid_limit(rec.accel, damping)
    if limit <= rec.pga:
        return f"{name}: PGA {rec.pga:.4g} g, the limit of Sa as T → 0"
    return (
        f"{name}: PGA {rec.pga:.4g} g; the record starts at {rec.accel[0]:.4g} g, a step from "
        f"rest that stiff oscillators overshoot: Sa → {limit:.4g} g as T → 0"
    )
