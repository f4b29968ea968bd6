"""A record as data: its JSON document and its Report (used by `record info` and `assess`)."""

from __future__ import annotations

from typing import Any

from rockcli.records.record import Record
from rockcli.terminal.table import Report, Table, key_value
from rockcli.units import AccelUnit

#: Version of the JSON written by ``rock record info --format json`` (2: a list of records,
#: each with its warnings and the header's event, station and component).
INFO_SCHEMA = 2

#: The header fields shown when the file names them.
ORIGIN_FIELDS = ("event", "station", "component")

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
        "unit_declared": rec.unit_declared,
        "event": rec.event,
        "station": rec.station,
        "component": rec.component,
        "notes": list(rec.notes),
        "warnings": list(rec.warnings),
    }


def info_document(records: list[Record]) -> dict[str, Any]:
    """The JSON document of ``rock record info``: one entry per file, in the order given."""
    return {"schema": INFO_SCHEMA, "records": [record_document(rec) for rec in records]}


def record_table(doc: dict[str, Any]) -> Table:
    """The table of one record document: header names, samples, dt, duration, PGA in units."""
    units = dict.fromkeys([AccelUnit.G, AccelUnit.M_S2, AccelUnit(doc["unit"])])
    pga = [(f"PGA ({SYMBOLS[u]})", doc["pga_g"] / u.to_g, SYMBOLS[u], "{:.6g}") for u in units]
    origin = [(key, doc[key], "", "") for key in ORIGIN_FIELDS if doc.get(key)]
    return key_value(
        f"Record {doc['name']}",
        [
            ("source", doc["source"], "", ""),
            ("format", doc["format"], "", ""),
            *origin,
            ("unit in file", unit_label(doc), "", ""),
            ("samples", doc["npts"], "", "{:d}"),
            ("dt", doc["dt"], "s", "{:.6g}"),
            ("duration", doc["duration"], "s", "{:.6g}"),
            *pga,
            ("time of PGA", doc["t_pga"], "s", "{:.6g}"),
        ],
    )


def unit_label(doc: dict[str, Any]) -> str:
    """The unit the values were read in, "(assumed)" when nothing declared it."""
    label = SYMBOLS.get(doc["unit"], doc["unit"])
    return label if doc.get("unit_declared", True) else f"{label} (assumed)"


def record_notes(doc: dict[str, Any], *, named: bool = False) -> tuple[str, ...]:
    """The record's notes, prefixed by its name if ``named``."""
    return tuple(f"{doc['name']}: {line}" if named else line for line in doc["notes"])


def record_warnings(doc: dict[str, Any], *, named: bool = False) -> tuple[str, ...]:
    """The record's warnings, prefixed by its name if ``named``."""
    lines = doc.get("warnings", ())
    return tuple(f"{doc['name']}: {line}" if named else line for line in lines)


def record_report(doc: dict[str, Any]) -> Report:
    """The Report of one record document (its table, then its notes and warnings)."""
    return Report(
        title=f"rock record info — {doc['name']}",
        tables=(record_table(doc),),
        notes=record_notes(doc),
        warnings=record_warnings(doc),
    )


def info_report(doc: dict[str, Any]) -> Report:
    """The Report of ``rock record info``: a table per record, then warnings and notes."""
    records = doc["records"]
    if len(records) == 1:
        return record_report(records[0])
    return Report(
        title=f"rock record info — {len(records)} records",
        tables=tuple(record_table(rec) for rec in records),
        notes=tuple(note for rec in records for note in record_notes(rec, named=True)),
        warnings=tuple(w for rec in records for w in record_warnings(rec, named=True)),
    )
