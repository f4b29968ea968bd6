"""What a worker does with a chunk of cases: read its record once, run every case, key rows.

Runs in a worker process (a local process pool started with ``spawn``, or a dask worker) or
in the main process (``--jobs 1``). Each process reads each record once and keeps one
:class:`~rockcli.codecheck.response.RecordSpectrum` per record, whose cache of ordinates then
serves every case of that record the process runs (spec/engine.md, "Studies at scale").
The module imports nothing heavy at the top, so a spawned worker can set its environment
(one numba/BLAS thread) before numpy and numba load.
"""

from __future__ import annotations

import threading
import unicodedata
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING, Any

from rockcli.errors import InputError
from rockcli.studies.sweep.cases import Case, Cases, build_model, case_error, case_labels
from rockcli.studies.sweep.columns import kinematic_columns, plain_number, sliding_columns
from rockcli.studies.sweep.study import RecordSource, StudyPlan

if TYPE_CHECKING:
    from rockcli.analyses.assess import AssessmentOutput
    from rockcli.codecheck.response import RecordSpectrum
    from rockcli.codecheck.result import KinematicResult
    from rockcli.dynamics.result import Assessment
    from rockcli.model.schema import Model
    from rockcli.records.record import Record
    from rockcli.studies.sweep.over_suite import SuiteInput

_records: dict[RecordSource, Record] = {}
_spectra: dict[tuple[RecordSource, float], RecordSpectrum] = {}
_lock = threading.Lock()  # dask workers run tasks on threads sharing these caches


@dataclass(frozen=True)
class Chunk:
    """Cases of one record (or none) sent to a worker together, by id (a range when they
    follow each other: what is sent is a few numbers, whatever the chunk's size)."""

    plan: StudyPlan
    record: int | None
    ids: Sequence[int]

    @cached_property
    def cases(self) -> tuple[Case, ...]:
        """The chunk's cases."""
        every = Cases(self.plan)
        return tuple(every[k] for k in self.ids)


def read_source(source: RecordSource) -> Record:
    """The record of a source, read once per process (scaled as the study says)."""
    with _lock:
        record = _records.get(source)
    if record is None:
        from rockcli.records import files, transform

        record = files.read_record(source.path, fmt=source.fmt, dt=source.dt, units=source.units)
        record = transform.scale(record, source.scale) if source.scale is not None else record
        record = transform.scale_to_pga(record, source.pga) if source.pga is not None else record
        with _lock:
            record = _records.setdefault(source, record)
    return record


def spectrum_of(source: RecordSource, g: float) -> RecordSpectrum:
    """The record's response spectrum, one per process (its ordinates are cached inside)."""
    from rockcli.codecheck.response import RecordSpectrum

    with _lock:
        spectrum = _spectra.get((source, g))
        if spectrum is None:
            spectrum = RecordSpectrum.from_record(_records[source], g=g)
            _spectra[(source, g)] = spectrum
    return spectrum


#: A chunk's cases as written: their ids and their lines of cases.csv.
ChunkLines = tuple[list[int], list[bytes]]


def run_chunk_lines(chunk: Chunk) -> ChunkLines:
    """The chunk's cases (:func:`run_chunk`) as their lines of cases.csv, made here in the
    worker (a batched chunk's from its result arrays, column by column)."""
    from rockcli.studies.sweep.output import column_lines, columns, row_lines

    plan = chunk.plan
    header = columns(plan)
    ids = [c.id for c in chunk.cases]
    batched = batched_cells(chunk)
    if batched is not None:
        return ids, column_lines(header, len(ids), batched)
    rows = run_chunk(chunk)
    labelled = [{**case_labels(plan, c), **r} for c, r in zip(chunk.cases, rows, strict=True)]
    return ids, row_lines(header, labelled)


def batched_cells(chunk: Chunk) -> dict[str, list[str]] | None:
    """The written fields of a batched chunk's rows by column (rockcli.studies.sweep.batch),
    or None when the chunk runs case by case."""
    from rockcli.studies.sweep.batch import cached_form, label_cells, result_cells, run_arrays

    plan = chunk.plan
    if chunk.record is None or plan.records[chunk.record].suite:
        return None
    form = cached_form(plan)
    if form is None:
        return None
    record = read_source(plan.records[chunk.record])
    found = run_arrays(form, chunk.cases, record.time, record.accel, record.dt)
    if found is None:
        return None
    return {**label_cells(plan, chunk.cases), **result_cells(*found)}


def batched_rows(
    chunk: Chunk, record: Record | None, suite: SuiteInput | None
) -> list[dict[str, Any]] | None:
    """The rows of a batched chunk (rockcli.studies.sweep.batch) under its record or suite,
    or None when the chunk runs case by case."""
    from rockcli.studies.sweep.batch import cached_form, rows_of, run_arrays, suite_rows

    form = cached_form(chunk.plan) if record is not None or suite is not None else None
    if form is None:
        return None
    if suite is not None:
        return suite_rows(form, chunk.cases, suite)
    assert record is not None
    found = run_arrays(form, chunk.cases, record.time, record.accel, record.dt)
    return None if found is None else rows_of(chunk.cases, *found)


def run_chunk(chunk: Chunk) -> list[dict[str, Any]]:
    """The result columns of every case of the chunk, each with its case id.

    A case that fails (bad input found at run time, or an internal error) gives a row with
    its ``error`` and no results: the study goes on, the summary counts it, and ``--resume``
    does not run it again.
    """
    from rockcli.studies.sweep.over_suite import read_suite, run_suite_case

    plan = chunk.plan
    source = plan.records[chunk.record] if chunk.record is not None else None
    suite = read_suite(source) if source is not None and source.suite else None
    record = read_source(source) if source is not None and suite is None else None
    batched = batched_rows(chunk, record, suite)
    if batched is not None:
        return batched
    rows = []
    for case in chunk.cases:
        known: dict[str, Any] = {"case": case.id}  # the block's R and α once computed
        try:
            model = build_model(plan, case)
            known["block_R"], known["block_alpha"] = model.geometry.polar
            if suite is not None:
                rows.append({"case": case.id, **run_suite_case(plan, model, suite)})
                continue
            spectrum = spectrum_of(source, model.analysis.g) if source is not None else None
            rows.append({"case": case.id, **run_case(plan, model, record, spectrum)})
        except InputError as exc:
            named = case_error(plan, case, exc)
            text = str(InputError(named.problem, value=named.value, allowed=named.allowed))
            rows.append({**known, "error": one_line(text)})
        except Exception as exc:  # noqa: BLE001 - any failure of one case is that case's row
            text = f"internal error (please report): {type(exc).__name__}: {exc}"
            rows.append({**known, "error": one_line(text)})
    return rows


def one_line(text: str) -> str:
    """Text with every control character (line breaks, tabs, escapes) made a space."""
    return "".join(" " if unicodedata.category(ch) == "Cc" else ch for ch in text)


def run_case(
    plan: StudyPlan, model: Model, record: Record | None, spectrum: RecordSpectrum | None
) -> dict[str, Any]:
    """The analyses of one case: the block, the rocking envelope, the code check."""
    from rockcli.analyses.compare import CodeDemand, classify, code_collapse, rocking_collapse
    from rockcli.model.catalogue import catalogue

    R, alpha = model.geometry.polar
    row: dict[str, Any] = {"block_R": R, "block_alpha": alpha}
    roc = kin = None
    mechanisms = catalogue(model)  # once a case: both analyses read these values
    if "kinematic" in plan.analyses:
        from rockcli.analyses.kinematic import kinematic_model

        own = record is not None and plan.code_demand == CodeDemand.RECORD
        kin = kinematic_model(
            model,
            record=record if own else None,
            spectrum=spectrum if own else None,
            grid_file=plan.grid_file,
            mechanisms=mechanisms,
        )
    mechanism, kin = case_mechanism(kin)
    if "rocking" in plan.analyses and record is not None:
        from rockcli.analyses.assess import assess_model_output
        from rockcli.analyses.floor import model_floor

        ground = plan.ground and model_floor(model) is not None
        out = assess_model_output(
            model, record, plan.engine, ground=ground, tolerance_check=plan.check_tolerance,
            mechanism=mechanism, mechanisms=mechanisms,
        )  # fmt: skip
        roc = out.result
        if out.mechanism is not None:  # a wall: the rocked body's R and α, its name
            row.update(block_R=out.block.R, block_alpha=out.block.alpha)
            mechanism = out.mechanism[0]
        row["input"] = "ground" if out.floor is None else "floor"
        row.update(rocking_columns(roc))
        if plan.check_tolerance:
            from rockcli.dynamics.tolerance import sensitive

            row["sensitive"] = sensitive(roc.runs)
        row["utilisation"] = max_utilisation(out)
    if kin is not None:
        row.update(kinematic_columns(kin))
    if mechanism is not None:
        row["mechanism"] = mechanism
    if roc is not None and kin is not None:
        row["classification"] = str(classify(code_collapse(kin), rocking_collapse(roc)))
    row.update(sliding_columns(plan, mechanisms, mechanism))
    return row


def case_mechanism(kin: KinematicResult | None) -> tuple[str | None, KinematicResult | None]:
    """(the mechanism a wall's case rocks and checks, its code check): as `rock compare`, the
    governing one (None, kin unchanged: a model of one block, or no code check)."""
    from rockcli.analyses.catalogue import main_mechanism
    from rockcli.analyses.compare import shown_result

    if kin is None:
        return None, None
    main = main_mechanism(kin)
    if main is None:
        return None, kin
    return main.name, shown_result(kin, main)


def max_utilisation(out: AssessmentOutput) -> float | None:
    """The largest force/strength of the restrainers that have a strength (None: none has)."""
    known = [c["utilisation"] for c in out.restrainer_checks]
    known = [u for u in known if u is not None]  # a member checked by its elongation alone
    return plain_number(max(known)) if known else None


def rocking_columns(result: Assessment) -> dict[str, Any]:
    """The polarity envelope of both rocking runs (and each polarity's peak)."""
    runs = {r.polarity: r for r in result.runs}
    overturns = [r.t_overturn for r in result.runs if r.t_overturn is not None]
    return {
        "max_ratio": plain_number(result.max_ratio),
        "max_ratio_pos": plain_number(runs[1].max_ratio) if 1 in runs else None,
        "max_ratio_neg": plain_number(runs[-1].max_ratio) if -1 in runs else None,
        "overturned": any(r.overturned for r in result.runs),
        "t_overturn": plain_number(min(overturns)) if overturns else None,
        "rocking": str(result.verdict),
    }
