"""Extreme but valid restrainers: `--format json` is strict JSON, never an exit 3 (issue 20, 4).

On main an ``anchor_capacity`` of 5e-324 N loaded, and `rock assess --format json` exited 3
(``ValueError: Out of range float values are not JSON compliant: inf``): the restrainer check's
utilisation, force / strength, overflowed dividing by the subnormal strength. A restrainer's
forces are now at least 1 N and a non-zero stiffness at least 1 N/m (rockcli.model.bounds),
so the models of the issue are refused with one line (exit 2), and the models at the ends of
the accepted ranges give finite numbers: the JSON parses with no Infinity or NaN token.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli

from .conftest import ROOT

RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
#: A wall 0.5 × 4 m, 3 m wide, 18 kN/m³ (108 kN), with one restrainer at the top.
WALL = (
    'name = "extreme"\nkind = "wall"\n[geometry]\nthickness = 0.5\nheight = 4.0\nwidth = 3.0\n'
    '[mass]\nunit_weight = 18.0\n[ntc]\nedition = "2019"\n[[restrainers]]\nposition = "top"\n'
)

#: At the ends of the accepted ranges: exit 0, strict JSON.
VALID = {
    "yield of 1 N, k = 1e12": "k = 1e12\nyield_pos = 1.0\nyield_neg = 1.0\n",
    "anchor of 1 N": "k = 1e6\nanchor_capacity = 1.0\n",
    "pretension of 1 N": "k = 1e6\nyield_pos = 2.0\nyield_neg = 2.0\npretension = 1.0\n",
    "largest forces": "k = 1e12\nyield_pos = 1e8\nyield_neg = 1e8\nanchor_capacity = 1e8\n",
    "softest spring": "k = 1.0\nyield_pos = 1.0\nyield_neg = 1.0\n",
    "1 mm rod, 1 km long, anchor of 1 N": (
        'kind = "tie-rod"\ndiameter = 0.001\nlength = 1000.0\ngrade = "S235"\n'
        "anchor_capacity = 1.0\n"
    ),
    "one side, 1 N": "k_pos = 1e12\nk_neg = 0\nyield_pos = 1.0\nyield_neg = 1.0\n",
}
#: The issue's values, and a subnormal stiffness (found here: P0/K and F/K overflowed): exit 2.
REFUSED = {
    "anchor of 5e-324 N": ("k = 1e6\nanchor_capacity = 5e-324\n", "anchor_capacity"),
    "yield of 1e-12 N": ("k = 1e6\nyield_pos = 1e-12\nyield_neg = 1e-12\n", "yield_pos"),
    "k = 5e-324": ("k = 5e-324\nanchor_capacity = 1.0\n", "k"),
}
COMMANDS = ["assess", "kinematic", "compare"]


def strict_json(text: str) -> Any:
    """json.loads refusing the Infinity, -Infinity and NaN tokens Python's json allows."""

    def refuse(token: str) -> None:
        raise AssertionError(f"non-finite number in the JSON: {token}")

    return json.loads(text, parse_constant=refuse)


def run(tmp_path: Path, keys: str, command: str) -> Any:
    path = tmp_path / "m.toml"
    path.write_text(WALL + keys, encoding="utf-8")
    args = [command, str(path), "--record", str(RICKER), "--format", "json"]
    return path, CliRunner().invoke(cli, args)


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("keys", VALID.values(), ids=VALID.keys())
def test_extreme_valid_restrainers_give_strict_json(
    tmp_path: Path, keys: str, command: str
) -> None:
    _, result = run(tmp_path, keys, command)
    assert result.exit_code == 0, result.output
    assert strict_json(result.stdout)["schema"] >= 1


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize(("keys", "key"), REFUSED.values(), ids=REFUSED.keys())
def test_the_issues_values_are_refused_with_one_line(
    tmp_path: Path, keys: str, key: str, command: str
) -> None:
    path, result = run(tmp_path, keys, command)
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert lines and all(line.startswith(f"error: {path}: restrainers[0].") for line in lines)
    assert f"restrainers[0].{key}:" in lines[0]
