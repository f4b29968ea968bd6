"""Fuzz of the case-file reader: mutated bundled case files load, or fail with an InputError.

Each bundled case file is parsed, one to three values or keys are mutated (a number set to an
edge of double precision or a wrong type, a key deleted or renamed, a value turned into a table
or an array), written back with tomli-w and loaded; the cases of the cheap kinds that load are
also run. Anything but a loaded case or an InputError is a bug (the CLI would print an internal
error). Bounded: 120 examples (a few seconds), like tests/unit/test_model_fuzz.py.
"""

from __future__ import annotations

import copy
import math
import tomllib
from typing import Any

import pytest
import tomli_w
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rockcli.casebook.load import load_case_file
from rockcli.casebook.run import run_case
from rockcli.errors import InputError
from tests.casebook.conftest import CASEBOOK

#: The kinds cheap enough to run on every example (no bisection, no long record).
CHEAP_KINDS = {"model", "kinematic", "spectrum"}
REPLACEMENTS: list[Any] = [
    0, 0.0, -1, -1.0, 1e300, -1e300, 1e-300, 5e-324, math.nan, math.inf, -math.inf,
    2**63 - 1, "0.5", "", "oracle", True, {}, [], [1.0], [2.0, 1.0], {"x": 1},
]  # fmt: skip


def absolute_models(data: dict[str, Any]) -> dict[str, Any]:
    """The case file with its model paths made absolute (the copy is written elsewhere)."""
    for case in data.get("cases", []):
        if isinstance(case.get("model"), str):
            case["model"] = str(CASEBOOK / case["model"])
    return data


BASES = [absolute_models(tomllib.loads(p.read_text(encoding="utf-8")))
         for p in sorted(CASEBOOK.glob("*.toml"))]  # fmt: skip


def paths(node: Any, prefix: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every key or index path in a nested table."""
    found: list[tuple[Any, ...]] = []
    if isinstance(node, dict):
        items = list(node.items())
    elif isinstance(node, list):
        items = list(enumerate(node))
    else:
        items = []
    for key, value in items:
        found.append((*prefix, key))
        found.extend(paths(value, (*prefix, key)))
    return found


def mutate(data: dict[str, Any], path: tuple[Any, ...], how: int, value: Any) -> None:
    parent = data
    for key in path[:-1]:
        parent = parent[key]
    key = path[-1]
    if how == 0 or isinstance(parent, list):
        # A copy: the same table or array put twice could end up inside itself (a later
        # mutation's path runs through it), which no TOML file can say.
        parent[key] = copy.deepcopy(value)
    elif how == 1:
        del parent[key]
    else:
        parent[f"{key}x"] = parent.pop(key)


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_mutated_case_files_load_or_raise_input_error(
    tmp_path_factory: pytest.TempPathFactory, data: st.DataObject
) -> None:
    base = copy.deepcopy(data.draw(st.sampled_from(BASES)))
    for _ in range(data.draw(st.integers(1, 3))):
        candidates = paths(base)
        if not candidates:
            break
        path = data.draw(st.sampled_from(candidates))
        mutate(base, path, data.draw(st.integers(0, 2)), data.draw(st.sampled_from(REPLACEMENTS)))
    try:
        text = tomli_w.dumps(base)
    except (TypeError, ValueError):
        return  # not representable in TOML (a nan key path, …): nothing to read
    file = tmp_path_factory.mktemp("fuzz") / "cases.toml"
    file.write_text(text, encoding="utf-8")
    try:
        cases = load_case_file(file)
    except InputError as exc:
        assert str(file) in str(exc)
        return
    for loaded in cases:
        if loaded.case.kind.value in CHEAP_KINDS:
            try:
                run_case(loaded, None)
            except InputError:
                pass


def number_leaves(node: Any, prefix: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """The key paths of every number (int or float, not a boolean) in a nested table."""
    if isinstance(node, dict):
        items: list[tuple[Any, Any]] = list(node.items())
    elif isinstance(node, list):
        items = list(enumerate(node))
    else:
        return [prefix] if isinstance(node, int | float) and not isinstance(node, bool) else []
    return [leaf for key, value in items for leaf in number_leaves(value, (*prefix, key))]


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_a_number_written_as_text_is_refused(
    tmp_path_factory: pytest.TempPathFactory, data: st.DataObject
) -> None:
    """Any number of a bundled case (its expected value, tolerance, an input; not the inline
    models, which the model schema reads) quoted as text: an InputError naming the file and
    that field, never the number read from the text (pydantic's lax mode did that)."""
    base = copy.deepcopy(data.draw(st.sampled_from(BASES)))
    leaves = [p for p in number_leaves(base) if "model" not in p]
    path = data.draw(st.sampled_from(leaves))
    parent = base
    for key in path[:-1]:
        parent = parent[key]
    text = parent[path[-1]] = str(parent[path[-1]])
    file = tmp_path_factory.mktemp("text") / "cases.toml"
    file.write_text(tomli_w.dumps(base), encoding="utf-8")
    with pytest.raises(InputError) as info:
        load_case_file(file)
    where = "".join(f"[{k}]" if isinstance(k, int) else f".{k}" for k in path).lstrip(".")
    assert info.value.file == str(file) and info.value.where == where, str(info.value)
    assert info.value.value == text  # "not a number", "not a whole number", "should be 1 or -1"
