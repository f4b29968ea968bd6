"""Fixtures of the rocking-physics tests: the shared real records and small synthetic records.

The real records of spec/records.md live next to the repository (../shared/records), never
inside it; rock does not ship them (users bring their own), so the tests that need them
skip with the reason.

The AT2 loader here is deliberately tiny and independent of :mod:`rockcli.records` (the record
parsers have tests of their own): a physics test must not fail because a parser changed. It
reads the classic PEER layout of the two records used here (ELC180.AT2, CPM000.AT2): four
header lines, ``DT=`` on line 4, then whitespace-separated values in g.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

#: The real records of spec/records.md, next to the repository.
SHARED_RECORDS = Path(__file__).resolve().parents[2].parent / "shared" / "records"

#: A ground-motion record as the engine takes it: sample times [s], accelerations [g], dt [s].
Record = tuple[np.ndarray, np.ndarray, float]


def load_at2(path: Path) -> Record:
    """(time [s], accel [g], dt [s]) of a classic PEER AT2 file (4 header lines, DT= on line 4)."""
    lines = path.read_text().splitlines()
    match = re.search(r"DT=\s*([0-9.Ee+-]+)", lines[3], flags=re.IGNORECASE)
    assert match, f"{path.name}: no DT= on line 4"
    dt = float(match.group(1))
    accel = np.array(" ".join(lines[4:]).split(), dtype=float)
    return np.arange(accel.size) * dt, accel, dt


@pytest.fixture(scope="session")
def shared_record() -> Callable[[str], Record]:
    """Load a real record by file name, or skip when this clone has no ../shared/records."""
    if not SHARED_RECORDS.is_dir():
        pytest.skip(
            f"real records not available: {SHARED_RECORDS} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    cache: dict[str, Record] = {}

    def load(name: str) -> Record:
        if name not in cache:
            cache[name] = load_at2(SHARED_RECORDS / name)
        return cache[name]

    return load
