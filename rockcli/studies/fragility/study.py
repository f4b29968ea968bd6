"""The study file of `rock fragility STUDY.toml`, validated by pydantic at the edge.

A fragility study names the model (with optional ``[[axes]]`` over its fields, as a `rock
sweep` study's base model), the records (``[[records]]`` files or suites, read as `rock
sweep` reads them), the intensity measure, the damage states and the method with its
intensities::

    model = "altar.toml"
    method = "ida"                       # or "msa"
    [intensity]
    measure = "pga"                      # pga, pgv, sa, pga-ratio, pgv-ratio
    [[damage_states]]
    level = 0.5                          # max θ/α, or "overturning"
    [ida]
    first = 0.05, step = 0.05, last = 2.0, tolerance = 0.005   # in the IM's unit
    [msa]
    levels = [0.1, 0.2, 0.3]             # in the IM's unit

Every problem is one InputError naming the file, the key, the value and what is allowed.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, Field, ValidationError

from rockcli.errors import InputError
from rockcli.model.schema_base import Table
from rockcli.records.periods import MAX_PERIOD, MIN_PERIOD
from rockcli.studies.fragility.search import MAX_SCAN_POINTS, MIN_TOLERANCE_SHARE, scan_problem
from rockcli.studies.sweep.paths import AxisSpec
from rockcli.studies.sweep.study import EngineName, RecordSource, RecordSpec, StudyPlan


class Measure(StrEnum):
    """The intensity measures (rockcli.studies.fragility.intensity)."""

    PGA = "pga"
    PGV = "pgv"
    SA = "sa"
    PGA_RATIO = "pga-ratio"
    PGV_RATIO = "pgv-ratio"


#: Each measure's name as shown, and its unit.
MEASURE_NAMES = {
    Measure.PGA: ("PGA", "g"),
    Measure.PGV: ("PGV", "m/s"),
    Measure.SA: ("Sa(T)", "g"),
    Measure.PGA_RATIO: ("PGA/(g·tan α)", "-"),
    Measure.PGV_RATIO: ("PGV·p/(g·tan α)", "-"),
}


#: A number of the study file: a TOML integer or float, never a string or a boolean.
Number = Annotated[float, Field(strict=True, allow_inf_nan=False)]

#: The largest intensity a study may name, by measure (in its unit): about twice the largest
#: ever recorded (PGA ≈ 4 g, PGV ≈ 3 m/s; Sa up to 2.5–3 times PGA), beyond which a scan or a
#: stripe measures nothing physical; the ratios' bound is 10 g over tan α = 0.01.
MAX_INTENSITY = {
    Measure.PGA: 10.0,
    Measure.PGV: 10.0,
    Measure.SA: 30.0,
    Measure.PGA_RATIO: 1000.0,
    Measure.PGV_RATIO: 1000.0,
}


#: The most stripes an MSA may have (each is a run of every record).
MAX_LEVELS = 1000


class Intensity(Table):
    """[intensity]: the measure, and the period of Sa(T)."""

    measure: Measure = Field(..., description="one of: pga, pgv, sa, pga-ratio, pgv-ratio")
    period: Number | Literal["mechanism"] | None = Field(
        None,
        description=f"the period of Sa(T): a number in [{MIN_PERIOD:g}, {MAX_PERIOD:g}] s, or "
        '"mechanism" (2π/p of the rocked block)',
    )


class DamageState(Table):
    """A [[damage_states]] entry: a level of max θ/α, or overturning."""

    name: str | None = Field(None, min_length=1, description="a non-empty label")
    level: Number | Literal["overturning"] = Field(
        ..., description='a level of max θ/α > 0, or "overturning"'
    )


class IdaScan(Table):
    """[ida]: the intensities of the scan, in the measure's unit."""

    first: Number = Field(..., gt=0, description="the first intensity > 0")
    step: Number = Field(..., gt=0, description="the scan's step > 0")
    last: Number = Field(..., gt=0, description="the last intensity ≥ first")
    tolerance: Number | None = Field(
        None,
        gt=0,
        allow_inf_nan=False,
        description="the bisection's tolerance > 0 [default: step / 20]",
    )
    ddof: Annotated[int, Field(strict=True, ge=0, le=1)] = Field(
        0, description="the divisor of β²: 0 (n, the maximum likelihood) or 1 (n − 1)"
    )


class MsaLevels(Table):
    """[msa]: the intensity levels (stripes), in the measure's unit."""

    levels: tuple[Number, ...] = Field(
        ...,
        min_length=2,
        max_length=MAX_LEVELS,
        description=f"from 2 to {MAX_LEVELS} increasing intensities > 0",
    )


class FragilityStudy(Table):
    """The whole fragility study file."""

    name: str | None = Field(None, min_length=1, description="a non-empty title")
    notes: str | None = Field(None, description="free text")
    model: str = Field(..., min_length=1, description="the model file, relative to the study")
    mechanism: str | None = Field(
        None, min_length=1, description="a wall's mechanism to rock [default: the governing one]"
    )
    ground: bool = Field(
        False, strict=True, description="true: a block at height rocks on the record itself"
    )
    engine: EngineName = Field(EngineName.FAST, description='"fast" or "reference"')
    method: Literal["ida", "msa"] = Field(..., description='"ida" or "msa"')
    records_dir: str | None = Field(None, description="the folder the record paths are relative to")
    axes: tuple[AxisSpec, ...] = Field((), description="[[axes]] tables with path and values")
    records: tuple[RecordSpec, ...] = Field(
        ..., min_length=1, description="[[records]] tables with path or suite"
    )
    intensity: Intensity = Field(..., description="[intensity] with measure (and period)")
    damage_states: tuple[DamageState, ...] = Field(
        ..., min_length=1, description="[[damage_states]] tables with level"
    )
    ida: IdaScan | None = Field(None, description="[ida] with first, step, last")
    msa: MsaLevels | None = Field(None, description="[msa] with levels")


@dataclass(frozen=True)
class State:
    """A damage state: its name, and its level of max θ/α (inf: overturning)."""

    name: str
    level: float


@dataclass(frozen=True)
class FragilityPlan:
    """A validated fragility study.

    Attributes:
        file: the study file. name: its title.
        study: the model, axes and records as a sweep study (rocking only).
        mechanism: the wall's mechanism to rock (None: the governing one).
        measure: the intensity measure. period: Sa's period [s], "mechanism", or None.
        states: the damage states, levels increasing.
        method: "ida" or "msa".
        scan: IDA's (first, step, last, tolerance), in the measure's unit.
        ddof: IDA's divisor offset of β².
        levels: MSA's intensities.
    """

    file: str
    name: str
    study: StudyPlan
    mechanism: str | None
    measure: str
    period: float | str | None
    states: tuple[State, ...]
    method: str
    scan: tuple[float, float, float, float] | None
    ddof: int
    levels: tuple[float, ...]

    @property
    def measure_label(self) -> str:
        """``PGA [g]``, ``Sa(T = 0.5 s) [g]``, ``Sa(2π/p) [g]``."""
        name, unit = MEASURE_NAMES[Measure(self.measure)]
        if self.measure == Measure.SA:
            name = "Sa(2π/p)" if self.period == "mechanism" else f"Sa(T = {self.period:g} s)"
        return f"{name} [{unit}]"


#: The study keys that name the model, axes and records (passed to the sweep's reader).
SWEEP_KEYS = ("axes", "records", "records_dir", "ground", "engine", "name")


def load_fragility(
    file: str,
    records_dir: str | None = None,
    *,
    allow_outside: bool = False,
) -> FragilityPlan:
    """Read and validate a fragility study file (InputError naming the key otherwise)."""
    from rockcli.model.load import read_toml

    data = read_toml(file)
    study = validate(data, file)
    shared = {k: data[k] for k in SWEEP_KEYS if k in data}
    plan = sweep_plan(
        {**shared, "base": study.model, "analyses": ["rocking"]}, file, records_dir, allow_outside
    )
    check_mechanism(study.mechanism, plan.base_file, file)
    return FragilityPlan(
        file=file,
        name=study.name or Path(file).stem,
        study=plan,
        mechanism=study.mechanism,
        measure=str(study.intensity.measure),
        period=check_period(study.intensity, file),
        states=check_states(study.damage_states, file),
        method=study.method,
        scan=check_scan(study, file),
        ddof=study.ida.ddof if study.ida is not None else 0,
        levels=check_levels(study, file),
    )


def sweep_plan(
    data: Mapping[str, Any], file: str, records_dir: str | None, allow_outside: bool
) -> StudyPlan:
    """The model, axes and records read as a sweep study's, a suite's records expanded into
    records of their own (each with its scale); an error about the sweep's ``base`` names
    this file's ``model``."""
    from dataclasses import replace

    from rockcli.studies.sweep.study import study_plan

    try:
        plan = study_plan(data, file, records_dir, allow_outside)
    except InputError as exc:
        where = exc.where
        if where is not None and where.startswith("base"):
            where = "model" + where.removeprefix("base")
        raise InputError(
            exc.problem, file=exc.file, where=where, value=exc.value, allowed=exc.allowed
        ) from None
    return replace(plan, records=expand_suites(plan.records))


def expand_suites(sources: Sequence[RecordSource]) -> tuple[RecordSource, ...]:
    """Every suite entry replaced by its records (``SUITE/RECORD``, scaled as the suite
    says); records as they are."""
    from rockcli.suites.load import load_suite

    out: list[RecordSource] = []
    for source in sources:
        if not source.suite:
            out.append(source)
            continue
        suite = load_suite(source.path, allow_outside=True)  # checked by the sweep's reader
        out.extend(
            RecordSource(f"{source.name}/{e.name}", str(e.path), scale=e.scale)
            for e in suite.entries
        )
    return tuple(out)


def validate(data: Mapping[str, Any], file: str) -> FragilityStudy:
    """The study table validated; InputError (the first problem) naming the key."""
    try:
        return FragilityStudy.model_validate(data)
    except ValidationError as exc:
        raise table_error(exc.errors()[0], file, FragilityStudy) from None


def table_error(err: Any, file: str, root: type[BaseModel]) -> InputError:
    """One pydantic error as one InputError naming the key, the value and what is allowed."""
    loc = [p for p in err["loc"] if isinstance(p, int) or not _is_member_tag(p)]
    where = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in loc).lstrip(".")
    field = _field(root, [p for p in loc if isinstance(p, str)])
    if err["type"] == "extra_forbidden":
        table = _field_table(root, [p for p in loc[:-1] if isinstance(p, str)])
        keys = ", ".join(table.model_fields) if table is not None else ""
        return InputError("unknown key", file=file, where=where, allowed=f"one of: {keys}")
    if err["type"] == "missing":
        allowed = field.description if field is not None else None
        return InputError("missing key", file=file, where=where, allowed=allowed or "required")
    value = err.get("input")
    return InputError(
        " ".join(err["msg"].split()).removeprefix("Value error, "),
        file=file,
        where=where,
        value=value if isinstance(value, bool | int | float | str) else None,
        allowed=field.description if field is not None else None,
    )


def _is_member_tag(part: str) -> bool:
    """A union member's tag in a pydantic location (``float``, ``literal['mechanism']``)."""
    return part in ("float", "int", "str", "bool", "none") or part.startswith(
        ("literal[", "function-", "tuple[")
    )


def _field_table(root: type[BaseModel], keys: Sequence[str]) -> type[BaseModel] | None:
    """The table class at that key path (None when it is not a table)."""
    table: type[BaseModel] | None = root
    for key in keys:
        info = table.model_fields.get(key) if table is not None else None
        table = _table_in(info.annotation) if info is not None else None
    return table


def _field(root: type[BaseModel], keys: Sequence[str]) -> Any:
    table = _field_table(root, keys[:-1])
    return table.model_fields.get(keys[-1]) if table is not None and keys else None


def _table_in(annotation: Any) -> type[BaseModel] | None:
    """The Table class inside an annotation (``X``, ``X | None``, ``tuple[X, ...]``)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()):
        found = _table_in(arg)
        if found is not None:
            return found
    return None


def check_mechanism(name: str | None, model_file: str, file: str) -> None:
    """A named mechanism must be one the model's time history rocks (its catalogue's; a
    model of one block has only its own)."""
    if name is None:
        return
    from rockcli.analyses.assess import BLOCK_MECHANISM
    from rockcli.analyses.rocked import rockable_names

    names = [str(n) for n in rockable_names(model_file) if n is not None] or [str(BLOCK_MECHANISM)]
    if name not in names:
        raise InputError(
            "no such mechanism in the model",
            file=file,
            where="mechanism",
            value=name,
            allowed="one of: " + "; ".join(names),
        )


def check_period(intensity: Intensity, file: str) -> float | str | None:
    """Sa's period: required for Sa, inside the spectrum's range, and only for Sa."""
    period = intensity.period
    if intensity.measure != Measure.SA:
        if period is not None:
            raise InputError(
                "a period is only for Sa(T)",
                file=file,
                where="intensity.period",
                value=period,
                allowed='measure = "sa", or no period',
            )
        return None
    if period is None:
        raise InputError(
            "Sa(T) needs its period",
            file=file,
            where="intensity.period",
            allowed=f'a period in [{MIN_PERIOD:g}, {MAX_PERIOD:g}] s, or "mechanism"',
        )
    if period != "mechanism" and not (MIN_PERIOD <= float(period) <= MAX_PERIOD):
        raise InputError(
            "outside the spectrum's range",
            file=file,
            where="intensity.period",
            value=period,
            allowed=f'a period in [{MIN_PERIOD:g}, {MAX_PERIOD:g}] s, or "mechanism"',
        )
    return period


def check_states(states: Sequence[DamageState], file: str) -> tuple[State, ...]:
    """The damage states, levels > 0 and increasing (overturning last), names unique."""
    out: list[State] = []
    for i, ds in enumerate(states):
        level = math.inf if ds.level == "overturning" else float(ds.level)
        where = f"damage_states[{i}].level"
        if not (level > 0.0 and not math.isnan(level)):
            raise InputError(
                "not a level > 0",
                file=file,
                where=where,
                value=ds.level,
                allowed='a level of max θ/α > 0, or "overturning"',
            )
        if out and level <= out[-1].level:
            raise InputError(
                "damage states out of order",
                file=file,
                where=where,
                value=ds.level,
                allowed=f"a level above the previous one ({_level_text(out[-1].level)}): "
                "levels increase, overturning last",
            )
        name = ds.name or ("overturning" if math.isinf(level) else f"θ/α ≥ {level:g}")
        if name in {s.name for s in out}:
            raise InputError(
                "two damage states with the same name",
                file=file,
                where=f"damage_states[{i}].name",
                value=name,
                allowed="a distinct name for each",
            )
        out.append(State(name, level))
    return tuple(out)


def _level_text(level: float) -> str:
    return "overturning" if math.isinf(level) else f"{level:g}"


def check_scan(study: FragilityStudy, file: str) -> tuple[float, float, float, float] | None:
    """IDA's scan (first, step, last, tolerance): [ida] for IDA only, last ≥ first."""
    if study.method != "ida":
        if study.ida is not None:
            raise InputError(
                '[ida] is for method = "ida"',
                file=file,
                where="ida",
                allowed='[msa] with method = "msa"',
            )
        return None
    scan = study.ida
    if scan is None:
        raise InputError(
            "IDA needs its scan",
            file=file,
            where="ida",
            allowed="[ida] with first, step, last (in the measure's unit)",
        )
    if scan.last < scan.first:
        raise InputError(
            "an empty scan: last is below first",
            file=file,
            where="ida.last",
            value=scan.last,
            allowed=f"an intensity ≥ first ({scan.first:g})",
        )
    check_bound(scan.last, "ida.last", study.intensity.measure, file)
    tolerance = scan.tolerance if scan.tolerance is not None else scan.step / 20.0
    problem = scan_problem(scan.first, scan.step, scan.last, tolerance)
    if problem is not None:
        too_many = problem.startswith("more")
        raise InputError(
            f"an unbounded scan: {problem}",
            file=file,
            where="ida.step" if too_many else "ida.tolerance",
            value=scan.step if too_many else tolerance,
            allowed=f"at most {MAX_SCAN_POINTS} scales from first to last, and a tolerance "
            f"≥ {MIN_TOLERANCE_SHARE:g} × last",
        )
    return (scan.first, scan.step, scan.last, tolerance)


def check_levels(study: FragilityStudy, file: str) -> tuple[float, ...]:
    """MSA's levels, finite, > 0 and increasing; [msa] for MSA only."""
    if study.method != "msa":
        if study.msa is not None:
            raise InputError(
                '[msa] is for method = "msa"',
                file=file,
                where="msa",
                allowed='[ida] with method = "ida"',
            )
        return ()
    if study.msa is None:
        raise InputError(
            "MSA needs its levels",
            file=file,
            where="msa",
            allowed="[msa] with levels = [...] (in the measure's unit)",
        )
    levels = study.msa.levels
    for i, level in enumerate(levels):
        bad = not (math.isfinite(level) and level > 0) or (i and level <= levels[i - 1])
        if bad:
            raise InputError(
                "not an increasing intensity > 0",
                file=file,
                where=f"msa.levels[{i}]",
                value=level,
                allowed="finite intensities > 0 in increasing order",
            )
        check_bound(level, f"msa.levels[{i}]", study.intensity.measure, file)
    return levels


def check_bound(value: float, where: str, measure: Measure, file: str) -> None:
    """An intensity of the study at most :data:`MAX_INTENSITY` of its measure."""
    bound = MAX_INTENSITY[measure]
    if value > bound:
        name, unit = MEASURE_NAMES[measure]
        raise InputError(
            "beyond any earthquake's intensity",
            file=file,
            where=where,
            value=value,
            allowed=f"{name} ≤ {bound:g}" + ("" if unit == "-" else f" {unit}"),
        )
