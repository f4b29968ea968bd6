"""A record as data: its JSON document and its Report (used by `record info` and `assess`)."""

from __future__ import annotations

from typing import Any

from rockcli.records.record import Record
from rockcli.report.table import Report, key_value
from rockcli.units import AccelUnit

#: Version of the JSON written by ``rock record info --format json``.
INFO_SCHEMA = 1

#: Display symbols of the acceleration units (rockcli.units.AccelUnit values).
SYMBOLS = {"g": "g", "m/s2": "m/s²", "cm/s2": "cm/s²"}


def record_document(rec: Record) -> dict[str, Any]:
    """The record as read and transformed, full precision (JSON)."""
    return {
        "name": rec.name,
        "source": rec.source,
        "format": rec.format,
        "npts": rec.npts,
        "dt": rec.dt,
        "duration": rec.duration,
        "pga_g": rec.pga,
        "t_pga": rec.t_pga,
        "unit": rec.unit,
        "notes": list(rec.notes),
    }


def info_document(rec: Record) -> dict[str, Any]:
    """The JSON document of ``rock record info``."""
    return {"schema": INFO_SCHEMA, **record_document(rec)}


def record_report(doc: dict[str, Any]) -> Report:
    """The table of a record document: samples, dt, duration, PGA in g, m/s² and its own unit."""
    units = dict.fromkeys([AccelUnit.G, AccelUnit.M_S2, AccelUnit(doc["unit"])])
    pga = [(f"PGA ({SYMBOLS[u]})", doc["pga_g"] / u.to_g, SYMBOLS[u], "{:.6g}") for u in units]
    table = key_value(
        f"Record {doc['name']}",
        [
            ("source", doc["source"], "", ""),
            ("format", doc["format"], "", ""),
            ("unit in file", SYMBOLS.get(doc["unit"], doc["unit"]), "", ""),
            ("samples", doc["npts"], "", "{:d}"),
            ("dt", doc["dt"], "s", "{:.6g}"),
            ("duration", doc["duration"], "s", "{:.6g}"),
            *pga,
            ("time of PGA", doc["t_pga"], "s", "{:.6g}"),
        ],
    )
    return Report(
        title=f"rock record info — {doc['name']}", tables=(table,), notes=tuple(doc["notes"])
    )
