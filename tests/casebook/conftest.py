"""Shared pieces of the casebook tests: paths, and a case file written to a folder."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CASEBOOK = ROOT / "examples" / "validation"
#: CI's copy of the NTC hazard grid, as the CI job names it (relative to the repository).
CI_GRID = "../shared/ntc/AllegatoB.txt"
GRID_FILE = ROOT / CI_GRID

#: A valid case of the cheapest kind, as TOML (the bad-input tests break one line of it).
SPECTRUM_CASE = """\
[[cases]]
id = "t.spectrum"
title = "Se(0.30 s), soil A"
kind = "spectrum"
quantity = "Se"
expected = 0.2070828
tolerance = 1e-12
tolerance_type = "relative"
tolerance_reason = "closed form, to rounding"
source = "closed form: NTC 2018 §3.2.3.2.1"
[cases.input]
ag = 0.0943
F0 = 2.44
Tc_star = 0.27
soil = "A"
period = 0.30
"""


@pytest.fixture
def grid_file() -> Path:
    """The shared NTC grid, or a skip when this clone has none beside it."""
    if not GRID_FILE.is_file():
        pytest.skip(f"NTC hazard grid not available: {GRID_FILE} is absent (not shipped)")
    return GRID_FILE


@pytest.fixture
def no_grid(monkeypatch: pytest.MonkeyPatch) -> None:
    """No grid from the environment either."""
    monkeypatch.delenv("ROCK_HAZARD_GRID", raising=False)


def write_casebook(folder: Path, text: str, name: str = "cases.toml") -> Path:
    """A casebook folder holding one case file."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_text(text, encoding="utf-8")
    return folder
