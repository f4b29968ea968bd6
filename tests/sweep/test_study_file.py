"""The study file: every mistake is one InputError line naming the study file and the key.

Source of the rules: the issue's contract (spec/README.md, `rock sweep`): pydantic with
extra="forbid"; an unknown key, a missing base, a bad path syntax, a path that is not in the
model and a missing record file each give one line naming the study file and the field.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from rockcli.errors import InputError
from rockcli.studies.sweep.paths import parse_path
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import STUDY, WriteStudy


def error_of(path: Path) -> str:
    with pytest.raises(InputError) as info:
        load_study(str(path))
    text = str(info.value)
    assert "\n" not in text
    assert text.startswith(f"{path}: ")
    return text.removeprefix(f"{path}: ")


def test_the_study_loads(write_study: WriteStudy) -> None:
    plan = load_study(str(write_study()))
    assert [a.name for a in plan.axes] == ["R", "alpha", "K"]
    assert [r.name for r in plan.records] == ["cosine", "ricker"]
    assert plan.analyses == ("rocking", "kinematic")
    assert plan.axes[2].paths == (("restrainers", 0, "k_pos"), ("restrainers", 0, "k_neg"))


@pytest.mark.parametrize(
    ("change", "expected"),
    [
        (
            ("base =", "colour = 1\nbase ="),
            "colour: unknown key (allowed: one of: name, notes, base,",
        ),
        (
            ('name = "R"', 'nme = "R"'),
            "axes[0].nme: unknown key (allowed: one of: path, values, name)",
        ),
        (('base = "wall.toml"\n', ""), "base: missing key (allowed: required)"),
        (("wall.toml", "nowall.toml"), "base: base model file not found (got 'nowall.toml';"),
        (("geometry.R", "geometry..R"), "axes[0].path: bad key path (got 'geometry..R';"),
        (
            ("geometry.R", "geometry.Rr"),
            "axes[0].path: not a field of the model: no key 'Rr' in this table of the model "
            "(got 'geometry.Rr'; allowed: one of: R, alpha, thickness, height, width,",
        ),
        (("geometry.R", "geometry"), "axes[0].path: not a field of the model: geometry is a table"),
        (
            ("restrainers[0].k_neg", "restrainers[1].k_neg"),
            "axes[2].path[1]: restrainers[1] is not in the base model",
        ),
        (
            ("restrainers[0].k_pos", "restrainers.k_pos"),
            "axes[2].path[0]: not a field of the model",
        ),
        (("ricker_Tp0.5s_0.5g.txt", "MRN.txt"), "records[1].path: record file not found (got '"),
        (("values = [1.5, 3.0]", "values = []"), "axes[0].values: Tuple should have at least 1"),
        (("values = [1.5, 3.0]", "values = [{a = 1}]"), "axes[0].values[0]: not a number, text"),
        (("values = [0.0, 1e6]", "values = [[0.0, 1.0, 2.0]]"), "axes[2].values[0]: a value must"),
        (('name = "alpha"', 'name = "R"'), "axes[1].name: another axis has this name (got 'R';"),
        (('name = "alpha"', 'name = "record"'), "axes[1].name: the name of a result column"),
        (
            ('path = "geometry.alpha"', 'path = "geometry.R"'),
            "axes[1].path: already set by axes[0]",
        ),
        (('name = "cosine"', 'name = "cosine"\nscale = -1.0'), "records[0].scale: Input should be"),
        (
            ('name = "cosine"', 'name = "cosine"\nformat = "pulse"'),
            "records[0].format: a generated",
        ),
        (('name = "ricker"', 'name = "cosine"'), "records[1]: two records with the same name"),
        (
            ("base =", 'analyses = ["rocking", "rocking"]\nbase ='),
            "analyses: an analysis is listed",
        ),
        (("base =", 'analyses = ["dynamic"]\nbase ='), "analyses[0]: Input should be 'rocking' or"),
        (
            ("base =", "record_demand = true\nbase ="),
            "record_demand: removed: each record's spectrum is the code demand by default now "
            '(got True; allowed: code_demand = "record" (the default) or "model" (the base '
            "model's code spectrum))",
        ),
        (
            ("base =", 'code_demand = "model"\nbase ='),
            "code_demand: the base model sets no code spectrum ([ntc.demand] or [ntc.site]) "
            '(got \'model\'; allowed: "record" (the default), or "model" with a base model '
            "that sets [ntc.demand] or [ntc.site])",
        ),
        (
            ("base =", 'code_demand = "code"\nbase ='),
            "code_demand: Input should be 'record' or 'model'",
        ),
        (
            ('[[axes]]\npath = "geometry.R"', '[[axes]\npath = "geometry.R"'),
            "line 4, column 7: malformed",
        ),
    ],
)
def test_one_line_per_mistake(
    write_study: WriteStudy, change: tuple[str, str], expected: str
) -> None:
    old, new = change
    assert old in STUDY
    assert error_of(write_study(STUDY.replace(old, new, 1))).startswith(expected)


def test_a_rocking_study_needs_a_record(write_study: WriteStudy) -> None:
    text = STUDY.split("[[records]]")[0]
    assert error_of(write_study(text)).startswith("records: no record to run")


def test_an_absent_optional_record_is_skipped_with_its_source(write_study: WriteStudy) -> None:
    text = (
        STUDY + '\n[[records]]\npath = "MRN.txt"\noptional = true\nsource = "ESM, IT-2012-0011"\n'
    )
    plan = load_study(str(write_study(text)))
    assert [r.name for r in plan.records] == ["cosine", "ricker"]
    assert [(s.name, s.source) for s in plan.skipped] == [("MRN", "ESM, IT-2012-0011")]


def test_only_absent_optional_records_is_an_error(write_study: WriteStudy) -> None:
    text = STUDY.split("[[records]]")[0] + '[[records]]\npath = "MRN.txt"\noptional = true\n'
    assert "every record is optional and absent" in error_of(write_study(text))


def test_records_dir_option_replaces_the_file_s(write_study: WriteStudy, tmp_path: Path) -> None:
    study = write_study(STUDY.replace('records_dir = "records"', 'records_dir = "elsewhere"'))
    with pytest.raises(InputError, match="record file not found"):
        load_study(str(study))
    plan = load_study(str(study), records_dir=str(tmp_path / "records"))
    assert Path(plan.records[0].path).parent == (tmp_path / "records").resolve()


@pytest.mark.parametrize(
    ("text", "path"),
    [
        ("geometry.R", ("geometry", "R")),
        ("restrainers[0].k_pos", ("restrainers", 0, "k_pos")),
        ("ntc.demand.SLV.ag", ("ntc", "demand", "SLV", "ag")),
        ("geometry..R", None),
        ("geometry.R.", None),
        ("restrainers[a].k", None),
        ("[0].k", None),
        ("geometry R", None),
    ],
)
def test_path_syntax(text: str, path: tuple[str | int, ...] | None) -> None:
    assert parse_path(text) == path
