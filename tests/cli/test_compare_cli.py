"""`rock compare`: the side-by-side table, the classification, the JSON contract (issue #4)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.analyses.compare import Classification, classify, code_sets_demand
from rockcli.cli.compare import CLASSIFICATIONS
from rockcli.cli.main import cli
from rockcli.model.load import load_model
from rockcli.terminal.compare import DIFFERENT_EARTHQUAKES
from tests.cli.conftest import PULSES, ROOT

ALTAR = ROOT / "examples" / "altar.toml"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


def demand_source(doc: dict, state: str) -> str:
    """Where the kinematic document's demand of a limit state comes from: "record NAME" for a
    record's spectrum, else the code spectrum's source ("[ntc.demand.SLV]", a site)."""
    demand = doc["kinematic"]["demand"][state]
    return f"record {demand['record']}" if "record" in demand else demand["source"]


@pytest.mark.parametrize(
    ("code", "rocking", "expected"),
    [
        (False, False, Classification.CONSISTENT_SAFE),
        (True, True, Classification.CONSISTENT_UNSAFE),
        (True, False, Classification.CODE_CONSERVATIVE),
        (False, True, Classification.CODE_UNCONSERVATIVE),
        (None, True, Classification.UNDETERMINED),
        (True, None, Classification.UNDETERMINED),
    ],
)
def test_classification_table(
    code: bool | None, rocking: bool | None, expected: Classification
) -> None:
    # Issue #4: code fails & rocking survives = code-conservative (the paper's §3.3
    # inconsistency), code passes & rocking overturns = code-unconservative.
    assert classify(code, rocking) is expected


def test_code_demand_detection() -> None:
    assert code_sets_demand(load_model(ALTAR))  # [ntc.demand.*] in the altar example
    assert not code_sets_demand(load_model(ROOT / "examples" / "wall.toml"))


def test_altar_elc180_side_by_side(shared_records: Path) -> None:
    # Issue #4 "Done when": the side-by-side table and the classification.
    code, out, err = run("compare", str(ALTAR), "--record", str(shared_records / "ELC180.AT2"))
    assert code == 0, err
    for word in (
        "activation",
        "collapse",
        "amplitude",
        "classification",
        "code (NTC kinematic)",
        "rocking (time history)",
    ):
        assert word in out
    assert any(c.value in out for c in Classification)


def test_json_reuses_both_schemas(shared_records: Path) -> None:
    code, out, err = run(
        "compare", str(ALTAR), "--record", str(shared_records / "ELC180.AT2"), "--format", "json"
    )
    assert code == 0, err
    doc = json.loads(out)
    assert {"kinematic", "rocking", "classification", "activation", "collapse"} <= set(doc)
    assert doc["kinematic"]["schema"] == 1 and "checks" in doc["kinematic"]
    assert doc["rocking"]["schema"] == 1 and len(doc["rocking"]["runs"]) == 2
    # The classification follows from the two verdicts it reports.
    code_collapse = doc["kinematic"]["verdict"]["ULS"] is False
    rocking_collapse = doc["rocking"]["verdict"] == "overturns"
    assert doc["classification"] == classify(code_collapse, rocking_collapse).value


def test_record_demand_when_the_model_sets_none(tmp_path: Path) -> None:
    # spec/README.md: the record's own response spectrum is the code demand unless the model
    # sets a code spectrum.
    code, out, err = run(
        "compare",
        str(ROOT / "examples" / "wall.toml"),
        "--record",
        str(PULSES[0]),
        "--format",
        "json",
    )
    assert code == 0, err
    doc = json.loads(out)
    assert doc["kinematic"]["demand"]["SLV"]["record"] == PULSES[0].stem


def test_the_record_is_both_sides_earthquake_by_default(shared_records: Path) -> None:
    # Issue #8 item 4: one earthquake on both sides. The altar sets [ntc.demand], yet the code
    # check sees the record's response spectrum, and the verdict line says nothing more.
    args = ("compare", str(ALTAR), "--record", str(shared_records / "ELC180.AT2"))
    code, out, err = run(*args, "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["code_demand"] == "record"
    for state in ("SLD", "SLV"):
        assert demand_source(doc, state).startswith("record ELC180")
    assert DIFFERENT_EARTHQUAKES not in doc["warnings"]
    code, out, err = run(*args)
    assert code == 0, err
    assert f"verdict: {doc['classification']}\n" in out


def test_code_demand_model_uses_the_models_spectrum_and_says_so(shared_records: Path) -> None:
    args = ("compare", str(ALTAR), "--record", str(shared_records / "ELC180.AT2"))
    code, out, err = run(*args, "--code-demand", "model", "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["code_demand"] == "model"
    for state in ("SLD", "SLV"):
        assert demand_source(doc, state) == f"[ntc.demand.{state}]"
    assert doc["warnings"][0] == DIFFERENT_EARTHQUAKES
    assert DIFFERENT_EARTHQUAKES == (
        "the code check used the model's spectrum, not the record: "
        "the two sides see different earthquakes"
    )
    # The classification stays the bare word (--fail-on compares it); the verdict line says
    # the two sides saw different earthquakes, once (not repeated as a warning).
    assert doc["classification"] in CLASSIFICATIONS
    code, out, err = run(*args, "--code-demand", "model")
    assert code == 0, err
    assert f"verdict: {doc['classification']} — {DIFFERENT_EARTHQUAKES}" in " ".join(out.split())
    assert " ".join(out.split()).count(DIFFERENT_EARTHQUAKES) == 1


def test_code_demand_model_on_a_model_without_a_code_spectrum_is_refused() -> None:
    wall = str(ROOT / "examples" / "wall.toml")
    code, out, err = run("compare", wall, "--record", str(PULSES[0]), "--code-demand", "model")
    assert code == 2 and out == ""
    assert err == (
        f"error: {wall}: --code-demand: the model sets no code spectrum ([ntc.demand] or "
        '[ntc.site]) (got \'model\'; allowed: "record" (the default), or "model" with a model '
        "that sets [ntc.demand] or [ntc.site])\n"
    )


def test_the_old_record_demand_flag_is_refused() -> None:
    # 0.x: no silent alias. The record's spectrum is the default now.
    code, out, err = run("compare", str(ALTAR), "--record", str(PULSES[0]), "--record-demand")
    assert code == 2 and out == ""
    assert err == (
        "error: --record-demand: removed: the record's spectrum is the code demand by default "
        "now (allowed: drop --record-demand (--code-demand model uses the model's spectrum))\n"
    )


def test_the_code_demand_choices_are_the_studies() -> None:
    from rockcli.analyses.compare import CodeDemand
    from rockcli.cli.compare import RECORD_DEMANDS, SUITE_DEMANDS
    from rockcli.studies.suite_run.compare import SuiteCodeDemand

    assert RECORD_DEMANDS == tuple(c.value for c in CodeDemand)
    assert SUITE_DEMANDS == tuple(c.value for c in SuiteCodeDemand)


def test_bad_record_is_one_error_line(tmp_path: Path) -> None:
    code, _, err = run("compare", str(ALTAR), "--record", str(tmp_path / "none.AT2"))
    assert code == 2 and err.startswith("error: ") and "none.AT2" in err


def test_fail_on_classification_exit_code(tmp_path: Path) -> None:
    # spec/README.md: a non-zero exit only when asked for, so CI can gate on verdicts.
    from rockcli.cli.compare import CLASSIFICATIONS

    assert set(CLASSIFICATIONS) == {c.value for c in Classification}
    args = [
        "compare",
        str(ROOT / "examples" / "wall.toml"),
        "--record",
        str(PULSES[0]),
        "--format",
        "json",
    ]
    code, out, _ = run(*args)
    assert code == 0
    got = json.loads(out)["classification"]
    other = next(c for c in CLASSIFICATIONS if c != got)
    assert run(*args, "--fail-on", other)[0] == 0
    assert run(*args, "--fail-on", other, "--fail-on", got)[0] == 1
