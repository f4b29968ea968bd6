"""`rock suite check SUITE --model MODEL` at height: each record's floor motion against the
code's floor spectrum at the block's height (Circolare 7/2019 §C7.2.3)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.codecheck.floor import floor_motion
from tests.suites.conftest import PULSES, ROOT, TARGET, newmark_peak, write_suite

ALTAR = ROOT / "examples" / "altar.toml"  # Z = 3.04 m, ψ = 0.51, γ = 1, T1 = 1.09 s, ξ = 5 %
WALL = ROOT / "examples" / "wall.toml"  # on the ground
T1, PSI, GAMMA, XI = 1.09, 0.51, 1.0, 0.05
#: As in test_compatibility: Newmark on a 1 ms step against the exact recurrence.
REFERENCE_RTOL = 1e-3


def check(path: Path, *extra: str) -> tuple[int, dict | None, str]:
    result = CliRunner().invoke(cli, ["suite", "check", str(path), *extra, "--format", "json"])
    doc = json.loads(result.stdout) if result.exit_code == 0 else None
    return result.exit_code, doc, result.stderr


def test_the_target_is_the_floor_spectrum_at_the_block(tmp_path: Path) -> None:
    # By hand (NTC §3.2.3.2.1, soil A, S = 1): Se(T1) = ag·F0·TC*/T1 for TC ≤ T1 < TD
    # (TD = 4·ag + 1.6 = 2.6 s); a_Z = Se(T1)·γ·ψ·√(1 + 0.0004·5²) (Circ. 7/2019 §C7.2.3);
    # on the plateau 0.8·T1 ≤ T < 1.1·T1 the floor spectrum is a_Z·1.1·0.05^−0.5 (η = 1).
    suite = write_suite(tmp_path, [{"path": str(p)} for p in PULSES])
    code, doc, err = check(suite, "--model", str(ALTAR))
    assert code == 0, err
    se_t1 = TARGET["ag"] * TARGET["F0"] * TARGET["Tc_star"] / T1
    a_z = se_t1 * GAMMA * PSI * math.sqrt(1.0 + 0.0004 * 25.0)
    assert doc["at_height"]["a_z"] == pytest.approx(a_z, rel=1e-12)
    periods = np.array(doc["periods"])
    plateau = (periods >= 0.8 * T1) & (periods < 1.1 * T1)
    assert plateau.any()
    expected = a_z * 1.1 / math.sqrt(0.05)
    assert np.allclose(np.array(doc["target"])[plateau], expected, rtol=1e-12, atol=0)
    assert doc["at_height"]["Z"] == 3.04


def test_the_mean_is_of_the_floor_motions(tmp_path: Path) -> None:
    # The floor motion ü_g + γψẍ₁ of each pulse (codecheck.floor, tested on its own against
    # closed forms), its spectrum by the independent Newmark reference, then the mean.
    suite = write_suite(tmp_path, [{"path": str(p)} for p in PULSES])
    code, doc, err = check(suite, "--model", str(ALTAR))
    assert code == 0, err
    periods = np.array(doc["periods"][::8])
    spectra = []
    for p, row in zip(PULSES, doc["records"], strict=True):
        data = np.loadtxt(p, comments="#")
        floor = floor_motion(data[:, 0], data[:, 1], T1=T1, psi=PSI, gamma=GAMMA, xi=XI)
        assert row["floor_pga_g"] == pytest.approx(np.abs(floor).max(), rel=1e-12)
        spectra.append(newmark_peak(data[:, 0], floor, periods, dt=1e-3, tail=3.0))
    mean = np.mean(spectra, axis=0)
    assert np.allclose(np.array(doc["mean"][::8]), mean, rtol=REFERENCE_RTOL, atol=0)


def test_the_report_says_at_height(tmp_path: Path) -> None:
    suite = write_suite(tmp_path, [{"path": str(p)} for p in PULSES])
    result = CliRunner().invoke(cli, ["suite", "check", str(suite), "--model", str(ALTAR)])
    assert result.exit_code == 0, result.stderr
    text = " ".join(result.stdout.split())
    assert "floor PGA" in text and "at height Z" in text and "floor motion" in text


def test_a_model_on_the_ground_is_refused(tmp_path: Path) -> None:
    suite = write_suite(tmp_path, [{"path": str(p)} for p in PULSES])
    code, _, err = check(suite, "--model", str(WALL))
    assert code == 2 and "--model: the model stands on the ground" in err
