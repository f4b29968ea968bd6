"""Unit slips give warnings, not silent confident verdicts (issue 7, item 6, model part).

A valid file whose magnitudes look like a slip of units (a thickness in mm, a height in cm,
a weight in tonnes) loads, and :func:`model_warnings` names the field, the value and the
likely slip. On main there was no such function, hence no warning at all.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path
from typing import Any

import pytest

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
def test_gravity_in_other_units(g: float) -> None:
    (found,) = warnings_of(analysis={"g": g})
    assert found.startswith(f"analysis.g = {g:g} m/s²")
