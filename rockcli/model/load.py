"""Read and write model files: bytes → TOML → pydantic → :class:`Model`, at the edge.

Every failure becomes one :class:`~rockcli.errors.InputError` on one line, naming the file,
the field path (``geometry.thickness``, ``restrainers[0].k_pos``) or the TOML line, the value
found and what is allowed (spec/README.md: "a bad file gets one clear message naming the field,
the value and what is allowed, never a traceback"; spec/style.md, principle 3).

The translation of pydantic's errors is table-driven: :data:`TRANSLATION` maps each error type
to the problem text and a function that says what is allowed, read from the schema itself
(the constraints and the ``[unit]`` of the field description, the keys of the table).
"""

from __future__ import annotations

import json
import math
import os
import re
import tomllib
from collections.abc import Callable, Mapping, Sequence
from enum import Enum
from inspect import isclass
from pathlib import Path
from typing import Any, get_args

import annotated_types as at
import tomli_w
from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo
from pydantic_core import ErrorDetails

from rockcli.errors import InputError
from rockcli.model.rules import RULE_ERROR
from rockcli.model.schema import Model

Loc = tuple[str | int, ...]

#: Longest value quoted back in a message [characters].
MAX_VALUE_CHARS = 60

_TOML_POSITION = re.compile(
    r"^(?P<problem>.*?)\s*\(at (?P<where>line \d+, column \d+|end of document)\)$"
)
_UNIT = re.compile(r"\[([^\]]+)\]\s*$")
_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def load_model(path: str | os.PathLike[str]) -> Model:
    """Read, parse and validate a model file.

    Args:
        path: the TOML file (named in errors as the user gave it).

    Raises:
        InputError: unreadable file, malformed TOML (with line and column) or invalid model.
    """
    file = os.fspath(path)
    return validate_model(read_toml(file), file=file)


def read_toml(file: str) -> dict[str, Any]:
    """The TOML table of a file; InputError when it cannot be read or parsed."""
    try:
        raw = Path(file).read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read the file: {exc.strerror or exc}", file=file) from None
    try:
        return tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise InputError("not UTF-8 text", file=file, where=_position(raw, exc.start)) from None
    except tomllib.TOMLDecodeError as exc:
        raise toml_error(exc, file) from None


def _position(raw: bytes, offset: int) -> str:
    """``line L, column C`` (1-based, columns in bytes) of a byte offset, as tomllib says it."""
    line = raw.count(b"\n", 0, offset) + 1
    column = offset - (raw.rfind(b"\n", 0, offset) + 1) + 1
    return f"line {line}, column {column}"


def toml_error(exc: tomllib.TOMLDecodeError, file: str) -> InputError:
    """InputError for malformed TOML, with the line and column tomllib reports."""
    text = " ".join(str(exc).split())
    match = _TOML_POSITION.match(text)
    problem, where = (match["problem"], match["where"]) if match else (text, None)
    return InputError(
        f"malformed TOML: {problem[:1].lower()}{problem[1:]}",
        file=file,
        where=where,
        allowed="TOML syntax, see https://toml.io",
    )


def validate_model(data: Mapping[str, Any], file: str | None = None) -> Model:
    """Validate a parsed model file; InputError (the first problem only) when it is invalid.

    Args:
        data: the TOML table, as tomllib returns it.
        file: the file it came from, for the message.
    """
    try:
        return Model.model_validate(data)
    except ValidationError as exc:
        raise translate_error(exc.errors()[0], file) from None


def to_toml(model: Model) -> str:
    """The model as TOML text that :func:`load_model` reads back to an equal model."""
    return dumps(model.model_dump(mode="json", exclude_none=True))


def dumps(data: Mapping[str, Any]) -> str:
    """TOML text by tomli-w, writing top-level arrays of flat tables as ``[[name]]`` blocks.

    tomli-w writes short arrays of tables inline; model files read better with one
    ``[[restrainers]]`` block per restrainer.
    """
    arrays = {k: v for k, v in data.items() if _is_array_of_tables(v)}
    rest = {k: v for k, v in data.items() if k not in arrays}
    chunks = [tomli_w.dumps(rest)]
    for key, rows in arrays.items():
        chunks += [f"\n[[{_key_text(key)}]]\n{tomli_w.dumps(row)}" for row in rows]
    return "".join(chunks)


def _is_array_of_tables(value: Any) -> bool:
    """A non-empty array of flat tables (tables of values, no sub-tables)."""
    return (
        isinstance(value, list | tuple)
        and bool(value)
        and all(
            isinstance(row, Mapping) and not any(isinstance(v, Mapping) for v in row.values())
            for row in value
        )
    )


# --- translation of pydantic errors --------------------------------------------------------

Explain = Callable[[ErrorDetails, Loc], str | None]


def _required(err: ErrorDetails, loc: Loc) -> str:
    return "required"


def _table_keys(err: ErrorDetails, loc: Loc) -> str:
    table = table_at(loc[:-1])
    keys = list(table.model_fields) if table else []
    return "one of: " + ", ".join(keys) if keys else "no keys"


def _number(err: ErrorDetails, loc: Loc) -> str:
    info = field_at(loc)
    bounds = [
        f"{symbol} {_format_bound(getattr(m, attr))}"
        for m in (info.metadata if info else [])
        for kind, attr, symbol in _BOUNDS
        if isinstance(m, kind)
    ]
    text = " ".join(["a number", " and ".join(bounds)]).strip()
    return f"{text} {_unit_of(info)}".strip()


def _integer(err: ErrorDetails, loc: Loc) -> str:
    return _number(err, loc).replace("a number", "a whole number", 1)


def _choices(err: ErrorDetails, loc: Loc) -> str:
    info = field_at(loc)
    enum = _find_class(info.annotation, Enum) if info else None
    if enum is None:
        return f"one of: {err.get('ctx', {}).get('expected', '?')}"
    return "one of: " + ", ".join(str(member.value) for member in enum)


def _table(err: ErrorDetails, loc: Loc) -> str:
    if loc and isinstance(loc[-1], int):
        return f"a [[{_dotted(loc[:-1])}]] table"
    return f"a [{_dotted(loc)}] table" if loc else "a TOML document"


def _array(err: ErrorDetails, loc: Loc) -> str:
    return f"an array of [[{_dotted(loc)}]] tables"


def _text(err: ErrorDetails, loc: Loc) -> str:
    return "a non-empty text string"


def _boolean(err: ErrorDetails, loc: Loc) -> str:
    return "true or false"


def _from_rule(err: ErrorDetails, loc: Loc) -> str | None:
    return err.get("ctx", {}).get("allowed")


def _nothing(err: ErrorDetails, loc: Loc) -> None:
    return None


#: pydantic error type → (problem, what is allowed); a ``None`` problem quotes the error's own.
TRANSLATION: dict[str, tuple[str | None, Explain]] = {
    "missing": ("missing key", _required),
    "extra_forbidden": ("unknown key", _table_keys),
    "greater_than": ("out of range", _number),
    "greater_than_equal": ("out of range", _number),
    "less_than": ("out of range", _number),
    "less_than_equal": ("out of range", _number),
    "finite_number": ("not a finite number", _number),
    "float_type": ("not a number", _number),
    "float_parsing": ("not a number", _number),
    "int_type": ("not a whole number", _integer),
    "int_parsing": ("not a whole number", _integer),
    "int_from_float": ("not a whole number", _integer),
    "enum": ("unknown value", _choices),
    "bool_type": ("not a boolean", _boolean),
    "bool_parsing": ("not a boolean", _boolean),
    "string_type": ("not a text string", _text),
    "string_too_short": ("empty", _text),
    "model_type": ("not a table", _table),
    "model_attributes_type": ("not a table", _table),
    "dict_type": ("not a table", _table),
    "tuple_type": ("not an array of tables", _array),
    "list_type": ("not an array of tables", _array),
    RULE_ERROR: (None, _from_rule),
}

_BOUNDS = ((at.Gt, "gt", ">"), (at.Ge, "ge", ">="), (at.Lt, "lt", "<"), (at.Le, "le", "<="))


def translate_error(err: ErrorDetails, file: str | None = None) -> InputError:
    """One pydantic error as one InputError: where (dotted path), problem, value, allowed."""
    problem, explain = TRANSLATION.get(err["type"], (None, _nothing))
    loc, value = _where_and_value(err)
    return InputError(
        problem or _one_line(err["msg"]),
        file=file,
        where=_dotted(loc) or None,
        value=_short(value),
        allowed=explain(err, loc),
    )


def _where_and_value(err: ErrorDetails) -> tuple[Loc, Any]:
    """The key path and value of an error; a rule error names its key in its context."""
    ctx = err.get("ctx", {})
    if err["type"] == RULE_ERROR:
        return tuple(err["loc"]) + tuple(ctx["field"]), ctx.get("value")
    if err["type"] == "missing":
        return tuple(err["loc"]), None
    return tuple(err["loc"]), err.get("input")


def _dotted(loc: Sequence[str | int]) -> str:
    """``('restrainers', 0, 'k_pos')`` → ``restrainers[0].k_pos`` (odd keys quoted as in TOML)."""
    text = ""
    for part in loc:
        if isinstance(part, int):
            text += f"[{part}]"
        else:
            text += ("." if text else "") + _key_text(part)
    return text


def _key_text(key: str) -> str:
    return key if _BARE_KEY.match(key) else json.dumps(key, ensure_ascii=False)


def _short(value: Any) -> Any:
    """The value to quote: scalars only (a whole table is not useful), long text cut."""
    if isinstance(value, Enum):
        return value.value
    if isinstance(value, bool | int | float):
        return value
    if isinstance(value, str):
        return value if len(value) <= MAX_VALUE_CHARS else value[: MAX_VALUE_CHARS - 3] + "..."
    return None


def _one_line(text: str) -> str:
    return " ".join(text.split())


def _format_bound(x: float) -> str:
    return "pi/2" if math.isclose(x, math.pi / 2) else f"{x:g}"


def _unit_of(info: FieldInfo | None) -> str:
    match = _UNIT.search(info.description or "") if info else None
    return f"[{match[1]}]" if match else ""


def table_at(loc: Sequence[str | int]) -> type[BaseModel] | None:
    """The schema table reached by a key path (list indices skipped); None off the schema."""
    table: type[BaseModel] | None = Model
    for part in loc:
        if isinstance(part, int):
            continue
        info = table.model_fields.get(part) if table else None
        table = _find_class(info.annotation, BaseModel) if info else None
    return table


def field_at(loc: Sequence[str | int]) -> FieldInfo | None:
    """The schema field at a key path, if the path is on the schema."""
    keys = [p for p in loc if isinstance(p, str)]
    if not keys:
        return None
    table = table_at(loc[: max(i for i, p in enumerate(loc) if isinstance(p, str))])
    return table.model_fields.get(keys[-1]) if table else None


def _find_class(annotation: Any, base: type) -> Any:
    """The first subclass of ``base`` inside a type annotation (Optional, tuple[...], …)."""
    if isclass(annotation) and issubclass(annotation, base):
        return annotation
    for arg in get_args(annotation):
        found = _find_class(arg, base)
        if found is not None:
            return found
    return None
