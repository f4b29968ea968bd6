"""`rock init KIND` templates: commented, and they load unchanged (spec/README.md, "Commands").

Also: every ``examples/*.toml`` loads (spec/style.md, "every examples/*.toml runs").
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.model.derive import to_block
from rockcli.model.load import load_model, validate_model
from rockcli.model.schema import Kind
from rockcli.model.template import TEMPLATES, render_template

KINDS = [k.value for k in Kind]
_KEY_LINE = re.compile(r"^[A-Za-z0-9_-]+ = ")


@pytest.mark.parametrize("kind", KINDS)
def test_template_loads_unchanged(kind: str, tmp_path: Path) -> None:
    text = render_template(Kind(kind))
    path = tmp_path / f"{kind}.toml"
    path.write_text(text, encoding="utf-8")
    model = load_model(path)
    assert model.kind == kind
    # What is written is what was built: the comments change nothing.
    assert model == validate_model(TEMPLATES[Kind(kind)])
    to_block(model)


@pytest.mark.parametrize("kind", KINDS)
def test_every_key_of_the_template_is_explained(kind: str) -> None:
    lines = render_template(Kind(kind)).splitlines()
    assert lines[0].startswith("# ")
    for before, line in zip(lines, lines[1:], strict=False):
        if _KEY_LINE.match(line):
            assert before.startswith("# "), line


@pytest.mark.parametrize("kind", KINDS)
def test_rock_init_prints_the_template(kind: str) -> None:
    result = CliRunner().invoke(cli, ["init", kind])
    assert result.exit_code == 0, result.output
    assert result.output == render_template(Kind(kind))
    validate_model(tomllib.loads(result.output))


def test_rock_init_writes_a_file_that_loads(tmp_path: Path) -> None:
    path = tmp_path / "facade.toml"
    result = CliRunner().invoke(cli, ["init", "facade", "-o", str(path)])
    assert result.exit_code == 0, result.output
    assert load_model(path).motion.sides == "one"


def test_rock_init_refuses_to_overwrite(tmp_path: Path) -> None:
    path = tmp_path / "wall.toml"
    path.write_text("mine", encoding="utf-8")
    result = CliRunner().invoke(cli, ["init", "wall", "-o", str(path)])
    assert result.exit_code == 2
    assert result.output.strip() == (
        f"error: {path}: --output: file exists (allowed: another path, or --force)"
    )
    assert path.read_text(encoding="utf-8") == "mine"


def test_rock_init_force_overwrites(tmp_path: Path) -> None:
    path = tmp_path / "wall.toml"
    path.write_text("mine", encoding="utf-8")
    result = CliRunner().invoke(cli, ["init", "wall", "-o", str(path), "--force"])
    assert result.exit_code == 0
    assert load_model(path).kind == "wall"


def test_rock_init_unwritable_path_is_an_input_error(tmp_path: Path) -> None:
    path = tmp_path / "no" / "such" / "dir.toml"
    result = CliRunner().invoke(cli, ["init", "altar", "-o", str(path)])
    assert result.exit_code == 2
    assert result.output.startswith(f"error: {path}: --output: the folder does not exist")


def test_rock_init_unknown_kind_is_a_usage_error() -> None:
    result = CliRunner().invoke(cli, ["init", "tower"])
    assert result.exit_code == 2
    assert "'tower' is not one of 'wall', 'altar', 'facade'" in result.output


def test_rock_init_help() -> None:
    result = CliRunner().invoke(cli, ["init", "--help"])
    assert result.exit_code == 0
    assert "template" in result.output
