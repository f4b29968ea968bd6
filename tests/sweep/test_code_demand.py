"""One earthquake on both sides of a sweep (issue #8 item 4): by default each record's own
response spectrum is the code check's demand, even when the base model sets a code spectrum;
the study key code_demand = "model" uses the base model's spectrum instead."""

from __future__ import annotations

import pytest

from rockcli.analyses.kinematic import kinematic_model
from rockcli.records.files import read_record
from rockcli.studies.sweep.cases import Case, build_model
from rockcli.studies.sweep.columns import uls_ratio
from rockcli.studies.sweep.study import load_study
from rockcli.studies.sweep.worker import run_case
from tests.sweep.conftest import BASE, STUDY, WriteStudy

#: A code spectrum far weaker than the shipped pulses (0.31 g and 0.5 g): ag = 0.05 g, so the
#: two demands give clearly different ULS ratios (F0 and Tc* are typical NTC values).
WEAK_SPECTRUM = """
[ntc.demand.SLD]
ag = 0.02
F0 = 2.5
Tc_star = 0.3

[ntc.demand.SLV]
ag = 0.05
F0 = 2.5
Tc_star = 0.3
"""


@pytest.mark.parametrize(
    ("setting", "uses_record"), [("", True), ('code_demand = "model"\n', False)]
)
def test_the_code_check_sees_the_record_unless_the_study_asks_for_the_model(
    write_study: WriteStudy, setting: str, uses_record: bool
) -> None:
    path = write_study(STUDY.replace("base =", setting + "base =", 1), base=BASE + WEAK_SPECTRUM)
    plan = load_study(str(path))
    model = build_model(plan, Case(0, 0, (0, 0, 0)))
    record = read_record(plan.records[0].path)
    row = run_case(plan, model, record, None)
    by_record = uls_ratio(kinematic_model(model, record=record).checks)
    by_model = uls_ratio(kinematic_model(model).checks)
    assert by_record is not None and by_model is not None
    assert by_record != pytest.approx(by_model, rel=0.1)  # the test can tell them apart
    # The same function computes both: exact equality.
    assert row["uls_ratio"] == (by_record if uses_record else by_model)
