"""The study file of `rock sweep`, validated by pydantic at the edge like the model file.

A study names a base model, the axes (any model field by its key path, several paths set
together), the records and what to run (spec/README.md, `rock sweep`; paper §3.3 and §4.4).
Every problem with the file is one :class:`~rockcli.errors.InputError` naming the study file
and the key (``axes[1].path``, ``records[0].path``), the value and what is allowed.

Paths of files inside the study (base, records_dir, records) are relative to the study file;
a record's path is relative to ``records_dir`` when one is set, and ``--records-dir`` (or the
environment variable ROCK_RECORDS_DIR) replaces the file's records_dir, so one study runs on
every machine whatever the records folder.
"""

from __future__ import annotations

import os
import stat
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from enum import StrEnum
from pathlib import Path
from typing import Any

from pydantic import BaseModel, Field, ValidationError, field_validator
from pydantic_core import ErrorDetails

from rockcli import inside
from rockcli.errors import InputError
from rockcli.inside import path_error
from rockcli.model.schema_base import Table
from rockcli.records.kinds import FILE_FORMATS, RecordFormat
from rockcli.studies.sweep.paths import Axis, AxisSpec, check_axes


class Analysis(StrEnum):
    """What a study runs on every case."""

    ROCKING = "rocking"
    KINEMATIC = "kinematic"


class EngineName(StrEnum):
    """The rocking engine (see `rock assess --engine`)."""

    FAST = "fast"
    REFERENCE = "reference"


class RecordSpec(Table):
    """One record of the study, and how to read and scale it."""

    path: str | None = Field(
        None, min_length=1, description="a record file, relative to records_dir"
    )
    suite: str | None = Field(
        None,
        min_length=1,
        description="a record suite file (rock suite check), relative to records_dir, "
        "instead of path: each case then runs every record of the suite and takes the code's "
        "rule",
    )
    name: str | None = Field(
        None,
        min_length=1,
        description="a non-empty label (default: the file name, or the suite's name)",
    )
    scale: float | None = Field(None, gt=0, description="a factor > 0 on the accelerations [-]")
    pga: float | None = Field(
        None, gt=0, description="a PGA > 0 to scale the record to, instead of scale [g]"
    )
    format: RecordFormat | None = Field(None, description="one of: at2, esm, coracc, plain")
    dt: float | None = Field(None, gt=0, description="the step > 0 of a one-column plain file [s]")
    units: str | None = Field(None, description="the unit of a plain file: g, m/s2 or cm/s2")
    optional: bool = Field(
        False,
        strict=True,
        description="true (skip the record with a note when its file is absent) or false",
    )
    source: str | None = Field(
        None, description="text: where to get the record (shown when it is absent)"
    )

    @field_validator("format")
    @classmethod
    def _a_file_format(cls, value: RecordFormat | None) -> RecordFormat | None:
        if value is not None and value not in FILE_FORMATS:
            raise ValueError("a generated pulse is not a file format")
        return value


class CodeDemandName(StrEnum):
    """The study key code_demand (as rockcli.analyses.compare.CodeDemand)."""

    RECORD = "record"
    MODEL = "model"


#: A key of older study files and the error that names its replacement (0.x: no silent alias).
REMOVED_KEYS = {
    "record_demand": (
        "removed: each record's spectrum is the code demand by default now",
        'code_demand = "record" (the default) or "model" (the base model\'s code spectrum)',
    ),
}


class Study(Table):
    """The whole study file."""

    name: str | None = Field(None, min_length=1, description="a non-empty title")
    notes: str | None = Field(None, description="free text")
    base: str = Field(
        ..., min_length=1, description="the base model file, relative to the study file"
    )
    analyses: tuple[Analysis, ...] = Field(
        (Analysis.ROCKING, Analysis.KINEMATIC),
        min_length=1,
        description='"rocking", "kinematic" or both, each once',
    )
    engine: EngineName = Field(EngineName.FAST, description='"fast" or "reference"')
    code_demand: CodeDemandName = Field(
        CodeDemandName.RECORD,
        description='"record" (each record\'s spectrum is the code demand: one earthquake on '
        'both sides) or "model" (the base model\'s [ntc.demand] or [ntc.site])',
    )
    ground: bool = Field(
        False,
        strict=True,
        description="true: cases at height (building.Z > 0) rock on the record itself, not on "
        "its floor motion (as --ground); default false",
    )
    records_dir: str | None = Field(
        None, description="the folder the record paths are relative to (from the study file)"
    )
    axes: tuple[AxisSpec, ...] = Field((), description="[[axes]] tables with path and values")
    records: tuple[RecordSpec, ...] = Field((), description="[[records]] tables with path")

    @field_validator("analyses")
    @classmethod
    def _unique(cls, value: tuple[Analysis, ...]) -> tuple[Analysis, ...]:
        if len(set(value)) != len(value):
            raise ValueError("an analysis is listed twice")
        return value


@dataclass(frozen=True)
class RecordSource:
    """A record file and how to read it, or a suite file (hashable: the key of the workers'
    cache).

    Attributes:
        name: the label. path: the file, resolved.
        fmt, dt, units: how to read a record file. scale, pga: how to scale it.
        suite: True when the file is a record suite (its records and scales inside).
    """

    name: str
    path: str
    fmt: str | None = None
    dt: float | None = None
    units: str | None = None
    scale: float | None = None
    pga: float | None = None
    suite: bool = False


@dataclass(frozen=True)
class SkippedRecord:
    """An optional record whose file is absent."""

    name: str
    path: str
    source: str | None


@dataclass(frozen=True)
class StudyPlan:
    """A validated study: the base model table, the axes, the records present and skipped."""

    file: str
    name: str
    base_file: str
    base: dict[str, Any]
    analyses: tuple[str, ...]
    engine: str
    code_demand: str
    axes: tuple[Axis, ...]
    records: tuple[RecordSource, ...]
    skipped: tuple[SkippedRecord, ...]
    ground: bool = False
    grid_file: str | None = None
    #: Run each rocking case again at tighter tolerances (--check-tolerance): a ``sensitive``
    #: column and a count of sensitive cases (rockcli.dynamics.tolerance).
    check_tolerance: bool = False


def study_error(err: ErrorDetails, file: str) -> InputError:
    """One pydantic error of the study file as one InputError naming the key."""
    loc = tuple(err["loc"])
    if err["type"] != "extra_forbidden":  # its last key is the unknown one: keep it
        # A union (path: text or array) reports the member tried; keep the keys and indices.
        loc = tuple(p for p in loc if isinstance(p, int) or p in _KEYS)
    where = _dotted(loc) or None
    if err["type"] == "extra_forbidden":
        table = _table_of(loc[:-1])
        keys = ", ".join(table.model_fields) if table else ""
        return InputError("unknown key", file=file, where=where, allowed=f"one of: {keys}")
    if err["type"] == "missing":
        return InputError("missing key", file=file, where=where, allowed="required")
    info = _field_of(loc)
    value = err.get("input")
    problem = " ".join(err["msg"].split()).removeprefix("Value error, ")
    if "values" in loc and err["type"] != "too_short":
        problem = "not a number, text or boolean"  # the union reports its first member
    return InputError(
        problem,
        file=file,
        where=where,
        value=value if isinstance(value, bool | int | float | str) else None,
        allowed=info.description if info is not None else None,
    )


_TABLES: dict[str, type[BaseModel]] = {"axes": AxisSpec, "records": RecordSpec}
_KEYS = set(Study.model_fields) | set(AxisSpec.model_fields) | set(RecordSpec.model_fields)


def _table_of(loc: Sequence[str | int]) -> type[BaseModel] | None:
    keys = [p for p in loc if isinstance(p, str)]
    if not keys:
        return Study
    return _TABLES.get(keys[0]) if len(keys) == 1 else None


def _field_of(loc: Sequence[str | int]) -> Any:
    keys = [p for p in loc if isinstance(p, str)]
    table = _table_of(loc[: max((i for i, p in enumerate(loc) if isinstance(p, str)), default=0)])
    return table.model_fields.get(keys[-1]) if table and keys else None


def _dotted(loc: Sequence[str | int]) -> str:
    text = ""
    for part in loc:
        text += f"[{part}]" if isinstance(part, int) else ("." if text else "") + part
    return text


def validate_study(data: Mapping[str, Any], file: str) -> Study:
    """The study table validated; InputError (the first problem) naming the key."""
    for key, (problem, allowed) in REMOVED_KEYS.items():
        if key in data:
            raise InputError(problem, file=file, where=key, value=data[key], allowed=allowed)
    try:
        return Study.model_validate(data)
    except ValidationError as exc:
        raise study_error(exc.errors()[0], file) from None


#: What a path of the study file may name without --allow-outside.
INSIDE_ALLOWED = (
    "a path inside the study file's folder (or inside --records-dir), or --allow-outside"
)


def check_inside(path: Path, folder: Path, file: str, where: str, value: str) -> None:
    """Refuse a path of the study file that leaves its folder (``..``, an absolute path, a
    symlink to elsewhere): a study from an untrusted pull request reads only its own files."""
    inside.check_inside(
        path, folder, file=file, where=where, value=value,
        problem="leaves the study's folder", allowed=INSIDE_ALLOWED,
    )  # fmt: skip


def relative_to_study(study_file: str, path: str) -> str:
    """A file of the study named from the study file's folder (``records/suite.toml``), as the
    error column of cases.csv names it: an absolute path would differ between machines and
    tell the user's folders to whoever reads the file. Its name alone when no relative path
    exists (another drive)."""
    try:
        return os.path.relpath(Path(path).resolve(), Path(study_file).parent.resolve())
    except (OSError, ValueError):
        return Path(path).name


def shown_path(study_file: str, path: str) -> str:
    """A file of the study as the user would name it: the study file's folder as given, then
    the file's path from there (``studies/records/suite.toml``)."""
    return os.path.join(os.path.dirname(study_file), relative_to_study(study_file, path))


def is_file(path: str | Path, file: str, where: str) -> bool:
    """True for an existing regular file, False when absent; a path the system refuses (a
    name longer than NAME_MAX, a loop of links) or one that is not a regular file (a folder,
    a FIFO that would block the read, a device) is an InputError naming the key."""
    from rockcli.textfile import file_kind

    try:
        mode = os.stat(path).st_mode
    except (FileNotFoundError, NotADirectoryError):
        return False
    except (OSError, ValueError) as exc:
        raise path_error(exc, file, where) from None
    if not stat.S_ISREG(mode):
        raise InputError(
            f"not a regular file ({file_kind(mode)})",
            file=file,
            where=where,
            value=str(path),
            allowed="a regular file (not a folder, pipe or device)",
        )
    return True


def load_study(
    file: str,
    records_dir: str | None = None,
    *,
    allow_outside: bool = False,
    grid_file: str | None = None,
) -> StudyPlan:
    """Read and validate a study file: schema, base model, axis paths, record files.

    Args:
        file: the study TOML (named in errors as given).
        records_dir: replaces the file's records_dir (the --records-dir option).
        allow_outside: let the file's paths leave its folder (the --allow-outside option).
        grid_file: the NTC hazard grid for sites (the --hazard-grid option; else
            $ROCK_HAZARD_GRID when a site needs it).
    """
    from rockcli.model.load import read_toml

    return study_plan(read_toml(file), file, records_dir, allow_outside, grid_file)


def study_plan(
    data: Mapping[str, Any],
    file: str,
    records_dir: str | None = None,
    allow_outside: bool = False,
    grid_file: str | None = None,
) -> StudyPlan:
    """The plan of a study table read from ``file`` (:func:`load_study`; rock fragility
    passes the part of its own study file that names the model, axes and records)."""
    from rockcli.model.load import read_toml

    study = validate_study(data, file)
    here = Path(file).parent
    base_file = str(here / study.base)
    if not allow_outside:
        check_inside(here / study.base, here, file, "base", study.base)
        if study.records_dir and not records_dir:
            check_inside(here / study.records_dir, here, file, "records_dir", study.records_dir)
    if not is_file(base_file, file, "base"):
        raise InputError(
            "base model file not found",
            file=file,
            where="base",
            value=study.base,
            allowed=f"a model file, relative to the study file ({base_file} is absent)",
        )
    base = read_toml(base_file)
    _check_code_demand(study, base, file)
    axes = check_axes(study.axes, base, file)
    folder = records_folder(study.records_dir, here, records_dir)
    records, skipped = record_sources(study.records, folder, file, allow_outside)
    if Analysis.ROCKING in study.analyses and not records:
        raise InputError(
            "no record to run" + (" (every record is optional and absent)" if skipped else ""),
            file=file,
            where="records",
            allowed="[[records]] tables with existing files (the rocking analysis needs one)",
        )
    return StudyPlan(
        file=file,
        name=study.name or Path(file).stem,
        base_file=base_file,
        base=base,
        analyses=tuple(str(a) for a in study.analyses),
        engine=str(study.engine),
        code_demand=str(study.code_demand),
        ground=study.ground,
        axes=axes,
        records=records,
        skipped=skipped,
        grid_file=grid_file,
    )


def _check_code_demand(study: Study, base: Mapping[str, Any], file: str) -> None:
    """Refuse code_demand = "model" when the base model sets no code spectrum."""
    ntc = base.get("ntc")
    sets = isinstance(ntc, Mapping) and ("demand" in ntc or "site" in ntc)
    if study.code_demand is CodeDemandName.MODEL and not sets:
        raise InputError(
            "the base model sets no code spectrum ([ntc.demand] or [ntc.site])",
            file=file,
            where="code_demand",
            value=str(study.code_demand),
            allowed='"record" (the default), or "model" with a base model that sets '
            "[ntc.demand] or [ntc.site]",
        )


def records_folder(given: str | None, here: Path, override: str | None) -> Path:
    """The folder of the record paths: --records-dir, else the file's records_dir (from the
    study file's folder ``here``), else the study file's folder."""
    if override:
        return Path(override)
    return here / given if given else here


def record_sources(
    specs: Sequence[RecordSpec], folder: Path, file: str, allow_outside: bool = False
) -> tuple[tuple[RecordSource, ...], tuple[SkippedRecord, ...]]:
    """The records present (paths resolved) and the optional ones absent."""
    from rockcli.records.files import record_name

    present: list[RecordSource] = []
    skipped: list[SkippedRecord] = []
    for i, spec in enumerate(specs):
        key, given = entry_file(spec, i, file)
        path = folder / given
        if not allow_outside:
            check_inside(path, folder, file, f"records[{i}].{key}", given)
        if spec.suite is not None:
            if not is_file(path, file, f"records[{i}].suite"):
                if spec.optional:
                    skipped.append(SkippedRecord(spec.name or given, str(path), spec.source))
                    continue
                raise InputError(
                    "suite file not found",
                    file=file,
                    where=f"records[{i}].suite",
                    value=str(path),
                    allowed="an existing suite file (relative to records_dir, or to the study "
                    "file), or optional = true to skip it",
                )
            source = suite_source(spec, path, folder, file, i, allow_outside)
            _check_unique(present, source.name, file, i)
            present.append(source)
            continue
        name = spec.name or record_name(path)
        if spec.scale is not None and spec.pga is not None:
            raise InputError(
                "not allowed together with scale",
                file=file,
                where=f"records[{i}].pga",
                value=spec.pga,
                allowed="scale or pga, not both",
            )
        if not is_file(path, file, f"records[{i}].path"):
            if spec.optional:
                skipped.append(SkippedRecord(name, str(path), spec.source))
                continue
            raise InputError(
                "record file not found",
                file=file,
                where=f"records[{i}].path",
                value=str(path),
                allowed="an existing file (paths are relative to records_dir, or to the study "
                "file; --records-dir sets the folder), or optional = true to skip it",
            )
        _check_unique(present, name, file, i)
        fmt = str(spec.format) if spec.format is not None else None
        present.append(
            RecordSource(name, str(path.resolve()), fmt, spec.dt, spec.units, spec.scale, spec.pga)
        )
    return tuple(present), tuple(skipped)


#: The keys of a [[records]] entry that read or scale one record file (not with suite).
RECORD_ONLY_KEYS = ("scale", "pga", "format", "dt", "units")


def entry_file(spec: RecordSpec, i: int, file: str) -> tuple[str, str]:
    """("path" or "suite", the file as written): exactly one of them, and no key that reads
    or scales one record beside a suite (the suite file holds its records' scales)."""
    if (spec.path is None) == (spec.suite is None):
        raise InputError(
            "give a record file or a suite file" if spec.path is None else "path and suite",
            file=file,
            where=f"records[{i}]",
            allowed="path = RECORD, or suite = SUITE.toml (not both)",
        )
    if spec.suite is None:
        return "path", str(spec.path)
    for key in RECORD_ONLY_KEYS:
        if getattr(spec, key) is not None:
            raise InputError(
                "reads or scales one record: not with suite",
                file=file,
                where=f"records[{i}].{key}",
                value=getattr(spec, key),
                allowed="scale in each [[records]] entry of the suite file",
            )
    return "suite", spec.suite


def suite_source(
    spec: RecordSpec, path: Path, folder: Path, file: str, i: int, allow_outside: bool
) -> RecordSource:
    """A suite entry, its file validated (rockcli.suites.load) and, unless allow_outside,
    each of its records inside the records folder (a study reads only its own files)."""
    from rockcli.suites.load import load_suite

    settings = load_suite(str(path), allow_outside=True)  # checked below, against the study's
    if not allow_outside:
        for k, entry in enumerate(settings.entries):
            check_inside(
                entry.path, folder, file, f"records[{i}].suite", f"record {k + 1}: {entry.path}"
            )
    return RecordSource(spec.name or settings.name, str(path.resolve()), suite=True)


def _check_unique(present: Sequence[RecordSource], name: str, file: str, i: int) -> None:
    """Refuse a second entry with the same name (cases are keyed by it)."""
    if name in {r.name for r in present}:
        raise InputError(
            "two records with the same name",
            file=file,
            where=f"records[{i}]",
            value=name,
            allowed="a distinct name = ... for each record",
        )
