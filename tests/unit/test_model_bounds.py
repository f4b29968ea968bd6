"""Absurd magnitudes and deep nesting: an error line, never a traceback (issue 7, item 9).

On main, ``g = 1e300``, ``weight = 1e-300``, ``radius = 1e300`` or ``k = 1.8e308`` loaded and
reached the core (OverflowError, ZeroDivisionError or NaN), and a TOML value nested 500 deep
raised RecursionError. Every number of the file now has a physical range
(rockcli/model/bounds.py) and the derived block is checked finite.
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
from rockcli.mechanics import Block
from rockcli.model.bounds import MIN_FORCE, MIN_WEIGHT
from rockcli.model.derived_checks import check_block
from rockcli.model.load import load_model, validate_model
from rockcli.model.schema import FORCE_KEYS, MAX_ANCHOR
from rockcli.terminal.schema_doc import bounds, sections, table_class

#: A valid wall with a spring at the top (needs a mass).
VALID: dict[str, Any] = {
    "name": "bounded wall",
    "kind": "wall",
    "geometry": {"thickness": 0.5, "height": 4.0, "width": 3.0},
    "mass": {"unit_weight": 18.0},
    "restrainers": [{"k": 1e6, "radius": 4.0, "angle": 0.1}],
}


#: The keys that, with the one under test, make a valid [[loads]] or [[thrusts]] table.
AT_THE_TOP: dict[str, dict[str, Any]] = {
    "loads": {"position": "top"},
    "thrusts": {"position": "top", "direction": "positive"},
}


def with_value(path: tuple[Any, ...], value: Any) -> dict[str, Any]:
    data = copy.deepcopy(VALID)
    target: Any = data
    for key in path[:-1]:
        if key in AT_THE_TOP:  # an array of tables: one valid table but for the value
            target = target.setdefault(key, [dict(AT_THE_TOP[key])])
        else:
            target = target.setdefault(key, {}) if isinstance(key, str) else target[key]
    target[path[-1]] = value
    return data


ABSURD = [
    (("geometry", "thickness"), 1e300),
    (("geometry", "height"), 1e-300),
    (("geometry", "width"), 1e300),
    (("mass", "unit_weight"), 1e-300),
    (("restrainers", 0, "radius"), 1e300),
    (("restrainers", 0, "k"), 1.7e308),  # the issue's 1.8e308 is inf: refused on main too
    (("ntc", "VN"), 1e300),
    (("ntc", "q"), 1e300),
    (("building", "gamma"), 1e300),
    (("loads", 0, "weight"), 1e300),
    (("thrusts", 0, "force"), 1e300),
]


@pytest.mark.parametrize(("path", "value"), ABSURD, ids=[".".join(map(str, p)) for p, _ in ABSURD])
def test_absurd_magnitude_is_out_of_range(path: tuple[Any, ...], value: float) -> None:
    with pytest.raises(InputError, match="out of range") as info:
        validate_model(with_value(path, value), file="m.toml")
    where = "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in path).lstrip(".")
    assert (info.value.file, info.value.where, info.value.value) == ("m.toml", where, value)


@pytest.mark.parametrize("weight", [1e-300, 1e300])
def test_absurd_weight_is_out_of_range(weight: float) -> None:
    data = copy.deepcopy(VALID)
    data["mass"] = {"weight": weight}
    with pytest.raises(InputError, match=r"mass\.weight: out of range"):
        validate_model(data)


def test_every_number_has_a_lower_and_an_upper_bound() -> None:
    # A one-sided bound (gt=0 on main) let 1e300 and 1e-300 through; analysis.g and
    # analysis.rest_velocity had one until issue 20 (g = 1e300, rest_velocity = 0.1 turning an
    # overturning block into a survivor).
    unbounded = []
    for section in sections():
        for key, info in section.table.model_fields.items():
            if table_class(info.annotation) is not None or info.annotation not in (
                float | None,
                float,
                int | None,
                int,
            ):
                continue
            found = bounds(info)
            if not ({"gt", "ge"} & found.keys() and {"lt", "le"} & found.keys()):
                unbounded.append(f"{section.paths[0]}.{key}".lstrip("."))
    assert not unbounded


@pytest.mark.parametrize("g", [1e308, 1e305, 1e300, 1e-300, 5e-324, 981.0])
def test_gravity_out_of_the_earths_range_is_refused(g: float) -> None:
    # Issue 20, item 8: g = 1e300 and 1e-300 passed the schema (gt=0 only) and reached the
    # engines (1e-300 hung `rock compare`); 1e308, 5e-324 and 1e305 were caught only on the
    # derived block (3g/(4R) overflowing, vanishing, K r²/I0 overflowing). Bounds 9–10 m/s².
    data = copy.deepcopy(VALID)
    data["analysis"] = {"g": g}
    with pytest.raises(InputError, match="out of range") as info:
        validate_model(data, file="m.toml")
    assert (info.value.file, info.value.where, info.value.value) == ("m.toml", "analysis.g", g)
    assert info.value.allowed == "a number >= 9 and <= 10 [m/s²]"


def test_check_block_accepts_a_real_block() -> None:
    check_block(Block(R=1.499, alpha=0.163, mass=3000.0))


@pytest.mark.parametrize(
    "block",
    [
        Block(R=1e-320, alpha=0.163),
        Block(R=1.0, alpha=0.1, mass=5e-324 / 9.81),
        Block(R=1.0, alpha=0.1, g=float("nan")),
    ],
    ids=["subnormal R", "zero mass", "NaN gravity"],
)
def test_check_block_refuses_a_degenerate_block(block: Block) -> None:
    with pytest.raises(InputError, match="not usable"):
        check_block(block)


@pytest.mark.parametrize(
    "value", ["[" * 500 + "1" + "]" * 500, "{a=" * 500 + "1" + "}" * 500], ids=["array", "table"]
)
def test_toml_nested_500_deep_names_the_line(tmp_path: Path, value: str) -> None:
    path = tmp_path / "deep.toml"
    path.write_text(f'name = "x"\nkind = "wall"\nnotes = {value}\n', encoding="utf-8")
    with pytest.raises(InputError, match="nested too deep") as info:
        load_model(path)
    assert (info.value.file, info.value.where) == (str(path), "line 3")


@pytest.mark.parametrize("g", [1e305, 1e300, 1e-300])
def test_rock_kinematic_on_absurd_gravity_exits_2(tmp_path: Path, g: float) -> None:
    path = tmp_path / "m.toml"
    data = {**VALID, "restrainers": [{"k": 1e9, "radius": 4.0, "angle": 0.1}]}
    path.write_text(tomli_w.dumps({**data, "analysis": {"g": g}}), encoding="utf-8")
    result = CliRunner().invoke(cli, ["kinematic", str(path)])
    assert result.exit_code == 2, result.output
    assert result.stderr.startswith(f"error: {path}: analysis.g: out of range (got {g!r}; ")


#: Found by the model-fuzz campaign: each loaded on main and crashed `rock kinematic`
#: (ZeroDivisionError for α = 5e-324; an infinite capacity/demand ratio, then a JSON
#: ValueError, for ag = 5e-324; NaN in the JSON for T1 = 5e-324, OverflowError for 1e-300).
FUZZ_FOUND = [
    ({"geometry": {"R": 1.5, "alpha": 5e-324, "width": 3.0}}, "geometry.alpha"),
    (
        {"ntc": {"demand": {"SLV": {"ag": 5e-324, "F0": 2.5, "Tc_star": 0.3}}}},
        "ntc.demand.SLV.ag",
    ),
    (
        {"ntc": {"demand": {"SLV": {"ag": 0.15, "F0": 2.5, "Tc_star": 5e-324}}}},
        "ntc.demand.SLV.Tc_star",
    ),
    ({"building": {"Z": 5e-324, "H": 9.0, "N": 3}}, "building.Z"),
    ({"building": {"Z": 3.0, "H": 9.0, "N": 3, "psi": 5e-324}}, "building.psi"),
    ({"building": {"Z": 3.0, "H": 9.0, "N": 3, "T1": 5e-324}}, "building.T1"),
]


@pytest.mark.parametrize(("tables", "where"), FUZZ_FOUND, ids=[w for _, w in FUZZ_FOUND])
def test_subnormal_inputs_found_by_fuzzing_are_refused(
    tables: dict[str, Any], where: str, tmp_path: Path
) -> None:
    path = tmp_path / "m.toml"
    path.write_text(tomli_w.dumps({**VALID, **tables}), encoding="utf-8")
    result = CliRunner().invoke(cli, ["kinematic", str(path), "--format", "json"])
    assert result.exit_code == 2, result.output
    assert result.stderr.startswith(f"error: {path}: {where}: ")
    assert "5e-324" in result.stderr


def test_a_tie_rod_whose_derived_stiffness_is_out_of_range_is_refused(tmp_path: Path) -> None:
    # Found in review: a tie-rod's K = E·A/L is derived, so the schema's stiffness bound did not
    # hold it (d = 1000 m, L = 1 mm, E = 1.2e12 Pa → K ≈ 9.4e20 N/m ran for minutes).
    from rockcli.model.load import load_model

    path = tmp_path / "rod.toml"
    path.write_text(
        'name = "rod"\nkind = "wall"\n[geometry]\nthickness = 0.5\nheight = 4.0\nwidth = 3.0\n'
        '[mass]\nunit_weight = 18.0\n[[restrainers]]\nname = "rod"\nkind = "tie-rod"\n'
        'diameter = 1000.0\nlength = 0.001\nE = 1.2e12\nposition = "top"\n',
        encoding="utf-8",
    )
    with pytest.raises(InputError, match="stiffness E·A/L"):
        load_model(path)


# --- a restrainer's forces: at least 1 N (issue 20, item 4) ----------------------------------

#: The issue's values: a yield of 1e-12 N never yielded, an anchor below ~1e-8 N never broke,
#: and 5e-324 N made `--format json` exit 3 (utilisation = force / 5e-324 = inf).
TINY_FORCES = [
    ("yield_pos", 1e-12),
    ("yield_neg", 0.5),
    ("anchor_capacity", 1e-9),
    ("anchor_capacity", 5e-324),
]


def with_restrainer(**keys: float) -> dict[str, Any]:
    """VALID with its spring given the law keys (both yields, so the law is complete)."""
    data = copy.deepcopy(VALID)
    data["restrainers"][0].update({"yield_pos": 5e3, "yield_neg": 5e3, **keys})
    return data


def test_every_key_in_newtons_is_a_restrainer_force_of_at_least_one_newton() -> None:
    # A key whose unit is N is a force: it is listed in FORCE_KEYS and bounded below by
    # MIN_FORCE (a pretension by 0 and the rule "0, or >= 1 N", checked below). Weights in kN
    # keep MIN_WEIGHT (1 mN): they enter the equation smoothly, without a level.
    found: dict[str, dict[str, float]] = {}
    for section in sections():
        for key, info in section.table.model_fields.items():
            unit = (info.description or "").rsplit("[", 1)[-1]
            if unit == "N]":
                found[key] = bounds(info)
            elif unit == "kN]":
                assert bounds(info).get("ge", 0.0) >= MIN_WEIGHT, key
    assert set(found) == set(FORCE_KEYS)
    for key, limits in found.items():
        assert limits.get("le") == MAX_ANCHOR, key
        assert limits.get("ge") == (0.0 if key == "pretension" else MIN_FORCE), key


@pytest.mark.parametrize(("key", "value"), TINY_FORCES, ids=[f"{k}={v:g}" for k, v in TINY_FORCES])
def test_a_force_below_one_newton_is_refused_with_its_bound(key: str, value: float) -> None:
    with pytest.raises(InputError, match="out of range") as info:
        validate_model(with_restrainer(**{key: value}), file="m.toml")
    assert (info.value.where, info.value.value) == (f"restrainers[0].{key}", value)
    assert info.value.allowed == "a number >= 1 and <= 1e+08 [N]"


def test_a_pretension_below_one_newton_is_refused_but_zero_is_none() -> None:
    with pytest.raises(InputError, match="below 1 N") as info:
        validate_model(with_restrainer(pretension=1e-3), file="m.toml")
    assert info.value.where == "restrainers[0].pretension"
    assert info.value.allowed is not None and info.value.allowed.startswith(
        "0, or 1 <= pretension <"
    )
    validate_model(with_restrainer(pretension=0.0))
    validate_model(with_restrainer(pretension=1.0))


def test_one_newton_is_accepted_for_every_force() -> None:
    validate_model(with_restrainer(yield_pos=1.0, yield_neg=1.0))
    validate_model(with_restrainer(anchor_capacity=1.0, yield_pos=2.0, yield_neg=2.0))


def test_rock_refuses_the_issues_tiny_yield_with_one_line(tmp_path: Path) -> None:
    path = tmp_path / "m.toml"
    path.write_text(tomli_w.dumps(with_restrainer(yield_pos=1e-12)), encoding="utf-8")
    ricker = Path(__file__).resolve().parents[2] / "records" / "ricker_Tp0.5s_0.5g.txt"
    args = ["assess", str(path), "--record", str(ricker), "--format", "json"]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 2, result.output
    assert result.stderr == (
        f"error: {path}: restrainers[0].yield_pos: out of range (got 1e-12; allowed: a number "
        ">= 1 and <= 1e+08 [N])\n"
    )
