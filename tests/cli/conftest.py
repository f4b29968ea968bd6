"""Shared paths of the CLI tests."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: Every example model.
ALL_EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
#: The examples the time history rocks (a wall of storeys with its mechanism catalogue is
#: checked by `rock kinematic` only until the catalogue rocks: WALL_EXAMPLES).
WALL_EXAMPLES = [p for p in ALL_EXAMPLES if "[[geometry.storeys]]" in p.read_text("utf-8")]
EXAMPLES = [p for p in ALL_EXAMPLES if p not in WALL_EXAMPLES]
PULSES = sorted((ROOT / "records").glob("*.txt"))
SHARED_RECORDS = ROOT.parent / "shared" / "records"


@pytest.fixture
def shared_records() -> Path:
    """The folder of real records, or a skip when this clone has no ../shared/records."""
    if not SHARED_RECORDS.is_dir():
        pytest.skip(
            f"real records not available: {SHARED_RECORDS} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    return SHARED_RECORDS
