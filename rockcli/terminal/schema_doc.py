"""The model-file reference (docs/model-reference.md), generated from the pydantic schema.

Nothing here is written by hand about a key: the tables, their keys and order
(``model_fields``), types and allowed values (annotations, enum members), bounds (``gt``,
``ge``, ``lt``, ``le`` in ``field.metadata``), defaults, and the unit (the ``[unit]`` at the
end of each description) are all read from :mod:`rockcli.model.schema` and
:mod:`rockcli.model.ntc`, so the reference cannot drift from what the loader accepts.
tests/docs/test_docs.py checks that the committed file equals :func:`model_reference`.

Regenerate with::

    python -m rockcli.terminal.schema_doc > docs/model-reference.md

Pure: pydantic and the schema only (no numpy, so it runs as fast as model validation).
"""

from __future__ import annotations

import enum
import inspect
import math
import re
import sys
import types
from dataclasses import dataclass
from typing import Any, Union, get_args, get_origin

import annotated_types as at
from pydantic import BaseModel
from pydantic.fields import FieldInfo

from rockcli.model.schema import Model

#: The command that writes docs/model-reference.md (quoted in the file and in test failures).
REGENERATE = "python -m rockcli.terminal.schema_doc > docs/model-reference.md"

_UNIT = re.compile(r"\s*\[(?P<unit>[^\]]+)\]\s*$")
#: Internal references in the docstrings ("(spec/ntc.md)", "; spec/rocking.md)"): the user
#: guide has no spec folder, so they are left out of the generated text.
_SPEC_PAREN = re.compile(r"\s*\(spec/[^()]*\)")
_SPEC_TAIL = re.compile(r";\s*spec/[^()]*\)")
_BOUNDS = ((at.Gt, "gt"), (at.Ge, "ge"), (at.Lt, "lt"), (at.Le, "le"))

PREAMBLE = f"""\
# Model file reference

<!-- Generated from the pydantic schema by `{REGENERATE}`. Do not edit by hand. -->

One TOML file describes one macro-element (wall, altar, façade); `rock assess`,
`rock kinematic` and `rock compare` all read it. This page lists every table and key the
loader accepts, read from the schema itself (`rockcli/model/schema.py`,
`rockcli/model/ntc.py`). For what the quantities mean see [conventions](conventions.md);
for the choices behind the defaults see [interpretations](interpretations.md).

- Every table rejects keys it does not know (and suggests the nearest known one); a bad value
  gets one line naming the key, the value and what is allowed, and every problem of the file
  is listed at once (up to ten).
- Every number has a physical range (lengths from 1 mm to 1 km, weights from 1 mN to 10⁷ kN,
  a restrainer's forces — yield, anchor capacity, a pretension other than 0 — from 1 N to
  10⁸ N, stiffnesses up to 10¹² N/m…): a value outside it is a slip (of units, of a digit),
  not an element, and is refused.
- *number*: a TOML integer or float, finite (`inf`/`nan` refused); a string or a boolean is
  refused. *integer*: a TOML integer.
- *unit*: SI, as in the file (`-` dimensionless). *default*: what is used when the key is
  absent; `—` means no value, and the description says what rock does then; *required*: the
  key must be given.
- Keys described as "with X" belong together (give both or neither); tables that offer
  alternative forms (e.g. `R` + `alpha` or `thickness` + `height`) accept exactly one.
"""


@dataclass(frozen=True)
class Section:
    """One table of the file (or several paths that share one table class).

    Attributes:
        paths: dotted TOML paths of the table ("" for the top level).
        table: the pydantic model of the table.
        array: True for an array of tables (``[[name]]``).
    """

    paths: tuple[str, ...]
    table: type[BaseModel]
    array: bool

    @property
    def anchor(self) -> str:
        """The HTML id of the section: the path, or the parent path of a shared table."""
        if not self.paths[0]:
            return "top-level"
        path = self.paths[0] if len(self.paths) == 1 else self.paths[0].rsplit(".", 1)[0]
        return path.replace(".", "-").replace("_", "-").lower()

    @property
    def heading(self) -> str:
        """The section heading: the TOML header(s) of the table."""
        if not self.paths[0]:
            return "Top level (keys before any table header)"
        return ", ".join(f"`{_header(p, self.array)}`" for p in self.paths)


def _header(path: str, array: bool) -> str:
    return f"[[{path}]]" if array else f"[{path}]"


def _members(annotation: Any) -> tuple[Any, ...]:
    """The types of an annotation, None left out (``X | None`` → X; ``tuple[X, ...]`` → X)."""
    origin = get_origin(annotation)
    if origin in (Union, types.UnionType):
        return tuple(m for a in get_args(annotation) if a is not type(None) for m in _members(a))
    if origin is tuple:
        return tuple(a for a in get_args(annotation) if a is not Ellipsis)
    return (annotation,)


def table_class(annotation: Any) -> type[BaseModel] | None:
    """The sub-table model of a field's annotation, if the field is a table or array of them."""
    for member in _members(annotation):
        if inspect.isclass(member) and issubclass(member, BaseModel):
            return member
    return None


def is_array(annotation: Any) -> bool:
    """True when a field holds an array of tables (``tuple[Table, ...]``)."""
    members = [annotation, *get_args(annotation)]
    return any(get_origin(m) is tuple for m in members)


def _scalar_keys(table: type[BaseModel]) -> list[str]:
    return [k for k, f in table.model_fields.items() if table_class(f.annotation) is None]


def sections(root: type[BaseModel] = Model) -> list[Section]:
    """Every table of the file in reading order, depth first.

    A table made only of sub-tables of one class (``[ntc.demand]``: SLO, SLD, SLV, SLC) gets
    no section of its own; its sub-tables share one section listing all their paths.
    """
    out: list[Section] = []
    _collect(root, ("",), False, out)
    return out


def _collect(
    table: type[BaseModel], paths: tuple[str, ...], array: bool, out: list[Section]
) -> None:
    if _scalar_keys(table) or not paths[0]:
        out.append(Section(paths, table, array))
    children: dict[type[BaseModel], list[tuple[str, bool]]] = {}
    for key, info in table.model_fields.items():
        sub = table_class(info.annotation)
        if sub is not None:
            children.setdefault(sub, []).append((key, is_array(info.annotation)))
    for sub, keys in children.items():
        child_paths = tuple(f"{p}.{k}" if p else k for p in paths for k, _ in keys)
        _collect(sub, child_paths, keys[0][1], out)


def split_unit(description: str | None) -> tuple[str, str]:
    """(text, unit) of a field description ending in ``[unit]``; unit "" when there is none."""
    text = description or ""
    match = _UNIT.search(text)
    if match is None:
        return text.strip(), ""
    return text[: match.start()].strip(), match["unit"]


def bounds(info: FieldInfo) -> dict[str, float]:
    """The numeric bounds of a field by name (gt, ge, lt, le), from its metadata."""
    found: dict[str, float] = {}
    for item in info.metadata:
        for kind, name in _BOUNDS:
            if isinstance(item, kind):
                found[name] = getattr(item, name)
    return found


def _number(x: Any) -> str:
    if isinstance(x, float) and math.isclose(x, math.pi / 2):
        return "π/2"
    return f"{x:g}" if isinstance(x, float) else str(x)


def bounds_text(info: FieldInfo) -> str:
    """``> 0``, ``≥ 0``, ``in (0, π/2)``, ``in [0, 1]``… ("" without bounds)."""
    b = bounds(info)
    low = ("(", b["gt"]) if "gt" in b else ("[", b["ge"]) if "ge" in b else None
    high = (")", b["lt"]) if "lt" in b else ("]", b["le"]) if "le" in b else None
    if low and high:
        return f"in {low[0]}{_number(low[1])}, {_number(high[1])}{high[0]}"
    if low:
        return f"{'>' if low[0] == '(' else '≥'} {_number(low[1])}"
    if high:
        return f"{'<' if high[0] == ')' else '≤'} {_number(high[1])}"
    return ""


def _min_length(info: FieldInfo) -> int:
    return max((getattr(m, "min_length", 0) or 0 for m in info.metadata), default=0)


def type_text(info: FieldInfo, anchors: dict[type[BaseModel], str]) -> str:
    """What the key accepts: number/integer with bounds, enum values, boolean, text, table."""
    sub = table_class(info.annotation)
    if sub is not None:
        return _table_type(sub, is_array(info.annotation), anchors)
    member = _members(info.annotation)[0]
    if inspect.isclass(member) and issubclass(member, enum.Enum):
        return "one of " + ", ".join(f'`"{m.value}"`' for m in member)
    if member is bool:
        return "boolean"
    if member is str:
        return "non-empty string" if _min_length(info) > 0 else "string"
    name = {int: "integer", float: "number"}.get(member, getattr(member, "__name__", "value"))
    return f"{name} {bounds_text(info)}".strip()


def _table_type(sub: type[BaseModel], array: bool, anchors: dict[type[BaseModel], str]) -> str:
    kind = "array of tables" if array else "table"
    if sub in anchors:
        return f"{kind}, see [below](#{anchors[sub]})"
    # A table of sub-tables only ([ntc.demand]): point to the section of its members.
    keys = ", ".join(f"`{k}`" for k in sub.model_fields)
    inner = dict.fromkeys(table_class(f.annotation) for f in sub.model_fields.values())
    links = ", ".join(f"[below](#{anchors[c]})" for c in inner if c in anchors)
    return f"{kind} of tables {keys}, see {links}"


def default_text(info: FieldInfo) -> str:
    """The default as it would be written in the file ("required", "—" for no value)."""
    if info.is_required():
        return "required"
    value = info.get_default(call_default_factory=True)
    if value is None:
        return "—"
    if isinstance(value, enum.Enum):
        return f'`"{value.value}"`'
    if isinstance(value, bool):
        return f"`{str(value).lower()}`"
    if isinstance(value, int | float):
        return f"`{_number(value)}`"
    if isinstance(value, str):
        return f'`"{value}"`'
    if isinstance(value, BaseModel):
        return "its defaults"
    if isinstance(value, tuple | list) and not value:
        return "none"
    return f"`{value!r}`"


def _cell(text: str) -> str:
    """Text safe inside a Markdown table cell."""
    return text.replace("\\", "\\\\").replace("|", "\\|").replace("*", "\\*")


def intro(table: type[BaseModel]) -> str:
    """The table's docstring, one paragraph a line, internal spec references left out."""
    doc = inspect.getdoc(table) or ""
    paragraphs = [" ".join(p.split()) for p in doc.split("\n\n") if p.strip()]
    text = _SPEC_TAIL.sub(")", _SPEC_PAREN.sub("", "\n\n".join(paragraphs)))
    return text.replace("*", "\\*")


def rows(table: type[BaseModel], anchors: dict[type[BaseModel], str]) -> list[str]:
    """The Markdown table of a section: key | accepts | unit | default | description."""
    out = [
        "| key | type / allowed values | unit | default | description |",
        "| --- | --- | --- | --- | --- |",
    ]
    for key, info in table.model_fields.items():
        text, unit = split_unit(info.description)
        cells = (f"`{key}`", type_text(info, anchors), unit, default_text(info), text)
        out.append("| " + " | ".join(_cell(c) if i > 1 else c for i, c in enumerate(cells)) + " |")
    return out


def section_text(section: Section, anchors: dict[type[BaseModel], str]) -> str:
    """One section: anchor, heading, the table's docstring, the key table."""
    lines = [f'<a id="{section.anchor}"></a>', "", f"## {section.heading}", ""]
    if section.array:
        lines += ["An array of tables: repeat the block once per item (any number).", ""]
    lines += [intro(section.table), "", *rows(section.table, anchors)]
    return "\n".join(lines)


def model_reference() -> str:
    """The whole model-file reference as Markdown (the content of docs/model-reference.md)."""
    found = sections()
    anchors = {s.table: s.anchor for s in found}
    contents = ["## Tables", ""] + [f"- [{s.heading}](#{s.anchor})" for s in found]
    parts = [PREAMBLE.rstrip(), "\n".join(contents), *(section_text(s, anchors) for s in found)]
    return "\n\n".join(parts) + "\n"


def main() -> None:
    """Write the reference to standard output, UTF-8 whatever the locale."""
    sys.stdout.flush()
    sys.stdout.buffer.write(model_reference().encode("utf-8"))
    sys.stdout.buffer.flush()


if __name__ == "__main__":
    main()
