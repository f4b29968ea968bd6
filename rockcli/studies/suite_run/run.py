"""Run a suite of records through the time history: every record, both polarities, on the
sweep executor's lanes (:func:`rockcli.studies.parallel.chunks.run_chunks`), each record a chunk.

The chunk carries the model's table, not a model: the worker validates it again (as
``rock retrofit`` does). A record's row is plain data, keyed by its place in the suite, and
becomes a :class:`~rockcli.studies.suite_run.rule.RecordOutcome` for the code's rule.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, MutableSequence, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rockcli.studies.suite_run.rule import RecordOutcome

if TYPE_CHECKING:
    from rockcli.records.record import Record
    from rockcli.studies.parallel.executor import Lane


@dataclass(frozen=True)
class SuiteRecord:
    """One record of a suite as it shakes the block: its name, the scale applied, the record
    (already scaled, accelerations in g)."""

    name: str
    scale: float
    record: Record


@dataclass(frozen=True)
class SuiteCase:
    """One record of the suite as a case of a chunk: its place in the suite (``id``, as the
    sweep's lanes name a case) and the record."""

    id: int
    item: SuiteRecord


@dataclass(frozen=True)
class SuiteChunk:
    """Records sent to a worker together, with the model they shake.

    Attributes:
        table: the model file's table (validated again in the worker).
        file: the model file's path, for messages. engine: "fast" or "reference".
        ground: a block at height rocks on the record itself, not its floor motion.
        cases: the records, each with its place in the suite.
        tolerance_check: run each record's polarities again at tighter tolerances.
        mechanism: a wall's mechanism to rock under every record (None: the governing one).
    """

    table: Mapping[str, Any]
    file: str | None
    engine: str
    ground: bool
    cases: tuple[SuiteCase, ...]
    tolerance_check: bool = True
    mechanism: str | None = None


def run_suite_chunk(chunk: SuiteChunk) -> list[dict[str, Any]]:
    """The row of every record of the chunk (runs in a worker or in this process)."""
    from rockcli.model.load import validate_model

    model = validate_model(dict(chunk.table), file=chunk.file)
    engine, ground, check = chunk.engine, chunk.ground, chunk.tolerance_check
    return [
        {
            "case": c.id,
            **record_row(
                model,
                c.item,
                engine,
                ground,
                chunk.file,
                tolerance_check=check,
                mechanism=chunk.mechanism,
            ),  # fmt: skip
        }
        for c in chunk.cases
    ]


def record_row(
    model: Any,
    item: SuiteRecord,
    engine: str,
    ground: bool,
    file: str | None,
    *,
    tolerance_check: bool = True,
    mechanism: str | None = None,
) -> dict:
    """Both polarities of the model under one record: max θ/α (overturn angle/α when it
    overturned), whether it overturned, the status of each run; with ``tolerance_check``,
    whether it is tolerance-sensitive (``sensitive``, rockcli.dynamics.tolerance) and each
    polarity's check (``tolerance``); a wall's ``mechanism`` rocked (None: the model's
    block)."""
    from rockcli.analyses.assess import assess_model_output
    from rockcli.dynamics.tolerance import sensitive

    out = assess_model_output(model, item.record, engine, ground=ground, file=file,
                              tolerance_check=tolerance_check, mechanism=mechanism)  # fmt: skip
    result = out.result
    return {
        "name": item.name,
        "scale": item.scale,
        "pga_g": float(item.record.pga),
        "max_ratio": float(result.max_ratio),
        "overturned": any(r.overturned for r in result.runs),
        "verdict": str(result.verdict),
        "input": "ground" if out.floor is None else "floor",
        "statuses": [str(r.status) for r in result.runs],
        "sensitive": sensitive(result.runs),
        "tolerance": [run_check(r) for r in result.runs],
        "mechanism": None if out.mechanism is None else out.mechanism[0],
    }


def run_check(run: Any) -> dict[str, Any]:
    """A run and its tolerance check as plain data: what the reports need to say it."""
    check = run.tolerance
    return {
        "polarity": run.polarity,
        "max_ratio": float(run.max_ratio),
        "impacts": run.impacts,
        "overturned": run.overturned,
        "rtol": run.rtol,
        "tolerance_check": None if check is None else {
            "rtol": check.rtol, "max_ratio": float(check.max_ratio), "impacts": check.impacts,
            "overturned": check.overturned, "sensitive": check.sensitive,
        },
    }  # fmt: skip


def run_suite(
    table: Mapping[str, Any],
    records: Sequence[SuiteRecord],
    lanes: MutableSequence[Lane],
    *,
    engine: str = "fast",
    ground: bool = False,
    file: str | None = None,
    progress: Callable[[int, int], None] | None = None,
    tolerance_check: bool = True,
    mechanism: str | None = None,
) -> list[dict[str, Any]]:
    """Every record's row in the suite's order, each record a chunk on the lanes. A record
    whose worker died twice is a row with an ``error`` (rockcli.studies.sweep.run)."""
    from rockcli.studies.parallel.chunks import run_chunks

    chunks = [
        SuiteChunk(
            table, file, engine, ground, (SuiteCase(k, item),), tolerance_check, mechanism
        )  # fmt: skip
        for k, item in enumerate(records)
    ]
    rows: list[dict[str, Any]] = []
    for done in run_chunks(lanes, chunks, run_suite_chunk):
        rows.extend(done)
        if progress is not None:
            progress(len(rows), len(chunks))
    return sorted(rows, key=lambda r: r["case"])


def outcomes(rows: Sequence[Mapping[str, Any]]) -> list[RecordOutcome]:
    """The rule's view of the rows: name, scale, PGA, max θ/α, overturned.

    Raises:
        ValueError: a row with an error (its record decides nothing; the caller says which).
    """
    broken = [r for r in rows if "error" in r]
    if broken:
        raise ValueError(f"record {broken[0]['case'] + 1} of the suite: {broken[0]['error']}")
    return [
        RecordOutcome(r["name"], r["scale"], r["pga_g"], r["max_ratio"], r["overturned"])
        for r in rows
    ]
