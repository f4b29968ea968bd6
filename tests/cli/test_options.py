"""Options (issue 7, item 17): one that does not apply is refused, conflicting ones too,
output files are checked before the analysis runs, and `rock kinematic` has a verdict gate."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.cli.conftest import PULSES, ROOT

ALTAR = str(ROOT / "examples" / "altar.toml")
WALL = str(ROOT / "examples" / "wall.toml")
RECORD = str(PULSES[0])


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, list(args))
    return result.exit_code, result.stdout, result.stderr


@pytest.mark.parametrize(
    ("option", "value"),
    [("--pga", "0.3"), ("--scale", "2"), ("--units", "g"), ("--dt", "0.01"), ("--as", "plain")],
)
def test_a_record_option_without_a_record_is_refused(option: str, value: str) -> None:
    # `rock kinematic altar.toml --pga 0.3` ran the model's own demand and ignored --pga.
    code, out, err = run("kinematic", ALTAR, option, value)
    assert code == 2 and out == ""
    assert err.startswith(f"error: {option}: applies only to a record (got ")
    assert f"allowed: --record FILE with {option}, or no {option})" in err


@pytest.mark.parametrize("command", ["kinematic", "assess", "compare"])
def test_scale_and_pga_together_are_refused(command: str) -> None:
    code, out, err = run(command, ALTAR, "--record", RECORD, "--scale", "2", "--pga", "0.3")
    assert code == 2 and out == ""
    assert err == (
        "error: --scale: conflicts with --pga (both set the record's amplitude) "
        "(got 2.0; allowed: either --scale FACTOR or --pga PGA)\n"
    )


def test_site_with_a_record_is_refused() -> None:
    code, out, err = run("kinematic", ALTAR, "--record", RECORD, "--site", "13.4,42.35")
    assert code == 2 and out == ""
    assert err.startswith("error: --site: conflicts with --record")


def test_a_hazard_grid_without_a_site_is_refused(tmp_path: Path) -> None:
    # The altar sets [ntc.demand]: a grid would not be read. The file need not exist: the
    # option is refused before anything reads it.
    grid = str(tmp_path / "grid.txt")
    code, _, err = run("kinematic", ALTAR, "--hazard-grid", grid)
    assert code == 2
    assert err.startswith(f"error: {ALTAR}: --hazard-grid: not used: no site sets the demand")
    code, _, err = run("kinematic", WALL, "--record", RECORD, "--hazard-grid", grid)
    assert code == 2
    assert err.startswith("error: --hazard-grid: not used: --record sets the demand")
    # compare: the record is the code demand unless --code-demand model asks for the model's.
    code, _, err = run("compare", ALTAR, "--record", RECORD, "--hazard-grid", grid)
    assert code == 2
    assert err.startswith("error: --hazard-grid: not used: --record sets the demand")
    code, _, err = run(
        "compare", ALTAR, "--record", RECORD, "--code-demand", "model", "--hazard-grid", grid
    )
    assert code == 2
    assert err.startswith(f"error: {ALTAR}: --hazard-grid: not used: no site sets the demand")


@pytest.mark.parametrize(
    ("command", "option", "name"),
    [
        ("assess", "--history", "h.csv"),
        ("assess", "--plot", "f.png"),
        ("kinematic", "--plot", "f.svg"),
        ("compare", "--plot", "f.png"),
    ],
)
def test_an_existing_output_is_refused_before_the_run(
    tmp_path: Path, command: str, option: str, name: str
) -> None:
    out = tmp_path / name
    out.write_text("keep me")
    args = [command, ALTAR, "--record", RECORD, option, str(out)]
    code, stdout, err = run(*args)
    assert code == 2
    assert stdout == ""  # refused before the analysis ran
    assert err == (f"error: {out}: {option}: file exists (allowed: another path, or --force)\n")
    assert out.read_text() == "keep me"
    code, _, err = run(*args, "--force", "--format", "json")
    assert code == 0, err
    assert err == f"wrote {out}\n"  # the one "wrote" line, on stderr
    assert out.read_text(errors="replace") != "keep me"


def test_a_missing_history_folder_is_refused_before_the_run(tmp_path: Path) -> None:
    out = tmp_path / "nowhere" / "h.csv"
    code, stdout, err = run("assess", ALTAR, "--record", RECORD, "--history", str(out))
    assert code == 2 and stdout == ""
    assert err.startswith(f"error: {out}: --history: the folder does not exist")


def _uls(*args: str) -> bool | None:
    code, out, err = run("kinematic", *args, "--format", "json")
    assert code == 0, err
    return json.loads(out)["verdict"]["ULS"]


def test_fail_on_uls_exits_1_when_the_uls_check_fails() -> None:
    # The altar's 2009 ULS is NOT satisfied (non-linear check at height, ζ = 0.490: paper §3.2).
    assert _uls(ALTAR) is False
    code, out, err = run("kinematic", ALTAR, "--fail-on-uls")
    assert code == 1
    assert "verdict:" in out
    assert err == "--fail-on-uls: ULS NOT satisfied\n"


def test_fail_on_uls_passes_a_satisfied_check() -> None:
    # The same altar under a tenth of the pulse: the ULS check is satisfied (exit 0).
    args = (ALTAR, "--record", RECORD, "--scale", "0.1")
    assert _uls(*args) is True
    code, _, err = run("kinematic", *args, "--fail-on-uls")
    assert code == 0 and err == ""


def test_fail_on_uls_exits_1_when_the_uls_is_not_evaluated(tmp_path: Path) -> None:
    # A restrained block whose non-linear check has no d0* and no ultimate displacement is
    # "not evaluated" (codecheck.result.deciding): a gate cannot pass on a check not made.
    model = _not_evaluated_model(tmp_path)
    assert _uls(str(model), "--record", RECORD) is None
    code, _, err = run("kinematic", str(model), "--record", RECORD, "--fail-on-uls")
    assert code == 1
    assert err == (
        "--fail-on-uls: ULS not evaluated (set ntc.ultimate_displacement or a restrainer's "
        "fails_at)\n"
    )


def _not_evaluated_model(tmp_path: Path) -> Path:
    """The façade with a tie-rod 100 times stiffer and its vault elastic: positive global
    stiffness, no d0*."""
    text = (ROOT / "examples" / "facade.toml").read_text(encoding="utf-8")
    model = tmp_path / "stiff.toml"
    # and its vault elastic (no fails_at): a spring of unlimited strength, the curve hardens
    text = text.replace("\nfails_at = 0.001 ", "\n# fails_at = 0.001 ", 1)
    model.write_text(text.replace("diameter = 0.020", "diameter = 0.200", 1), encoding="utf-8")
    return model


def test_history_to_standard_output_is_refused(tmp_path: Path, monkeypatch) -> None:
    # `-` means standard output, which carries the report: refused (it wrote a file named "-").
    monkeypatch.chdir(tmp_path)
    code, out, err = run("assess", ALTAR, "--record", RECORD, "--history", "-")
    assert code == 2 and out == ""
    assert err == (
        "error: --history: standard output carries the report (got '-'; allowed: a file path)\n"
    )
    assert not (tmp_path / "-").exists()


def test_init_dash_output_is_standard_output(tmp_path: Path, monkeypatch) -> None:
    # `rock init wall -o -` wrote a file named "-"; `-o -` means standard output.
    monkeypatch.chdir(tmp_path)
    code, out, err = run("init", "wall", "-o", "-")
    assert code == 0, err
    assert not (tmp_path / "-").exists()
    assert out == run("init", "wall")[1] and out.startswith("#")
