"""Run the candidates of a retrofit: both analyses of each diameter, on the sweep's lanes.

Each candidate is one case of a chunk sent to the sweep executor's lanes
(:func:`rockcli.studies.parallel.chunks.run_chunks`): this process's thread with ``--jobs 1``, and
worker processes with more. The chunk carries the model table, not a model: the worker
validates it again (pickling a pydantic model is not cheaper, and the table is what the plan
validated). A candidate's row is plain data (SI units), keyed by its case id.

Every candidate of a process reads one response spectrum of the record
(:func:`shared_spectrum`), as a study's cases do (rockcli.studies.sweep.worker.spectrum_of):
the 2019 demand of a record is the maximum of its spectrum over [T0, T_SLV], sought on an
absolute period grid (rockcli.codecheck.demand.RANGE_STEP) whose ordinates the spectrum keeps,
so a candidate computes only the few its neighbours have not.
"""

from __future__ import annotations

import hashlib
import math
import threading
from collections import OrderedDict
from collections.abc import Callable, MutableSequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from rockcli.analyses.choices import Analyses
from rockcli.dynamics.result import RunStatus
from rockcli.notes import Note
from rockcli.studies.retrofit.candidates import RetrofitPlan, build_candidate

if TYPE_CHECKING:
    from rockcli.analyses.assess import AssessmentOutput
    from rockcli.codecheck.response import RecordSpectrum
    from rockcli.codecheck.result import KinematicResult
    from rockcli.dynamics.result import Assessment
    from rockcli.records.record import Record
    from rockcli.studies.parallel.executor import Lane


@dataclass(frozen=True)
class Candidate:
    """One diameter to try: its case id (its place in the plan) and size [mm]."""

    id: int
    diameter_mm: float


@dataclass(frozen=True)
class RetrofitChunk:
    """Candidates sent to a worker together, with what they share."""

    plan: RetrofitPlan
    #: None: the code check alone, on the model's own spectra (no time history).
    record: Record | None
    analyses: Analyses
    cases: tuple[Candidate, ...]
    #: The code check's demand: "record" (its spectrum) or "model" (the model's spectra).
    code_demand: str = "record"
    #: The hazard grid for a model's site (code_demand "model"; None: $ROCK_HAZARD_GRID).
    grid_file: str | None = None


def run_retrofit_chunk(chunk: RetrofitChunk) -> list[dict[str, Any]]:
    """The row of every candidate of the chunk (runs in a worker or in this process)."""
    return [
        {
            "case": c.id,
            **run_candidate(
                chunk.plan,
                c.diameter_mm,
                chunk.record,
                chunk.analyses,
                chunk.code_demand,
                chunk.grid_file,
            ),
        }
        for c in chunk.cases
    ]


#: Record spectra a process keeps for its candidates (one per `rock retrofit`; a report sizes a
#: rod per record), the least recently used dropped first.
SPECTRA_KEPT = 4
_spectra: OrderedDict[tuple[bytes, float], RecordSpectrum] = OrderedDict()
_lock = threading.Lock()


def shared_spectrum(record: Record, g: float) -> RecordSpectrum:
    """The record's response spectrum at gravity g [m/s²], one per process for every
    candidate, whose ordinates are cached inside (each candidate making its own computed the
    ~600 ordinates of the 2019 demand's period grid again: 15 times slower). Keyed by the
    record's samples, since a worker process receives a new copy of the record with each
    chunk."""
    from rockcli.codecheck.response import RecordSpectrum

    digest = hashlib.blake2b(record.time.tobytes())
    digest.update(record.accel.tobytes())
    key = (digest.digest(), float(g))
    with _lock:
        spectrum = _spectra.get(key)
        if spectrum is None:
            spectrum = RecordSpectrum.from_record(record, g=g)
            _spectra[key] = spectrum
            while len(_spectra) > SPECTRA_KEPT:
                _spectra.popitem(last=False)
        _spectra.move_to_end(key)
    return spectrum


def run_candidate(
    plan: RetrofitPlan, diameter_mm: float, record: Record | None, analyses: Analyses,
    code_demand: str = "record", grid_file: str | None = None,
) -> dict[str, Any]:  # fmt: skip
    """Both analyses of the model with the rod of this diameter, mechanism by mechanism: the
    code check of the whole catalogue on the record's spectrum (one earthquake on both sides,
    as ``rock compare``; ``code_demand`` "model": on the model's own spectra, as a report's
    verification), and the time history of both polarities of every mechanism the rod is on
    (:func:`mechanism_rows`). The candidate's own columns are those of the governing
    mechanism of that check (with this rod: a stronger rod can hand the governing role to
    another); ``mechanisms`` has every one, with its status (studies.retrofit.choose).
    Without a record (None) the code check alone, on the model's own spectra."""
    from rockcli.analyses.kinematic import kinematic_model
    from rockcli.model.catalogue import catalogue

    model = build_candidate(plan, diameter_mm)
    own = code_demand == "record" and record is not None
    spectrum = shared_spectrum(record, model.analysis.g) if own and record is not None else None
    mechanisms = catalogue(model)
    kin = kinematic_model(model, edition=analyses.edition, record=record if own else None,
                          spectrum=spectrum, grid_file=grid_file,
                          mechanisms=mechanisms)  # fmt: skip
    rows = mechanism_rows(model, kin, mechanisms, plan, record, analyses)
    first = rows[0]
    return {
        "diameter_mm": diameter_mm,
        **rod_columns(model, plan.index),
        **{k: v for k, v in first.items() if k not in ("name", "type", "status", "side")},
        "mechanisms": rows,
    }


def mechanism_rows(
    model: Any, kin: KinematicResult, mechanisms: Any, plan: RetrofitPlan, record: Record | None,
    analyses: Analyses,
) -> list[dict[str, Any]]:  # fmt: skip
    """Every mechanism of the catalogue with the rod, the governing one first: its code ULS
    on the governing side, whether the rod restrains it (on it, and not slack on that side),
    and where the rod is on it the time history with the rod's checks; its status."""
    from rockcli.analyses.catalogue import side_check
    from rockcli.analyses.kinematic import check_settings
    from rockcli.model.catalogue import named
    from rockcli.studies.retrofit.choose import mechanism_status

    settings = check_settings(model, analyses.edition)
    rows = []
    for m in kin.catalogue or ():
        mech = named(mechanisms, m.name)
        rod = [r for r in side_check(mech, m.result.side, settings).restrainers
               if r.name == plan.name]  # fmt: skip
        arch = mech.spec is not None and mech.spec.limit_by == plan.name  # its thrust's tie
        row: dict[str, Any] = {
            "name": m.name,
            "type": m.type,
            "side": m.result.side,
            "mechanism": None if mech.wall is None else m.name,  # a block file's: the block
            "on_mechanism": bool(rod) or arch,
            "restrained": arch or (bool(rod) and rod[0].slack_side != m.result.side),
            **code_columns(m.result),
            **rocked_columns(model, record, analyses, plan, m.name, mechanisms, bool(rod)),
        }
        row["status"] = mechanism_status(row)
        rows.append(row)
    return rows


def rocked_columns(
    model: Any, record: Record | None, analyses: Analyses, plan: RetrofitPlan, name: str,
    mechanisms: Any, on_it: bool,
) -> dict[str, Any]:  # fmt: skip
    """The time history of a mechanism the rod is on (as ``rock compare`` rocks it), with the
    rod's checks; not run (every column None, nothing failing) where the rod is not on it or
    without a record (the code check alone)."""
    not_rocked: dict[str, Any] = {"input": None, "rocking": None, "max_ratio": None,
                                  "overturned": False,
                  "broken_runs": [], "max_force": None, "utilisation": None, "ductility": None,
                  "anchor": None, "ruptured": False}  # fmt: skip
    if not on_it:
        return not_rocked
    if record is None:  # the code check alone: the rod's anchorage needs no time history
        return {**not_rocked, "anchor": static_anchor(model, plan.index)}
    from rockcli.analyses.assess import assess_model_output
    from rockcli.errors import InputError

    try:
        out = assess_model_output(
            model, record, analyses.engine, ground=analyses.ground, file=plan.file,
            tolerance_check=False,  # assess, compare and report check it; the sizing does not
            mechanism=name, mechanisms=mechanisms,
        )  # fmt: skip
    except InputError as exc:  # a mechanism the time history does not rock: why, and go on
        return {**not_rocked, "not_rocked": exc.render().removeprefix("error: ")}
    return {"input": "ground" if out.floor is None else "floor",
            **rocking_columns(out, member_index(out, plan.name))}  # fmt: skip


def static_anchor(model: Any, index: int) -> dict[str, Any] | None:
    """The rod's anchorage check (capacity design, γov·A·fy against the anchor's capacity:
    rockcli.codecheck.tie.anchorage), which no time history decides; None when the rod is not
    a bar of known steel."""
    from rockcli.analyses.strength import verification_document
    from rockcli.codecheck.tie import anchorage
    from rockcli.model.derive import to_restrainer

    rod = to_restrainer(model, index)
    if rod.overstrength <= 0:
        return None
    return verification_document(anchorage(rod.overstrength, rod.anchor_capacity))


def member_index(out: AssessmentOutput, name: str) -> int | None:
    """The rod's place among the members of the body rocked (None: not one of them)."""
    names = [r.name for r in out.block.restrainers]
    return names.index(name) if name in names else None


def rod_columns(model: Any, index: int) -> dict[str, Any]:
    """The rod as derived from the candidate model: its stiffness K [N/m] (the stiffer side)
    and strength [N]."""
    from rockcli.model.derive import to_restrainer

    rod = to_restrainer(model, index)
    return {"K": max(rod.k_pos, rod.k_neg), "strength": _finite(rod.strength)}


def code_columns(kin: KinematicResult) -> dict[str, Any]:
    """The code's ULS: pass (None: not evaluated) and the governing ζ = capacity/demand
    (the rule of the sweep's column, rockcli.studies.sweep.columns.uls_ratio)."""
    from rockcli.studies.sweep.columns import uls_ratio

    return {"code_uls_passed": kin.verdict()["ULS"], "code_zeta": uls_ratio(kin.checks)}


def rocking_columns(out: AssessmentOutput, index: int | None) -> dict[str, Any]:
    """The time history over both polarities: max θ/α, overturning, the rod's peak force,
    its utilisation (rockcli.analyses.strength) and whether it ruptured (``index``: the rod
    among the members of the body rocked; None: not one of them, no force)."""
    result = out.result
    common = {
        "rocking": str(result.verdict),
        "max_ratio": float(result.max_ratio),
        "overturned": any(r.overturned for r in result.runs),
        "broken_runs": broken_runs(result),
    }
    if index is None:
        return {**common, "max_force": None, "utilisation": None, "ductility": None,
                "anchor": None, "ruptured": False}  # fmt: skip
    peaks = [run.restrainers[index] for run in result.runs]
    return {
        **common,
        "max_force": max(float(p.max_force) for p in peaks),
        **rod_check(out, index),
        "ruptured": any(p.t_fail is not None for p in peaks),
    }


def broken_runs(result: Assessment) -> list[dict[str, Any]]:
    """The runs that ended in a non-finite state (their numbers decide nothing): polarity,
    status and message, as the assess document has them (usually none)."""
    return [
        {"polarity": r.polarity, "status": str(r.status), "message": r.message}
        for r in result.runs
        if r.status is RunStatus.NONFINITE
    ]


def rod_check(out: AssessmentOutput, index: int) -> dict[str, Any]:
    """The rod's row of the assessment's restrainer checks (rockcli.analyses.strength): its
    utilisation (force over strength; None: no strength), its ductility and its anchorage
    (each {demand, capacity, passed, rule}; None: not a bar of known steel)."""
    rows = [r for r in out.restrainer_checks if r["index"] == index]
    if not rows:
        return {"utilisation": None, "ductility": None, "anchor": None}
    row = rows[0]
    return {k: row[k] for k in ("utilisation", "ductility", "anchor")}


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def run_retrofit(
    plan: RetrofitPlan,
    record: Record | None,
    lanes: MutableSequence[Lane],
    analyses: Analyses,
    progress: Callable[[int, int], None] | None = None,
    code_demand: str = "record",
    grid_file: str | None = None,
) -> list[dict[str, Any]]:
    """Every candidate's row, ascending in diameter, each diameter a chunk on the lanes
    (``code_demand``: the code check's, :func:`run_candidate`).

    Raises RuntimeError when a worker process died on a candidate (the sweep's row error).
    """
    from rockcli.studies.parallel.chunks import run_chunks

    cases = [Candidate(i, d) for i, d in enumerate(plan.diameters_mm)]
    chunks = [RetrofitChunk(plan, record, analyses, (c,), code_demand, grid_file) for c in cases]
    rows: dict[int, dict[str, Any]] = {}
    if progress:
        progress(0, len(cases))
    for chunk_rows in run_chunks(lanes, chunks, run_retrofit_chunk):
        for row in chunk_rows:
            if "error" in row:
                raise RuntimeError(f"{plan.diameters_mm[row['case']]:g} mm: {row['error']}")
            rows[row.pop("case")] = row
        if progress:
            progress(len(rows), len(cases))
    return [rows[c.id] for c in cases]


@dataclass(frozen=True)
class Sizing:
    """What `rock retrofit` finds for a model's tie-rod (under a record, or by the code check
    alone): the rod, its steel and bars, the diameters tried [mm], the chosen row (None: none
    passes) and why; or, when the model has no single tie-rod to size, only why not
    (``reason``)."""

    reason: Note
    rod: str = ""
    grade: str = ""
    bars: int = 0
    diameters_mm: tuple[float, ...] = ()
    chosen: dict[str, Any] | None = None
    #: The diameter of the rod in the model [mm] (None: not given).
    installed_mm: float | None = None
    #: The mechanisms that need another intervention with the chosen diameter (or the
    #: largest tried): the rod does not restrain them (studies.retrofit.choose.others).
    others: tuple[str, ...] = ()
    #: What the code check of each diameter read: "record" or "model" (its own spectra).
    code_demand: str = "record"
    #: Whether each diameter was rocked under a record (False: the code check alone).
    rocked: bool = True


def size_rod(
    model_path: str,
    record: Record | None,
    analyses: Analyses,
    code_demand: str = "record",
    grid_file: str | None = None,
) -> Sizing:
    """`rock retrofit MODEL --record R` with its defaults (the model's one tie-rod, the default
    diameters, its steel), in this process: the smallest diameter that makes safe every
    mechanism the rod restrains (rockcli.studies.retrofit.choose); ``code_demand`` "model":
    the code check on the model's own spectra (a report's verification); without a record
    (None) that check alone."""
    from rockcli.model.load import read_toml, validate_model
    from rockcli.studies.parallel.executor import local_executor
    from rockcli.studies.retrofit.candidates import DEFAULT_DIAMETERS_MM, make_plan, tie_rods
    from rockcli.studies.retrofit.choose import choose, others

    table = read_toml(model_path)
    model = validate_model(table, file=model_path)
    rods = tie_rods(model)
    if len(rods) != 1:
        return Sizing(
            Note("retro_no_rod", "no tie-rod to size: place one with rock retrofit --at "
                 "HEIGHT,FROM_PIVOT --length L")
            if not rods
            else Note("retro_several", "{n} tie-rods: size one with rock retrofit --name",
                      n=len(rods))
        )  # fmt: skip
    plan = make_plan(table, model, file=model_path, diameters_mm=DEFAULT_DIAMETERS_MM)
    with local_executor(1) as lanes:
        rows = run_retrofit(
            plan, record, lanes, analyses, code_demand=code_demand, grid_file=grid_file
        )
    chosen, reason = choose(rows, rocked=record is not None)
    installed = model.restrainers[rods[0]].diameter
    shown = chosen or (rows[-1] if rows else {})
    return Sizing(reason, plan.name, plan.grade, plan.count, plan.diameters_mm, chosen,
                  None if installed is None else 1e3 * float(installed),
                  tuple(others(shown)), code_demand, record is not None)  # fmt: skip
