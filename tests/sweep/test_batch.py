"""A batched study (rockcli/studies/sweep/batch.py) against the case-by-case path.

1. The check before the run refuses exactly the cases the model loader refuses, and names the
   first with the loader's message: random studies of a plain block whose axes break each rule
   the varied values can break (a field's bounds and type, a stiffness below 1 N/m or above
   1e12, a spring without a mass, an attachment outside the thinner block).
2. The rows of a chunk run as arrays are the rows of the same cases run one by one through
   the model loader, rockcli.dynamics.simulate.assess and worker.run_case: equal, bit for bit
   (every float compared with ==), over random studies that vary every batched field, with
   symmetric and asymmetric springs (the mirror image and both polarities integrated).

Records: the shipped pulses (3–4 s), so every run is short. Example counts are bounded.
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import tomli_w
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from rockcli.errors import InputError
from rockcli.studies.sweep import batch, worker
from rockcli.studies.sweep.cases import Case, build_model, case_labels, check_cases, expand
from rockcli.studies.sweep.output import column_lines, columns, row_lines
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import PULSES, STUDY

PULSE = "ricker_Tp0.5s_0.5g.txt"
#: Each example writes its study in a folder of its own under tmp_path.
SCOPED = [HealthCheck.function_scoped_fixture]


def write_plan(folder: Path, base: dict[str, Any], axes: list[dict[str, Any]]) -> Any:
    """The study of base with axes on one pulse, written in folder and loaded."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "wall.toml").write_text(tomli_w.dumps(base))
    shutil.copy(PULSES / PULSE, folder / PULSE)
    study = {
        "base": "wall.toml",
        "analyses": ["rocking"],
        "axes": axes,
        "records": [{"path": PULSE, "name": "ricker"}],
    }
    (folder / "study.toml").write_text(tomli_w.dumps(study))
    return load_study(str(folder / "study.toml"))


def placement(kind: str) -> dict[str, Any]:
    if kind == "top":
        return {"position": "top"}
    if kind == "polar":
        return {"radius": 1.2, "angle": 0.15}
    return {"height": 1.0, "from_pivot": 0.05}


#: The member laws a batched spring can have (rockcli/dynamics/motion.py): elastic; yielding on
#: both sides, alike or not; yielding on the positive side only (a stiff negative side then
#: breaks the schema's rule); pretensioned, with and without a yield; lost past an elongation;
#: an anchor of finite capacity; and the tie-rod of a steel grade (it yields and breaks).
MEMBERS: dict[str, dict[str, Any]] = {
    "elastic": {},
    "yield": {"yield_pos": 800.0, "yield_neg": 800.0},
    "yield-asymmetric": {"yield_pos": 800.0, "yield_neg": 500.0},
    "yield+": {"yield_pos": 800.0},
    "pretension": {"pretension": 200.0},
    "pretension-yield": {"pretension": 200.0, "yield_pos": 900.0, "yield_neg": 900.0},
    "fails": {"fails_at": 0.004},
    "anchor": {"anchor_capacity": 3000.0},
}
LAWS = [*MEMBERS, "tie-rod"]


@st.composite
def plain_blocks(draw: st.DrawFn) -> dict[str, Any]:
    """A plain block's model table: either geometric form, weight or unit weight (or no mass
    when no spring is stiff), Housner's e (with a factor or not) or an explicit e, 0–2 springs
    placed each of the three ways, each with a law of MEMBERS or a tie-rod; two-sided or
    one-sided motion (either side stopped), and sometimes the linearized equation, a tail of
    its own, other tolerances."""
    polar = draw(st.booleans())
    base: dict[str, Any] = {"name": "batched", "kind": draw(st.sampled_from(["wall", "altar"]))}
    geometry: dict[str, Any] = (
        {"R": draw(st.sampled_from([0.8, 1.5, 3.0])), "alpha": draw(st.sampled_from([0.1, 0.2]))}
        if polar
        else {"thickness": draw(st.sampled_from([0.3, 0.5])), "height": 2.0}
    )
    springs = draw(st.sampled_from([0, 1, 2, 2]))
    mass = draw(st.sampled_from(["weight", "unit_weight", "none"] if not springs else
                                ["weight", "unit_weight"]))  # fmt: skip
    if mass == "weight":
        base["mass"] = {"weight": draw(st.sampled_from([5.0, 50.0]))}
    elif mass == "unit_weight":
        geometry["width"] = 1.0
        base["mass"] = {"unit_weight": 18.0}
    base["geometry"] = geometry
    e = draw(st.sampled_from(["housner", "factor", "explicit"]))
    if e == "factor":
        base["restitution"] = {"factor": 0.9}
    elif e == "explicit":
        base["restitution"] = {"e": 0.8}
    rows = []
    for i in range(springs):
        row: dict[str, Any] = {"name": f"spring {i}", **placement(draw(st.sampled_from(
            ["top", "polar", "point"])))}  # fmt: skip
        law = draw(st.sampled_from(LAWS))
        if law == "tie-rod":
            row |= {"kind": "tie-rod", "diameter": 0.012, "length": 4.0, "grade": "S235"}
            rows.append(row)
            continue
        if draw(st.booleans()) and law != "yield+":
            row["k"] = 1e4
        else:
            row["k_pos"], row["k_neg"] = 1e4, draw(st.sampled_from([1e4, 3e3, 0.0]))
        row |= MEMBERS[law]
        rows.append(row)
    if rows:
        base["restrainers"] = rows
    motion = draw(st.sampled_from(["two", "one", "one-positive"]))
    if motion != "two":
        base["motion"] = {"sides": "one", "rebound": 0.8}
        if motion == "one-positive":
            base["motion"]["stopped"] = "positive"
    analysis: dict[str, Any] = {}
    if draw(st.booleans()):
        analysis["linearized"] = True
    if draw(st.booleans()):
        analysis["tail"] = draw(st.sampled_from([0.0, 2.0, 40.0]))
    if draw(st.booleans()):
        analysis["rtol"] = analysis["atol"] = 1e-6
    if analysis:
        base["analysis"] = analysis
    return base


def axis_paths(base: dict[str, Any]) -> list[str]:
    """Every batched path the base gives a value to."""
    paths = [f"geometry.{k}" for k in base["geometry"]]
    paths += [f"mass.{k}" for k in base.get("mass", {})]
    paths += [f"restitution.{k}" for k in base.get("restitution", {})]
    for i, row in enumerate(base.get("restrainers", [])):
        paths += [f"restrainers[{i}].{k}" for k in ("k", "k_pos", "k_neg") if k in row]
    return paths


#: Values that each field's rules accept, by the last key of the path.
GOOD = {
    "R": [0.6, 1.0, 2.5, 7.0],
    "alpha": [0.05, 0.12, 0.3],
    "thickness": [0.25, 0.4, 0.8],
    "height": [1.5, 3.0],
    "width": [0.5, 2.0],
    "weight": [1.0, 20.0],
    "unit_weight": [16.0, 22.0],
    "factor": [0.7, 1.0],
    "e": [0.5, 0.95],
    "k": [0.0, 1e3, 1e6],
    "k_pos": [0.0, 2e3, 1e7],
    "k_neg": [0.0, 5e2, 1e7],
}

#: Values that break a rule, by the last key: out of bounds, of the wrong type, and values
#: that break a rule between fields (a spring placed at 0.05 m from the pivot outside a block
#: 2b thinner than that).
BAD = {
    "R": [-1.0, 0.0, 1e9, "2", True, 1e-5, math.inf],
    "alpha": [0.0, 1.6, math.nan, 0.02, 1e-5],
    "thickness": [-0.1, 0.05, 1e-5],
    "height": [0.0, 2e6],
    "width": [-2.0, 1e-5],
    "weight": [-5.0, 0.0, 1e-30],
    "unit_weight": [-1.0, 1e-30],
    "factor": [-0.1, 1.5],
    "e": [-0.1, 1.2],
    "k": [0.5, -1.0, 1e13, 1e12],
    "k_pos": [0.5, -3.0, 1e13, 1e12],
    "k_neg": [0.2, 2e12],
}


@st.composite
def studies(draw: st.DrawFn, bad: bool) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    """A plain block and 1–3 axes on its batched paths (two paths set together sometimes),
    with values that break a rule when bad."""
    base = draw(plain_blocks())
    paths = draw(st.lists(st.sampled_from(axis_paths(base)), min_size=1, max_size=4,
                          unique=True))  # fmt: skip
    axes = []
    for n, path in enumerate(paths):
        key = path.rsplit(".", 1)[1]
        pool = GOOD[key] + (BAD[key] if bad else [])
        # the first value accepted, so that the first case is valid and the grid is checked
        first = draw(st.sampled_from(GOOD[key]))
        more = draw(st.lists(st.sampled_from(pool), max_size=3, unique_by=repr))
        values = [first, *(v for v in more if repr(v) != repr(first))]
        axes.append({"path": path, "name": f"a{n}", "values": values})
    return base, axes


def loader_accepts(plan: Any, case: Case) -> bool:
    try:
        build_model(plan, case)
    except InputError:
        return False
    return True


@settings(
    max_examples=200, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(study=studies(bad=True))
def test_the_check_refuses_what_the_loader_refuses(tmp_path: Path, study: Any) -> None:
    base, axes = study
    folder = tmp_path / f"s{abs(hash(repr(study)))}"
    plan = write_plan(folder, base, axes)
    try:
        form = batch.batch_form(plan)
    except InputError:  # the first case is invalid: the loader's own message
        assert not loader_accepts(plan, expand(plan)[0])
        return
    assert form is not None, "a plain block's study on batched paths is batched"
    cases = expand(plan)
    indices = batch.grid_indices(plan, 0, len(cases))
    _, valid = batch.derive(form, indices)
    expected = np.array([loader_accepts(plan, c) for c in cases])
    assert (valid == expected).all(), [
        (c.id, c.indices) for c, v, e in zip(cases, valid, expected, strict=True) if v != e
    ]
    # the first refused case is named with the message the case-by-case check gives
    if expected.all():
        assert batch.check_grid(plan) == len(cases)
        return
    with pytest.raises(InputError) as fast:
        batch.check_grid(plan)
    with pytest.raises(InputError) as slow:
        check_cases(plan)
    assert str(fast.value) == str(slow.value)


def per_case_rows(plan: Any, cases: list[Case]) -> list[dict[str, Any]]:
    record = worker.read_source(plan.records[0])
    return [
        {"case": c.id, **worker.run_case(plan, build_model(plan, c), record, None)} for c in cases
    ]


@settings(
    max_examples=25, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(study=studies(bad=False))
def test_a_chunk_in_one_call_is_the_cases_one_by_one(tmp_path: Path, study: Any) -> None:
    base, axes = study
    plan = write_plan(tmp_path / f"s{abs(hash(repr(study)))}", base, axes)
    try:
        form = batch.batch_form(plan)
    except InputError:  # a rule between GOOD values (a yield missing on a stiff side)
        assume(False)
    assert form is not None
    cases = [c for c in expand(plan) if loader_accepts(plan, c)]
    if not cases:
        return
    record = worker.read_source(plan.records[0])
    found = batch.run_arrays(form, cases, record.time, record.accel, record.dt)
    assert found is not None
    slow = per_case_rows(plan, cases)
    assert batch.rows_of(cases, *found) == slow
    # and the lines of cases.csv, written column by column, are the rows' lines
    header = columns(plan)
    cells = {**batch.label_cells(plan, cases), **batch.result_cells(*found)}
    labelled = [{**case_labels(plan, c), **r} for c, r in zip(cases, slow, strict=True)]
    assert column_lines(header, len(cases), cells) == row_lines(header, labelled)


def test_the_pulse_study_is_batched_and_identical(write_study: Any) -> None:
    """The 16 cases of the sweep tests' study (tests/sweep/conftest.py), rocking alone: the
    same rows from worker.run_chunk (batched) as case by case."""
    plan = load_study(str(write_study('analyses = ["rocking"]\n' + STUDY)))
    assert batch.batch_form(plan) is not None
    for record in range(len(plan.records)):
        cases = [c for c in expand(plan) if c.record == record]
        rows = worker.run_chunk(worker.Chunk(plan, record, tuple(c.id for c in cases)))
        source = worker.read_source(plan.records[record])
        slow = [{"case": c.id, **worker.run_case(plan, build_model(plan, c), source, None)}
                for c in cases]  # fmt: skip
        assert rows == slow


@pytest.mark.parametrize(
    ("change", "why"),
    [
        ('analyses = ["rocking", "kinematic"]\n', "the code check needs each case's model"),
        ('analyses = ["rocking"]\nengine = "reference"\n', "the reference engine is Python"),
    ],
)
def test_what_is_not_batched(write_study: Any, change: str, why: str) -> None:
    plan = load_study(str(write_study(change + STUDY)))
    assert batch.batch_form(plan) is None, why


def spring_wall(**restrainer: Any) -> dict[str, Any]:
    return {
        "name": "rule",
        "kind": "wall",
        "geometry": {"R": 1.0, "alpha": 0.1, "width": 1.0},
        "mass": {"unit_weight": 18.0},
        "restrainers": [{"name": "s", "k": 1e4} | restrainer],
    }


#: One study per rule between fields that a batched axis can break, its second value breaking
#: it: (base, axes, why).
RULES = [
    (spring_wall(height=1.0, from_pivot=0.05), [("geometry.alpha", [0.1, 0.02])],
     "an attachment 0.05 m from the pivot is outside a block 2b = 0.04 m thick"),
    ({**spring_wall(position="top", k=1e12), "mass": {"weight": 10.0}},
     [("mass.weight", [10.0, 1e-300])], "a weight below its bound (the bounds keep K r²/I0 "
     "finite for a batched block: derived_checks' overflow cannot be reached here)"),
    ({k: v for k, v in spring_wall(position="top").items() if k != "mass"}
     | {"geometry": {"R": 1.0, "alpha": 0.1}},
     [("restrainers[0].k", [0.0, 1e4])], "a stiff spring needs a mass"),
    (spring_wall(position="top"), [("restrainers[0].k", [1e4, 0.5])],
     "a stiffness between 0 and 1 N/m"),
    (spring_wall(position="top"), [("geometry.R", [1.0, 1e-4])], "R below its bound"),
]  # fmt: skip


@pytest.mark.parametrize(("base", "axes", "why"), RULES, ids=[r[2] for r in RULES])
def test_each_rule_between_fields(tmp_path: Path, base: Any, axes: Any, why: str) -> None:
    plan = write_plan(tmp_path, base, [{"path": p, "values": v} for p, v in axes])
    form = batch.batch_form(plan)
    assert form is not None
    cases = expand(plan)
    _, valid = batch.derive(form, batch.grid_indices(plan, 0, len(cases)))
    assert valid.tolist() == [True, False], why
    assert [loader_accepts(plan, c) for c in cases] == [True, False], why
    with pytest.raises(InputError) as fast:
        batch.check_grid(plan)
    with pytest.raises(InputError) as slow:
        check_cases(plan)
    assert str(fast.value) == str(slow.value)


def test_the_paper_study_on_real_records_is_the_same_file_batched(
    tmp_path: Path, shared_records: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The paper's §4.4 study (examples/studies/paper-4.4.toml: R × α × K of the wall with its
    top spring), rocking alone, on the real records: cases.csv batched is cases.csv case by
    case, byte for byte, and so is the summary (its wall time and folder aside)."""
    import json

    from rockcli.studies.parallel.executor import local_executor
    from rockcli.studies.sweep.run import run_sweep
    from tests.sweep.conftest import STUDIES

    text = (STUDIES / "paper-4.4.toml").read_text(encoding="utf-8")
    rocking = text.replace('analyses = ["rocking", "kinematic"]', 'analyses = ["rocking"]')
    assert rocking != text
    study = tmp_path / "paper-4.4.toml"
    study.write_text(rocking, encoding="utf-8")
    shutil.copy(STUDIES / "paper-4.4-wall.toml", tmp_path / "paper-4.4-wall.toml")
    plan = load_study(str(study), records_dir=str(shared_records))
    assert batch.batch_form(plan) is not None
    with local_executor(2) as lanes:
        fast = run_sweep(plan, str(tmp_path / "fast"), lanes).summary
    monkeypatch.setattr(batch, "cached_form", lambda plan: None)
    monkeypatch.setattr(batch, "batch_form", lambda plan: None)
    with local_executor(1) as lanes:
        slow = run_sweep(plan, str(tmp_path / "slow"), lanes).summary
    fast_csv = (tmp_path / "fast" / "cases.csv").read_bytes()
    assert fast_csv == (tmp_path / "slow" / "cases.csv").read_bytes()
    assert len(fast_csv.splitlines()) == 1 + len(expand(plan))
    for summary in (fast, slow):
        for key in ("wall_time_s", "out", "jobs"):
            summary.pop(key, None)
    assert json.dumps(fast, sort_keys=True) == json.dumps(slow, sort_keys=True)


def test_a_suite_study_batched_is_the_cases_one_by_one(write_study: Any, tmp_path: Path) -> None:
    """A rocking-only study whose records are a suite (the three pulses of
    tests/sweep/test_suite_entries.py, one scaled): each case's row, the suite's rule over
    its records run as arrays, equals the row of run_suite_case, bit for bit."""
    from rockcli.studies.sweep.over_suite import read_suite, run_suite_case
    from tests.sweep.test_suite_entries import SUITE

    study = 'analyses = ["rocking"]\n' + STUDY.replace(
        '[[records]]\npath = "one-cosine_Tp2s_0.31g.txt"\nname = "cosine"\n',
        '[[records]]\nsuite = "suite.toml"\n',
    )
    path = write_study(study)
    (tmp_path / "records" / "suite.toml").write_text(SUITE, encoding="utf-8")
    plan = load_study(str(path))
    assert plan.records[0].suite and batch.batch_form(plan) is not None
    suite = read_suite(plan.records[0])
    cases = [c for c in expand(plan) if c.record == 0]
    rows = worker.run_chunk(worker.Chunk(plan, 0, tuple(c.id for c in cases)))
    slow = [{"case": c.id, **run_suite_case(plan, build_model(plan, c), suite)} for c in cases]
    assert rows == slow
    assert {r["rocking"] for r in rows} == {"passes", "fails"}  # both verdicts met


def test_a_record_timed_from_another_origin(tmp_path: Path) -> None:
    """Samples timed from 100 s (the engines run them from 0 and shift the times back; a
    record read from a file starts at 0, this is the API's case): the batched envelope,
    overturning times included, is rockcli.dynamics.simulate.assess's case by case."""
    from rockcli.analyses.assess import settings_from
    from rockcli.dynamics.simulate import assess
    from rockcli.model.derive import solver_options, to_block

    base = spring_wall(position="top", k=0.0)
    axes = [
        {"path": "geometry.alpha", "values": [0.05, 0.1, 0.2]},
        {"path": "geometry.R", "values": [0.05, 0.1, 0.5, 1.0]},
        {"path": "restrainers[0].k", "values": [0.0, 1e3]},
    ]
    plan = write_plan(tmp_path, base, axes)
    form = batch.batch_form(plan)
    assert form is not None
    cases = list(expand(plan))
    record = worker.read_source(plan.records[0])
    time = record.time + 100.0
    found = batch.run_arrays(form, cases, time, record.accel, record.dt)
    assert found is not None
    rows = batch.rows_of(cases, *found)
    for case, row in zip(cases, rows, strict=True):
        model = build_model(plan, case)
        result = assess(to_block(model), time, record.accel, record.dt,
                        settings=settings_from(solver_options(model)))  # fmt: skip
        expected = worker.rocking_columns(result)
        assert {k: row[k] for k in expected} == expected
    assert any(r["t_overturn"] is not None and r["t_overturn"] > 100.0 for r in rows)


def test_a_member_checked_by_its_elongation_beside_one_with_a_strength(tmp_path: Path) -> None:
    """One spring has an anchor (a strength), another is lost past 4 mm (no strength): the
    utilisation column is the first's force over its strength. Case by case it used to take
    the max over a number and None, and every case was an internal error; batched and case by
    case now give the same rows."""
    base = spring_wall(position="top", k=1e4, anchor_capacity=3000.0)
    base["restrainers"].append({"name": "lost", "k": 2e4, "fails_at": 0.004,
                                "height": 1.0, "from_pivot": 0.05})  # fmt: skip
    axes = [{"path": "geometry.alpha", "values": [0.05, 0.1]},
            {"path": "restrainers[1].k", "values": [0.0, 2e4]}]  # fmt: skip
    plan = write_plan(tmp_path, base, axes)
    form = batch.batch_form(plan)
    assert form is not None
    cases = list(expand(plan))
    record = worker.read_source(plan.records[0])
    found = batch.run_arrays(form, cases, record.time, record.accel, record.dt)
    assert found is not None
    slow = per_case_rows(plan, cases)
    assert batch.rows_of(cases, *found) == slow
    assert all(isinstance(r["utilisation"], float) and r["utilisation"] > 0 for r in slow), slow
