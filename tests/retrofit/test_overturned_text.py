"""An overturned block in what a person reads (issue 19, item 7): "overturned", not the
overturning angle over α.

A block that overturns reaches |θ| = π/2 (the overturning angle), so its max θ/α is
(π/2)/α: 31.4159 for the façade's α = 0.05 rad (paper §4.2). On main `rock retrofit` showed
that number in its max θ/α column and the assessment plot's legend said "max θ/α = 31.416":
a number that says nothing about the block but reads like a result.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.plots.histories import _run_label
from rockcli.plots.phrases import english
from rockcli.terminal.retrofit import retrofit_report
from tests.cli.conftest import ROOT

FACADE = ROOT / "examples" / "facade.toml"
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
#: The façade's slenderness [rad] (examples/facade.toml, paper §4.2).
ALPHA = 0.05


def test_retrofit_says_overturned_for_the_thin_rods() -> None:
    # Ø10 mm lets the façade overturn under the Ricker pulse, Ø20 mm (the paper's rod) holds
    # it; the JSON keeps the number and the flag, the table says "overturned".
    args = ["retrofit", str(FACADE), "--record", str(RICKER), "--diameters", "10,20"]
    doc = CliRunner().invoke(cli, [*args, "--format", "json"]).stdout
    import json

    thin, paper = json.loads(doc)["candidates"]
    assert thin["overturned"] and not paper["overturned"]
    assert math.isclose(thin["max_ratio"], (math.pi / 2) / ALPHA, rel_tol=1e-3)
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0
    rows = [line for line in result.stdout.splitlines() if line.lstrip("│ ").startswith("10 ")]
    assert len(rows) == 1 and "overturned" in rows[0], rows
    assert f"{thin['max_ratio']:.4f}" not in result.stdout
    assert f"{paper['max_ratio']:.4f}" in result.stdout


def test_the_retrofit_report_cell() -> None:
    row = {
        "diameter_mm": 10.0, "K": 5.5e6, "strength": 2.0e4, "code_uls_passed": True,
        "code_zeta": 2.3, "max_ratio": (math.pi / 2) / ALPHA, "overturned": True,
        "max_force": 2.0e4, "utilisation": 1.0, "ruptured": False,
    }  # fmt: skip
    doc = {
        "model": {"name": "m"}, "record": {"name": "r", "pga_g": 0.5, "input": "ground"},
        "rod": {"name": "rod", "placed": None}, "grade": "S275", "count": 1,
        "candidates": [row], "chosen": None, "reason": "none", "warnings": [],
    }  # fmt: skip
    (table,) = retrofit_report(doc).tables
    assert table.rows[0]["max_ratio"] == "overturned"


def test_the_plot_legend_of_an_overturned_run_has_no_ratio() -> None:
    fallen = SimpleNamespace(polarity=1, t_overturn=0.85, max_ratio=(math.pi / 2) / ALPHA)
    standing = SimpleNamespace(polarity=-1, t_overturn=None, max_ratio=0.3143)
    assert _run_label(fallen, english) == "polarity +1: overturns at 0.85 s"  # type: ignore[arg-type]
    assert _run_label(standing, english) == "polarity −1: max θ/α = 0.314"  # type: ignore[arg-type]
