"""[[loads]], [[thrusts]] and [building]: the wall's physical description in the model.

Source: issue 8, items 1 and 6 (the loads and the building move out of [ntc] so both analyses
read them; the contract of the keys is the issue's). Every bad input is one line naming the
file, the key, the value and what is allowed, exit 2 through the CLI; a valid model gives a
block whose loads and thrusts carry the file's numbers in SI units (kN → N, x_neg = 2b − x).
No rocking result is asserted: the physics of loads is not this module's.
"""

from __future__ import annotations

import copy
from pathlib import Path
from typing import Any

import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.mechanics import NEGATIVE, POSITIVE
from rockcli.model.catalogue import catalogue
from rockcli.model.derive import describe, to_block
from rockcli.model.derive_ntc import building_settings, ntc_settings
from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"

#: A wall 2b = 0.5 m thick, 2h = 3.0 m high (b = 0.25, h = 1.5: exact in binary), with a
#: floor at the top, a tied floor that only pushes, and a roof thrust towards θ < 0.
VALID: dict[str, Any] = {
    "name": "wall with loads",
    "kind": "wall",
    "geometry": {"thickness": 0.5, "height": 3.0, "width": 3.0},
    "mass": {"unit_weight": 18.0},
    "loads": [
        {"name": "floor", "weight": 20.0, "position": "top"},
        {"weight": 5.0, "height": 1.25, "from_pivot": 0.125, "bears": False},
    ],
    "thrusts": [{"name": "roof", "force": 8.0, "direction": "negative", "height": 2.5}],
    "building": {"Z": 3.0, "H": 9.0, "N": 3},
    "ntc": {"edition": "2009"},
}


def write(tmp_path: Path, data: dict[str, Any]) -> Path:
    path = tmp_path / "m.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    return path


def changed(path: tuple[Any, ...], value: Any) -> dict[str, Any]:
    """VALID with the value at ``path`` replaced (``None``: the key removed)."""
    data = copy.deepcopy(VALID)
    node: Any = data
    for key in path[:-1]:
        node = node.setdefault(key, {}) if isinstance(key, str) else node[key]
    if value is None:
        node.pop(path[-1], None)
    else:
        node[path[-1]] = value
    return data


def error_of(tmp_path: Path, data: dict[str, Any]) -> InputError:
    with pytest.raises(InputError) as info:
        load_model(write(tmp_path, data))
    return info.value


# --- a valid model: the block's loads and thrusts -------------------------------------------


def test_the_block_carries_the_loads_in_newtons_about_each_pivot(tmp_path: Path) -> None:
    block = to_block(load_model(write(tmp_path, VALID)))
    floor, tied = block.loads
    # position = "top": z = 2h = 3.0, x = b = 0.25 from both pivots; 20 kN = 20 000 N.
    assert (floor.name, floor.weight, floor.x_pos, floor.x_neg, floor.z) == (
        "floor",
        20_000.0,
        0.25,
        0.25,
        3.0,
    )
    assert (floor.bears, floor.moves) == (True, True)
    # x_neg = 2b − x = 0.5 − 0.125 = 0.375 (exact in binary); unnamed: "load 2".
    assert (tied.name, tied.weight, tied.x_pos, tied.x_neg, tied.z) == (
        "load 2",
        5_000.0,
        0.125,
        0.375,
        1.25,
    )
    assert (tied.bears, tied.moves) == (False, True)


def test_the_block_carries_the_thrusts_with_their_direction(tmp_path: Path) -> None:
    (roof,) = to_block(load_model(write(tmp_path, VALID))).thrusts
    # 8 kN = 8000 N towards θ < 0, at the mid-plane (default from_pivot = b = 0.25).
    assert (roof.name, roof.force, roof.direction) == ("roof", 8_000.0, NEGATIVE)
    assert (roof.x_pos, roof.x_neg, roof.z) == (0.25, 0.25, 2.5)
    data = changed(("thrusts", 0, "direction"), "positive")
    assert to_block(load_model(write(tmp_path, data))).thrusts[0].direction == POSITIVE


def test_the_description_lists_the_loads_and_thrusts_of_the_block(tmp_path: Path) -> None:
    model = load_model(write(tmp_path, VALID))
    block, description = to_block(model), describe(model)
    assert (description.loads, description.thrusts) == (block.loads, block.thrusts)


def test_a_point_on_the_face_within_the_rounding_slack_is_at_zero_from_the_other_pivot(
    tmp_path: Path,
) -> None:
    # from_pivot = 0.504 is 0.8 % past 2b = 0.5, inside the 1 % slack for rounded files:
    # accepted, and 2b − x < 0 is clamped to 0 (a point cannot be behind the other pivot).
    data = changed(("loads", 1, "from_pivot"), 0.504)
    assert to_block(load_model(write(tmp_path, data))).loads[1].x_neg == 0.0


def test_the_building_feeds_the_code_settings(tmp_path: Path) -> None:
    model = load_model(write(tmp_path, VALID))
    building = building_settings(model)
    assert (building.Z, building.H, building.N, building.T1) == (3.0, 9.0, 3, None)
    assert building.damping == 0.05  # the default, the code's 5 % spectra
    assert ntc_settings(model).building == building


def test_a_model_without_building_is_on_the_ground(tmp_path: Path) -> None:
    data = changed(("building",), None)
    assert building_settings(load_model(write(tmp_path, data))).Z == 0.0


def test_the_kinematic_mechanism_carries_the_models_loads_and_thrusts(tmp_path: Path) -> None:
    # The code check reads the same block as the rocking analysis: its loads and thrusts.
    model = load_model(write(tmp_path, VALID))
    block, settings = to_block(model), ntc_settings(model)
    (only,) = catalogue(model)
    for side in (POSITIVE, NEGATIVE):
        mech = only.check(side, settings.distributed, settings.edition == "2019")
        assert mech.side == side
        assert (mech.view.block.loads, mech.view.block.thrusts) == (block.loads, block.thrusts)


# --- bad input: one line naming the key, the value and what is allowed ----------------------

BAD = [
    # (path, value, where, problem, fragment of what is allowed)
    (("loads", 0, "from_pivot"), 0.6, "loads[0].from_pivot", "outside the block", "2b = 0.5"),
    (("loads", 1, "height"), 3.5, "loads[1].height", "outside the block", "2h = 3"),
    (("thrusts", 0, "from_pivot"), 0.8, "thrusts[0].from_pivot", "outside the block", "2b"),
    (("thrusts", 0, "height"), 3.2, "thrusts[0].height", "outside the block", "2h = 3"),
    (("loads", 0, "weight"), -1.0, "loads[0].weight", "out of range", "[kN]"),
    (("loads", 0, "weight"), 0.0, "loads[0].weight", "out of range", "[kN]"),
    (("thrusts", 0, "force"), 0.0, "thrusts[0].force", "out of range", "[kN]"),
    (("thrusts", 0, "force"), -2.0, "thrusts[0].force", "out of range", "[kN]"),
    (("thrusts", 0, "direction"), "up", "thrusts[0].direction", "unknown value", "positive"),
    (("thrusts", 0, "direction"), None, "thrusts[0].direction", "missing key", "required"),
    (("building", "Z"), 12.0, "building.Z", "above the building height H = 9 m", "Z <= H"),
    (("building", "H"), None, "building.H", "required when Z > 0", "[m]"),
    (("building", "T1"), 0.0, "building.T1", "out of range", "[s]"),
    (("building", "T1"), -0.5, "building.T1", "out of range", "[s]"),
    (("building", "psi"), 1.6, "building.psi", "out of range", "<= 1"),
    (("building", "psi"), -0.1, "building.psi", "out of range", ">= 0.001"),
    (("building", "damping"), 0.6, "building.damping", "out of range", "<= 0.5"),
    (("building", "damping"), 0.0, "building.damping", "out of range", "> 0"),
    # Derived: 200 kN pushing at 2.5 m against 81 kN of wall (W·b ≈ 20 kN·m): it falls at rest.
    (("thrusts", 0, "force"), 200.0, "thrusts", "overturn the block towards θ < 0", "α0 > 0"),
    (("analysis", "linearized"), True, "analysis.linearized", "lone block", "false with"),
    (("loads", 0, "bears"), "yes", "loads[0].bears", "not a boolean", "true or false"),
    (("loads", 0, "height"), 2.0, "loads[0].position", "not allowed together", "height"),
    (("loads", 0, "position"), None, "loads[0]", "missing the point", 'position = "top"'),
]


@pytest.mark.parametrize(
    ("path", "value", "where", "problem", "allowed"),
    BAD,
    ids=[f"{w}={v}" for _, v, w, _, _ in BAD],
)
def test_bad_value_is_one_line(
    tmp_path: Path, path: tuple[Any, ...], value: Any, where: str, problem: str, allowed: str
) -> None:
    err = error_of(tmp_path, changed(path, value))
    assert err.where == where
    assert problem in err.problem
    assert err.allowed is not None and allowed in err.allowed
    assert "\n" not in str(err)


def test_a_load_that_neither_bears_nor_moves_is_refused(tmp_path: Path) -> None:
    data = changed(("loads", 0, "bears"), False)
    data["loads"][0]["moves"] = False
    err = error_of(tmp_path, data)
    assert err.where == "loads[0].moves" and "does nothing" in err.problem
    assert err.allowed is not None and "bears = true" in err.allowed


@pytest.mark.parametrize("table", ["loads", "thrusts"])
def test_loads_and_thrusts_need_the_block_weight(tmp_path: Path, table: str) -> None:
    data = changed(("mass",), None)
    data.pop("thrusts" if table == "loads" else "loads")
    err = error_of(tmp_path, data)
    assert err.where == "mass" and f"[[{table}]]" in err.problem
    assert err.allowed is not None and "[mass]" in err.allowed


MOVED = [
    ("Z", 3.0, "[building] Z"),
    ("H", 9.0, "[building] H"),
    ("N", 3, "[building] N"),
    ("T1", 0.3, "[building] T1"),
    ("gamma", 1.2, "[building] gamma"),
    ("psi", 0.5, "[building] psi"),
    ("loads", [{"weight": 5.0, "height": 1.0}], "[[loads]]"),
]


@pytest.mark.parametrize(("key", "value", "allowed"), MOVED, ids=[k for k, _, _ in MOVED])
def test_each_old_ntc_key_names_its_new_place(
    tmp_path: Path, key: str, value: Any, allowed: str
) -> None:
    err = error_of(tmp_path, changed(("ntc", key), value))
    assert err.where == f"ntc.{key}"
    assert err.problem.startswith("moved to ")
    assert err.allowed is not None and err.allowed.startswith(allowed)
    # One error, not also an "unknown key" for the same key.
    assert str(err).count("ntc.") == 1


def test_an_old_file_hears_of_every_moved_key_at_once(tmp_path: Path) -> None:
    # An [ntc] table written for rock before the move: one line, the first key as the error,
    # the others named with their new place, so the file is fixed in one edit.
    data = copy.deepcopy(VALID)
    data["ntc"].update({"Z": 3.0, "H": 9.0, "loads": [{"weight": 5.0, "height": 1.0}]})
    err = error_of(tmp_path, data)
    assert err.where == "ntc.Z"
    assert err.problem.endswith("also moved: ntc.H to [building], ntc.loads to [[loads]]")


# --- through the CLI: exit 2 and the one line the user sees ---------------------------------


def run(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stderr


def test_kinematic_refuses_an_old_key_with_the_exact_line(tmp_path: Path) -> None:
    path = write(tmp_path, changed(("ntc", "Z"), 3.0))
    code, err = run("kinematic", str(path))
    assert code == 2
    assert err == (
        f"error: {path}: ntc.Z: moved to [building] (the building is shared by both analyses) "
        "(got 3.0; allowed: [building] Z = height of the base above the foundation [m])\n"
    )


def test_kinematic_refuses_a_load_outside_the_block(tmp_path: Path) -> None:
    path = write(tmp_path, changed(("loads", 0, "from_pivot"), 0.6))
    code, err = run("kinematic", str(path))
    assert code == 2
    assert err == (
        f"error: {path}: loads[0].from_pivot: outside the block "
        "(got 0.6; allowed: a number >= 0 and <= the thickness 2b = 0.5 [m])\n"
    )


def test_assess_refuses_a_load_that_does_nothing(tmp_path: Path) -> None:
    data = changed(("loads", 0, "bears"), False)
    data["loads"][0]["moves"] = False
    code, err = run("assess", str(write(tmp_path, data)), "--record", str(PULSE))
    assert code == 2
    assert err.startswith("error: ") and "loads[0].moves" in err and err.count("\n") == 1


def test_assess_refuses_a_thrust_without_direction(tmp_path: Path) -> None:
    path = write(tmp_path, changed(("thrusts", 0, "direction"), None))
    code, err = run("assess", str(path), "--record", str(PULSE))
    assert code == 2
    assert f"{path}: thrusts[0].direction: missing key" in err and err.count("\n") == 1
