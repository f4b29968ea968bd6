"""The reference paper's systemic finding is written only for a block its study covers: one
free-standing rectangular block with R in 1.5–10 m and α in 0.05–0.25 rad (paper §3.3, Fig. 8;
to 1 %, so the paper's own altar of §3.2, R = 1.499 m, is one)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.document.conclusions import in_papers_range

ROOT = Path(__file__).resolve().parents[2]
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
FREE = {"R": 3.5, "alpha": 0.10, "sides": "two", "chain": None, "loads": [], "thrusts": [],
        "restrainers": []}  # fmt: skip


@pytest.mark.parametrize(
    ("change", "covered"),
    [
        ({}, True),
        ({"R": 1.499, "alpha": 0.163}, True),  # the paper's altar (§3.2)
        ({"R": 10.0, "alpha": 0.25}, True),  # the grid's corner
        ({"R": 1.4}, False),  # smaller than the smallest wall of the study
        ({"R": 12.0}, False),
        ({"alpha": 0.04}, False),
        ({"alpha": 0.30}, False),
        ({"restrainers": [{"name": "tie-rod"}]}, False),  # not free-standing
        ({"loads": [{"name": "floor"}]}, False),
        ({"chain": {"bodies": 2}}, False),  # a chain of bodies is not the paper's block
        ({"sides": "one"}, False),  # one-sided (a façade against its return walls)
    ],
)
def test_the_papers_range(change: dict, covered: bool) -> None:
    assert in_papers_range({"model": {**FREE, **change}, "mechanism": None}) is covered


def test_a_walls_mechanism_is_not_the_papers_block() -> None:
    # A wall's overturning mechanism rocks as one body whose R and α may fall in the range;
    # its section is the wall's (stepped storeys), not the study's rectangle.
    rocked = {"model": FREE, "mechanism": {"name": "overturning", "type": "overturning"}}
    assert not in_papers_range(rocked)


def conclusions(model: Path, tmp_path: Path) -> str:
    pytest.importorskip("jinja2", reason="the report extra (jinja2) is not installed")
    pytest.importorskip("matplotlib", reason="the report extra (matplotlib) is not installed")
    html = tmp_path / "r.html"
    result = CliRunner().invoke(
        cli, ["report", str(model), "--record", str(PULSE), "-o", str(html)]
    )
    assert result.exit_code == 0, result.stderr
    text = html.read_text(encoding="utf-8")
    return re.search(r'<section id="conclusions".*?</section>', text, re.S).group(0)  # type: ignore[union-attr]


def test_the_altar_report_cites_the_papers_finding(tmp_path: Path) -> None:
    assert "100 analisi sistematiche" in conclusions(ROOT / "examples" / "altar.toml", tmp_path)


def test_a_restrained_facade_report_does_not(tmp_path: Path) -> None:
    text = conclusions(ROOT / "examples" / "facade.toml", tmp_path)
    assert "analisi sistematic" not in text and "articolo di riferimento" not in text
