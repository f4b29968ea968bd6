"""The worked example reports in docs/reports/ are what this version writes: each is made
again with the command docs/report.md gives and compared, its figures and the source digest
aside (the first are matplotlib's drawing, the second changes with any edit of the code).
"""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli

ROOT = Path(__file__).resolve().parents[2]
GUIDE = ROOT / "docs" / "report.md"
EPOCH = "1795392000"
#: The lines of docs/report.md that make the examples.
COMMAND = re.compile(r"SOURCE_DATE_EPOCH=(\d+) (rock report [^\n]*\\\n[^\n]*)")

pytest.importorskip("jinja2", reason="the report extra is not installed")
pytest.importorskip("matplotlib", reason="the report extra is not installed")


def commands() -> list[list[str]]:
    found = [
        shlex.split(text.replace("\\\n", " "))
        for epoch, text in COMMAND.findall(GUIDE.read_text(encoding="utf-8"))
        if epoch == EPOCH
    ]
    assert len(found) == 2, "docs/report.md should give the two example commands"
    return found


def comparable(html: str) -> str:
    """The page without its figures and its source digest."""
    html = re.sub(r"<svg.*?</svg>", "<svg/>", html, flags=re.S)
    return re.sub(r"\b[0-9a-f]{64}\b(?=</td>)", "DIGEST", html, count=1)


@pytest.mark.parametrize("args", commands(), ids=lambda a: Path(a[a.index("-o") + 1]).stem)
def test_the_example_report_is_what_rock_writes(
    args: list[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(ROOT)
    monkeypatch.setenv("SOURCE_DATE_EPOCH", EPOCH)
    monkeypatch.delenv("ROCK_HAZARD_GRID", raising=False)  # the examples run no grid case
    committed = ROOT / args[args.index("-o") + 1]
    fresh = tmp_path / committed.name
    args = [*args[1:]]
    args[args.index("-o") + 1] = str(fresh)
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.stderr
    made = fresh.read_text(encoding="utf-8").replace(str(fresh), str(committed.relative_to(ROOT)))
    assert comparable(made) == comparable(committed.read_text(encoding="utf-8")), (
        f"{committed.relative_to(ROOT)} is not what this version writes: make it again with "
        f"the command in docs/report.md"
    )
