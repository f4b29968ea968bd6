"""Every bad model file gets one line naming the file, the field, the value and what is allowed.

Source of the expectations: spec/README.md ("Every quantity in the file is validated; a bad
file gets one clear message naming the field, the value and what is allowed, never a
traceback") and the decisions of the model file contract (rockcli/model/schema.py).
"""

from __future__ import annotations

import copy
import math
import pickle
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.errors import InputError
from rockcli.model.load import MAX_ERRORS, InputErrors, load_model, validate_model

#: A valid model: a wall with unit weight (needs width) and one spring at the top.
VALID: dict[str, Any] = {
    "name": "test wall",
    "kind": "wall",
    "geometry": {"thickness": 0.5, "height": 4.0, "width": 3.0},
    "mass": {"unit_weight": 18.0},
    "restrainers": [{"name": "spring", "k": 1e6, "position": "top"}],
}

#: What a length accepts (rockcli/model/bounds.py: 1 mm to 1 km).
LENGTH = "a number >= 0.001 and <= 1000 [m]"

Edit = Callable[[dict[str, Any]], object]


def message_for(tmp_path: Path, edit: Edit) -> str:
    """Write VALID changed by ``edit`` to m.toml, load it, and return the error line."""
    data = copy.deepcopy(VALID)
    edit(data)
    path = tmp_path / "m.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    with pytest.raises(InputError) as info:
        load_model(path)
    return str(info.value)


def restrainer(**keys: Any) -> Edit:
    """Replace the restrainer by one with these keys."""
    return lambda d: d.update(restrainers=[keys])


def table(name: str, **keys: Any) -> Edit:
    """Replace (or add) table ``name`` with these keys."""
    return lambda d: d.update({name: keys})


def put(name: str, **keys: Any) -> Edit:
    """Set keys in table ``name``."""
    return lambda d: d[name].update(keys)


def drop(*path: str) -> Edit:
    """Remove a key (a top-level key, or a key of a table)."""

    def edit(d: dict[str, Any]) -> None:
        target = d
        for key in path[:-1]:
            target = target[key]
        del target[path[-1]]

    return edit


def test_valid_model_loads(tmp_path: Path) -> None:
    path = tmp_path / "m.toml"
    path.write_text(tomli_w.dumps(VALID), encoding="utf-8")
    assert load_model(path).restrainers[0].k == 1e6


# --- exact lines: the format users see --------------------------------------------------------


def test_unknown_table_at_top_level_exact_line(tmp_path: Path) -> None:
    line = message_for(tmp_path, table("results", edition=2019))
    assert line == (
        f"{tmp_path / 'm.toml'}: unknown table [results] (allowed: one of: name, kind, notes, "
        "geometry, mass, restitution, motion, analysis, restrainers, loads, thrusts, building, "
        "base, ntc, return_walls, masonry, mechanisms, frame)"
    )


def test_negative_thickness_exact_line(tmp_path: Path) -> None:
    line = message_for(tmp_path, put("geometry", thickness=-0.5))
    assert line == (
        f"{tmp_path / 'm.toml'}: geometry.thickness: out of range "
        "(got -0.5; allowed: a number >= 0.001 and <= 1000 [m])"
    )


def test_negative_stiffness_exact_line(tmp_path: Path) -> None:
    line = message_for(tmp_path, restrainer(k_pos=-1.0, k_neg=0.0, position="top"))
    assert line == (
        f"{tmp_path / 'm.toml'}: restrainers[0].k_pos: out of range "
        "(got -1.0; allowed: a number >= 0 and <= 1e+12 [N/m])"
    )


def test_missing_name_exact_line(tmp_path: Path) -> None:
    line = message_for(tmp_path, drop("name"))
    assert line == f"{tmp_path / 'm.toml'}: name: missing key (allowed: required)"


# --- contents: field path, value, allowed ------------------------------------------------------

CASES: list[tuple[str, Edit, list[str]]] = [
    (
        "unknown key in a table",
        put("geometry", thikness=0.5),
        [
            "geometry.thikness",
            "unknown key",
            "got 0.5",
            "one of: R, alpha, thickness, height, width, pivot_height",
        ],
    ),
    (
        "unknown key in a restrainer",
        restrainer(k=1.0, position="top", stiffness=3.0),
        ["restrainers[0].stiffness", "unknown key", "one of: name, kind, k_pos, k_neg, k,"],
    ),
    ("missing kind", drop("kind"), ["kind", "missing key", "required"]),
    ("missing geometry", drop("geometry"), ["geometry", "missing key", "required"]),
    (
        "missing dimensions",
        table("geometry", width=3.0),
        [
            "geometry: missing the block's dimensions",
            "either R + alpha, thickness + height, or [[geometry.storeys]]",
        ],
    ),
    (
        "zero height",
        put("geometry", height=0.0),
        ["geometry.height", "got 0.0", "a number >= 0.001 and <= 1000 [m]"],
    ),
    (
        "negative width",
        put("geometry", width=-3),
        ["geometry.width", "got -3", "a number >= 0.001 and <= 1000 [m]"],
    ),
    (
        "negative pivot height",
        put("geometry", pivot_height=-1.0),
        ["geometry.pivot_height", "got -1.0", "a number >= 0 and <= 1000 [m]"],
    ),
    (
        "zero R",
        table("geometry", R=0.0, alpha=0.1),
        ["geometry.R", "got 0.0", "a number >= 0.001 and <= 1000 [m]"],
    ),
    (
        "alpha zero",
        table("geometry", R=1.0, alpha=0.0),
        ["geometry.alpha", "got 0.0", "a number >= 1e-06 and < pi/2 [rad]"],
    ),
    (
        "alpha negative",
        table("geometry", R=1.0, alpha=-0.1),
        ["geometry.alpha", "got -0.1", "a number >= 1e-06 and < pi/2 [rad]"],
    ),
    (
        "alpha pi/2",
        table("geometry", R=1.0, alpha=math.pi / 2),
        ["geometry.alpha", f"got {math.pi / 2!r}", "a number >= 1e-06 and < pi/2 [rad]"],
    ),
    (
        "alpha in degrees",
        table("geometry", R=1.0, alpha=9.34),
        ["geometry.alpha", "got 9.34", "a number >= 1e-06 and < pi/2 [rad]"],
    ),
    (
        "both geometry forms",
        put("geometry", R=1.499, alpha=0.163),
        [
            "geometry.thickness",
            "not allowed together with R",
            "got 0.5",
            "either R + alpha, thickness + height, or [[geometry.storeys]]",
        ],
    ),
    (
        "R without alpha",
        table("geometry", R=1.499, width=3.0),
        [
            "geometry.alpha",
            "required with R",
            "either R + alpha, thickness + height, or [[geometry.storeys]]",
        ],
    ),
    (
        "height without thickness",
        table("geometry", height=4.0, width=3.0),
        ["geometry.thickness", "required with height"],
    ),
    (
        "unit_weight without width",
        drop("geometry", "width"),
        ["geometry.width", "required with mass.unit_weight", LENGTH],
    ),
    (
        "weight and unit_weight",
        put("mass", weight=100.0),
        [
            "mass.unit_weight",
            "not allowed together with weight",
            "got 18.0",
            "either weight [kN] or unit_weight [kN/m³]",
        ],
    ),
    ("empty mass table", table("mass"), ["mass: missing the weight"]),
    (
        "zero weight",
        table("mass", weight=0),
        ["mass.weight", "got 0", "a number >= 1e-06 and <= 1e+07 [kN]"],
    ),
    (
        "restrainer without mass",
        drop("mass"),
        [
            "mass: required because restrainers[0] has a stiffness",
            "a [mass] table with weight [kN] or unit_weight [kN/m³]",
        ],
    ),
    (
        "tie-rod without mass",
        lambda d: (
            d.pop("mass"),
            d.update(
                restrainers=[
                    {"kind": "tie-rod", "diameter": 0.02, "length": 3.0, "position": "top"}
                ]
            ),
        ),
        ["mass: required because restrainers[0] has a stiffness"],
    ),
    (
        "e above 1",
        table("restitution", e=1.2),
        ["restitution.e", "got 1.2", "a number >= 0 and <= 1 [-]"],
    ),
    (
        "e below 0",
        table("restitution", e=-0.1),
        ["restitution.e", "got -0.1", "a number >= 0 and <= 1 [-]"],
    ),
    (
        "factor zero",
        table("restitution", factor=0.0),
        ["restitution.factor", "got 0.0", "a number > 0 and <= 1 [-]"],
    ),
    (
        "factor above 1",
        table("restitution", factor=1.1),
        ["restitution.factor", "got 1.1", "a number > 0 and <= 1 [-]"],
    ),
    (
        "e and factor",
        table("restitution", e=0.8, factor=0.9),
        ["restitution.factor", "not allowed together with e", "got 0.9"],
    ),
    (
        "explicit without e",
        table("restitution", model="explicit"),
        ["restitution.e", 'required with model = "explicit"'],
    ),
    (
        "housner with e",
        table("restitution", model="housner", e=0.8),
        ["restitution.e", 'not allowed with model = "housner"', "got 0.8"],
    ),
    (
        "unknown restitution model",
        table("restitution", model="kelvin"),
        ["restitution.model", "unknown value", "got 'kelvin'", "one of: housner, explicit"],
    ),
    (
        "stopped with two sides",
        table("motion", stopped="negative"),
        ["motion.stopped", 'only allowed with sides = "one"', "got 'negative'"],
    ),
    (
        "rebound with two sides",
        table("motion", sides="two", rebound=0.5),
        ["motion.rebound", 'only allowed with sides = "one"', "got 0.5"],
    ),
    (
        "rebound above 1",
        table("motion", sides="one", rebound=1.5),
        ["motion.rebound", "got 1.5", "a number >= 0 and <= 1 [-]"],
    ),
    (
        "unknown side",
        table("motion", sides="one", stopped="left"),
        ["motion.stopped", "got 'left'", "one of: negative, positive"],
    ),
    (
        "unknown kind",
        lambda d: d.update(kind="tower"),
        ["kind", "unknown value", "got 'tower'", "one of: wall, altar, facade"],
    ),
    ("empty name", lambda d: d.update(name=""), ["name", "empty", "a non-empty text string"]),
    (
        "number as text",
        put("geometry", thickness="0.5"),
        ["geometry.thickness", "not a number", "got '0.5'", "a number >= 0.001 and <= 1000 [m]"],
    ),
    (
        "boolean as number",
        put("geometry", thickness=True),
        ["geometry.thickness", "not a number", "got True"],
    ),
    (
        "infinite number",
        put("geometry", height=math.inf),
        ["geometry.height", "not a finite number", "got inf"],
    ),
    (
        "table as number",
        lambda d: d.update(geometry=2.0),
        ["geometry", "not a table", "got 2.0", "a [geometry] table"],
    ),
    (
        "rtol too loose",
        table("analysis", rtol=0.1),
        ["analysis.rtol", "got 0.1", "a number >= 1e-12 and <= 0.01 [-]"],
    ),
    ("atol zero", table("analysis", atol=0.0), ["analysis.atol", "a number >= 1e-12 and <= 0.01"]),
    (
        "rtol below the floor (rounding, not accuracy)",
        table("analysis", rtol=1e-13),
        ["analysis.rtol", "got 1e-13", "a number >= 1e-12 and <= 0.01 [-]"],
    ),
    (
        "overturn angle above pi/2",
        table("analysis", overturn_angle=2.0),
        ["analysis.overturn_angle", "got 2.0", "a number > 0 and <= pi/2 [rad]"],
    ),
    (
        "negative tail",
        table("analysis", tail=-1.0),
        ["analysis.tail", "got -1.0", "a number >= 0 and <= 3600 [s]"],
    ),
    (
        "tail of 1e9 s (745 GiB at the record's dt before the bound)",
        table("analysis", tail=1e9),
        ["analysis.tail", "got 1000000000.0", "a number >= 0 and <= 3600 [s]"],
    ),
    (
        "zero rest velocity",
        table("analysis", rest_velocity=0.0),
        ["analysis.rest_velocity", "a number > 0 and <= 0.01 [rad/s]"],
    ),
    ("zero gravity", table("analysis", g=0.0), ["analysis.g", "a number >= 9 and <= 10 [m/s²]"]),
    (
        "linearized as text",
        table("analysis", linearized="yes"),
        ["analysis.linearized", "not a boolean", "got 'yes'", "true or false"],
    ),
    (
        "restrainer without stiffness",
        restrainer(position="top"),
        ["restrainers[0]: missing the stiffness", "k or k_pos + k_neg [N/m]"],
    ),
    (
        "k_pos without k_neg",
        restrainer(k_pos=1e6, position="top"),
        ["restrainers[0].k_neg", "required with k_pos"],
    ),
    (
        "k and k_pos",
        restrainer(k=1e6, k_pos=1e6, k_neg=0.0, position="top"),
        ["restrainers[0].k_pos", "not allowed together with k", "got 1000000.0"],
    ),
    (
        "negative k",
        restrainer(k=-5.0, position="top"),
        ["restrainers[0].k", "got -5.0", "a number >= 0 and <= 1e+12 [N/m]"],
    ),
    (
        "tie-rod without length",
        restrainer(kind="tie-rod", diameter=0.02, position="top"),
        ["restrainers[0].length", 'required with kind = "tie-rod"'],
    ),
    (
        "tie-rod with k",
        restrainer(kind="tie-rod", diameter=0.02, length=3.0, k=1.0, position="top"),
        ["restrainers[0].k", 'not allowed with kind = "tie-rod"', "got 1.0"],
    ),
    (
        "spring with diameter",
        restrainer(k=1.0, diameter=0.02, position="top"),
        ["restrainers[0].diameter", 'only allowed with kind = "tie-rod"', "got 0.02"],
    ),
    (
        "zero diameter",
        restrainer(kind="tie-rod", diameter=0.0, length=3.0, position="top"),
        ["restrainers[0].diameter", "got 0.0", "a number >= 0.001 and <= 1000 [m]"],
    ),
    (
        "unknown acts",
        restrainer(kind="tie-rod", diameter=0.02, length=3.0, acts="up", position="top"),
        ["restrainers[0].acts", "got 'up'", "one of: both, positive, negative"],
    ),
    (
        "no attachment point",
        restrainer(k=1.0),
        [
            "restrainers[0]: missing the attachment point",
            'radius + angle, or height + from_pivot, or position = "top"',
        ],
    ),
    (
        "two attachment points",
        restrainer(k=1.0, radius=7.0, angle=0.07, position="top"),
        ["restrainers[0].position", "not allowed together with radius", "got 'top'"],
    ),
    (
        "radius without angle",
        restrainer(k=1.0, radius=7.0),
        ["restrainers[0].angle", "required with radius"],
    ),
    (
        "zero radius",
        restrainer(k=1.0, radius=0.0, angle=0.07),
        ["restrainers[0].radius", "got 0.0", "a number >= 0.001 and <= 2000 [m]"],
    ),
    (
        "angle above pi/2",
        restrainer(k=1.0, radius=1.0, angle=2.0),
        ["restrainers[0].angle", "got 2.0", "a number >= 0 and <= pi/2 [rad]"],
    ),
    (
        "from_pivot beyond the thickness",
        restrainer(k=1.0, height=3.0, from_pivot=0.6),
        [
            "restrainers[0].from_pivot",
            "outside the block",
            "got 0.6",
            "<= the thickness 2b = 0.5 [m]",
        ],
    ),
    (
        "zero fails_at",
        restrainer(k=1.0, position="top", fails_at=0.0),
        ["restrainers[0].fails_at", "got 0.0", "a number >= 1e-06 and <= 1000 [m]"],
    ),
    (
        "unknown position",
        restrainer(k=1.0, position="middle"),
        ["restrainers[0].position", "got 'middle'", "one of: top"],
    ),
    (
        "second restrainer",
        lambda d: d["restrainers"].append({"k": 1.0, "radius": -1.0, "angle": 0.1}),
        ["restrainers[1].radius", "got -1.0"],
    ),
    (
        "restrainers not an array",
        lambda d: d.update(restrainers=5),
        ["restrainers", "not an array of tables", "got 5"],
    ),
]


@pytest.mark.parametrize(("edit", "parts"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_bad_model_names_file_field_value_and_allowed(
    tmp_path: Path, edit: Edit, parts: list[str]
) -> None:
    line = message_for(tmp_path, edit)
    assert "\n" not in line
    assert line.startswith(f"{tmp_path / 'm.toml'}: ")
    for part in parts:
        assert part in line


# --- every problem at once (issue 7, item 16) ----------------------------------------------------


def test_every_error_is_reported_one_line_each(tmp_path: Path) -> None:
    # Main reported only the first (geometry.thickness) and hid the other two.
    text = message_for(
        tmp_path,
        lambda d: (d["geometry"].update(thickness=-1.0, height=-2.0), d.update(kind="tower")),
    )
    lines = text.split("\n")
    path = tmp_path / "m.toml"
    assert lines == [
        f"{path}: kind: unknown value (got 'tower'; allowed: one of: wall, altar, facade, frame)",
        f"{path}: geometry.thickness: out of range (got -1.0; allowed: {LENGTH})",
        f"{path}: geometry.height: out of range (got -2.0; allowed: {LENGTH})",
    ]


def test_several_errors_keep_the_first_as_the_structured_fields(tmp_path: Path) -> None:
    with pytest.raises(InputErrors) as info:
        validate_model({**VALID, "kind": "tower", "name": ""}, file="f.toml")
    err = info.value
    assert isinstance(err, InputError)
    assert (err.file, err.where, err.value) == ("f.toml", "name", "")
    assert [e.where for e in err.errors] == ["name", "kind"]


def test_more_than_ten_errors_are_counted(tmp_path: Path) -> None:
    # 12 unknown keys: 10 lines shown (MAX_ERRORS), then one line counting the other 2.
    keys = {f"extra_{i:02d}": i for i in range(12)}
    text = message_for(tmp_path, lambda d: d.update(keys))
    lines = text.split("\n")
    assert len(lines) == MAX_ERRORS + 1
    assert lines[-1] == f"{tmp_path / 'm.toml'}: and 2 more problems (fix these and run again)"
    assert "extra_09" in lines[9]
    assert "extra_10" not in text


def test_cli_prints_every_error_prefixed(tmp_path: Path) -> None:
    data = copy.deepcopy(VALID)
    data["geometry"].update(thickness=-1.0, height=-2.0)
    path = tmp_path / "m.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    result = CliRunner().invoke(cli, ["kinematic", str(path)])
    assert result.exit_code == 2
    lines = result.stderr.splitlines()
    assert len(lines) == 2
    assert all(line.startswith(f"error: {path}: geometry.") for line in lines)


@pytest.mark.parametrize(
    ("edit", "expected"),
    [
        (
            lambda d: d.update(geometri=d.pop("geometry")),
            "unknown table [geometri]; did you mean [geometry]?",
        ),
        (
            lambda d: d.update(Geometry=d.pop("geometry")),
            "unknown table [Geometry]; did you mean [geometry]?",
        ),
        (
            lambda d: d.update(restrainer=d.pop("restrainers")),
            "unknown table [[restrainer]]; did you mean [[restrainers]]?",
        ),
        (
            lambda d: d.update(ntc={"sit": {"lon": 13.4, "lat": 42.35}}),
            "unknown table [ntc.sit]; did you mean [ntc.site]?",
        ),
    ],
    ids=["misspelt", "capitalised", "array of tables", "nested"],
)
def test_unknown_table_is_named_with_its_near_miss(
    tmp_path: Path, edit: Edit, expected: str
) -> None:
    # Main said "geometry: missing key" and never named [geometri].
    text = message_for(tmp_path, edit)
    assert "\n" not in text
    assert text.startswith(f"{tmp_path / 'm.toml'}: {expected} (allowed: one of: ")
    assert "missing key" not in text


@pytest.mark.parametrize(
    ("edit", "expected"),
    [
        (put("geometry", thikness=0.5), "geometry.thikness: unknown key; did you mean thickness?"),
        (put("geometry", Width=3.0), "geometry.Width: unknown key; did you mean width?"),
        (lambda d: d.update(kind="wal"), "kind: unknown value; did you mean 'wall'?"),
        (restrainer(k=1.0, position="Top"), "position: unknown value; did you mean 'top'?"),
    ],
    ids=["key typo", "key case", "value typo", "value case"],
)
def test_near_miss_suggests_the_known_name(tmp_path: Path, edit: Edit, expected: str) -> None:
    assert expected in message_for(tmp_path, edit)


def test_no_suggestion_when_nothing_is_close(tmp_path: Path) -> None:
    # "results" vs "restrainers": difflib ratio 0.67 < NEAR_MISS = 0.75.
    assert "did you mean" not in message_for(tmp_path, table("results", edition=2019))


@pytest.mark.parametrize(
    ("given", "edition"),
    [
        (2019, "2019"),
        (2009, "2009"),
        (2018, "2019"),
        (2008, "2009"),
        ("2018", "2019"),
        ("2008", "2009"),
        ("2019", "2019"),
    ],
)
def test_edition_as_a_number_and_by_the_code_year(given: object, edition: str) -> None:
    # NTC 2008 is applied with Circolare 617/2009, NTC 2018 with Circolare 7/2019; main
    # refused edition = 2019 (an integer) and both code years.
    model = validate_model({**VALID, "ntc": {"edition": given}})
    assert model.ntc is not None and model.ntc.edition == edition


@pytest.mark.parametrize("given", [2017, True, "NTC"])
def test_other_editions_refused(tmp_path: Path, given: object) -> None:
    text = message_for(tmp_path, table("ntc", edition=given))
    assert "ntc.edition: unknown value" in text
    assert "one of: 2009, 2019" in text


def test_zero_stiffness_restrainer_needs_no_mass() -> None:
    data = copy.deepcopy(VALID)
    del data["mass"]
    data["geometry"].pop("width")
    data["restrainers"] = [{"k_pos": 0.0, "k_neg": 0, "position": "top"}]
    assert validate_model(data).mass is None


def test_from_pivot_within_rounding_of_the_thickness_is_accepted() -> None:
    # The altar's R = 1.499, α = 0.163 (paper §3.2, 3 decimals) give 2b = 0.4864 m for the
    # 0.487 m wall: a point on the far face written as 0.487 must be accepted.
    data = copy.deepcopy(VALID)
    data["geometry"] = {"R": 1.499, "alpha": 0.163, "width": 2.4}
    data["restrainers"] = [{"k": 1.0, "height": 2.0, "from_pivot": 0.487}]
    assert validate_model(data).restrainers[0].from_pivot == 0.487


def test_odd_key_is_quoted_on_one_line(tmp_path: Path) -> None:
    line = message_for(tmp_path, lambda d: d.update({"a\nb": 1}))
    assert '"a\\nb": unknown key' in line
    assert "\n" not in line


def test_long_text_value_is_cut(tmp_path: Path) -> None:
    line = message_for(tmp_path, lambda d: d.update(kind="x" * 500))
    assert "x" * 57 + "..." in line
    assert len(line) < 300


def test_validate_without_file_has_no_file_prefix() -> None:
    with pytest.raises(InputError) as info:
        validate_model({"name": "x", "kind": "wall"})
    assert str(info.value) == "geometry: missing key (allowed: required)"
    assert info.value.where == "geometry"
    assert info.value.allowed == "required"


def test_error_carries_structured_fields(tmp_path: Path) -> None:
    message_for(tmp_path, put("geometry", thickness=-0.5))
    with pytest.raises(InputError) as info:
        validate_model({**VALID, "geometry": {"thickness": -0.5, "height": 4.0}}, file="f.toml")
    err = info.value
    assert (err.file, err.where, err.value, err.allowed) == (
        "f.toml",
        "geometry.thickness",
        -0.5,
        "a number >= 0.001 and <= 1000 [m]",
    )


# --- the file itself ----------------------------------------------------------------------------


def test_malformed_toml_names_line_and_column(tmp_path: Path) -> None:
    path = tmp_path / "bad.toml"
    path.write_text('name = "x"\nkind = "wall"\n[geometry\nR = 1.0\n', encoding="utf-8")
    with pytest.raises(InputError) as info:
        load_model(path)
    line = str(info.value)
    assert line.startswith(f"{path}: line 3, column ")
    assert "malformed TOML" in line
    assert "\n" not in line


def test_malformed_value_names_its_line(tmp_path: Path) -> None:
    path = tmp_path / "bad.toml"
    path.write_text('name = "x"\nkind = "wall"\n\n[geometry]\nR = 1.0.5\n', encoding="utf-8")
    with pytest.raises(InputError) as info:
        load_model(path)
    assert f"{path}: line 5, column" in str(info.value)


def test_missing_file(tmp_path: Path) -> None:
    path = tmp_path / "nowhere.toml"
    with pytest.raises(InputError) as info:
        load_model(path)
    assert str(info.value) == f"{path}: cannot read the file: No such file or directory"


def test_directory_instead_of_file(tmp_path: Path) -> None:
    with pytest.raises(InputError) as info:
        load_model(tmp_path)
    assert str(info.value).startswith(f"{tmp_path}: not a regular file (a folder)")


def test_not_utf8(tmp_path: Path) -> None:
    path = tmp_path / "latin1.toml"
    path.write_bytes('kind = "facade"\nname = "Facciata è"\n'.encode("latin-1"))
    with pytest.raises(InputError) as info:
        load_model(path)
    assert str(info.value) == f"{path}: line 2, column 18: not UTF-8 text"


def test_several_errors_take_the_file_together() -> None:
    # A lower layer without the file name (validate_model(data)) hands it on with with_file.
    with pytest.raises(InputErrors) as info:
        validate_model({**VALID, "kind": "tower", "name": ""})
    named = info.value.with_file("m.toml")
    assert isinstance(named, InputErrors)
    assert [line.split(": ")[0] for line in named.lines] == ["m.toml"] * 2


def test_several_errors_survive_pickling() -> None:
    # Sweep workers send exceptions between processes; main's InputError pickles, and so must
    # the several-error form (its constructor takes a list, not the rendered text).
    with pytest.raises(InputErrors) as info:
        validate_model({**VALID, "kind": "tower", "name": ""}, file="m.toml")
    copy_ = pickle.loads(pickle.dumps(info.value))
    assert isinstance(copy_, InputErrors)
    assert str(copy_) == str(info.value)
    assert copy_.where == "name"
