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
