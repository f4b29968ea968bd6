"""matplotlib is loaded only to draw (spec/style.md: plots are output, imported lazily).

Run in a fresh interpreter: the test session itself may have imported matplotlib already.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from tests.cli.conftest import ROOT


def imported_by(code: str) -> set[str]:
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT
    )
    return set(out.stdout.split())


@pytest.mark.parametrize("args", [["--help"], ["assess", "--help"], ["compare", "--help"]])
def test_help_does_not_import_matplotlib(args: list[str]) -> None:
    mods = imported_by(
        "import sys\nfrom click.testing import CliRunner\nfrom rockcli.cli.main import cli\n"
        f"r = CliRunner().invoke(cli, {args!r})\nassert r.exit_code == 0, r.output\n"
        "print(' '.join(sys.modules))"
    )
    assert "matplotlib" not in mods


def test_the_plot_module_imports_no_matplotlib() -> None:
    mods = imported_by("import sys, rockcli.plots\nprint(' '.join(sys.modules))")
    assert "matplotlib" not in mods
    assert "numpy" not in mods
