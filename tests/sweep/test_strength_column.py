"""A study reports each case's largest restrainer utilisation (force/strength; issue 9)."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from rockcli.analyses.assess import assess_model
from rockcli.analyses.strength import restrainer_checks
from rockcli.model.derive import to_block
from rockcli.records.files import read_record
from rockcli.studies.parallel.executor import local_executor
from rockcli.studies.sweep.cases import build_model, expand
from rockcli.studies.sweep.run import run_sweep
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import WriteStudy

BASE = """\
name = "wall with a rod"
kind = "wall"

[geometry]
thickness = 0.5
height = 3.0
width = 3.0

[mass]
unit_weight = 18.0

[[restrainers]]
name = "rod"
kind = "tie-rod"
diameter = 0.012
length = 3.0
grade = "S275"
position = "top"
"""

STUDY = """\
base = "wall.toml"
analyses = ["rocking"]

[[records]]
path = "records/ricker_Tp0.5s_0.5g.txt"

[[axes]]
path = "restrainers[0].diameter"
name = "d"
values = [0.012, 0.030]
"""


def test_each_case_has_the_utilisation_of_its_rod(write_study: WriteStudy, tmp_path: Path) -> None:
    plan = load_study(str(write_study(STUDY, BASE)))
    with local_executor(1) as lanes:
        run_sweep(plan, str(tmp_path / "out"), lanes)
    with (tmp_path / "out" / "cases.csv").open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    record = read_record(plan.records[0].path)
    for row, case in zip(rows, expand(plan), strict=True):
        model = build_model(plan, case)
        (check,) = restrainer_checks(to_block(model), assess_model(model, record, "fast"))
        assert float(row["utilisation"]) == pytest.approx(check["utilisation"], rel=1e-12)
