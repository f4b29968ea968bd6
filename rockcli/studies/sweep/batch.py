"""Studies of a plain block at the kernel's speed: every case checked at once, every chunk one
compiled call, no model per case.

A study is *batched* when it asks for the rocking analysis alone with the fast engine (no
tolerance check; records or suites) of a block that rockcli.dynamics.batch can run as arrays
(a plain block on the ground: no loads, thrusts, wall, floor; restrainers of any law) and its
axes change only the values of
:data:`BATCH_FIELDS` that its first case already gives (a study that changes the form of a
table, e.g. sets ``geometry.R`` on a block given by thickness and height, runs case by case,
where each case's model says what is wrong).

For a batched study:

- the check before the run (:func:`first_invalid`) takes every case of the grid: each axis
  value through its field's own validator (pydantic, the schema's bounds and types), then the
  rules between fields that these values can break, as arrays (the schema's cross-table rules
  and rockcli.model.derived_checks, written here for a plain block). The first invalid case is
  then validated by the model loader, which gives its message: the same one a case-by-case
  check gives. A property test (tests/sweep/test_batch.py) draws random studies, with cases
  that break each rule, and checks that this check refuses exactly the cases the loader
  refuses.
- a chunk's blocks are derived as arrays from the axis values (:func:`derive`) and run in one
  call (rockcli.dynamics.batch.run_blocks); its rows come from the output arrays
  (:func:`rows_of`), the same numbers as the case-by-case path, bit for bit.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache
from typing import TYPE_CHECKING, Annotated, Any

import numpy as np

from rockcli.errors import InputError
from rockcli.studies.sweep.cases import Case, build_model
from rockcli.studies.sweep.study import StudyPlan

if TYPE_CHECKING:
    from rockcli.dynamics.batch import Blocks, Runs
    from rockcli.mechanics import Block
    from rockcli.model.schema import Model
    from rockcli.studies.sweep.over_suite import SuiteInput

#: The model values a batched study may vary: (table, key); a restrainer's key for every
#: element of [[restrainers]].
BATCH_FIELDS = frozenset(
    {
        ("geometry", "R"),
        ("geometry", "alpha"),
        ("geometry", "thickness"),
        ("geometry", "height"),
        ("geometry", "width"),
        ("mass", "weight"),
        ("mass", "unit_weight"),
        ("restitution", "factor"),
        ("restitution", "e"),
        ("restrainers", "k"),
        ("restrainers", "k_pos"),
        ("restrainers", "k_neg"),
    }
)

#: A value's key inside a case: ("geometry", "R"), or ("restrainers", 0, "k_pos").
Key = tuple[str | int, ...]

#: Cases checked at once before a run (memory: a few arrays of this length).
CHECK_BLOCK = 65_536


@dataclass(frozen=True)
class Form:
    """What every case of a batched study shares: the first case's model and block, and each
    axis' values, each validated by its field.

    Attributes:
        model: the first case's model (valid); block: its block.
        keys: for each axis, the key of each of its paths.
        values: for each axis and path, the value of each index as a float (nan where the
            value is refused by its field).
        valid: for each axis, True where every path's value passes its field.
    """

    model: Model
    block: Block
    keys: tuple[tuple[Key, ...], ...]
    values: tuple[tuple[np.ndarray, ...], ...]
    valid: tuple[np.ndarray, ...]


def batch_form(plan: StudyPlan) -> Form | None:
    """The study's form when it is batched (module docstring), else None. InputError when
    the study's first case is not a valid model (its message)."""
    from rockcli.studies.sweep.output import has_sliding_column

    if plan.analyses != ("rocking",) or plan.engine != "fast" or plan.check_tolerance:
        return None
    if has_sliding_column(plan):  # the slides column is the catalogue's: case by case
        return None
    if not plan.records:
        return None
    keys = tuple(tuple(_key(path) for path in axis.paths) for axis in plan.axes)
    if any(key is None for axis in keys for key in axis):
        return None
    model = build_model(plan, Case(0, None, (0,) * len(plan.axes)))
    block = plain_block(model, plan.ground)
    if block is None or not all(_given(model, key) for axis in keys for key in axis):  # type: ignore[arg-type]
        return None
    values, valid = [], []
    for axis, axis_keys in zip(plan.axes, keys, strict=True):
        columns = [
            np.array([v[p] for v in axis.values], dtype=object) for p in range(len(axis_keys))
        ]
        checked = [_field_values(key, col) for key, col in zip(axis_keys, columns, strict=True)]  # type: ignore[arg-type]
        values.append(tuple(c[0] for c in checked))
        valid.append(np.logical_and.reduce([c[1] for c in checked]))
    return Form(model, block, keys, tuple(values), tuple(valid))  # type: ignore[arg-type]


def _key(path: Sequence[str | int]) -> Key | None:
    """The key of a path that a batched study may vary, else None."""
    if len(path) == 2 and (path[0], path[1]) in BATCH_FIELDS and path[0] != "restrainers":
        return tuple(path)
    if len(path) == 3 and path[0] == "restrainers" and isinstance(path[1], int):
        if ("restrainers", path[2]) in BATCH_FIELDS:
            return tuple(path)
    return None


def _given(model: Model, key: Key) -> bool:
    """True when the model gives the value at key (the axis changes it, not the form)."""
    node: Any = model
    for part in key:
        node = node[part] if isinstance(part, int) else getattr(node, part, None)
        if node is None:
            return False
    return True


def plain_block(model: Model, ground: bool) -> Block | None:
    """The model's block when rockcli.dynamics.batch can run it (a catalogue of one mechanism
    that rocks as the paper's rectangle without loads, on the ground or run at the ground
    with --ground), else None."""
    from rockcli.analyses.floor import model_floor
    from rockcli.mechanics import Block
    from rockcli.model.catalogue import catalogue

    if model.loads or model.thrusts or model.geometry.gable_height is not None:
        return None
    if not ground and model_floor(model) is not None:
        return None
    try:
        mechanisms = catalogue(model)
    except InputError:
        return None
    if len(mechanisms) != 1:
        return None
    block = mechanisms[0].rocker
    if not isinstance(block, Block) or block.loaded or block.e_neg is not None:
        return None
    return block


def _field_values(key: Key, column: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(each value as its field validates it, nan where refused; True where accepted). A
    stiffness must also be 0 or at least MIN_STIFFNESS (schema.Restrainer._check_spring)."""
    from rockcli.model.bounds import MIN_STIFFNESS

    adapter = _adapter(tuple(k for k in key if isinstance(k, str)))
    out = np.full(column.size, np.nan)
    ok = np.zeros(column.size, dtype=bool)
    for i, value in enumerate(column):
        try:
            number = adapter.validate_python(value)
        except Exception:  # noqa: BLE001 - pydantic's ValidationError: the value is refused
            continue
        if number is None:
            continue
        out[i], ok[i] = float(number), True
    if key[0] == "restrainers":
        ok &= ~((out > 0.0) & (out < MIN_STIFFNESS))
    return out, ok


@cache
def _adapter(keys: tuple[str, ...]) -> Any:
    """The validator of the schema field at keys, as the model applies it."""
    from pydantic import TypeAdapter

    from rockcli.model.load import field_at

    info = field_at(keys)
    assert info is not None
    return TypeAdapter(Annotated[info.annotation, info])  # type: ignore[arg-type]


def case_values(form: Form, indices: np.ndarray) -> tuple[dict[Key, np.ndarray], np.ndarray]:
    """(each varied key's value per case, True where every axis value passes its field).
    indices: shape (cases, axes), each case's index on each axis."""
    values: dict[Key, np.ndarray] = {}
    valid = np.ones(indices.shape[0], dtype=bool)
    for a, (keys, columns) in enumerate(zip(form.keys, form.values, strict=True)):
        at = indices[:, a]
        valid &= form.valid[a][at]
        for key, column in zip(keys, columns, strict=True):
            values[key] = column[at]
    return values, valid


def derive(form: Form, indices: np.ndarray) -> tuple[Blocks, np.ndarray]:
    """The blocks of the cases at indices (shape (cases, axes)), and True where the case is a
    valid model (see first_invalid); an invalid case's block holds nan or inf.

    The block of rockcli.model.derive.to_block, as arrays: (R, α) given or from the half-sizes
    b = t/2, h = H/2 (R = √(b² + h²), α = atan2(b, h)); the weight given, or γ·2b·2h·width;
    m = W/g; Housner's e = max(1 − 1.5 sin²α, 0)·factor, or e given; each restrainer's K per
    side, its attachment (the top corner: r = 2R, φ = α; a point at height z and distance x
    from O: √(x² + z²), atan2(x, z), and 2b − x from O′). Same operations, same order.
    """
    from rockcli.dynamics.batch import Blocks, exactly, housner_e, python_max
    from rockcli.mechanics import point_polar
    from rockcli.model.derive import NEWTONS_PER_KILONEWTON

    model, base = form.model, form.block
    n = indices.shape[0]
    given, valid = case_values(form, indices)

    def value(*key: str | int) -> np.ndarray:
        found = given.get(key)
        if found is not None:
            return found
        node: Any = model
        for part in key:
            node = node[part] if isinstance(part, int) else getattr(node, part)
        return np.full(n, float(node))

    geometry = model.geometry
    with np.errstate(all="ignore"):
        if geometry.R is not None:
            R, alpha = value("geometry", "R"), value("geometry", "alpha")
            b = R * exactly(math.sin, alpha)
            h = R * exactly(math.cos, alpha)
        else:
            b = value("geometry", "thickness") / 2.0
            h = value("geometry", "height") / 2.0
            R, alpha = exactly(math.hypot, b, h), exactly(math.atan2, b, h)
        mass = None
        if model.mass is not None:
            if model.mass.weight is not None:
                weight = value("mass", "weight") * NEWTONS_PER_KILONEWTON
            else:
                weight = (value("mass", "unit_weight") * NEWTONS_PER_KILONEWTON * (2 * b)
                          * (2 * h) * value("geometry", "width"))  # fmt: skip
            mass = weight / model.analysis.g
        if model.restitution.e is not None:
            e = value("restitution", "e")
        else:
            factor = 1.0 if model.restitution.factor is None else value("restitution", "factor")
            e = housner_e(alpha, factor)
        sides: list[list[np.ndarray]] = [[], [], [], [], [], []]
        for i, table in enumerate(model.restrainers):
            sp = base.restrainers[i]
            if table.kind.value == "tie-rod":  # E·A/L of its bar: not a batched value
                k_pos, k_neg = np.full(n, sp.k_pos), np.full(n, sp.k_neg)
            elif table.k is not None:
                k_pos = k_neg = value("restrainers", i, "k")
            else:
                k_pos, k_neg = value("restrainers", i, "k_pos"), value("restrainers", i, "k_neg")
            if table.position is not None:  # the top corner
                r_pos = r_neg = 2 * R
                phi_pos = phi_neg = alpha
            elif table.from_pivot is not None:
                r_pos, phi_pos = np.full(n, sp.r_pos), np.full(n, sp.phi_pos)
                other = python_max(2 * b - table.from_pivot, 0.0)
                z = np.full(n, float(table.height))  # type: ignore[arg-type]
                r_neg = exactly(lambda x, z_: point_polar(x, z_)[0], other, z)
                phi_neg = exactly(lambda x, z_: point_polar(x, z_)[1], other, z)
            else:
                r_pos = r_neg = np.full(n, sp.r_pos)
                phi_pos = phi_neg = np.full(n, sp.phi_pos)
            for column, v in zip(
                sides, (k_pos, k_neg, r_pos, phi_pos, r_neg, phi_neg), strict=True
            ):
                column.append(v)
    arrays = [np.stack(c, axis=1) if c else np.zeros((n, 0)) for c in sides]
    blocks = Blocks(base, R, alpha, mass, e, *arrays)
    valid &= valid_blocks(model, blocks, b)
    return blocks, valid


def valid_blocks(model: Model, blocks: Blocks, b: np.ndarray) -> np.ndarray:
    """True where a block passes the rules its varied values can break: the schema's
    cross-table rules (Model._check_mass, _check_points with the geometry's half-thickness b)
    and rockcli.model.derived_checks.check_block (with the block's b = R sin α, h = R cos α),
    for a plain block."""
    from rockcli.dynamics.batch import exactly
    from rockcli.model.bounds import MAX_STIFFNESS
    from rockcli.model.schema import CONTAINMENT_RTOL

    def usable(x: np.ndarray) -> np.ndarray:
        return np.isfinite(x) & (x > 0.0)

    with np.errstate(all="ignore"):
        half_b = blocks.R * exactly(math.sin, blocks.alpha)
        half_h = blocks.R * exactly(math.cos, blocks.alpha)
        ok = usable(blocks.R) & usable(half_b) & usable(half_h) & usable(blocks.p2)
        stiff = np.zeros(blocks.size, dtype=bool)
        for i, table in enumerate(model.restrainers):
            stiff |= (blocks.k_pos[:, i] != 0.0) | (blocks.k_neg[:, i] != 0.0)
            if table.effective_law.value == "elastic-plastic" and table.kind.value == "spring":
                # schema.Restrainer._check_law: a stiff side needs its yield force
                for k, key in ((blocks.k_pos, "yield_pos"), (blocks.k_neg, "yield_neg")):
                    if getattr(table, key) is None:
                        ok &= ~(k[:, i] != 0.0)
            if table.from_pivot is not None:
                ok &= ~(table.from_pivot > 2.0 * b * (1 + CONTAINMENT_RTOL))
        if blocks.mass is None:
            return ok & ~stiff
        inertia = blocks.inertia
        ok &= usable(blocks.mass) & usable(blocks.mass * blocks.base.g) & usable(inertia)
        for k, r in ((blocks.k_pos, blocks.r_pos), (blocks.k_neg, blocks.r_neg)):
            for i in range(k.shape[1]):
                ok &= ~(k[:, i] > MAX_STIFFNESS) & usable(r[:, i])
                ok &= np.isfinite(k[:, i] * r[:, i] * r[:, i] / inertia)
    return ok


def grid_indices(plan: StudyPlan, start: int, stop: int) -> np.ndarray:
    """The axis indices of the grid's points start..stop-1 (first axis outermost), shape
    (points, axes)."""
    sizes = [len(a.values) for a in plan.axes]
    ids = np.arange(start, stop)
    if not sizes:
        return np.zeros((ids.size, 0), dtype=np.int64)
    return np.stack(np.unravel_index(ids, sizes), axis=1).astype(np.int64)


def first_invalid(plan: StudyPlan, form: Form) -> None:
    """Every case of the grid checked at once (module docstring); the loader's InputError
    for the first invalid one, naming it."""
    total = math.prod(len(a.values) for a in plan.axes)
    for start in range(0, total, CHECK_BLOCK):
        indices = grid_indices(plan, start, min(total, start + CHECK_BLOCK))
        _, valid = derive(form, indices)
        bad = np.flatnonzero(~valid)
        if bad.size:
            point = tuple(int(i) for i in indices[bad[0]])
            build_model(plan, Case(start + int(bad[0]), None, point))  # raises its message
            raise RuntimeError(
                f"the study's check refused case {start + int(bad[0])}, which the model "
                "loader accepts (please report)"
            )


def check_grid(plan: StudyPlan, check: Any = None) -> int:
    """Check the study's cases before any work: every case at once when the study is batched
    (:func:`first_invalid`), else as rockcli.studies.sweep.cases.check_cases does; the
    number of grid points checked."""
    from rockcli.studies.sweep.cases import check_cases

    form = batch_form(plan) if check is None else None
    if form is None:
        return check_cases(plan, check)
    first_invalid(plan, form)
    return math.prod(len(a.values) for a in plan.axes)


def plan_key(plan: StudyPlan) -> str:
    """A text that is the same for the same study (a worker's cache of forms)."""
    axes = [(a.paths, a.values) for a in plan.axes]
    return json.dumps([plan.file, plan.base, axes, plan.analyses, plan.engine, plan.ground,
                       plan.check_tolerance, [s.suite for s in plan.records]],
                      default=repr, sort_keys=True)  # fmt: skip


_forms: dict[str, Form | None] = {}


def cached_form(plan: StudyPlan) -> Form | None:
    """batch_form, once per study in a process (a worker runs many chunks of one study)."""
    key = plan_key(plan)
    if key not in _forms:
        try:
            _forms[key] = batch_form(plan)
        except InputError:
            _forms[key] = None  # the first case is invalid: the case-by-case path says why
    return _forms[key]


def run_arrays(
    form: Form, cases: Sequence[Case], time: np.ndarray, accel: np.ndarray, dt: float
) -> tuple[Blocks, Runs] | None:
    """The blocks of a chunk's cases and their runs under one record, as arrays; None when
    one of them is not valid (the chunk then runs case by case, which gives its error row)."""
    from rockcli.analyses.assess import settings_from
    from rockcli.dynamics.batch import run_blocks
    from rockcli.model.derive import solver_options

    indices = np.array([c.indices for c in cases], dtype=np.int64).reshape(len(cases), -1)
    blocks, valid = derive(form, indices)
    if not valid.all():
        return None
    return blocks, run_blocks(time, accel, dt, blocks, settings_from(solver_options(form.model)))


def suite_rows(form: Form, cases: Sequence[Case], suite: SuiteInput) -> list[dict[str, Any]] | None:
    """The rows of rockcli.studies.sweep.over_suite.run_suite_case (the time history alone) for a
    chunk's cases under a suite, every record run as arrays; None when a case is not valid.

    Each record's max θ/α (the envelope of its polarities) and overturning go, case by case,
    through the suite's own rule (rockcli.studies.suite_run.rule.suite_measure, with outcomes
    made as rockcli.studies.suite_run.run.outcomes makes them): the same numbers as case by case.
    """
    from rockcli.analyses.assess import settings_from
    from rockcli.dynamics.batch import run_blocks
    from rockcli.model.derive import solver_options
    from rockcli.studies.suite_run.assess import limit_for
    from rockcli.studies.suite_run.rule import RecordOutcome, suite_measure

    indices = np.array([c.indices for c in cases], dtype=np.int64).reshape(len(cases), -1)
    blocks, valid = derive(form, indices)
    if not valid.all():
        return None
    settings = settings_from(solver_options(form.model))
    state = suite.settings.target.limit_state.value
    limit = limit_for(form.model, state)
    per_record = []
    for item in suite.items:
        rec = item.record
        e = envelope(blocks, run_blocks(rec.time, rec.accel, rec.dt, blocks, settings))
        per_record.append((item, float(rec.pga), e["max_ratio"].tolist(),
                           e["overturned"].tolist()))  # fmt: skip
    rows = []
    for k, case in enumerate(cases):
        measure = suite_measure(
            [RecordOutcome(item.name, item.scale, pga, ratio[k], over[k])
             for item, pga, ratio, over in per_record],
            limit,
        )  # fmt: skip
        rows.append({
            "case": case.id,
            "block_R": float(blocks.R[k]),
            "block_alpha": float(blocks.alpha[k]),
            "limit_state": state,
            "max_ratio": float(measure.measure),
            "overturned": measure.overturned_records > 0,
            "rocking": "passes" if measure.passed else "fails",
            "input": "ground",
            "suite_rule": measure.rule,
            "suite_records": measure.n,
            "suite_overturned": measure.overturned_records,
        })  # fmt: skip
    return rows


def envelope(blocks: Blocks, runs: Runs) -> dict[str, np.ndarray]:
    """The result columns of rockcli.studies.sweep.worker.run_case for the runs, as arrays:
    each block's R and α, the envelope of the two polarities (worker.rocking_columns; nan
    where a value is None)."""
    from rockcli.dynamics import layout as L

    f, status = runs.out_f, runs.out_i[..., L.I_STATUS]
    with np.errstate(all="ignore"):
        ratio = f[..., L.O_MAX_A] / blocks.alpha[:, None]
    pos, neg = ratio[:, 0], ratio[:, 1]
    best = np.where(neg > pos, neg, pos)  # max over the runs, as Python's max
    over = status == L.STATUS_OVERTURNED
    t = np.fmin(f[:, 0, L.O_T_OVERTURN], f[:, 1, L.O_T_OVERTURN])
    verdict = np.where(
        (status == L.STATUS_NONFINITE).any(axis=1),
        "undecided",
        np.where(
            over.any(axis=1),
            "overturns",
            np.where((status != L.STATUS_COMPLETED).any(axis=1), "undecided", "survives"),
        ),
    )
    return {
        "block_R": blocks.R,
        "block_alpha": blocks.alpha,
        "max_ratio": best,
        "max_ratio_pos": pos,
        "max_ratio_neg": neg,
        "overturned": over.any(axis=1),
        "t_overturn": t,
        "rocking": verdict,
        "utilisation": utilisation(blocks, runs),
    }


def utilisation(blocks: Blocks, runs: Runs) -> np.ndarray:
    """worker.max_utilisation of each case: the largest, over the restrainers with a strength
    (in their order), of the larger peak force of the two polarities over the strength
    (rockcli.analyses.strength.check_row); nan where no restrainer has a strength."""
    from rockcli.dynamics import layout as L
    from rockcli.dynamics.batch import python_max

    out = np.full(blocks.size, np.nan)
    first = True
    for j, sp in enumerate(blocks.base.restrainers):
        if not math.isfinite(sp.strength):
            continue
        peaks = runs.spring_out[:, :, j, L.S_MAX_FORCE]
        ratio = python_max(peaks[:, 0], peaks[:, 1]) / sp.strength
        out = ratio if first else python_max(out, ratio)
        first = False
    return out


def rows_of(cases: Sequence[Case], blocks: Blocks, runs: Runs) -> list[dict[str, Any]]:
    """The rows of rockcli.studies.sweep.worker.run_case for the cases' runs (envelope), the
    block on the ground."""
    e = envelope(blocks, runs)
    columns = zip(
        *(e[k].tolist() for k in ("block_R", "block_alpha", "max_ratio", "max_ratio_pos",
                                  "max_ratio_neg", "overturned", "t_overturn", "rocking",
                                  "utilisation")),
        strict=True,
    )  # fmt: skip
    return [
        {
            "case": case.id,
            "block_R": R,
            "block_alpha": alpha,
            "input": "ground",
            "max_ratio": m,
            "max_ratio_pos": p,
            "max_ratio_neg": q,
            "overturned": o,
            "t_overturn": None if math.isnan(tt) else tt,
            "rocking": v,
            "utilisation": None if math.isnan(u) else u,
        }
        for case, (R, alpha, m, p, q, o, tt, v, u) in zip(cases, columns, strict=True)
    ]


def float_cells(values: np.ndarray) -> list[str]:
    """Each float as cases.csv writes it (output.cell: repr, empty for nan)."""
    return ["" if v != v else repr(v) for v in values.tolist()]


def result_cells(blocks: Blocks, runs: Runs) -> dict[str, list[str]]:
    """The written fields of the result columns of the runs (envelope), by column: the same
    text as output.row_lines writes for rows_of's rows."""
    from rockcli.studies.sweep.output import cell, csv_field

    e = envelope(blocks, runs)
    floats = ("block_R", "block_alpha", "max_ratio", "max_ratio_pos", "max_ratio_neg",
              "t_overturn", "utilisation")  # fmt: skip
    out = {k: float_cells(e[k]) for k in floats}
    out["overturned"] = ["true" if o else "false" for o in e["overturned"].tolist()]
    out["rocking"] = [csv_field(cell(v)) for v in e["rocking"].tolist()]
    out["input"] = [csv_field(cell("ground"))] * blocks.size
    return out


def label_cells(plan: StudyPlan, cases: Sequence[Case]) -> dict[str, list[str]]:
    """The written fields of the cases' first columns (id, record, axis values), by column:
    the text output.row_lines writes for cases.case_labels."""
    from rockcli.studies.sweep.output import cell, csv_field

    out = {"case": [str(c.id) for c in cases]}
    out["record"] = [
        "" if c.record is None else csv_field(cell(plan.records[c.record].name)) for c in cases
    ]
    for k, axis in enumerate(plan.axes):
        fields = [csv_field(cell(axis.label(i))) for i in range(len(axis.values))]
        out[axis.name] = [fields[c.indices[k]] for c in cases]
    return out
