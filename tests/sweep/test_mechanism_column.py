"""A study of a wall: each case rocks and checks one mechanism of its catalogue, named in a
``mechanism`` column (issue 22, contract); a study of a block writes the header it always did.

The two-storey façade (examples/two-storey-facade.toml) under the shipped Ricker pulse, with
the gable's height as the axis: the code check on the record's spectrum governs, and the case
rocks the governing mechanism when the time history rocks it (`rock compare`'s rule), so the
classification compares one mechanism on both sides.
"""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.studies.sweep.output import RESULT_COLUMNS
from tests.cli.conftest import ROOT
from tests.sweep.conftest import PULSES

STUDY = """\
name = "the façade's gable"
base = "facade.toml"
analyses = ["rocking", "kinematic"]
records_dir = "records"

[[axes]]
path = "geometry.gable_height"
name = "gable"
values = [2.5, 3.0]

[[records]]
name = "ricker"
path = "ricker_Tp0.5s_0.5g.txt"
"""


def test_a_wall_study_names_the_mechanism_of_each_case(tmp_path: Path) -> None:
    records = tmp_path / "records"
    records.mkdir()
    shutil.copy(PULSES / "ricker_Tp0.5s_0.5g.txt", records)
    shutil.copy(ROOT / "examples" / "two-storey-facade.toml", tmp_path / "facade.toml")
    (tmp_path / "study.toml").write_text(STUDY, encoding="utf-8")
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["sweep", str(tmp_path / "study.toml"), "--out", str(out)])
    assert result.exit_code == 0, result.stderr
    with (out / "cases.csv").open(encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 2 and all(not row["error"] for row in rows)
    for row in rows:
        assert row["mechanism"]  # the column exists and names a mechanism
        # The same mechanism `rock compare` shows for this case (the façade with this gable).
        model = (tmp_path / "facade.toml").read_text(encoding="utf-8")
        case = tmp_path / f"case-{row['case']}.toml"
        case.write_text(model.replace("gable_height = 2.5", f"gable_height = {row['gable']}"),
                        encoding="utf-8")  # fmt: skip
        done = CliRunner().invoke(cli, ["compare", str(case), "--record",
                                        str(records / "ricker_Tp0.5s_0.5g.txt"),
                                        "--format", "json"])  # fmt: skip
        assert done.exit_code == 0, done.stderr
        doc = json.loads(done.stdout)
        assert row["mechanism"] == doc["kinematic"]["mechanism"]
        assert row["classification"] == doc["classification"]
        # The envelope of both polarities, as the sweep writes it.
        assert float(row["max_ratio"]) == max(r["max_ratio"] for r in doc["rocking"]["runs"])


def test_a_block_study_keeps_its_header() -> None:
    # The header of a study of a block is the one it always had: no mechanism column.
    from rockcli.studies.sweep.output import MECHANISM_COLUMNS

    assert "mechanism" not in RESULT_COLUMNS and "mechanism" in MECHANISM_COLUMNS


#: A one-storey wall whose only mechanism is its vertical flexure, the hinge's height an axis.
FLEXURE_WALL = """\
name = "wall in flexure"
kind = "wall"
[geometry]
width = 1.0
[[geometry.storeys]]
height = 4.0
thickness = 0.25
[mass]
unit_weight = 18.0
[[loads]]
name = "floor"
weight = 2.0
height = 4.0
moves = false
[[mechanisms]]
type = "vertical-flexure"
storey = 1
hinge_height = 2.0
"""

FLEXURE_STUDY = """\
name = "the hinge of a flexure"
base = "wall.toml"
analyses = ["rocking", "kinematic"]
records_dir = "records"

[[axes]]
path = "mechanisms[0].hinge_height"
name = "hinge"
values = [1.5, 2.5]

[[records]]
name = "ricker"
path = "ricker_Tp0.5s_0.5g.txt"
"""


def test_a_study_varies_a_flexures_hinge_and_rocks_its_chain(tmp_path: Path) -> None:
    # An axis on a mechanism key: each case rocks the two-block chain at its own hinge, and
    # its uplift-side numbers are that case's (the same as `rock assess` on the case's file).
    records = tmp_path / "records"
    records.mkdir()
    shutil.copy(PULSES / "ricker_Tp0.5s_0.5g.txt", records)
    (tmp_path / "wall.toml").write_text(FLEXURE_WALL, encoding="utf-8")
    (tmp_path / "study.toml").write_text(FLEXURE_STUDY, encoding="utf-8")
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["sweep", str(tmp_path / "study.toml"), "--out", str(out)])
    assert result.exit_code == 0, result.stderr
    with (out / "cases.csv").open(encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 2 and all(not row["error"] for row in rows)
    ratios = []
    for row in rows:
        assert row["mechanism"] == "vertical flexure, storey 1"
        case = tmp_path / f"case-{row['case']}.toml"
        case.write_text(FLEXURE_WALL.replace("hinge_height = 2.0",
                                             f"hinge_height = {row['hinge']}"),
                        encoding="utf-8")  # fmt: skip
        done = CliRunner().invoke(cli, ["assess", str(case), "--record",
                                        str(records / "ricker_Tp0.5s_0.5g.txt"),
                                        "--format", "json"])  # fmt: skip
        assert done.exit_code == 0, done.stderr
        doc = json.loads(done.stdout)
        assert doc["mechanism"]["type"] == "vertical-flexure"
        assert float(row["max_ratio"]) == max(r["max_ratio"] for r in doc["runs"])
        ratios.append(float(row["max_ratio"]))
    assert ratios[0] != ratios[1]  # the hinge's height changes the chain
