"""Fixtures of the sweep tests: a small base model, the shipped pulses, a study writer.

The pulses (records/*.txt, 3–4 s at 0.005 s) keep every run short; the real records of
../shared/records are used only where a test says so, with a skip when they are absent.
"""

from __future__ import annotations

import shutil
from collections.abc import Callable
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PULSES = ROOT / "records"
STUDIES = ROOT / "examples" / "studies"
SHARED_RECORDS = ROOT.parent / "shared" / "records"

#: A wall with a top spring, the paper's §4.4 settings (examples/studies/paper-4.4-wall.toml).
BASE = """\
name = "test wall"
kind = "wall"

[geometry]
R = 1.5
alpha = 0.1
width = 3.0

[mass]
unit_weight = 18.0

[restitution]
factor = 0.9

[[restrainers]]
name = "top spring"
position = "top"
k_pos = 0.0
k_neg = 0.0

[ntc]
edition = "2009"
FC = 1.0
"""

#: Two sizes × two slendernesses × two stiffnesses × two pulses = 16 cases.
STUDY = """\
base = "wall.toml"
records_dir = "records"

[[axes]]
path = "geometry.R"
name = "R"
values = [1.5, 3.0]

[[axes]]
path = "geometry.alpha"
name = "alpha"
values = [0.1, 0.2]

[[axes]]
path = ["restrainers[0].k_pos", "restrainers[0].k_neg"]
name = "K"
values = [0.0, 1e6]

[[records]]
path = "one-cosine_Tp2s_0.31g.txt"
name = "cosine"

[[records]]
path = "ricker_Tp0.5s_0.5g.txt"
name = "ricker"
"""

WriteStudy = Callable[..., Path]


@pytest.fixture
def write_study(tmp_path: Path) -> WriteStudy:
    """Write a study (default: STUDY) and its base model (default: BASE) into tmp_path, with
    the shipped pulses in tmp_path/records; returns the study file."""
    records = tmp_path / "records"
    if not records.exists():
        shutil.copytree(PULSES, records)

    def write(study: str = STUDY, base: str = BASE, name: str = "study.toml") -> Path:
        (tmp_path / "wall.toml").write_text(base, encoding="utf-8")
        path = tmp_path / name
        path.write_text(study, encoding="utf-8")
        return path

    return write


@pytest.fixture
def shared_records() -> Path:
    """The folder of real records, or a skip when this clone has no ../shared/records."""
    if not SHARED_RECORDS.is_dir():
        pytest.skip(
            f"real records not available: {SHARED_RECORDS} is absent "
            "(rock does not ship it; see Development in the README)"
        )
    return SHARED_RECORDS
