"""Fixtures of the code-check tests: the NTC hazard grid and a real record, both shared.

Both live next to the repository (../shared), never inside it (rock must not ship the grid);
rock ships neither (users bring their own copies), so the tests that need them skip with
the reason.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from rockcli.codecheck.hazard import HazardGrid, read_grid
from rockcli.records.files import read_record
from rockcli.records.record import Record

SHARED = Path(__file__).resolve().parents[2].parent / "shared"
#: DM 14/01/2008 Allegato B, the copy described in ../shared/ntc/PROVENANCE.md.
GRID_FILE = SHARED / "ntc" / "AllegatoB.txt"
#: El Centro 1940, 180° component (PEER AT2), spec/records.md.
ELC180 = SHARED / "records" / "ELC180.AT2"


@pytest.fixture(scope="session")
def ntc_grid() -> HazardGrid:
    """The NTC hazard grid, or a skip when this clone has no ../shared/ntc/AllegatoB.txt."""
    if not GRID_FILE.is_file():
        pytest.skip(
            f"NTC hazard grid not available: {GRID_FILE} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    return read_grid(GRID_FILE)


@pytest.fixture(scope="session")
def elc180() -> Record:
    """ELC180.AT2 read by rock's own reader, or a skip when ../shared/records is absent."""
    if not ELC180.is_file():
        pytest.skip(
            f"real records not available: {ELC180} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    return read_record(ELC180)
