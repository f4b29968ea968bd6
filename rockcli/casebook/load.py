"""Read and validate the case files of a casebook folder, at the edge.

Every problem is one :class:`~rockcli.errors.InputError` naming the file, the field
(``cases[2].tolerance``), the value and what is allowed.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import ValidationError
from pydantic_core import ErrorDetails

from rockcli.casebook.schema import (
    INPUTS,
    NEEDS_MODEL,
    QUANTITIES,
    Case,
    CaseFile,
    Table,
    ToleranceType,
)
from rockcli.errors import InputError
from rockcli.model.load import TRANSLATION, load_model, read_toml, validate_model
from rockcli.model.schema import Model
from rockcli.suites.load import dotted

#: The bundled casebook's place in a source checkout.
BUNDLED_PATH = Path("examples") / "validation"
#: Where the bundled casebook is looked for: in the installed package (setup.py copies it to
#: rockcli/casebook/bundled when it builds the package), then in the source checkout the
#: package runs from (an editable install).
BUNDLED = (
    Path(__file__).resolve().parent / "bundled" / "validation",
    Path(__file__).resolve().parents[2] / BUNDLED_PATH,
)
#: Longest text value quoted back in an error line [characters].
MAX_QUOTED = 60


@dataclass(frozen=True)
class LoadedCase:
    """A validated case: the case, its kind's input, its model (if any) and its file."""

    case: Case
    input: Table
    model: Model | None
    file: str


def casebook_folder(folder: str | Path | None) -> Path:
    """The folder to read: the given one, else the bundled casebook (InputError if absent)."""
    if folder is None:
        found = next((path for path in BUNDLED if path.is_dir()), None)
        if found is None:
            raise InputError(
                "the bundled casebook is not installed with this rock",
                where="casebook",
                value=str(BUNDLED[0]),
                allowed="reinstall rock (pip install .), or --casebook DIR",
            )
        return found
    path = Path(folder)
    if not path.is_dir():
        raise InputError(
            "not a folder of case files",
            where="--casebook",
            value=str(path),
            allowed="a folder of *.toml case files",
        )
    return path


def load_casebook(folder: str | Path | None = None) -> list[LoadedCase]:
    """Every case of every ``*.toml`` in the folder (not its subfolders), files in name order.

    Raises:
        InputError: no case file, a malformed file or case, a repeated id.
    """
    path = casebook_folder(folder)
    files = sorted(path.glob("*.toml"))
    if not files:
        raise InputError(
            "no case files", where="casebook", value=str(path), allowed="one or more *.toml"
        )
    cases = [case for file in files for case in load_case_file(file)]
    check_unique(cases)
    return cases


def load_case_file(path: str | Path) -> list[LoadedCase]:
    """The cases of one file, each validated with its kind's input and its model."""
    file = str(path)
    data = validate_table(CaseFile, read_toml(file), file, "")
    assert isinstance(data, CaseFile)
    return [load_case(case, i, file) for i, case in enumerate(data.cases)]


def load_case(case: Case, index: int, file: str) -> LoadedCase:
    """One case: its quantity, input and model checked against its kind."""
    where = f"cases[{index}]"
    quantities = QUANTITIES[case.kind]
    if case.quantity not in quantities:
        raise InputError(
            f"not a quantity of kind {case.kind.value!r}",
            file=file,
            where=f"{where}.quantity",
            value=case.quantity,
            allowed="one of " + ", ".join(quantities),
        )
    if case.tolerance_type is ToleranceType.RELATIVE and case.expected == 0:
        raise InputError(
            "a relative tolerance of an expected 0 measures nothing",
            file=file,
            where=f"{where}.tolerance_type",
            value=case.tolerance_type.value,
            allowed="absolute when expected = 0",
        )
    model = case_model(case, file, where)
    inputs = validate_table(INPUTS[case.kind], case.input, file, f"{where}.input")
    check_bracket(inputs, file, f"{where}.input.bracket")
    return LoadedCase(case, inputs, model, file)


def case_model(case: Case, file: str, where: str) -> Model | None:
    """The case's model: a file beside the case file, or an inline table; None if unused."""
    needed = case.kind in NEEDS_MODEL
    if case.model is None and needed:
        raise InputError(
            f"kind {case.kind.value!r} needs a model",
            file=file,
            where=f"{where}.model",
            allowed="a model file path (relative to the case file) or an inline model table",
        )
    if case.model is not None and not needed:
        raise InputError(
            f"kind {case.kind.value!r} takes no model",
            file=file,
            where=f"{where}.model",
            allowed="no model key for this kind",
        )
    if case.model is None:
        return None
    if isinstance(case.model, str):
        path = Path(file).parent / case.model
        if not path.is_file():
            raise InputError(
                "no such model file",
                file=file,
                where=f"{where}.model",
                value=case.model,
                allowed="a model file path relative to the case file, or an inline model table",
            )
        return load_model(path)
    return validate_model(case.model, file=f"{file} {where}.model")


def validate_table(schema: type[Table], data: Mapping[str, Any], file: str, where: str) -> Table:
    """``schema.model_validate(data)``, the first problem as an InputError."""
    try:
        return schema.model_validate(data)
    except ValidationError as exc:
        # An unknown key first: a misspelt key also shows as the right one missing.
        errors = sorted(exc.errors(), key=lambda err: err["type"] != "extra_forbidden")
        raise translate(errors[0], file, where, keys_of(schema, errors[0]["loc"])) from None


def keys_of(schema: type[Table], loc: tuple[int | str, ...]) -> str:
    """The keys allowed where an unknown key was found (a case's, or the schema's own)."""
    table = Case if schema is CaseFile and len(loc) > 1 else schema
    return ", ".join(table.model_fields)


def translate(err: ErrorDetails, file: str, prefix: str, keys: str = "") -> InputError:
    """One pydantic error as one InputError, the field path after ``prefix``."""
    problem, _ = TRANSLATION.get(err["type"], (None, None))
    ctx = err.get("ctx", {})
    limits = (("gt", ">"), ("ge", ">="), ("lt", "<"), ("le", "<="))
    bounds = " and ".join(f"{symbol} {ctx[key]}" for key, symbol in limits if key in ctx)
    value = None if err["type"] == "missing" else err.get("input")
    if isinstance(value, str) and len(value) > MAX_QUOTED:
        value = value[:MAX_QUOTED] + "…"
    path = dotted(err["loc"])
    where = ".".join(p for p in (prefix, path) if p) or None
    return InputError(
        problem or " ".join(err["msg"].split()),
        file=file,
        where=where,
        value=value if isinstance(value, int | float | str) else None,
        allowed=f"a number {bounds}" if bounds else _allowed(err, keys),
    )


def _allowed(err: ErrorDetails, keys: str) -> str | None:
    ctx = err.get("ctx", {})
    if "expected" in ctx:
        return f"one of: {ctx['expected']}"
    if "pattern" in ctx:
        return "letters, digits, '.', '_' and '-', starting with a letter or digit"
    if err["type"] == "extra_forbidden":
        return f"the keys {keys}" if keys else None
    if err["type"] == "missing":
        return "required"
    if err["type"].startswith(("float", "int", "finite")):
        return "a number"
    return None


def check_bracket(inputs: Table, file: str, where: str) -> None:
    """A bisection bracket must be [lo, hi] with lo < hi."""
    bracket = getattr(inputs, "bracket", None)
    if bracket is not None and not bracket[0] < bracket[1]:
        raise InputError(
            "the bracket's ends are not in order",
            file=file,
            where=where,
            value=list(bracket),
            allowed="[lo, hi] with lo < hi",
        )


def check_unique(cases: Sequence[LoadedCase]) -> None:
    """Every id once in the casebook."""
    seen: dict[str, str] = {}
    for loaded in cases:
        case_id = loaded.case.id
        if case_id in seen:
            raise InputError(
                f"repeated case id (first in {seen[case_id]})",
                file=loaded.file,
                where="id",
                value=case_id,
                allowed="a unique id per case",
            )
        seen[case_id] = loaded.file
