"""Run an overturning spectrum on the sweep's lanes: one point (a pulse ratio, or a record and
a block size) per chunk (rockcli.studies.parallel.chunks.run_chunks).

A chunk carries the model table, not a model (as a retrofit's: the worker validates it again,
rockcli.studies.retrofit.run), and for a record point the record itself. Each point derives
its block and the motion it sees as `rock assess` does (rockcli.analyses.assess.rocked_input:
a block at height on its floor motion), then searches the lowest overturning intensity
(rockcli.studies.fragility.spectrum). A point's row is plain data, keyed by its case id.
"""

from __future__ import annotations

from collections.abc import Callable, MutableSequence, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rockcli.records.kinds import PulseKind
from rockcli.studies.fragility.spectrum import Scan, Threshold

if TYPE_CHECKING:
    from rockcli.analyses.floor import Floor
    from rockcli.mechanics import Rocker
    from rockcli.model.schema import Model
    from rockcli.records.record import Record
    from rockcli.studies.parallel.executor import Lane

#: The pulses of a pulse spectrum, and their length in periods Tp (rockcli.records.pulses).
PULSE_LENGTHS = {
    PulseKind.ONE_SINE: 1.0,
    PulseKind.ONE_COSINE: 1.0,
    PulseKind.RICKER: 3.0,
}
#: Periods T1 of the building's free vibration kept after a pulse that reaches a block at
#: height through its floor: at ξ = 5 % the floor's ringing decays as exp(−2πξ·n), to 8e-5 of
#: its amplitude after 30 periods.
FLOOR_RING_PERIODS = 30.0


@dataclass(frozen=True)
class Target:
    """What rocks: a model table (validated already), its file, the mechanism (a wall's), the
    input (``ground``: a block at height on the ground motion itself) and the engine."""

    table: dict[str, Any]
    file: str | None = None
    mechanism: str | None = None
    ground: bool = False
    engine: str = "fast"


@dataclass(frozen=True)
class PulseCase:
    """One point of a pulse spectrum: the pulse and its ωp/p."""

    id: int
    kind: str
    ratio: float


@dataclass(frozen=True)
class RecordCase:
    """One point of a record spectrum: the record and the size that varies, the block's
    semi-diagonal R [m] (``key`` "R") or the building's period T1 [s] (``key`` "T1")."""

    id: int
    record: Record
    value: float
    key: str = "R"


@dataclass(frozen=True)
class SpectrumChunk:
    """Points sent to a worker together, with what they share."""

    target: Target
    scan: Scan
    cases: tuple[PulseCase | RecordCase, ...] = field(default_factory=tuple)


def run_overturning_chunk(chunk: SpectrumChunk) -> list[dict[str, Any]]:
    """The row of every point of the chunk (runs in a worker or in this process)."""
    rows = []
    for case in chunk.cases:
        if isinstance(case, PulseCase):
            row = pulse_row(chunk.target, chunk.scan, case)
        else:
            row = record_row(chunk.target, chunk.scan, case)
        rows.append({"case": case.id, **row})
    return rows


def pulse_row(target: Target, scan: Scan, case: PulseCase) -> dict[str, Any]:
    """The lowest ap/a0 that overturns under the pulse of ωp/p = case.ratio (a0: the block's
    uplift acceleration), the pulse reaching a block at height through its floor."""
    from rockcli.studies.fragility.spectrum import sampled_pulse

    model = _model(target)
    block, floor = rocked_block(model, target)
    period = pulse_period_of(case.ratio, block)
    total = None
    if floor is not None:
        total = PULSE_LENGTHS[PulseKind(case.kind)] * period + FLOOR_RING_PERIODS * floor.T1
    pulse = sampled_pulse(case.kind, block.uplift_acceleration, period, total)
    found = search(model, target, pulse, scan, 1.0)
    return {**_threshold_columns(found), "period": period, **_block_columns(block)}


def record_row(target: Target, scan: Scan, case: RecordCase) -> dict[str, Any]:
    """The lowest scale of the record that overturns the block of semi-diagonal R, or the
    model in a building of period T1 (case.key, case.value)."""
    table = (
        sized_table(target.table, case.value)
        if case.key == "R"
        else with_period(target.table, case.value)
    )
    model = _model(Target(table, target.file, target.mechanism, target.ground, target.engine))
    block, _ = rocked_block(model, target)
    pga = float(max(abs(case.record.accel.max()), abs(case.record.accel.min())))
    per_unit = block.uplift_acceleration / pga  # the scale at intensity 1 (PGA = a0)
    found = search(model, target, case.record, scan, per_unit)
    scale = None if found.value is None else found.value * per_unit
    below = None if found.below is None else found.below * per_unit
    return {
        **_threshold_columns(found),
        "scale": scale,
        "scale_below": below,
        "pga": pga,
        **_block_columns(block),
    }


def search(model: Model, target: Target, record: Record, scan: Scan, per_unit: float) -> Threshold:
    """The first overturning intensity of the model under record × (intensity × per_unit)."""
    from rockcli.analyses.assess import rocked_input, settings_from
    from rockcli.dynamics.settings import Engine
    from rockcli.model.derive import solver_options
    from rockcli.studies.fragility.spectrum import lowest_overturn, overturn_response

    block, shaking, _, _ = rocked_input(model, record, target.ground, target.file, target.mechanism)
    settings = settings_from(solver_options(model))
    engine = Engine(target.engine)

    def response(intensity: float) -> tuple[float, bool]:
        accel = shaking.accel * (intensity * per_unit)
        return overturn_response(block, shaking.time, accel, shaking.dt, settings, engine)

    return lowest_overturn(response, scan)


def pulse_period_of(ratio: float, block: Rocker) -> float:
    """Tp [s] of ωp/p = ratio for the block."""
    from rockcli.studies.fragility.spectrum import pulse_period

    return pulse_period(ratio, block.p)


def rocked_block(model: Model, target: Target) -> tuple[Rocker, Floor | None]:
    """The block the runs rock and its floor (None: the ground motion itself), as
    rockcli.analyses.assess.rocked_input derives them (the record does not matter when the
    mechanism is named or the model is a block: a short probe stands in for it)."""
    from rockcli.analyses.assess import rocked_input
    from rockcli.records.pulses import make_pulse

    probe = make_pulse(PulseKind.ONE_SINE, 0.1, 1.0, dt=0.01)
    block, _, floor, _ = rocked_input(model, probe, target.ground, target.file, target.mechanism)
    return block, floor


#: Geometry keys that give a block's size and slenderness (replaced by R and α).
SIZE_KEYS = ("R", "alpha", "thickness", "height")


def sized_table(table: dict[str, Any], R: float) -> dict[str, Any]:
    """The model table with the block's semi-diagonal R [m], its slenderness α kept (a block
    given by thickness and height is given by R and α instead; its other keys kept)."""
    from rockcli.model.load import validate_model

    alpha = validate_model(table).geometry.polar[1]
    kept = {k: v for k, v in table["geometry"].items() if k not in SIZE_KEYS}
    return {**table, "geometry": {**kept, "R": R, "alpha": alpha}}


def with_period(table: dict[str, Any], T1: float) -> dict[str, Any]:
    """The model table in a building of first period T1 [s] (its floor motion follows)."""
    return {**table, "building": {**table["building"], "T1": T1}}


def _model(target: Target) -> Model:
    from rockcli.model.load import validate_model

    return validate_model(target.table, file=target.file)


def _threshold_columns(found: Threshold) -> dict[str, Any]:
    return {
        "threshold": found.value,
        "below": found.below,
        "runs": found.runs,
        "unsettled": found.unsettled,
        "undecided": found.undecided,
    }


def _block_columns(block: Rocker) -> dict[str, Any]:
    return {
        "p": block.p,
        "R": block.R,
        "uplift_g": block.uplift_acceleration,
        "e": block.e,
        "linearized": block.linearized,
    }


def run_spectrum(
    target: Target,
    scan: Scan,
    cases: Sequence[PulseCase | RecordCase],
    lanes: MutableSequence[Lane],
    progress: Callable[[int, int], None] | None = None,
) -> list[dict[str, Any]]:
    """Every point's row, in the order of ``cases``, each point a chunk on the lanes.

    Raises RuntimeError when a worker process died on a point.
    """
    from rockcli.studies.parallel.chunks import run_chunks

    chunks = [SpectrumChunk(target, scan, (case,)) for case in cases]
    rows: dict[int, dict[str, Any]] = {}
    if progress:
        progress(0, len(cases))
    for chunk_rows in run_chunks(lanes, chunks, run_overturning_chunk):
        for row in chunk_rows:
            if "error" in row:
                raise RuntimeError(f"point {row['case'] + 1}: {row['error']}")
            rows[row.pop("case")] = row
        if progress:
            progress(len(rows), len(cases))
    return [rows[case.id] for case in cases]


def radius_of(p: float, g: float) -> float:
    """R = 3g/(4p²) [m] of a rectangular block of frequency parameter p [rad/s] (Housner
    1963: p² = 3g/(4R))."""
    return 3.0 * g / (4.0 * p * p)
