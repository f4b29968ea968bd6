"""Issue 34, finding F12: every documented `rock fragility examples/fragility/*.toml
--records-dir DIR` runs (its model lies inside the study's folder, as the rule for the files a
study names asks), on the real records of ../shared/records."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples" / "fragility"
RECORDS = ROOT.parent / "shared" / "records"


def test_the_examples_model_is_the_altar_of_examples() -> None:
    """examples/fragility/altar.toml is a copy of examples/altar.toml, byte for byte: the two
    never drift apart."""
    copy = (EXAMPLES / "altar.toml").read_bytes()
    assert copy == (ROOT / "examples" / "altar.toml").read_bytes()


@pytest.mark.parametrize("study", sorted(p.name for p in EXAMPLES.glob("altar-*.toml")))
def test_each_example_runs_as_documented(study: str, tmp_path: Path) -> None:
    if not RECORDS.is_dir():
        pytest.skip(f"no real records beside this clone ({RECORDS} is absent)")
    args = ["fragility", str(EXAMPLES / study), "--records-dir", str(RECORDS),
            "--out", str(tmp_path / "out"), "--format", "json", "--no-progress"]  # fmt: skip
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert len(doc["records"]) == 7
    assert all(s["median"] is None or s["median"] > 0 for s in doc["damage_states"])
