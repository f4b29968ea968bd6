"""The displacement demand of a record (issue #19, items 1–2): Circolare 7/2019
§C8.7.1.2.1.8, "La domanda di spostamento sul meccanismo locale allo SLV corrisponde al valore
massimo dello spostamento spettrale valutato nell'intervallo di periodi [T0, T_SLV]. Questo
criterio deve essere seguito nel caso in cui siano stati selezionati accelerogrammi di sito…";
the same for SLC. Each check says the damping, the period range and the value it used.

References are independent of rock's spectrum code: the record's Sd is integrated here by
Newmark's average-acceleration method on a finer step (tests.suites.conftest.newmark_peak,
Chopra §5.4), on a dense period grid.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.codecheck.demand import period_grid, range_maximum
from tests.cli.conftest import ROOT
from tests.suites.conftest import newmark_peak

FACADE = ROOT / "examples" / "facade.toml"
ALTAR = ROOT / "examples" / "altar.toml"
#: The altar with LC1's FC, which the 2019 rules ask of a block (§C8.7.1.2.1.3).
ALTAR_2019 = ROOT / "tests" / "data" / "altar-2019.toml"
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
G = 9.81
#: Newmark's average acceleration at a step of 1 ms against the exact piecewise-linear
#: recurrence: period error ~ (ω dt)²/12 < 1e-4 for T > 0.3 s, and a grid of 5 ms on the
#: reference side against rock's refined maximum: 0.5 % covers both.
REFERENCE_RTOL = 5e-3


def json_of(command: str, *args: str) -> dict:
    result = CliRunner().invoke(cli, [command, *map(str, args), "--format", "json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def check_of(doc: dict, ls: str, method: str = "nonlinear", where: str = "ground") -> dict:
    return next(
        c
        for c in doc["checks"]
        if c["limit_state"] == ls and c["method"] == method and c["location"] == where
    )


def reference_sd(periods: np.ndarray, damping: float) -> np.ndarray:
    """Sd [m] of the Ricker pulse by Newmark on 1 ms steps, 10 s of free vibration after it."""
    t, a = np.loadtxt(RICKER, comments="#", unpack=True)
    Sa = newmark_peak(t, a, periods, dt=1e-3, tail=10.0, damping=damping)
    return Sa * G * (periods / (2 * math.pi)) ** 2


@pytest.mark.parametrize(("ls", "xi"), [("SLV", 8.0), ("SLC", 10.0)])
def test_record_demand_is_the_maximum_over_the_period_range(ls: str, xi: float) -> None:
    # The façade (2019) on the Ricker pulse: T_SLV = 3.59 s, where the pulse's 8 %-damped Sd
    # is 0.0576 m, far below its peak near 0.9 s (0.0715 m): the demand is that peak.
    doc = json_of("kinematic", FACADE, "--record", RICKER)
    c = check_of(doc, ls)
    T_secant = doc[f"T_{ls}"]
    assert c["demand_damping"] == xi
    assert c["demand_period_range"] == [0.0, T_secant]
    periods = np.arange(0.05, T_secant, 0.005)
    sd = reference_sd(periods, xi / 100)
    assert c["demand_spectral"] == pytest.approx(sd.max(), rel=REFERENCE_RTOL)
    assert c["demand_period"] == pytest.approx(periods[sd.argmax()], abs=0.01)
    at_secant = reference_sd(np.array([T_secant]), xi / 100)[0]
    assert c["demand_spectral"] > 1.15 * at_secant  # the old reading was this much short
    # ζ = d_ls / max Sd (a record scales linearly with its PGA).
    assert c["ratio"] == pytest.approx(doc[f"d_{ls}"] / c["demand_spectral"], rel=1e-9)


def test_code_spectrum_demand_stays_at_the_secant_period(tmp_path: Path) -> None:
    # With the code's spectrum (the façade's [ntc.demand]), the demand is SDe(T_SLV): no range.
    model = FACADE.read_text(encoding="utf-8") + (
        "\n[ntc.demand.SLD]\nag = 0.06\nF0 = 2.5\nTc_star = 0.28\n"
        "[ntc.demand.SLV]\nag = 0.16\nF0 = 2.5\nTc_star = 0.3\n"
        "[ntc.demand.SLC]\nag = 0.2\nF0 = 2.5\nTc_star = 0.31\n"
    )
    path = tmp_path / "model.toml"
    path.write_text(model, encoding="utf-8")
    doc = json_of("kinematic", path)
    c = check_of(doc, "SLV")
    assert c["demand_period_range"] is None
    assert c["demand_period"] == doc["T_SLV"]
    assert c["demand_damping"] == 8.0
    assert c["demand_spectral"] == c["demand_at_secant"]


def test_record_at_height_takes_the_maximum_of_its_floor_spectrum() -> None:
    # The altar at height, 2019 rules: the demand is the floor spectrum's displacement built on
    # the record; the rule is the same maximum over [0, T_SLV] (§C8.7.1.2.1.8), so it is never
    # less than the value at T_SLV.
    doc = json_of("kinematic", ALTAR_2019, "--record", RICKER, "--edition", "2019")
    c = check_of(doc, "SLV", where="height")
    assert c["demand_period_range"] == [0.0, doc["T_SLV"]]
    assert c["demand_spectral"] >= c["demand_at_secant"] > 0.0
    assert c["demand_period"] <= doc["T_SLV"]


def test_2009_reads_the_secant_period_and_says_what_2019_would() -> None:
    # Circolare 617/2009 §C8A.4.2.3 has no range rule: the demand stays SDe(Ts) at 5 %, and the
    # note gives the 2019 maximum where the record's spectrum peaks below Ts.
    doc = json_of("kinematic", ALTAR, "--record", RICKER)
    c = check_of(doc, "ULS")
    assert c["demand_period"] == doc["Ts"]
    assert c["demand_period_range"] is None
    assert c["demand_damping"] == 5.0
    sd = reference_sd(np.array([doc["Ts"]]), 0.05)[0]
    assert c["demand"] == pytest.approx(sd, rel=REFERENCE_RTOL)
    assert "max Sd over [0, Ts]" in c["note"]


def test_spectral_values_carry_the_damping_each_check_used() -> None:
    # The demand table used to show the 5 % values while the SLV check used 8 %.
    doc = json_of("kinematic", FACADE, "--record", RICKER)
    values = {v["at"]: v for v in doc["demand"]["SLV"]["spectral_values"]}
    assert values["T_SLV"]["damping"] == 8.0
    peak = next(v for name, v in values.items() if name.startswith("max over"))
    assert peak["SDe"] == pytest.approx(check_of(doc, "SLV")["demand_spectral"], rel=1e-12)
    slc = {v["at"]: v for v in doc["demand"]["SLC"]["spectral_values"]}
    assert slc["T_SLC"]["damping"] == 10.0


def test_terminal_shows_the_rule_and_the_period_formula() -> None:
    result = CliRunner().invoke(cli, ["kinematic", str(FACADE), "--record", str(RICKER)])
    text = " ".join(result.output.split())
    assert "T_SLV = 1.68π·√(d_SLV/a(d_SLV)) [C8.7.1.10]" in text
    assert "max Sd over [T0, T_SLV]" in text
    assert "(5 % damping)" not in text


def test_range_maximum_finds_a_peak_between_grid_points() -> None:
    # A narrow peak at 1.2345 s (closed form): the grid brackets it, the golden section lands
    # within its tolerance; the range's end counts too.
    T, value = range_maximum(lambda T: 1.0 - abs(T - 1.2345), 0.0, 3.0)
    assert T == pytest.approx(1.2345, abs=2e-5)
    assert value == pytest.approx(1.0, abs=2e-5)
    assert range_maximum(lambda T: T, 0.0, 3.59) == (3.59, 3.59)
    assert period_grid(0.0, 0.05) == pytest.approx([0.01, 0.02, 0.03, 0.04, 0.05])
