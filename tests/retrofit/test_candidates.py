"""Candidate rods of `rock retrofit`: options parsed, the rod found or placed, each diameter a
model validated like a model file (its stiffness and strength from the one derivation)."""

from __future__ import annotations

import copy
import math
from typing import Any

import pytest

from rockcli.errors import InputError
from rockcli.model.derive import to_block
from rockcli.model.load import read_toml, validate_model
from rockcli.studies.retrofit.candidates import (
    DEFAULT_DIAMETERS_MM,
    PLACED_NAME,
    Placement,
    build_candidate,
    candidate_table,
    make_plan,
    parse_at,
    parse_diameters,
)
from tests.cli.conftest import ROOT

FACADE = ROOT / "examples" / "facade.toml"
#: Facade example's geometry: R = 5.04 m, α = 0.05 rad → 2b = 2R sin α, 2h = 2R cos α [m].
THICKNESS = 2 * 5.04 * math.sin(0.05)
HEIGHT = 2 * 5.04 * math.cos(0.05)


def facade() -> dict[str, Any]:
    return read_toml(str(FACADE))


def plan_of(table: dict[str, Any], **options: Any):
    options.setdefault("diameters_mm", (16.0, 20.0))
    return make_plan(table, validate_model(table), file="m.toml", **options)


# --- options -------------------------------------------------------------------------------


def test_diameters_parsed_sorted_once() -> None:
    assert parse_diameters(" 24,16 ,20,16") == (16.0, 20.0, 24.0)
    assert parse_diameters(None) == tuple(float(d) for d in DEFAULT_DIAMETERS_MM)


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("", "no diameter given"),
        (" , ", "no diameter given"),
        ("16,abc", "not a diameter: 'abc'"),
        ("16,,20", "an empty item: ''"),
        ("0", "not a diameter: '0'"),
        ("-12", "not a diameter: '-12'"),
        ("nan", "not a diameter: 'nan'"),
        ("inf", "not a diameter: 'inf'"),
    ],
)
def test_bad_diameters(text: str, problem: str) -> None:
    with pytest.raises(InputError) as info:
        parse_diameters(text)
    assert info.value.where == "--diameters"
    assert info.value.problem == problem


def test_at_parsed() -> None:
    assert parse_at("5.0,0.3") == (5.0, 0.3)


@pytest.mark.parametrize("text", ["5", "5,0.3,1", "a,b", "5,nan", ""])
def test_bad_at(text: str) -> None:
    with pytest.raises(InputError) as info:
        parse_at(text)
    assert info.value.where == "--at"


# --- the rod ---------------------------------------------------------------------------------


def test_models_tie_rod_is_found_and_keeps_its_place() -> None:
    plan = plan_of(facade())
    assert (plan.index, plan.name, plan.grade, plan.count) == (1, "tie-rod", "S275", 1)
    rod = candidate_table(plan, 16.0)["restrainers"][1]
    assert rod["diameter"] == pytest.approx(0.016)
    assert (rod["radius"], rod["angle"], rod["length"]) == (7.0, 0.072, 3.0)


def test_candidate_stiffness_and_strength_come_from_the_derivation() -> None:
    # Ø20 S275, L = 3 m: K = E·π·d²/4 / L = 210e9·π·0.02²/4/3 = 2.1991e7 N/m (paper Table 2:
    # 22.0E6); N_t,Rd = min(A·fy/γM0, 0.9·A·fu/γM2) = min(314.16 mm²·275/1.05,
    # 0.9·314.16·430/1.25) N = 82.28 kN (NTC 2018 §4.2.4.1.2). 1e-9: the same formulas.
    rod = to_block(build_candidate(plan_of(facade()), 20.0)).restrainers[1]
    assert rod.k_pos == pytest.approx(210e9 * math.pi * 0.02**2 / 4 / 3.0, rel=1e-9)
    area = math.pi * 0.02**2 / 4
    assert rod.strength == pytest.approx(min(area * 275e6 / 1.05, 0.9 * area * 430e6 / 1.25))


def test_grade_and_count_options_replace_the_models() -> None:
    table = facade()
    table["restrainers"][1].pop("grade")
    table["restrainers"][1].update(fy=200e6, fu=300e6, count=2)
    plan = plan_of(table)
    assert (plan.grade, plan.count) == ("S275", 2)  # no grade in the model: S275
    rod = candidate_table(plan, 20.0)["restrainers"][1]
    assert "fy" not in rod and "fu" not in rod and rod["grade"] == "S275"
    plan = plan_of(table, grade="S355", count=3)
    assert candidate_table(plan, 20.0)["restrainers"][1]["count"] == 3


def test_candidate_table_leaves_the_base_alone() -> None:
    table = facade()
    before = copy.deepcopy(table)
    candidate_table(plan_of(table), 40.0)
    assert table == before


def test_unknown_grade() -> None:
    with pytest.raises(InputError) as info:
        plan_of(facade(), grade="S500")
    assert str(info.value) == "--grade: unknown steel grade (got 'S500'; allowed: S235, S275, S355)"


def test_no_tie_rod_and_no_at() -> None:
    table = facade()
    del table["restrainers"][1]
    with pytest.raises(InputError) as info:
        plan_of(table)
    assert info.value.where == "restrainers"
    assert 'no kind = "tie-rod" restrainer' in info.value.problem
    assert "--at HEIGHT,FROM_PIVOT --length L" in str(info.value.allowed)


def test_several_tie_rods_need_a_name() -> None:
    table = facade()
    second = {**table["restrainers"][1], "name": "upper rod", "radius": 9.0}
    table["restrainers"].append(second)
    with pytest.raises(InputError) as info:
        plan_of(table)
    assert info.value.problem == "several tie-rods"
    assert info.value.allowed == "--name with one of 'tie-rod', 'upper rod'"
    assert plan_of(table, name="upper rod").index == 2
    with pytest.raises(InputError, match="no tie-rod of that name"):
        plan_of(table, name="vault")


def test_placed_rod_is_added() -> None:
    table = facade()
    plan = plan_of(table, placement=Placement(9.0, 0.2, 4.0))
    assert (plan.index, plan.name) == (2, PLACED_NAME)
    rods = candidate_table(plan, 16.0)["restrainers"]
    assert len(rods) == 3 and rods[1] == table["restrainers"][1]
    assert rods[2]["height"] == 9.0 and rods[2]["from_pivot"] == 0.2 and rods[2]["length"] == 4.0
    assert plan_of(table, placement=Placement(HEIGHT, THICKNESS, 4.0)).index == 2  # the corner


@pytest.mark.parametrize(
    ("height", "from_pivot", "problem"),
    [
        (HEIGHT * 1.01, 0.2, "height outside the block"),
        (-1.0, 0.2, "height outside the block"),
        (0.0, 0.2, "height outside the block"),
        (5.0, THICKNESS * 1.01, "from_pivot outside the block"),
        (5.0, -0.1, "from_pivot outside the block"),
    ],
)
def test_placement_outside_the_block(height: float, from_pivot: float, problem: str) -> None:
    with pytest.raises(InputError) as info:
        plan_of(facade(), placement=Placement(height, from_pivot, 4.0))
    assert (info.value.where, info.value.problem) == ("--at", problem)


def test_name_with_at_is_refused() -> None:
    with pytest.raises(InputError, match="not with --at"):
        plan_of(facade(), name="tie-rod", placement=Placement(5.0, 0.2, 4.0))


def test_a_diameter_that_makes_the_model_invalid_is_named() -> None:
    # A pretension of 50 kN is above the yield force of a Ø10 S275 bar (78.5 mm²·275 MPa =
    # 21.6 kN) but below a Ø20's (86.4 kN): the schema refuses the Ø10 candidate.
    table = facade()
    table["restrainers"][1]["pretension"] = 50e3
    with pytest.raises(InputError) as info:
        plan_of(table, diameters_mm=(10.0, 20.0))
    assert info.value.where == "--diameters"
    assert info.value.problem.startswith("the rod of 10 mm makes the model invalid: ")
    assert "pretension" in info.value.problem
    assert plan_of(table, diameters_mm=(20.0,)).diameters_mm == (20.0,)


def test_grade_is_read_in_any_case() -> None:
    assert plan_of(facade(), grade="s355").grade == "S355"
