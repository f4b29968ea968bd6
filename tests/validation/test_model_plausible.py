"""Unit slips give warnings, not silent confident verdicts (issue 7, item 6, model part).

A valid file whose magnitudes look like a slip of units (a thickness in mm, a height in cm,
a weight in tonnes) loads, and :func:`model_warnings` names the field, the value and the
likely slip. On main there was no such function, hence no warning at all.
"""

from __future__ import annotations

import copy
import json
import math
import tomllib
from pathlib import Path
from typing import Any

import pytest
import tomli_w

from rockcli.errors import InputError
from rockcli.model.load import load_model, validate_model
from rockcli.model.plausible import model_warnings
from rockcli.model.template import TEMPLATES

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted(p for p in (ROOT / "examples").glob("*.toml"))

#: A plausible wall: 0.5 × 4 × 3 m, 18 kN/m³ (the paper's §4.4), with a 20 mm tie-rod.
WALL: dict[str, Any] = {
    "name": "wall",
    "kind": "wall",
    "geometry": {"thickness": 0.5, "height": 4.0, "width": 3.0},
    "mass": {"unit_weight": 18.0},
    "restrainers": [
        {"kind": "tie-rod", "diameter": 0.02, "length": 3.0, "position": "top"},
    ],
}


def warnings_of(**tables: dict[str, Any]) -> tuple[str, ...]:
    data = copy.deepcopy(WALL)
    data.update(tables)
    return model_warnings(validate_model(data))


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.name for p in EXAMPLES])
def test_examples_give_no_warning(path: Path) -> None:
    assert model_warnings(load_model(path)) == ()


@pytest.mark.parametrize("kind", list(TEMPLATES))
def test_templates_give_no_warning(kind: Any) -> None:
    assert model_warnings(validate_model(TEMPLATES[kind])) == ()


def test_plausible_wall_gives_no_warning() -> None:
    assert warnings_of() == ()


def test_thickness_in_millimetres() -> None:
    # The case: thickness 500 (mm) with height 4 m → α = atan(250/2) = 1.5628 rad.
    found = warnings_of(geometry={"thickness": 500.0, "height": 4.0, "width": 3.0})
    assert any("thickness 2b = 500 m" in w and "millimetres" in w for w in found)
    assert any(f"α = {math.atan(250 / 2):.4g} rad > π/4" in w for w in found)
    assert f"{math.atan(250 / 2):.4g}" == "1.563"


def test_height_in_centimetres() -> None:
    found = warnings_of(geometry={"thickness": 0.5, "height": 400.0, "width": 3.0})
    assert any(w.startswith("geometry: height 2h = 400 m") for w in found)


def test_height_in_millimetres_is_out_of_range() -> None:
    # 4000 m exceeds the 1 km bound of every length (rockcli/model/bounds.py): an error.
    with pytest.raises(InputError, match=r"geometry\.height: out of range"):
        validate_model({**WALL, "geometry": {"thickness": 0.5, "height": 4000.0, "width": 3.0}})


def test_semi_diagonal_above_100_m() -> None:
    found = warnings_of(geometry={"R": 150.0, "alpha": 0.1, "width": 3.0})
    assert any("semi-diagonal R = 150 m" in w for w in found)


def test_thickness_above_height() -> None:
    found = warnings_of(geometry={"thickness": 4.0, "height": 0.5, "width": 3.0})
    assert len(found) == 1
    assert "thickness 2b = 4 m exceeds height 2h = 0.5 m" in found[0]
    assert "swapped" in found[0]


def test_unit_weight_in_tonnes_per_cubic_metre() -> None:
    (found,) = warnings_of(mass={"unit_weight": 1.8})
    assert found.startswith("mass.unit_weight = 1.8 kN/m³, outside masonry's 10–30 kN/m³")


@pytest.mark.parametrize(("weight", "warned"), [(108.0, False), (1080.0, True), (10.8, True)])
def test_weight_inconsistent_with_the_volume(weight: float, warned: bool) -> None:
    # Volume 0.5·4·3 = 6 m³: 108 kN is 18 kN/m³ (plausible); ×10 and ÷10 are not.
    found = warnings_of(mass={"weight": weight})
    assert bool(found) is warned
    if warned:
        assert f"mass.weight = {weight:g} kN over the volume" in found[0]
        assert f"gives {weight / 6:.4g} kN/m³" in found[0]


def test_tie_rod_diameter_in_millimetres() -> None:
    # A long rod keeps E·A/L inside the stiffness bound (2.1e11·π·10²/100 = 6.6e11 N/m), so
    # the slip is a warning; a short one is refused outright (see test_model_bounds.py).
    rod = {"kind": "tie-rod", "diameter": 20.0, "length": 100.0, "position": "top"}
    (found,) = warnings_of(restrainers=[rod])
    assert found.startswith("restrainers[0].diameter = 20 m")


@pytest.mark.parametrize("g", [981.0, 1.0, 32.17])
def test_gravity_in_other_units_is_out_of_range(g: float) -> None:
    # g in cm/s², in g, in ft/s²: outside the Earth's 9.76–9.83 m/s² by a factor of 3 or
    # more, refused by the schema's bounds (9 to 10 m/s², rockcli/model/bounds.py).
    with pytest.raises(InputError, match=r"analysis\.g: out of range") as info:
        warnings_of(analysis={"g": g})
    assert info.value.allowed == "a number >= 9 and <= 10 [m/s²]"


@pytest.mark.parametrize(("g", "warned"), [(9.3, True), (9.81, False), (10.0, False)])
def test_gravity_far_from_the_earths_warns(g: float, warned: bool) -> None:
    # Within the bounds but more than 2 % from 9.80665 m/s² (below 9.61): a typo.
    found = warnings_of(analysis={"g": g})
    assert bool(found) is warned
    if warned:
        assert found[0].startswith(f"analysis.g = {g:g} m/s², more than 2% from")


# Issue 19, item 4: a restrainer typed in kN where N is asked ----------------------------------

#: The issue's restrainer on the 108 kN wall (0.5 × 4 × 3 m at 18 kN/m³, WALL), typed in kN
#: where N is asked: meant 80 kN yield, 60 kN anchor and 2.2e7 N/m (the paper's Ø 20 mm rod,
#: Table 2), given as 80, 60 and 2.2e4.
KN_SLIP: dict[str, Any] = {
    "name": "tie",
    "k": 2.2e4,
    "yield_pos": 80.0,
    "yield_neg": 80.0,
    "anchor_capacity": 60.0,
    "position": "top",
}
FACADE = ROOT / "examples" / "facade.toml"


def facade_with(index: int, **changes: Any) -> tuple[str, ...]:
    """The warnings of examples/facade.toml with restrainer ``index`` changed."""
    table = tomllib.loads(FACADE.read_text(encoding="utf-8"))
    table["restrainers"][index].update(changes)
    return model_warnings(validate_model(table))


def test_restrainer_forces_in_kn_warn_and_state_the_bound() -> None:
    # At the top, z = 2h = 4 m: W·b/z = 108 kN · 0.25 m / 4 m = 6750 N, and 2 % of it 135 N.
    (found,) = warnings_of(restrainers=[KN_SLIP])
    assert found.startswith(
        "restrainers[0]: yield_pos = 80 N, yield_neg = 80 N, anchor_capacity = 60 N, below 2% "
        "of W·b/z = 6750 N"
    )
    assert "z = 4 m" in found and "W = 108 kN" in found and "in kN where N is asked" in found


def test_the_same_restrainer_in_newtons_does_not_warn() -> None:
    tie = {**KN_SLIP, "k": 2.2e7, "yield_pos": 80e3, "yield_neg": 80e3, "anchor_capacity": 60e3}
    assert warnings_of(restrainers=[tie]) == ()


@pytest.mark.parametrize(("height", "warned"), [(1.0, True), (4.0, False)])
def test_the_strength_bound_follows_the_height(height: float, warned: bool) -> None:
    # 500 N: below 2 % of 108 kN · 0.25 m / 1 m = 27 kN (540 N) at z = 1 m, above 2 % of
    # 6.75 kN (135 N) at z = 4 m.
    tie = {"k": 2.2e7, "anchor_capacity": 500.0, "height": height, "from_pivot": 0.25}
    found = warnings_of(restrainers=[tie])
    assert bool(found) is warned
    if warned:
        assert "anchor_capacity = 500 N, below 2% of W·b/z = 2.7e+04 N" in found[0]


def test_a_tie_rod_too_thin_for_its_block_warns_with_its_design_strength() -> None:
    # Ø 2 mm S275: N_pl,Rd = π·(0.001 m)²·275 MPa / 1.05 = 822.8 N (NTC 2018 §4.2.4.1.2);
    # the façade (1755 kN, b = 5.04·sin 0.05 = 0.2519 m) at z = 7·cos 0.072 = 6.982 m:
    # W·b/z = 1755 kN · 0.2519 m / 6.982 m = 63.32 kN, 2 % = 1266 N. Its stiffness, 2.2e5 N/m,
    # still gives c_K/c_E = 2.2e5·7²/(1755e3·5.04) = 1.2.
    (found,) = facade_with(1, diameter=0.002)
    assert found.startswith("restrainers[1]: its design yield force N_pl,Rd = 822.8 N, below 2%")
    assert "W·b/z = 6.332e+04 N" in found


def test_a_stiffness_in_kn_per_mm_warns() -> None:
    # The vault's 4e6 N/m typed in kN/mm (4): c_K/c_E = K·r²/(W·R) = 4·7²/(1755e3·5.04)
    # = 2.22e-05, below 1e-3, the same on both sides (radius and angle fix r on both).
    (found,) = facade_with(0, k=4.0)
    assert found.startswith("restrainers[0]: stiffness K = 4 N/m (both sides) gives c_K/c_E")
    assert "= 2.22e-05, below 0.001" in found


def test_the_papers_softest_springs_do_not_warn() -> None:
    """§4.4's grid (examples/studies/paper-4.4.toml): K = 1e3, 1e4, 1e6 N/m at the top of
    walls 3 m wide at 18 kN/m³, R = 1.5–10 m, α = 0.05–0.25 rad. Its smallest c_K/c_E =
    4KR/W is K = 1e3 on R = 10, α = 0.25: W = 18e3·(2R sin α)(2R cos α)·3 = 5.18e6 N, so
    0.0077, above the 1e-3 bound."""
    W = 18e3 * (2 * 10 * math.sin(0.25)) * (2 * 10 * math.cos(0.25)) * 3
    assert 4 * 1e3 * 10 / W == pytest.approx(0.0077, abs=5e-5)
    for R in (1.5, 2.0, 2.5, 3.0, 3.5, 7.0, 10.0):
        for alpha in (0.05, 0.10, 0.15, 0.25):
            for k in (1e3, 1e4, 1e6):
                spring = {"position": "top", "k_pos": k, "k_neg": k}
                geometry = {"R": R, "alpha": alpha, "width": 3.0}
                assert warnings_of(geometry=geometry, restrainers=[spring]) == (), (R, alpha, k)


MODELS = sorted(
    [*(ROOT / "examples" / "validation" / "models").glob("*.toml"),
     *(ROOT / "examples" / "studies").glob("*-wall.toml")]
)  # fmt: skip


@pytest.mark.parametrize("path", MODELS, ids=[p.name for p in MODELS])
def test_study_and_validation_models_give_no_warning(path: Path) -> None:
    assert model_warnings(load_model(path)) == ()


def test_the_restrainer_warning_reaches_the_assess_table_and_json(tmp_path: Path) -> None:
    from click.testing import CliRunner

    from rockcli.cli.main import cli

    model = tmp_path / "kn.toml"
    model.write_text(tomli_w.dumps({**copy.deepcopy(WALL), "restrainers": [KN_SLIP]}))
    pulse = str(next((ROOT / "records").glob("*.txt")))
    args = ["assess", str(model), "--record", pulse]
    result = CliRunner().invoke(cli, [*args, "--format", "json"])
    assert result.exit_code == 0, result.stderr
    assert any("anchor_capacity = 60 N" in w for w in json.loads(result.stdout)["warnings"])
    result = CliRunner().invoke(cli, args)
    assert "warning: restrainers[0]: yield_pos = 80 N" in result.stdout
