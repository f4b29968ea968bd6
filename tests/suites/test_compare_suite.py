"""`rock compare MODEL --suite SUITE`: the code check on the suite's target (or mean) spectrum
against the suite's time history by the code's rule, both at the target's limit state."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from rockcli.analyses.compare import classify
from rockcli.cli.main import cli
from rockcli.codecheck.demand import MeanSpectrum
from rockcli.codecheck.spectra import ElasticSpectrum
from tests.suites.conftest import PULSES, ROOT, newmark_peak, pulse_copies, write_suite

WALL = ROOT / "examples" / "wall.toml"
ALTAR = ROOT / "examples" / "altar.toml"
SCALED_SUITE = ROOT / "examples" / "suites" / "laquila-slv-scaled.toml"
#: The altar's own [ntc.demand.SLD] (examples/altar.toml: Reggiolo, TR 50 years).
ALTAR_SLD_AG = 0.0443
#: The reference spectrum's agreement with rock's (tests/suites/test_compatibility.py says
#: why 1e-3: Newmark on a 1 ms step against the exact recurrence).
REFERENCE_RTOL = 1e-3


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["compare", *args])
    return result.exit_code, result.stdout, result.stderr


def pulse_suite(folder: Path, count: int = 3, **keys) -> Path:
    """``count`` copies of the shipped pulses, scales 1.0, 1.1, …; target TARGET (SLV)."""
    records = [
        {"path": str(p), "name": f"r{k}", "scale": 1 + k / 10}
        for k, p in enumerate(pulse_copies(folder, count))
    ]
    return write_suite(folder, records, **keys)


def test_parameter_target_sets_its_state_and_the_model_the_others(tmp_path: Path) -> None:
    # The altar (2009: SLD, SLV) under a target that gives SLV only: the code's SLV demand
    # is the target's (soil A: S = 1), SLD the model's own [ntc.demand.SLD].
    code, out, err = run(str(ALTAR), "--suite", str(pulse_suite(tmp_path)), "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    slv, sld = doc["kinematic"]["demand"]["SLV"], doc["kinematic"]["demand"]["SLD"]
    assert (slv["ag"], slv["F0"], slv["Tc_star"], slv["S"]) == (0.25, 2.5, 0.3, 1.0)
    assert slv["source"].startswith("the suite's target")
    assert sld["ag"] == ALTAR_SLD_AG
    assert doc["limit_state"] == "SLV"
    assert doc["collapse"]["code_verdict"] == "ULS"  # 2009: SLV is the ULS check
    assert doc["code_demand"] == "target"
    assert any("soil C (target: A)" in note for note in doc["notes"])


def test_classification_is_the_two_verdicts_of_the_state(tmp_path: Path) -> None:
    doc = json.loads(run(str(ALTAR), "--suite", str(pulse_suite(tmp_path)), "--format", "json")[1])
    code_passed = doc["kinematic"]["verdict"]["ULS"]
    rocking_passed = doc["suite"]["verdict"] == "passes"
    assert doc["collapse"] == {"code": not code_passed, "code_verdict": "ULS",
                               "rocking": not rocking_passed}  # fmt: skip
    assert doc["classification"] == str(classify(not code_passed, not rocking_passed))


def test_suite_mean_is_the_mean_of_the_scaled_records(tmp_path: Path) -> None:
    # --code-demand suite-mean: PGA and Se at the check's periods are the means of the scaled
    # records', computed here from the files by an independent integrator (newmark_peak).
    suite = pulse_suite(tmp_path)
    code, out, err = run(str(WALL), "--suite", str(suite), "--code-demand", "suite-mean",
                         "--format", "json")  # fmt: skip
    assert code == 0, err
    doc = json.loads(out)
    records = [np.loadtxt(p, comments="#") for p in sorted(tmp_path.glob("rec*.txt"))]
    scales = [r["scale"] for r in doc["suite"]["records"]]
    demand = doc["kinematic"]["demand"]["SLV"]
    pga = np.mean([s * np.abs(r[:, 1]).max() for s, r in zip(scales, records, strict=True)])
    assert demand["PGA"] == pytest.approx(pga, rel=1e-12)
    values = demand.get("spectral_values", [])
    assert values, "the 2019 SLV check reads the spectrum at T_SLV"
    for v in values:
        T = np.array([v["T"]])
        ref = np.mean([s * newmark_peak(r[:, 0], r[:, 1], T, dt=1e-3, tail=3.0,
                                        damping=v["damping"] / 100)[0]
                       for s, r in zip(scales, records, strict=True)])  # fmt: skip
        assert v["Se"] == pytest.approx(ref, rel=REFERENCE_RTOL)


def test_mean_spectrum_of_two_code_spectra_is_their_average() -> None:
    # Closed form: on the plateau Se = ag·S·F0 (soil A, η = 1), so the mean of ag 0.1 and 0.3
    # is 0.2·2.5 = 0.5 g; the PGA mean is (0.1 + 0.3)/2 (NTC §3.2.3.2.1).
    low, high = ElasticSpectrum(0.1, 2.5, 0.3), ElasticSpectrum(0.3, 2.5, 0.3)
    mean = MeanSpectrum((low, high))
    assert mean.Se(0.2) == pytest.approx(0.5, rel=1e-12)
    assert mean.SDe(1.0) == pytest.approx((low.SDe(1.0) + high.SDe(1.0)) / 2, rel=1e-12)
    assert mean.pga_ground == pytest.approx(0.2, rel=1e-12)


def test_gate_on_the_classification(tmp_path: Path) -> None:
    suite = str(pulse_suite(tmp_path))
    doc = json.loads(run(str(ALTAR), "--suite", suite, "--format", "json")[1])
    code, _, _ = run(str(ALTAR), "--suite", suite, "--fail-on", doc["classification"])
    assert code == 1
    other = "consistent-safe" if doc["classification"] != "consistent-safe" else "undetermined"
    assert run(str(ALTAR), "--suite", suite, "--fail-on", other)[0] == 0


@pytest.mark.parametrize(
    ("model", "suite_keys", "extra", "where"),
    [
        (WALL, {}, (), "target"),  # SLV parameters only, the wall sets no [ntc] spectrum
        (ALTAR, {"limit_state": "SLC"}, (), "target.limit_state"),  # 2009 has no SLC check
        (ALTAR, {"limit_state": "SLO"}, (), "target.limit_state"),  # no code check at SLO
        (ALTAR, {}, ("--code-demand", "record"), "--code-demand"),
        (ALTAR, {}, ("--code-demand", "model"), "--code-demand"),
        (ALTAR, {}, ("--plot", "x.png"), "--plot"),
        (ALTAR, {}, ("--record", str(PULSES[0])), "--suite"),
        (ALTAR, {}, ("--scale", "2"), "--scale"),
    ],
)
def test_bad_input(tmp_path: Path, model, suite_keys, extra, where) -> None:
    suite = pulse_suite(tmp_path)
    if suite_keys:
        data = suite.read_text(encoding="utf-8").replace(
            "[target]\n", "[target]\n" + "".join(f'{k} = "{v}"\n' for k, v in suite_keys.items())
        )
        suite.write_text(data, encoding="utf-8")
    code, out, err = run(str(model), "--suite", str(suite), *extra)
    assert code == 2, out + err
    assert where in err and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1


def test_suite_mean_with_a_record_is_refused() -> None:
    code, _, err = run(str(ALTAR), "--record", str(PULSES[0]), "--code-demand", "suite-mean")
    assert code == 2 and "--code-demand" in err and "--suite" in err


def test_the_docs_suite_on_the_altar(shared_records: Path, grid_file: Path) -> None:
    # The done-when of the suite comparison: the per-record table, the compatibility verdict,
    # the code's rule and the side-by-side classification, on the compatible example suite.
    # The code's SLV demand is the suite's target (the same spectrum `rock suite check` shows).
    # The example's records are in ../shared, outside its folder: --allow-outside.
    args = (str(ALTAR), "--suite", str(SCALED_SUITE), "--hazard-grid", str(grid_file),
            "--allow-outside")  # fmt: skip
    code, out, err = run(*args)
    assert code == 0, err
    for text in ("Records of the suite, both polarities", "Lazio-Abruzzo 1984 ISE WE",
                 ": compatible", "rule: the mean over 7 or more records", "SLV verdict",
                 "classification"):  # fmt: skip
        assert text in out
    doc = json.loads(run(*args, "--format", "json")[1])
    check = CliRunner().invoke(
        cli, ["suite", "check", str(SCALED_SUITE), "--hazard-grid", str(grid_file), "--format",
              "json", "--allow-outside"],
    )  # fmt: skip
    target = json.loads(check.stdout)["target_parameters"]
    slv = doc["kinematic"]["demand"]["SLV"]
    assert (slv["ag"], slv["F0"], slv["Tc_star"], slv["TR"]) == (
        target["ag"], target["F0"], target["Tc_star"], target["TR"])  # fmt: skip
    assert doc["suite"]["compatibility"]["passed"] is True
    assert doc["suite"]["n"] == 7 and doc["suite"]["rule"] == "mean"
    assert math.isclose(
        doc["suite"]["measure"],
        sum(r["max_ratio"] for r in doc["suite"]["records"]) / 7,
        rel_tol=1e-12,
    )
