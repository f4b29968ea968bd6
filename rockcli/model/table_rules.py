"""The either/or rules of the model file, as pydantic errors that name the offending key.

pydantic reports an error of a model validator at the table; these helpers raise a
:class:`~pydantic_core.PydanticCustomError` of type :data:`RULE_ERROR` whose context carries
the key path inside the table, what is allowed and the value found, so that
:func:`rockcli.model.load.translate_error` names ``geometry.thickness`` rather than
``geometry`` (spec/README.md: "one clear message naming the field, the value and what is
allowed").
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from pydantic import Field
from pydantic_core import PydanticCustomError

#: Error type of the either/or rules; its context names the key, what is allowed, the value.
RULE_ERROR = "rock_rule"


def rule_error(
    field: str | Sequence[str | int] | None,
    problem: str,
    allowed: str,
    value: Any = None,
) -> PydanticCustomError:
    """An error of an either/or rule, naming the key (relative to the table it is raised in).

    Args:
        field: key or key path inside the validated table (``None``: the table itself).
        problem: what is wrong (one line, no braces).
        allowed: what would be accepted.
        value: the offending value, if any.
    """
    path = () if field is None else (field,) if isinstance(field, str) else tuple(field)
    return PydanticCustomError(
        RULE_ERROR, problem, {"field": path, "allowed": allowed, "value": value}
    )


def given(values: Mapping[str, Any], keys: Sequence[str]) -> list[str]:
    """The keys among ``keys`` that have a value (not ``None``)."""
    return [k for k in keys if values.get(k) is not None]


def choose_group(
    values: Mapping[str, Any], groups: Sequence[tuple[str, ...]], allowed: str
) -> tuple[str, ...] | None:
    """The one group of keys given together; raise if two groups or part of one are given.

    Returns ``None`` when no key of any group is given (the caller decides if that is allowed).
    """
    present = [g for g in groups if given(values, g)]
    if len(present) > 1:
        first, second = present[0], present[1]
        key = given(values, second)[0]
        raise rule_error(
            key, f"not allowed together with {given(values, first)[0]}", allowed, values[key]
        )
    if not present:
        return None
    missing = [k for k in present[0] if values.get(k) is None]
    if missing:
        raise rule_error(missing[0], f"required with {given(values, present[0])[0]}", allowed)
    return present[0]


def forbid(values: Mapping[str, Any], keys: Sequence[str], problem: str, allowed: str) -> None:
    """Raise on the first of ``keys`` that is given."""
    for key in given(values, keys):
        raise rule_error(key, problem, allowed, values[key])


def number(
    description: str,
    default: Any = None,
    *,
    gt: float | None = None,
    ge: float | None = None,
    lt: float | None = None,
    le: float | None = None,
) -> Any:
    """A finite number field (an int or a float in TOML, never a bool or a string)."""
    return Field(
        default,
        description=description,
        strict=True,
        allow_inf_nan=False,
        gt=gt,
        ge=ge,
        lt=lt,
        le=le,
    )
