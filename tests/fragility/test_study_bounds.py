"""Issue 34, finding F16: a fragility study's intensities have a physical bound and its numbers
a strict type (a string or a boolean is never read as a number): one line, exit 2.

The bounds are rockcli.studies.fragility.study.MAX_INTENSITY, about twice the largest intensities
ever recorded (PGA ≈ 4 g, PGV ≈ 3 m/s): PGA ≤ 10 g, PGV ≤ 10 m/s, Sa ≤ 30 g, the ratios ≤ 1000.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.fragility.test_folder import make_study


def run(study: Path, text: str, tmp_path: Path) -> tuple[int, str]:
    study.write_text(text, encoding="utf-8")
    args = ["fragility", str(study), "--out", str(tmp_path / "out"), "--no-progress"]
    result = CliRunner().invoke(cli, args)
    return result.exit_code, result.stderr


@pytest.mark.parametrize(
    ("old", "new", "where", "said"),
    [
        ("last = 1.0", "last = 1e300", "ida.last", "allowed: PGA ≤ 10 g"),
        ("last = 1.0", "last = 10.5", "ida.last", "allowed: PGA ≤ 10 g"),
        ("last = 1.0", 'last = "1.0"', "ida.last", "valid number"),
        ("last = 1.0", "last = true", "ida.last", "valid number"),
        ("first = 0.2", 'first = "0.2"', "ida.first", "valid number"),
        ("step = 0.1", "step = true", "ida.step", "valid number"),
        ("tolerance = 0.01", 'tolerance = "0.01"', "ida.tolerance", "valid number"),
        ('level = "overturning"', "level = true", "damage_states[0].level", "valid number"),
        ('level = "overturning"', 'level = "0.5"', "damage_states[0].level", "valid number"),
        ("[ida]", "[ida]\nddof = true", "ida.ddof", "valid integer"),
    ],
)
def test_ida_numbers_are_strict_and_bounded(
    tmp_path: Path, old: str, new: str, where: str, said: str
) -> None:
    study = make_study(tmp_path / "s")
    text = study.read_text(encoding="utf-8")
    assert old in text
    code, err = run(study, text.replace(old, new, 1), tmp_path)
    assert code == 2 and err.count("\n") == 1, err
    assert f": {where}:" in err and said in err


MSA = """
[msa]
levels = {levels}
"""


@pytest.mark.parametrize(
    ("measure", "levels", "said"),
    [
        ("pga", "[0.2, 1e300]", "allowed: PGA ≤ 10 g"),
        ("pgv", "[0.2, 12.0]", "allowed: PGV ≤ 10 m/s"),
        ("pga-ratio", "[0.2, 2000.0]", "allowed: PGA/(g·tan α) ≤ 1000)"),
        ("pga", '[0.2, "0.4"]', "valid number"),
        ("pga", "[0.2, false]", "valid number"),
    ],
)
def test_msa_levels_are_strict_and_bounded(
    tmp_path: Path, measure: str, levels: str, said: str
) -> None:
    study = make_study(tmp_path / "s")
    text = study.read_text(encoding="utf-8")
    text = text[: text.index("[ida]")].replace('"ida"', '"msa"').replace('"pga"', f'"{measure}"')
    code, err = run(study, text + MSA.format(levels=levels), tmp_path)
    assert code == 2 and err.count("\n") == 1, err
    assert ": msa.levels[1]" in err and said in err


def test_the_bound_itself_is_accepted(tmp_path: Path) -> None:
    """10 g is the last PGA allowed: the study is read (it runs; the pulses' runs at that
    intensity overturn)."""
    from rockcli.studies.fragility.study import load_fragility

    study = make_study(tmp_path / "s")
    text = study.read_text(encoding="utf-8").replace("last = 1.0", "last = 10")
    study.write_text(text.replace("step = 0.1", "step = 1"), encoding="utf-8")
    assert load_fragility(str(study)).scan == (0.2, 1.0, 10.0, 0.01)
