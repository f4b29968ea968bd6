"""Fixtures of the record tests: the shared real records, and small text files in tmp_path."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

#: The real records of spec/records.md live next to the repository, never inside it.
SHARED_RECORDS = Path(__file__).resolve().parents[2].parent / "shared" / "records"


@pytest.fixture
def shared_records() -> Path:
    """The folder of real records, or a skip when this clone has no ../shared/records."""
    if not SHARED_RECORDS.is_dir():
        pytest.skip(
            f"real records not available: {SHARED_RECORDS} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    return SHARED_RECORDS


@pytest.fixture
def write_file(tmp_path: Path) -> Callable[[str, str], Path]:
    """Write text (line ends kept as given) to a file in tmp_path and return its path."""

    def write(name: str, text: str) -> Path:
        path = tmp_path / name
        path.write_bytes(text.encode("utf-8"))
        return path

    return write
