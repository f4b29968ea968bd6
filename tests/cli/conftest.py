"""Shared paths of the CLI tests."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
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
