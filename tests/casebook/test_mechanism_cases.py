"""The mechanism catalogue's cases (examples/validation/mechanisms.toml) and the kinematic
kind's ``mechanism`` input.

Every case of the file passes under `rock validate --casebook`, the file checks every
mechanism type of the catalogue, no ``mechanism`` reads the governing one (as before), and an
unknown name or a quantity the mechanism has not is one line of bad input (exit 2).
"""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

from rockcli.analyses.kinematic import kinematic_model
from rockcli.casebook.code import catalogue_entry, kinematic_quantity
from rockcli.casebook.load import load_case_file
from rockcli.casebook.schema import KinematicInput
from rockcli.cli.main import cli
from rockcli.model.load import load_model
from rockcli.model.wall_tables import MechanismKind
from tests.casebook.conftest import CASEBOOK, write_casebook

CASE_FILE = CASEBOOK / "mechanisms.toml"
TWO_STOREY = CASEBOOK / "models" / "mech-two-storey.toml"

#: A kinematic case on the two-storey model, its mechanism and quantity to fill in.
CASE = f"""\
[[cases]]
id = "t.mechanism"
title = "a mechanism of the catalogue"
kind = "kinematic"
quantity = "{{quantity}}"
expected = 0.1
tolerance = 1e-12
tolerance_type = "relative"
tolerance_reason = "closed form, to rounding"
source = "closed form: Circolare 617/2009 §C8A.4.1"
model = "{TWO_STOREY.as_posix()}"
[cases.input]
mechanism = "{{mechanism}}"
"""


def invoke(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["validate", *args])
    return result.exit_code, result.stdout, result.stderr


def alone(tmp_path: Path) -> Path:
    """A casebook of mechanisms.toml alone, its model paths made absolute."""
    text = CASE_FILE.read_text(encoding="utf-8")
    text = text.replace('model = "models/', f'model = "{(CASEBOOK / "models").as_posix()}/')
    return write_casebook(tmp_path / "book", text, "mechanisms.toml")


def test_mechanism_cases_pass(tmp_path: Path) -> None:
    code, out, err = invoke("--casebook", str(alone(tmp_path)), "--format", "json")
    assert code == 0, out + err
    doc = json.loads(out)
    assert doc["failed"] == 0 and doc["skipped"] == 0
    assert doc["passed"] == len(doc["cases"]) >= 4
    assert all(case["id"].startswith("mechanism.") for case in doc["cases"])


def test_every_mechanism_type_has_a_case() -> None:
    types = set()
    for loaded in load_case_file(CASE_FILE):
        if loaded.case.kind != "kinematic":  # the rocking of a rigid mechanism (issue 22)
            continue
        assert loaded.model is not None and isinstance(loaded.input, KinematicInput)
        result = kinematic_model(loaded.model, edition=loaded.input.edition)
        types.add(catalogue_entry(result, loaded.input.mechanism).type)
    assert types == {kind.value for kind in MechanismKind}


def test_no_mechanism_reads_the_governing_one() -> None:
    model = load_model(TWO_STOREY)
    result = kinematic_model(model)
    assert result.catalogue[0].name == result.governing
    assert kinematic_quantity(model, KinematicInput(), "alpha0") == result.alpha0
    named = KinematicInput(mechanism=result.governing)
    assert kinematic_quantity(model, named, "M_star") == result.catalogue[0].M_star


def test_unknown_mechanism_is_one_line_of_bad_input(tmp_path: Path) -> None:
    text = CASE.format(quantity="alpha0", mechanism="overturning, storey 3")
    code, out, err = invoke("--casebook", str(write_casebook(tmp_path / "book", text)))
    assert code == 2, out + err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    assert "input.mechanism" in lines[0] and "no such mechanism" in lines[0]
    assert "overturning, storey 3" in lines[0] and "t.mechanism" in lines[0]
    assert "'overturning, whole wall'" in lines[0] and "'overturning, storey 2'" in lines[0]
    assert "Traceback" not in err + out


def test_instability_of_an_overturning_is_bad_input(tmp_path: Path) -> None:
    text = CASE.format(quantity="instability_displacement", mechanism="overturning, storey 2")
    code, out, err = invoke("--casebook", str(write_casebook(tmp_path / "book", text)))
    assert code == 2, out + err
    assert err.count("\n") == 1 and "a quantity of a vertical flexure only" in err


def test_empty_mechanism_name_is_refused(tmp_path: Path) -> None:
    text = CASE.format(quantity="alpha0", mechanism="")
    code, _, err = invoke("--casebook", str(write_casebook(tmp_path / "book", text)))
    assert code == 2 and "cases[0].input.mechanism" in err
