"""Key paths into the model: check them against the schema and the base file, set them.

A path names a value field of the model (``geometry.R``, ``restrainers[0].k_pos``,
``ntc.FC``): every key must be a field of its table, every ``[i]`` an element the base
model has (a study changes restrainers, it does not invent them), and the path must end at
a value, not a table. Tables the base leaves out (an absent ``[ntc]``) are created when a
value is set in them; the case's validation then says whether the result is a valid model.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, get_args, get_origin

from pydantic import BaseModel, Field

from rockcli.errors import InputError
from rockcli.model.schema import Model
from rockcli.model.schema_base import Table

#: A value an axis sets: a TOML scalar.
Scalar = bool | int | float | str
#: A key path inside the model: ("restrainers", 0, "k_pos").
KeyPath = tuple[str | int, ...]

_PATH = re.compile(
    r"^[A-Za-z_][A-Za-z0-9_]*(\[\d+\])*(\.[A-Za-z_][A-Za-z0-9_]*(\[\d+\])*)*$", re.ASCII
)
_PART = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)|\[(\d+)\]", re.ASCII)
PATH_ALLOWED = "dotted keys with [i] indices, e.g. geometry.R or restrainers[0].k_pos"


class AxisSpec(Table):
    """One axis of the grid: a model field (or several set together) and its values."""

    path: str | tuple[str, ...] = Field(
        ..., description="a key path such as geometry.R, or an array of them set together"
    )
    values: tuple[Scalar | tuple[Scalar, ...], ...] = Field(
        ...,
        min_length=1,
        description="a non-empty array of numbers, text or booleans (with several paths, "
        "each an array of one value per path, or one value for all)",
    )
    name: str | None = Field(
        None,
        min_length=1,
        description="a non-empty label (default: the last key of the first path)",
    )

    @property
    def paths(self) -> tuple[str, ...]:
        """The key paths as text."""
        return (self.path,) if isinstance(self.path, str) else self.path


@dataclass(frozen=True)
class Axis:
    """An axis ready to expand: its label, key paths and values (one tuple per path)."""

    name: str
    paths: tuple[KeyPath, ...]
    texts: tuple[str, ...]
    values: tuple[tuple[Scalar, ...], ...]

    def label(self, index: int) -> Scalar:
        """The index-th value as shown: the value, or ``a/b`` when the paths differ."""
        value = self.values[index]
        if all(v == value[0] and type(v) is type(value[0]) for v in value):
            return value[0]
        return "/".join(str(v) for v in value)


def parse_path(text: str) -> KeyPath | None:
    """``restrainers[0].k_pos`` → ("restrainers", 0, "k_pos"); None if the syntax is bad."""
    if not _PATH.match(text):
        return None
    return tuple(key if key else int(index) for key, index in _PART.findall(text))


#: Column names of the results: an axis cannot take them.
RESERVED = frozenset(
    {
        "case",
        "record",
        "block_R",
        "block_alpha",
        "max_ratio",
        "max_ratio_pos",
        "max_ratio_neg",
        "overturned",
        "t_overturn",
        "rocking",
        "input",
        "utilisation",
        "code_dls",
        "code_uls",
        "uls_ratio",
        "a0_star",
        "Ts",
        "classification",
        "error",
    }
)


def _table_in(annotation: Any) -> type[BaseModel] | None:
    """The table class inside an annotation (Optional[T], tuple[T, ...]), if any."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in get_args(annotation):
        found = _table_in(arg)
        if found is not None:
            return found
    return None


def _is_array(annotation: Any) -> bool:
    """True for tuple[T, ...] (or Optional of it): an array of tables in TOML."""
    if get_origin(annotation) is tuple:
        return True
    return any(_is_array(a) for a in get_args(annotation) if a is not type(None))


def schema_problem(path: KeyPath) -> tuple[str, str] | None:
    """(problem, allowed) when the path does not name a value field of the model, else None."""
    table: type[BaseModel] = Model
    i = 0
    while i < len(path):
        key = path[i]
        keys = "one of: " + ", ".join(table.model_fields)
        if isinstance(key, int):
            return "an index where a key is expected", keys
        info = table.model_fields.get(key)
        if info is None:
            return f"no key {key!r} in this table of the model", keys
        sub, array = _table_in(info.annotation), _is_array(info.annotation)
        i += 1
        if array:
            if i == len(path) or not isinstance(path[i], int):
                return f"{key} is an array of tables: give an index", f"{key}[0].<key>"
            i += 1
        if sub is None:
            return None if i == len(path) else (f"{key} is a value, not a table", keys)
        if i == len(path):
            return f"{key} is a table, not a value", "a key inside it: " + ", ".join(
                sub.model_fields
            )
        table = sub
    return None


def base_problem(path: KeyPath, base: Mapping[str, Any]) -> str | None:
    """A problem when an index of the path is not an element of the base model."""
    node: Any = base
    for depth, key in enumerate(path):
        if isinstance(key, int):
            if not isinstance(node, list) or key >= len(node):
                return f"{_text(path[: depth + 1])} is not in the base model"
        elif not isinstance(node, Mapping) or key not in node:
            rest = path[depth + 1 :]
            if any(isinstance(k, int) for k in rest):  # an element of an absent array
                first = depth + 1 + next(i for i, k in enumerate(rest) if isinstance(k, int))
                return f"{_text(path[: first + 1])} is not in the base model"
            return None  # an absent table or value: created when set
        node = node[key]
    return None


def _text(path: Sequence[str | int]) -> str:
    out = ""
    for part in path:
        out += f"[{part}]" if isinstance(part, int) else ("." if out else "") + part
    return out


def with_values(
    base: Mapping[str, Any], axes: Sequence[Axis], indices: Sequence[int]
) -> dict[str, Any]:
    """The base model table with each axis at its index-th value, the base untouched.

    Only the tables and arrays on the axes' paths are copied (one level each); the rest is
    shared with the base, which nothing mutates (validation reads the table). A deep copy of
    the whole table per case was a third of a case's time in a large study.
    """
    data = dict(base)
    for axis, index in zip(axes, indices, strict=True):
        for path, value in zip(axis.paths, axis.values[index], strict=True):
            set_copied(data, path, value)
    return data


def set_copied(data: dict[str, Any], path: KeyPath, value: Scalar) -> None:
    """Set a value in a table whose containers on the path are copied first (and absent tables
    created), so that tables shared with another table are never changed."""
    node: Any = data
    for key in path[:-1]:
        if isinstance(key, int):
            child = list(node[key]) if isinstance(node[key], list) else dict(node[key])
        else:
            found = node.get(key)
            child = (
                {} if found is None else (list(found) if isinstance(found, list) else dict(found))
            )
        node[key] = child
        node = child
    node[path[-1]] = value


def check_axes(specs: Sequence[AxisSpec], base: Mapping[str, Any], file: str) -> tuple[Axis, ...]:
    """The axes of a study, each path checked; InputError naming the axis key otherwise."""
    axes: list[Axis] = []
    seen: dict[KeyPath, int] = {}
    for i, spec in enumerate(specs):
        paths = tuple(
            _checked_path(text, i, j, spec, base, file) for j, text in enumerate(spec.paths)
        )
        for path in paths:
            if path in seen:
                raise InputError(
                    f"already set by axes[{seen[path]}]",
                    file=file,
                    where=f"axes[{i}].path",
                    value=_text(path),
                    allowed="each model field on one axis only",
                )
            seen[path] = i
        values = tuple(
            _values_of(spec, k, v, len(paths), i, file) for k, v in enumerate(spec.values)
        )
        name = spec.name or next(str(p) for p in reversed(paths[0]) if isinstance(p, str))
        _check_name(name, i, [a.name for a in axes], file)
        axes.append(Axis(name, paths, spec.paths, values))
    return tuple(axes)


def _checked_path(
    text: str, i: int, j: int, spec: AxisSpec, base: Mapping[str, Any], file: str
) -> KeyPath:
    where = f"axes[{i}].path" + (f"[{j}]" if not isinstance(spec.path, str) else "")
    path = parse_path(text)
    if path is None:
        raise InputError("bad key path", file=file, where=where, value=text, allowed=PATH_ALLOWED)
    problem = schema_problem(path)
    if problem is not None:
        raise InputError(
            f"not a field of the model: {problem[0]}",
            file=file,
            where=where,
            value=text,
            allowed=problem[1],
        )
    missing = base_problem(path, base)
    if missing is not None:
        raise InputError(
            missing, file=file, where=where, value=text, allowed="an element of the base model"
        )
    return path


def _values_of(
    spec: AxisSpec, k: int, value: Any, n_paths: int, i: int, file: str
) -> tuple[Scalar, ...]:
    """One value per path: a scalar for all, or an array with one per path."""
    if not isinstance(value, tuple):
        return (value,) * n_paths
    if n_paths > 1 and len(value) == n_paths:
        return tuple(value)
    raise InputError(
        "a value must be a number, text or boolean"
        + (f", or an array of {n_paths} (one per path)" if n_paths > 1 else ""),
        file=file,
        where=f"axes[{i}].values[{k}]",
        allowed="one value per path" if n_paths > 1 else "a TOML scalar",
    )


def _check_name(name: str, i: int, taken: Sequence[str], file: str) -> None:
    if name in taken:
        raise InputError(
            "another axis has this name",
            file=file,
            where=f"axes[{i}].name",
            value=name,
            allowed='name = "..." different from the other axes\' names',
        )
    if name in RESERVED:
        raise InputError(
            "the name of a result column",
            file=file,
            where=f"axes[{i}].name",
            value=name,
            allowed='name = "..." not one of: ' + ", ".join(sorted(RESERVED)),
        )
