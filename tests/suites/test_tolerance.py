"""The tolerance check over a record suite (`rock assess|compare MODEL --suite`): every record
checked, the suite's ``sensitive`` and ``sensitive_records``, a warning naming the record.

Source: the case of the project's issue 19 (item 5) — the wall with an 18 kN load on top
0.10 m from O on NORTHR_ARL360 × 0.8, whose polarity −1 moves from max θ/α 0.2727 to 0.2524
at rtol 1e-11 (tests/cli/test_tolerance_check.py) — in a suite with two shipped pulses that
do not move (tests/cli/test_tolerance_check.py, the robust case).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from tests.cli.test_tolerance_check import ISSUE_WALL, RECORD
from tests.suites.conftest import PULSES, beside


def suite_with_the_issues_record(folder: Path, shared_records: Path) -> Path:
    """A suite: the issue's record at 0.8 and two pulses, target by its parameters (each
    copied beside the suite file, which reads only its own folder)."""
    entries = [(shared_records / RECORD, "northr", 0.8), (PULSES[0], "p0", 1.0),
               (PULSES[1], "p1", 1.0)]  # fmt: skip
    text = 'name = "issue"\n[target]\nag = 0.2\nF0 = 2.5\nTc_star = 0.3\n\n' + "".join(
        f'[[records]]\npath = "{beside(folder, {"path": str(path)})["path"]}"\n'
        f'name = "{name}"\nscale = {scale}\n\n'
        for path, name, scale in entries
    )
    path = folder / "suite.toml"
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize(
    "command", [["assess"], ["compare", "--code-demand", "suite-mean"]], ids=lambda c: c[0]
)
def test_a_suite_names_its_sensitive_record(
    tmp_path: Path, shared_records: Path, command: list[str]
) -> None:
    model = tmp_path / "wall.toml"
    model.write_text(ISSUE_WALL, encoding="utf-8")
    suite = suite_with_the_issues_record(tmp_path, shared_records)
    args = [*command, str(model), "--suite", str(suite), "--format", "json"]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["sensitive"] is True and doc["sensitive_records"] == ["northr"]
    # The suite's contract (issue 10) is unchanged.
    assert set(doc["suite"]["records"][0]) == {"name", "scale", "pga_g", "max_ratio",
                                               "overturned"}  # fmt: skip
    (warning,) = [w for w in doc["warnings"] if "integration tolerance" in w]
    assert warning.startswith("record northr, polarity -1: max θ/α depends on the integration")
    assert "0.2727 (" in warning and "0.2524 (" in warning
