"""Running a study: the CSV, resume after an interruption, order independence, the counts.

Sources: the issue's contract (cases.csv columns, one row per case, per-chunk writes,
--resume runs only the missing cases, results keyed by case id whatever the completion
order) and rock compare (the counts of a study equal a loop of compare_model over its cases).
"""

from __future__ import annotations

import csv
import json
from collections import Counter
from pathlib import Path
from typing import Any

import pytest

from rockcli.analyses.compare import compare_model_output
from rockcli.errors import InputError
from rockcli.model.load import validate_model
from rockcli.records.files import read_record
from rockcli.studies.parallel.executor import local_executor
from rockcli.studies.sweep import run as sweep_run
from rockcli.studies.sweep.cases import case_table, expand
from rockcli.studies.sweep.output import RESULT_COLUMNS
from rockcli.studies.sweep.run import SweepResult, run_sweep
from rockcli.studies.sweep.study import StudyPlan, load_study
from rockcli.studies.sweep.worker import Chunk
from rockcli.terminal.compare import comparison_output_document
from tests.sweep.conftest import STUDY, WriteStudy

N_CASES = 16


def run(plan: StudyPlan, out: Path, jobs: int = 1, **options: Any) -> SweepResult:
    with local_executor(jobs) as lanes:
        return run_sweep(plan, str(out), lanes, **options)


def read_csv(path: Path) -> list[dict[str, str]]:
    with path.open(encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture
def plan(write_study: WriteStudy) -> StudyPlan:
    return load_study(str(write_study()))


def test_the_csv_has_one_row_per_case(plan: StudyPlan, tmp_path: Path) -> None:
    result = run(plan, tmp_path / "out")
    rows = read_csv(tmp_path / "out" / "cases.csv")
    assert list(rows[0]) == ["case", "record", "R", "alpha", "K", *RESULT_COLUMNS]
    assert [int(r["case"]) for r in rows] == list(range(N_CASES))
    assert {r["record"] for r in rows} == {"cosine", "ricker"}
    assert {r["overturned"] for r in rows} <= {"true", "false"}
    # "": not evaluated (a stiff spring leaves the non-linear check without d0*).
    assert {r["code_uls"] for r in rows} <= {"pass", "fail", ""}
    assert {r["rocking"] for r in rows} <= {"survives", "overturns"}
    assert rows[1]["K"] == "1000000.0"
    assert float(rows[0]["max_ratio"]) == max(
        float(rows[0]["max_ratio_pos"]), float(rows[0]["max_ratio_neg"])
    )
    assert result.summary["cases"] == N_CASES
    state = json.loads((tmp_path / "out" / "sweep.json").read_text())
    assert state["complete"] is True
    assert json.loads((tmp_path / "out" / "summary.json").read_text())["cases"] == N_CASES


def test_the_counts_equal_a_loop_of_compare_model(plan: StudyPlan, tmp_path: Path) -> None:
    summary = run(plan, tmp_path / "out").summary
    records = [read_record(r.path) for r in plan.records]
    kinds: Counter[str] = Counter()
    code = rocking = 0
    for case in expand(plan):
        model = validate_model(case_table(plan, case))
        record = records[case.record or 0]
        doc = comparison_output_document(compare_model_output(model, record), record)
        kinds[doc["classification"]] += 1
        code += doc["collapse"]["code"] is True
        rocking += doc["collapse"]["rocking"] is True
    assert summary["code_collapses"] == code
    assert summary["rocking_collapses"] == rocking
    assert summary["code_conservative"] == kinds["code-conservative"]
    assert summary["code_unconservative"] == kinds["code-unconservative"]
    assert summary["consistent_safe"] == kinds["consistent-safe"]
    assert summary["consistent_unsafe"] == kinds["consistent-unsafe"]
    assert code > 0 and kinds["code-conservative"] > 0  # the tiny study exercises both
    share = summary["inconsistency_share"]
    assert share == kinds["code-conservative"] / code
    by_alpha = {(r["record"], r["alpha"]): r for r in summary["by_record_alpha"]}
    assert sum(r["cases"] for r in by_alpha.values()) == N_CASES
    assert sum(r["code_collapses"] for r in by_alpha.values()) == code
    assert [r["K"] for r in summary["by_axis_alpha"]["K"]] == [0.0, 0.0, 1e6, 1e6]


def test_the_summary_keys(plan: StudyPlan, tmp_path: Path) -> None:
    summary = run(plan, tmp_path / "out").summary
    for key in (
        "schema", "cases", "rocking_collapses", "code_collapses", "code_conservative",
        "code_unconservative", "wall_time_s", "inconsistency_share", "unconservative_share",
        "records", "by_record_alpha", "by_axis_alpha", "out", "axes", "skipped_records",
    ):  # fmt: skip
        assert key in summary, key
    assert summary["schema"] == 1
    assert summary["out"] == str(tmp_path / "out")
    json.dumps(summary, allow_nan=False)


def test_jobs_1_and_jobs_2_write_the_same_csv(plan: StudyPlan, tmp_path: Path) -> None:
    run(plan, tmp_path / "one", jobs=1, chunk_size=3)
    run(plan, tmp_path / "two", jobs=2, chunk_size=1)
    one = (tmp_path / "one" / "cases.csv").read_text()
    two = (tmp_path / "two" / "cases.csv").read_text()
    assert one == two


class Interrupt(Exception):
    pass


def test_resume_runs_only_the_missing_cases(
    plan: StudyPlan, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = tmp_path / "out"
    full = run(plan, tmp_path / "full").summary
    chunks: list[int] = []

    def stop_after_three(done: int, total: int) -> None:
        chunks.append(done)
        if len(chunks) == 4:  # the initial call, then three chunks of 2 cases
            raise Interrupt

    with pytest.raises(Interrupt):
        run(plan, out, chunk_size=2, progress=stop_after_three)
    kept = read_csv(out / "cases.csv")
    assert len(kept) == 6
    with (out / "cases.csv").open("a") as f:
        f.write("13,ricker,3.0,0.1,100")  # a line cut short by the interruption
    with pytest.raises(InputError, match="--resume to continue"):
        run(plan, out)

    ran: list[int] = []
    original = sweep_run.run_chunk_lines

    def counting(chunk: Chunk) -> Any:
        ran.extend(c.id for c in chunk.cases)
        return original(chunk)

    monkeypatch.setattr(sweep_run, "run_chunk_lines", counting)
    summary = run(plan, out, resume=True).summary
    done = {int(r["case"]) for r in kept}
    assert sorted(ran) == sorted(set(range(N_CASES)) - done)
    assert summary["resumed_cases"] == 6
    assert summary["computed_cases"] == N_CASES - 6
    assert (out / "cases.csv").read_text() == (tmp_path / "full" / "cases.csv").read_text()
    for key in ("code_collapses", "rocking_collapses", "code_conservative"):
        assert summary[key] == full[key]


def test_a_complete_study_runs_again_but_another_is_refused(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    plan = load_study(str(write_study()))
    run(plan, out)
    run(plan, out)  # the same study, complete: run again
    other = load_study(str(write_study(STUDY.replace("[1.5, 3.0]", "[1.5, 4.0]"), name="o.toml")))
    for resume in (False, True):
        with pytest.raises(InputError, match="holds the results of another study"):
            run(other, out, resume=resume)
    assert run(other, out, overwrite=True).summary["cases"] == N_CASES


@pytest.mark.parametrize("analysis", ["rocking", "kinematic"])
def test_one_analysis_leaves_the_other_s_counts_unknown(
    write_study: WriteStudy, tmp_path: Path, analysis: str
) -> None:
    text = STUDY.replace("base =", f'analyses = ["{analysis}"]\nbase =')
    summary = run(load_study(str(write_study(text))), tmp_path / "out").summary
    known, unknown = (
        ("rocking_collapses", "code_collapses")
        if analysis == "rocking"
        else ("code_collapses", "rocking_collapses")
    )
    assert isinstance(summary[known], int)
    assert summary[unknown] is None
    assert summary["code_conservative"] is None
    assert summary["inconsistency_share"] is None
    rows = read_csv(tmp_path / "out" / "cases.csv")
    assert {r["classification"] for r in rows} == {""}
    assert {r["code_uls" if analysis == "rocking" else "rocking"] for r in rows} == {""}
