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

import difflib
import json
import math
import os
import re
import tomllib
from collections.abc import Callable, Mapping, Sequence
from enum import Enum
from inspect import isclass
from typing import Any, get_args

import annotated_types as at
import tomli_w
from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo
from pydantic_core import ErrorDetails

from rockcli.errors import InputError
from rockcli.model.derive import derive_block
from rockcli.model.derived_checks import FINITE_POSITIVE, check_block
from rockcli.model.schema import Model
from rockcli.model.table_rules import RULE_ERROR
from rockcli.textfile import TOML_LIMIT, read_limited, reason

Loc = tuple[str | int, ...]

#: Nesting depth at which the line of a file too deeply nested for tomllib is reported (a
#: model file needs 4 levels; tomllib's recursion runs out near 300 at Python's default limit).
MAX_NESTING = 100

#: Most problems listed for one file; the others are counted ("and N more").
MAX_ERRORS = 10

#: Similarity (difflib ratio) above which an unknown name is a near miss of a known one: 0.6
#: is difflib's own default; 0.75 keeps ``[results]`` from suggesting ``[restrainers]``
#: while ``thikness`` → ``thickness`` (0.94) and ``geometri`` → ``geometry`` (0.88) pass.
NEAR_MISS = 0.75


#: Longest value quoted back in a message [characters].
MAX_VALUE_CHARS = 60

_TOML_POSITION = re.compile(
    r"^(?P<problem>.*?)\s*\(at (?P<where>line \d+, column \d+|end of document)\)$"
)
_QUOTED = re.compile(r'"(?:[^"\\]|\\.)*"|\'[^\']*\'')
_UNIT = re.compile(r"\[([^\]]+)\]\s*$")
_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


class InputErrors(InputError):
    """Several problems in one input: one :class:`InputError` line each, at most ten shown.

    The first problem's fields are this error's own (callers that read ``where`` or
    ``problem`` see the first); :attr:`lines` holds one line per problem, which the CLI prints
    each as its own ``error: …`` line; ``str()`` joins them with line breaks.

    Args:
        errors: the problems shown, in the order found (at least two).
        more: how many further problems were found and not shown.
    """

    def __init__(self, errors: Sequence[InputError], *, more: int = 0) -> None:
        self.errors = tuple(errors)
        self.more = max(more, 0)
        first = self.errors[0]
        super().__init__(
            first.problem,
            file=first.file,
            where=first.where,
            value=first.value,
            allowed=first.allowed,
        )

    @property
    def lines(self) -> tuple[str, ...]:
        """One line per problem, then ``and N more problems`` when some were not shown."""
        lines = [err.render() for err in self.errors]
        if self.more:
            head = f"{self.errors[0].file}: " if self.errors[0].file else ""
            lines.append(f"{head}and {self.more} more problems (fix these and run again)")
        return tuple(lines)

    def render(self) -> str:
        """The lines, joined by line breaks."""
        return "\n".join(self.lines)

    def with_file(self, file: str) -> InputError:
        """The same errors, each naming the file."""
        return InputErrors([err.with_file(file) for err in self.errors], more=self.more)

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle by the errors (a sweep worker's exception crosses a process boundary)."""
        return _input_errors, (self.errors, self.more)


def _input_errors(errors: Sequence[InputError], more: int) -> InputErrors:
    return InputErrors(errors, more=more)


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
    """The TOML table of a file; InputError when it cannot be read or parsed, is not a regular
    file or is larger than :data:`rockcli.textfile.TOML_LIMIT` (1 MiB)."""
    try:
        raw = read_limited(file, "TOML file", TOML_LIMIT)
    except (OSError, ValueError) as exc:  # absent, no permission, a NUL in the path
        raise InputError(f"cannot read the file: {reason(exc)}", file=file) from None
    try:
        return tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise InputError("not UTF-8 text", file=file, where=_position(raw, exc.start)) from None
    except tomllib.TOMLDecodeError as exc:
        raise toml_error(exc, file) from None
    except RecursionError:
        raise InputError(
            "malformed TOML: arrays or tables nested too deep to read",
            file=file,
            where=_deep_line(raw.decode("utf-8")),
            allowed="arrays and inline tables nested a few levels deep (a model needs 4)",
        ) from None


def _deep_line(text: str) -> str | None:
    """``line N``: the first line where brackets nest deeper than :data:`MAX_NESTING`.

    A scan that skips quoted strings on a line (enough to point at the culprit; tomllib has
    already refused the file).
    """
    depth = 0
    for number, line in enumerate(text.splitlines(), start=1):
        for char in _QUOTED.sub("", line).split("#", 1)[0]:
            depth += (char in "[{") - (char in "]}")
            if depth > MAX_NESTING:
                return f"line {number}"
    return None


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
    """Validate a parsed model file; InputError naming every problem when it is invalid.

    Args:
        data: the TOML table, as tomllib returns it.
        file: the file it came from, for the message.

    Raises:
        InputError: one problem; :class:`InputErrors` (an InputError) for several.
    """
    try:
        model = Model.model_validate(data)
    except ValidationError as exc:
        raise translate_errors(exc.errors(), file) from None
    check_derived(model, file)
    return model


def check_derived(model: Model, file: str | None = None) -> None:
    """InputError when the block derived from a valid model is not finite (see
    :mod:`rockcli.model.derived_checks`)."""
    try:
        check_block(derive_block(model))
    except InputError as exc:
        raise exc.with_file(file) if file else exc from None
    except ArithmeticError as exc:
        raise InputError(
            f"the block's derived quantities cannot be computed ({exc})",
            file=file,
            where="geometry, mass, analysis, restrainers",
            allowed=FINITE_POSITIVE,
        ) from None


def to_toml(model: Model) -> str:
    """The model as TOML text that :func:`load_model` reads back to an equal model (a frame
    without the [geometry] its [frame] writes)."""
    data = model.model_dump(mode="json", exclude_none=True)
    if model.frame is not None:
        data.pop("geometry", None)
    return dumps(data)


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


def translate_errors(errors: Sequence[ErrorDetails], file: str | None = None) -> InputError:
    """Every pydantic error of a file as one InputError (several: :class:`InputErrors`).

    An unknown key that is a near miss of a missing required one (``[geometri]`` for
    ``[geometry]``) is reported once, as the unknown key with its suggestion.
    """
    explained = {
        loc[:-1] + (hint,)
        for err in errors
        if err["type"] == "extra_forbidden"
        for loc in [tuple(err["loc"])]
        for hint in [_near_miss(loc)]
        if hint is not None
    }
    found = [
        translate_error(err, file)
        for err in errors
        if not (err["type"] == "missing" and tuple(err["loc"]) in explained)
    ]
    if len(found) == 1:
        return found[0]
    return InputErrors(found[:MAX_ERRORS], more=len(found) - MAX_ERRORS)


def translate_error(err: ErrorDetails, file: str | None = None) -> InputError:
    """One pydantic error as one InputError: where (dotted path), problem, value, allowed."""
    if err["type"] == "extra_forbidden":
        return _unknown_key(err, file)
    problem, explain = TRANSLATION.get(err["type"], (None, _nothing))
    loc, value = _where_and_value(err)
    if err["type"] == "enum" and isinstance(value, str) and not value.isdigit():
        problem = f"{problem}{_did_you_mean(value, _enum_values(loc))}"
    return InputError(
        problem or _one_line(err["msg"]),
        file=file,
        where=_dotted(loc) or None,
        value=_short(value),
        allowed=explain(err, loc),
    )


def _unknown_key(err: ErrorDetails, file: str | None) -> InputError:
    """An unknown key, or an unknown table named as TOML writes it, with a near match."""
    loc = tuple(err["loc"])
    value = err.get("input")
    hint = _near_miss(loc)
    allowed = _table_keys(err, loc)
    if _is_table(value):
        brackets = ("[[", "]]") if isinstance(value, list) else ("[", "]")
        name = "{}{}{}".format(brackets[0], "{}", brackets[1])
        suggestion = f"; did you mean {name.format(_dotted(loc[:-1] + (hint,)))}?" if hint else ""
        problem = f"unknown table {name.format(_dotted(loc))}{suggestion}"
        return InputError(problem, file=file, allowed=allowed)
    suggestion = f"; did you mean {hint}?" if hint else ""
    return InputError(
        f"unknown key{suggestion}",
        file=file,
        where=_dotted(loc),
        value=_short(value),
        allowed=allowed,
    )


def _is_table(value: Any) -> bool:
    """A TOML table, or an array of tables."""
    if isinstance(value, Mapping):
        return True
    return isinstance(value, list) and bool(value) and all(isinstance(v, Mapping) for v in value)


def _near_miss(loc: Loc) -> str | None:
    """The key of the schema closest to an unknown key at ``loc`` (difflib), if any."""
    key = loc[-1] if loc else None
    table = table_at(loc[:-1])
    if not isinstance(key, str) or table is None:
        return None
    keys = list(table.model_fields)
    folded = {k.casefold(): k for k in keys}
    if key.casefold() in folded:
        return folded[key.casefold()]
    matches = difflib.get_close_matches(key, keys, n=1, cutoff=NEAR_MISS)
    return matches[0] if matches else None


def _enum_values(loc: Loc) -> list[str]:
    info = field_at(loc)
    enum = _find_class(info.annotation, Enum) if info else None
    return [str(member.value) for member in enum] if enum is not None else []


def _did_you_mean(word: str, choices: Sequence[str]) -> str:
    """``; did you mean 'x'?`` for a near miss among ``choices`` (difflib), else nothing."""
    folded = {c.casefold(): c for c in choices}
    match = folded.get(word.strip().casefold())
    if match is None:
        close = difflib.get_close_matches(word, list(choices), n=1, cutoff=NEAR_MISS)
        match = close[0] if close else None
    return f"; did you mean {match!r}?" if match is not None else ""


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
