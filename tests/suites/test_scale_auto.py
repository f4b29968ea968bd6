"""`--scale auto`: one common factor f = (1 + lo)/min(mean/target), kept when f·max(mean/target)
≤ 1 + hi (the method documented with the command)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.records.files import read_record
from rockcli.suites.compat import auto_scale
from tests.suites.conftest import PULSES, multiple_of, newmark_peak, se_by_hand, write_suite

RICKER = next(p for p in PULSES if p.name.startswith("ricker"))
#: The reference spectrum agrees with rock's to ≤ 6e-5 on the pulses (test_compatibility).
REFERENCE_RTOL = 1e-3
#: A factor on spectra that are linear in the records: equal to rounding.
LINEAR_RTOL = 1e-12


def multiples(folder: Path, factors: list[float], **keys: object) -> Path:
    """A suite of the Ricker pulse times ``factors``: file i holds the pulse times i + 1 (a
    suite holds each motion once) and its ``scale`` is factor/(i + 1)."""
    records = []
    for i, factor in enumerate(factors):
        copy = multiple_of(RICKER, folder / f"ricker{i}.txt", i + 1)
        records.append({"path": copy.name, "scale": factor / (i + 1)})
    return write_suite(folder, records, **keys)


def auto(path: Path) -> dict:
    args = ["suite", "check", str(path), "--scale", "auto", "--format", "json"]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.output + result.stderr
    return json.loads(result.stdout)


def test_factor_of_exact_multiples_is_recovered(tmp_path: Path) -> None:
    # Copies at 2.5 × (0.5, 1, 1.5): the mean is 2.5 × the pulse, so the factor is 1/2.5 of
    # the pulse's own factor 0.9/min(Sa/Se) (Sa from the independent reference).
    doc = auto(multiples(tmp_path, [1.25, 2.5, 3.75]))
    periods = np.array(doc["periods"])
    rec = read_record(RICKER)
    sa = newmark_peak(rec.time, rec.accel, periods, dt=1e-3, tail=3.0)
    pulse_factor = 0.9 / float(np.min(sa / se_by_hand(periods)))
    assert doc["scale_auto"]["factor"] * 2.5 == pytest.approx(pulse_factor, rel=REFERENCE_RTOL)
    # After the factor the smallest ratio sits on the lower bound, to rounding.
    assert doc["scale_auto"]["min_ratio"] == pytest.approx(0.9, rel=LINEAR_RTOL)


def test_factor_scales_inversely_with_the_records(tmp_path: Path) -> None:
    (tmp_path / "one").mkdir(), (tmp_path / "two").mkdir()
    one = auto(multiples(tmp_path / "one", [1.0, 2.0, 3.0]))
    two = auto(multiples(tmp_path / "two", [2.0, 4.0, 6.0]))
    factor = one["scale_auto"]["factor"]
    assert two["scale_auto"]["factor"] == pytest.approx(factor / 2.0, rel=LINEAR_RTOL)


def test_a_pulse_cannot_fit_the_2018_band(tmp_path: Path) -> None:
    # A single pulse's spectrum is far from the code's shape: its largest ratio is more than
    # 1.3/0.9 times its smallest, so no common factor passes (told, not hidden).
    path = multiples(tmp_path, [1.0, 2.0, 3.0])
    doc = auto(path)
    assert doc["max_ratio"] / doc["min_ratio"] > 1.3 / 0.9
    assert doc["scale_auto"]["feasible"] is False and doc["scale_auto"]["passed"] is False
    text = CliRunner().invoke(cli, ["suite", "check", str(path), "--scale", "auto"]).stdout
    assert "no common factor makes this suite compatible" in " ".join(text.split())


def test_a_wide_upper_bound_makes_the_factor_pass(tmp_path: Path) -> None:
    # A tenth of the pulse: below the lower bound somewhere (min ratio < 0.9), so it fails
    # before the factor and passes with it when the upper bound is out of reach.
    doc = auto(multiples(tmp_path, [0.1, 0.2, 0.3], tolerance=[-0.10, 100.0]))
    assert doc["passed"] is False and doc["min_ratio"] < 0.9
    assert doc["scale_auto"]["feasible"] is True and doc["scale_auto"]["passed"] is True


def test_a_mean_of_zero_has_no_factor() -> None:
    # Unreachable from a suite file (a record of zeros is refused) but kept honest: a zero
    # ratio cannot be lifted by any factor, and no division by zero.
    result = auto_scale(np.array([0.0, 1.0]), (-0.10, 0.30))
    assert result.factor is None and result.feasible is False
