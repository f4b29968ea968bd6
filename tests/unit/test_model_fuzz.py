"""Fuzz of the model loader: mutated example models give a Model or an InputError, nothing else.

Each example is parsed, one to three values or keys are mutated (a number set to 0, −1,
±1e300, 1e−300, nan, inf; a value turned into text, a boolean, a table or an array; a key
deleted, renamed, or copied into another table; a value nested deep), written back with
tomli-w and loaded. A model that loads must derive a finite block (the engine's input) and its
warnings; an error must be InputError lines naming the file. Bounded: 150 examples per test
(a few seconds). Issue 7, items 9 and 16.
"""

from __future__ import annotations

import copy
import math
import tomllib
from pathlib import Path
from typing import Any

import tomli_w
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rockcli.errors import InputError
from rockcli.model.derive import derive_block, describe
from rockcli.model.derived_checks import check_block
from rockcli.model.load import MAX_ERRORS, load_model
from rockcli.model.plausible import model_warnings
from rockcli.model.template import TEMPLATES

ROOT = Path(__file__).resolve().parents[2]
BASES = [tomllib.loads(p.read_text(encoding="utf-8")) for p in sorted(ROOT.glob("examples/*.toml"))]
BASES += [copy.deepcopy(t) for t in TEMPLATES.values()]

#: Values a number or a key may be replaced with: edges of double precision, wrong types.
REPLACEMENTS: list[Any] = [
    0,
    0.0,
    -1,
    -1.0,
    1e300,
    -1e300,
    1e-300,
    5e-324,
    1.7e308,
    math.nan,
    math.inf,
    -math.inf,
    2**63 - 1,
    "0.5",
    "",
    True,
    {},
    [],
    [1.0],
    {"x": 1},
]

Path_ = tuple[str | int, ...]


def paths(data: Any, prefix: Path_ = ()) -> list[Path_]:
    """Every key path of a parsed TOML document (tables and arrays walked)."""
    found: list[Path_] = []
    items = data.items() if isinstance(data, dict) else enumerate(data)
    for key, value in items:
        found.append((*prefix, key))
        if isinstance(value, dict | list):
            found += paths(value, (*prefix, key))
    return found


def parent(data: Any, path: Path_) -> Any:
    for key in path[:-1]:
        data = data[key]
    return data


def mutate(data: dict[str, Any], path: Path_, how: int, value: Any) -> None:
    """Apply mutation ``how`` at ``path``: replace, delete, rename, copy up, nest deep."""
    holder, key = parent(data, path), path[-1]
    if how == 0 or isinstance(holder, list):
        holder[key] = copy.deepcopy(value)
    elif how == 1:
        del holder[key]
    elif how == 2:
        holder[f"{key}x"[1:] or "x"] = holder.pop(key)
    elif how == 3:
        data[str(key)] = copy.deepcopy(holder[key])
    else:
        nested: Any = holder[key]
        for _ in range(60):
            nested = [nested]
        holder[key] = nested


@st.composite
def mutated(draw: st.DrawFn) -> dict[str, Any]:
    data = copy.deepcopy(draw(st.sampled_from(BASES)))
    for _ in range(draw(st.integers(1, 3))):
        every = paths(data)
        if not every:
            break
        mutate(
            data,
            draw(st.sampled_from(every)),
            draw(st.integers(0, 4)),
            draw(st.sampled_from(REPLACEMENTS)),
        )
    return data


def check_load(path: Path) -> None:
    """Load a file: a model whose block is finite, or InputError lines naming the file."""
    try:
        model = load_model(path)
    except InputError as exc:
        lines = getattr(exc, "lines", None) or (str(exc),)
        assert 1 <= len(lines) <= MAX_ERRORS + 1
        assert all(line.startswith(f"{path}: ") and "\n" not in line for line in lines), lines
        return
    check_block(derive_block(model))
    describe(model)
    assert all(isinstance(w, str) for w in model_warnings(model))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated())
def test_mutated_model_loads_or_is_refused(tmp_path_factory: Any, data: dict[str, Any]) -> None:
    path = tmp_path_factory.mktemp("fuzz") / "m.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    check_load(path)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(sorted(ROOT.glob("examples/*.toml"))), st.data())
def test_damaged_model_text_loads_or_is_refused(
    tmp_path_factory: Any, example: Path, data: st.DataObject
) -> None:
    # Byte-level damage: a cut, a deleted span, a repeated span, a stray character.
    raw = example.read_bytes()
    at = data.draw(st.integers(0, len(raw)))
    span = data.draw(st.integers(0, 40))
    edit = data.draw(st.sampled_from(["cut", "delete", "repeat", "insert"]))
    stray = data.draw(st.sampled_from([b"[", b"]", b"=", b'"', b"\n", b"\xff", b"{", b"#", b"."]))
    damaged = {
        "cut": raw[:at],
        "delete": raw[:at] + raw[at + span :],
        "repeat": raw[:at] + raw[at : at + span] * 2 + raw[at + span :],
        "insert": raw[:at] + stray + raw[at:],
    }[edit]
    path = tmp_path_factory.mktemp("fuzz") / "m.toml"
    path.write_bytes(damaged)
    check_load(path)
