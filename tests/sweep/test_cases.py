"""Case expansion: records × the product of the axes, each case a validated model.

Sources: the issue's contract (every case rebuilt and validated with validate_model on the
modified table; several paths set together; a case whose model is invalid is an error naming
its axis values) and the model's rule for position = "top": r = 2R, φ = α (paper Eq. 4).
"""

from __future__ import annotations

import csv
import json
import math

import pytest

from rockcli.errors import InputError
from rockcli.model.derive import to_block
from rockcli.studies.sweep.cases import Case, build_model, case_label, check_cases, expand
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import STUDY, WriteStudy


def test_records_outermost_then_the_axes_in_file_order(write_study: WriteStudy) -> None:
    plan = load_study(str(write_study()))
    cases = expand(plan)
    assert len(cases) == 2 * 2 * 2 * 2
    assert [c.id for c in cases] == list(range(16))
    assert cases[0] == Case(0, 0, (0, 0, 0))
    assert cases[1] == Case(1, 0, (0, 0, 1))  # the last axis (K) varies fastest
    assert cases[2] == Case(2, 0, (0, 1, 0))
    assert cases[8] == Case(8, 1, (0, 0, 0))  # then the second record
    assert (
        case_label(plan, cases[13])
        == "case 13 (R = 3.0, alpha = 0.1, K = 1000000.0, record ricker)"
    )


def test_each_case_sets_its_values_and_validates(write_study: WriteStudy) -> None:
    plan = load_study(str(write_study()))
    model = build_model(plan, Case(7, 0, (1, 1, 1)))
    assert model.geometry.R == 3.0
    assert model.geometry.alpha == 0.2
    # Several paths set together: both sides of the spring.
    assert model.restrainers[0].k_pos == 1e6
    assert model.restrainers[0].k_neg == 1e6
    # The base is not modified by the cases.
    assert plan.base["geometry"]["R"] == 1.5


def test_the_top_spring_follows_the_geometry(write_study: WriteStudy) -> None:
    plan = load_study(str(write_study()))
    for case in expand(plan)[:8]:
        block = to_block(build_model(plan, case))
        spring = block.restrainers[0]
        # position = "top": r = 2R, φ = α on both sides (paper Eq. 4).
        assert spring.r_pos == pytest.approx(2 * block.R, rel=1e-12)
        assert spring.phi_pos == pytest.approx(block.alpha, rel=1e-12)
        assert spring.r_neg == pytest.approx(2 * block.R, rel=1e-12)


def test_one_value_per_path(write_study: WriteStudy) -> None:
    text = STUDY.replace("values = [0.0, 1e6]", "values = [[1e3, 0.0], 1e4]")
    plan = load_study(str(write_study(text)))
    axis = plan.axes[2]
    assert axis.values == ((1e3, 0.0), (1e4, 1e4))
    assert axis.label(0) == "1000.0/0.0"
    assert axis.label(1) == 1e4
    model = build_model(plan, Case(0, 0, (0, 0, 0)))
    assert (model.restrainers[0].k_pos, model.restrainers[0].k_neg) == (1e3, 0.0)


def test_a_table_absent_from_the_base_is_created(write_study: WriteStudy) -> None:
    text = STUDY.replace('path = "geometry.R"', 'path = "restitution.factor"').replace(
        "values = [1.5, 3.0]", "values = [0.8, 1.0]"
    )
    base_without = "\n".join(
        line for line in write_study().with_name("wall.toml").read_text().splitlines()
        if not line.startswith(("[restitution]", "factor"))
    )  # fmt: skip
    plan = load_study(str(write_study(text, base=base_without + "\n")))
    assert build_model(plan, Case(0, 0, (1, 0, 0))).restitution.factor == 1.0


def test_an_invalid_case_names_its_axis_values(write_study: WriteStudy) -> None:
    # α ≥ π/2 is not a block (schema: 0 < alpha < π/2).
    path = write_study(STUDY.replace("values = [0.1, 0.2]", f"values = [0.1, {math.pi / 2}]"))
    plan = load_study(str(path))
    with pytest.raises(InputError) as info:
        check_cases(plan)
    assert str(info.value) == (
        f"{path}: case 2 (R = 1.5, alpha = {math.pi / 2}, K = 0.0): geometry.alpha: out of "
        f"range (got {math.pi / 2}; allowed: a number >= 1e-06 and < pi/2 [rad])"
    )


def test_a_case_the_code_check_refuses_is_a_row_with_its_error(
    write_study: WriteStudy,
) -> None:
    # Issue 7, item 13: a case that fails at run time is recorded (cases.csv, column error)
    # and the study goes on; the summary counts it, never as a collapse. The kinematic check
    # alone, without records and without a code spectrum in the model: every case fails, so
    # the study ends as bad input once it is written (issue 20, item 3).
    from rockcli.studies.parallel.executor import local_executor
    from rockcli.studies.sweep.run import run_sweep

    text = STUDY.split("[[records]]")[0].replace("base =", 'analyses = ["kinematic"]\nbase =')
    path = write_study(text)
    plan = load_study(str(path))
    with local_executor(1) as lanes, pytest.raises(InputError, match="no case of the study"):
        run_sweep(plan, str(path.parent / "out"), lanes)
    summary = json.loads((path.parent / "out" / "summary.json").read_text(encoding="utf-8"))
    assert summary["cases"] == 8  # 2 R × 2 alpha × 2 K, no record
    assert summary["errors"] == 8
    assert summary["undetermined"] == 8
    assert summary["code_collapses"] == 0
    with (path.parent / "out" / "cases.csv").open(encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 8
    assert all(r["error"].startswith("ntc: no seismic demand") for r in rows)
    assert {r["code_uls"] for r in rows} == {""}
