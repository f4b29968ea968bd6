"""A study varies the loads, the thrusts and the building by path like any other field.

Source: issue 8, item 6 (the wall's physical description is part of the model, so a study
can vary it). Each case is rebuilt from the base table and validated, so the values checked
here are the ones the engines receive: the model's tables and the derived block (kN → N).
No engine runs: only the case models are built.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from rockcli.errors import InputError
from rockcli.model.derive import to_block
from rockcli.studies.sweep.cases import build_model, expand
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import BASE, WriteStudy

#: The sweep's base wall with a floor at the top, a roof thrust and a building 9 m tall.
PHYSICAL_BASE = (
    BASE
    + """
[[loads]]
name = "floor"
weight = 20.0
position = "top"

[[thrusts]]
name = "roof"
force = 0.5
direction = "positive"
position = "top"

[building]
H = 9.0
N = 3
"""
)

#: One axis per new table: 2 weights × 2 forces × 2 heights Z = 8 cases, no record.
PHYSICAL_STUDY = """\
base = "wall.toml"
analyses = ["kinematic"]

[[axes]]
path = "loads[0].weight"
name = "floor_weight"
values = [10.0, 40.0]

[[axes]]
path = "thrusts[0].force"
name = "thrust"
values = [0.2, 0.8]

[[axes]]
path = "building.Z"
name = "Z"
values = [0.0, 3.0]
"""

#: kN → N, the unit change of the derived block.
NEWTONS_PER_KILONEWTON = 1e3


def test_each_case_carries_its_load_thrust_and_height(write_study: WriteStudy) -> None:
    plan = load_study(str(write_study(PHYSICAL_STUDY, PHYSICAL_BASE)))
    cases = expand(plan)
    assert len(cases) == 8
    seen = set()
    for case in cases:
        model = build_model(plan, case)
        weight = (10.0, 40.0)[case.indices[0]]
        force = (0.2, 0.8)[case.indices[1]]
        z = (0.0, 3.0)[case.indices[2]]
        assert (model.loads[0].weight, model.thrusts[0].force, model.building.Z) == (
            weight,
            force,
            z,
        )
        block = to_block(model)
        # Exact: the kN value times 1e3 (a power of ten, the same double either way).
        assert block.loads[0].weight == weight * NEWTONS_PER_KILONEWTON
        assert block.thrusts[0].force == force * NEWTONS_PER_KILONEWTON
        seen.add((weight, force, z))
    assert len(seen) == 8  # every combination once
    # The base is not modified by the cases.
    assert plan.base["loads"][0]["weight"] == 20.0


def test_a_case_outside_the_block_names_its_values(write_study: WriteStudy) -> None:
    # A load raised above the top of the block (2h = 2R cos α ≈ 2.985 m for R = 1.5,
    # α = 0.1) is refused for that case, naming the path and the case.
    study = """\
base = "wall.toml"
analyses = ["kinematic"]

[[axes]]
path = "loads[0].height"
name = "floor_height"
values = [2.0, 5.0]
"""
    base = PHYSICAL_BASE.replace('weight = 20.0\nposition = "top"', "weight = 20.0\nheight = 1.0")
    plan = load_study(str(write_study(study, base)))
    assert build_model(plan, expand(plan)[0]).loads[0].height == 2.0
    with pytest.raises(InputError, match="outside the block") as info:
        build_model(plan, expand(plan)[1])
    assert "floor_height = 5.0" in str(info.value)
    assert "loads[0].height" in str(info.value)


def test_a_case_at_height_rocks_on_the_floor_motion(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # building.Z swept from the ground to 3 m: the case at height runs on the floor motion,
    # the same numbers `rock assess` gives for that model (analyses.assess, floor input).
    import csv

    from rockcli.analyses.assess import assess_model_output
    from rockcli.records.files import read_record
    from rockcli.studies.parallel.executor import local_executor
    from rockcli.studies.sweep.cases import case_table
    from rockcli.studies.sweep.run import run_sweep

    study = """\
base = "wall.toml"
analyses = ["rocking"]

[[records]]
path = "records/ricker_Tp0.5s_0.5g.txt"

[[axes]]
path = "building.Z"
name = "Z"
values = [0.0, 3.0]
"""
    plan = load_study(str(write_study(study, PHYSICAL_BASE)))
    with local_executor(1) as lanes:
        run_sweep(plan, str(tmp_path / "out"), lanes)
    with (tmp_path / "out" / "cases.csv").open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert [r["input"] for r in rows] == ["ground", "floor"]
    record = read_record(plan.records[0].path)
    for row, case in zip(rows, expand(plan), strict=True):
        model = build_model(plan, case)
        out = assess_model_output(model, record, "fast")
        assert float(row["max_ratio"]) == pytest.approx(out.result.max_ratio, rel=1e-12)
        assert case_table(plan, case)["building"]["Z"] == float(row["Z"])


def test_a_study_with_ground_rocks_every_case_on_the_record(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # ground = true is --ground for a study: the case at height runs on the record itself,
    # the case on the ground is unchanged (no error), and the column says "ground" for both.
    import csv

    from rockcli.analyses.assess import assess_model_output
    from rockcli.records.files import read_record
    from rockcli.studies.parallel.executor import local_executor
    from rockcli.studies.sweep.run import run_sweep

    study = """\
base = "wall.toml"
analyses = ["rocking"]
ground = true

[[records]]
path = "records/ricker_Tp0.5s_0.5g.txt"

[[axes]]
path = "building.Z"
name = "Z"
values = [0.0, 3.0]
"""
    plan = load_study(str(write_study(study, PHYSICAL_BASE)))
    with local_executor(1) as lanes:
        run_sweep(plan, str(tmp_path / "out"), lanes)
    with (tmp_path / "out" / "cases.csv").open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert [r["input"] for r in rows] == ["ground", "ground"]
    record = read_record(plan.records[0].path)
    at_height = build_model(plan, expand(plan)[1])
    ground = assess_model_output(at_height, record, "fast", ground=True).result
    floor = assess_model_output(at_height, record, "fast").result
    # Both overturn under this pulse: the time of overturning tells the two inputs apart.
    assert float(rows[1]["t_overturn"]) == pytest.approx(
        min(r.t_overturn for r in ground.runs if r.t_overturn is not None), rel=1e-12
    )
    assert [r.t_overturn for r in ground.runs] != [r.t_overturn for r in floor.runs]
