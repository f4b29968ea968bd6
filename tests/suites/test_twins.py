"""Two records of a suite that are one motion (rockcli.suites.twins): a copy flipped, padded
with a zero sample or scaled warns, under the table and in the JSON ``warnings``; different
records do not. On main such copies counted as new records, silently.

The numbers: ρ = ±1 is exact for a copy shifted by whole samples and multiplied by a constant
(Cauchy–Schwarz, equality iff the histories are proportional); the tolerance 1e-12 on it is
rounding over a few thousand products.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.cli.main import cli
from rockcli.records.files import read_record
from rockcli.records.record import Record
from rockcli.suites.twins import TWIN_CORRELATION, best_correlation, find_twins, twin_groups
from tests.suites.conftest import EXAMPLE_SUITE, PULSES, write_suite

#: Rounding of ρ over a few thousand products of doubles.
RHO_TOL = 1e-12


def record(accel: np.ndarray, dt: float = 0.01, name: str = "r") -> Record:
    time = dt * np.arange(accel.size)
    return Record(name, "generated", "plain", time, np.asarray(accel, float), dt)


def noise(seed: int, n: int = 2000) -> np.ndarray:
    return np.random.default_rng(seed).normal(0.0, 0.1, n)


def test_a_copy_shifted_flipped_or_scaled_correlates_at_one() -> None:
    a = noise(1)
    base = record(a)
    for shift in (0, 1, 37):
        for factor in (1.0, -1.0, 2.5):
            copy = record(factor * np.r_[np.zeros(shift), a])
            rho, lag = best_correlation(base, copy)
            assert rho == pytest.approx(math.copysign(1.0, factor), abs=RHO_TOL)
            assert lag == pytest.approx(shift * 0.01, abs=1e-12)  # the copy runs later
            rho, lag = best_correlation(copy, base)
            assert lag == pytest.approx(-shift * 0.01, abs=1e-12)  # the original runs earlier


def test_different_noises_do_not_correlate() -> None:
    # Two independent white noises of n samples: |ρ| at any lag is of order √(2 ln(2n)/n),
    # about 0.09 for n = 2000; far below the threshold.
    rho, _ = best_correlation(record(noise(1)), record(noise(2)))
    assert abs(rho) < 0.2 < TWIN_CORRELATION


def test_a_copy_on_another_time_step_is_compared_on_the_finer() -> None:
    # A smooth motion (a 1 Hz sine) sampled at 0.01 s and at 0.02 s: the coarser one,
    # interpolated linearly onto 0.01 s, is the same motion to the interpolation error
    # (ω²·dt²/8 ≈ 5e-4 of the amplitude): ρ > 0.999.
    t_fine, t_coarse = 0.01 * np.arange(1000), 0.02 * np.arange(500)
    fine = Record("f", "g", "plain", t_fine, np.sin(2 * np.pi * t_fine), 0.01)
    coarse = Record("c", "g", "plain", t_coarse, np.sin(2 * np.pi * t_coarse), 0.02)
    rho, lag = best_correlation(fine, coarse)
    assert rho > TWIN_CORRELATION and lag == 0.0


def test_groups_join_a_copy_of_a_copy() -> None:
    a = noise(3)
    records = [record(a), record(noise(4)), record(-a), record(np.r_[0.0, a])]
    groups = twin_groups(len(records), find_twins(records))
    assert groups == [[0, 2, 3]]


@settings(max_examples=40, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    shift=st.integers(0, 50),
    factor=st.floats(0.1, 10.0) | st.floats(-10.0, -0.1),
    n=st.integers(2, 400),
)
def test_any_copy_is_found_and_any_correlation_is_bounded(
    seed: int, shift: int, factor: float, n: int
) -> None:
    a = np.random.default_rng(seed).normal(0.0, 1.0, n)
    rho, lag = best_correlation(record(a), record(factor * np.r_[np.zeros(shift), a]))
    assert abs(rho) == pytest.approx(1.0, abs=1e-9) and math.copysign(1, rho) == math.copysign(
        1, factor
    )
    assert lag == pytest.approx(shift * 0.01, abs=1e-9)
    other = np.random.default_rng(seed + 1).normal(0.0, 1.0, n + shift)
    rho, _ = best_correlation(record(a), record(other))
    assert abs(rho) <= 1.0 + 1e-12  # Cauchy–Schwarz


def check_json(suite: Path) -> dict:
    result = CliRunner().invoke(cli, ["suite", "check", str(suite), "--format", "json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def test_a_flipped_and_a_padded_copy_warn_in_the_suite(tmp_path: Path) -> None:
    original = read_record(PULSES[2])
    np.savetxt(tmp_path / "flipped.txt", np.c_[original.time, -original.accel], fmt="%.17g")
    padded = np.r_[0.0, original.accel]
    times = original.dt * np.arange(padded.size)
    np.savetxt(tmp_path / "padded.txt", np.c_[times, padded], fmt="%.17g")
    records = [{"path": str(p)} for p in PULSES]
    records += [{"path": "flipped.txt"}, {"path": "padded.txt"}]
    doc = check_json(write_suite(tmp_path, records))
    (warning,) = [w for w in doc["warnings"] if "one motion" in w]
    name = PULSES[2].stem
    assert warning.startswith(f"records '{name}', 'flipped' and 'padded' are one motion")
    assert "'flipped' ρ = -1.0000, flipped" in warning
    assert f"'padded' ρ = +1.0000, {original.dt:g} s later" in warning
    assert "this suite holds 3 different records, not 5" in warning
    text = CliRunner().invoke(cli, ["suite", "check", str(tmp_path / "suite.toml")]).stdout
    assert "warning: records" in text


def test_seven_files_of_six_motions_say_the_rule_changes(tmp_path: Path) -> None:
    # Six different motions (the pulses and their negatives would be copies: use the pulses
    # and noise) and a flipped copy of one: 7 files, 6 records — the worst effect governs.
    records = [{"path": str(p)} for p in PULSES]
    for seed in range(3):
        np.savetxt(tmp_path / f"n{seed}.txt", np.c_[0.01 * np.arange(500), noise(seed, 500)])
        records.append({"path": f"n{seed}.txt"})
    np.savetxt(tmp_path / "copy.txt", np.c_[0.01 * np.arange(500), -noise(0, 500)])
    records.append({"path": "copy.txt"})
    doc = check_json(write_suite(tmp_path, records))
    (warning,) = [w for w in doc["warnings"] if "one motion" in w]
    assert "holds 6 different records, not 7" in warning
    assert "the worst effect governs, not the mean" in warning


def test_different_records_do_not_warn(tmp_path: Path) -> None:
    doc = check_json(write_suite(tmp_path, [{"path": str(p)} for p in PULSES]))
    assert not [w for w in doc["warnings"] if "one motion" in w]


def test_the_example_suites_real_records_do_not_warn(shared_records: Path) -> None:
    result = CliRunner().invoke(
        cli, ["suite", "check", str(EXAMPLE_SUITE), "--allow-outside", "--format", "json",
              "--hazard-grid", str(shared_records.parent / "ntc" / "AllegatoB.txt")],
    )  # fmt: skip
    if result.exit_code == 2 and "hazard grid" in result.stderr:
        pytest.skip("the NTC hazard grid is absent")
    assert result.exit_code == 0, result.stderr
    assert not [w for w in json.loads(result.stdout)["warnings"] if "one motion" in w]
