"""The annual rate of a damage state on a site's hazard (rock risk --fragility), against
computations written here without the code's own:

- on a hazard curve that is one power law λ = k0·im^−k, the integral is the closed form
  k0·θ^−k·exp(k²β²/2) exactly (Cornell et al. 2002, the lognormal's moment);
- on the issue's site (13.40 E, 42.35 N, soil A) the grid gives ag 0.07877, 0.26075 and
  0.33407 g at 30, 475 and 975 years; the median θ = 0.30 g alone comes back every 714 years
  (log–log between 475 and 975 years, by hand); the damage state, by the total probability
  theorem in its direct form ∫ P(DS | im)·|dλ| on a dense grid of this file, every 461
  years (λ = 2.167e-3: the issue's "about 2.0e-3, 495 years" leaves out part of the rate
  above the 2475-year PGA, where P(DS | im) > 0.88: docs/risk.md);
- the probability in 50 years is 1 − exp(−50·λ).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner
from scipy.stats import norm

from rockcli.cli.main import cli
from rockcli.risk.curve import HazardCurve, damage_rate

SHARED = Path(__file__).resolve().parents[2].parent / "shared"
GRID_FILE = SHARED / "ntc" / "AllegatoB.txt"
SITE = "13.40,42.35"
GRID_TR = (30.0, 50.0, 72.0, 101.0, 140.0, 201.0, 475.0, 975.0, 2475.0)


def grid_or_skip() -> Path:
    if not GRID_FILE.is_file():
        pytest.skip(f"NTC hazard grid not available: {GRID_FILE} is absent (rock does not ship it)")
    return GRID_FILE


@pytest.mark.parametrize(("k", "theta", "beta"), [(2.9, 0.3, 0.35), (1.8, 0.05, 0.6),
                                                  (3.5, 1.2, 0.2), (2.5, 0.3, 4.0),
                                                  (3.0, 50.0, 1e-6)])  # fmt: skip
def test_a_power_law_curve_gives_the_closed_form(k: float, theta: float, beta: float) -> None:
    k0 = 1e-4
    im = tuple(np.geomspace(0.01, 2.0, 9))
    curve = HazardCurve(im, tuple(k0 * x**-k for x in im))
    got = damage_rate(curve, theta, beta)
    expected = k0 * theta**-k * math.exp(0.5 * k * k * beta * beta)
    assert got.rate == pytest.approx(expected, rel=1e-9)
    assert got.closed_form == pytest.approx(expected, rel=1e-12)
    assert got.k == pytest.approx(k, rel=1e-12)


def direct_rate(ag: list[float], theta: float, beta: float) -> float:
    """∫ P(DS | im)·|dλ(im)| on a dense grid in ln im: λ log–log between the nine points,
    their end segments' power laws beyond, trapezoids of P·|Δλ|."""
    x, y = np.log(ag), np.log([1.0 / tr for tr in GRID_TR])
    k = -np.diff(y) / np.diff(x)
    t = np.linspace(math.log(theta) - 14 * beta, x[-1] + 40.0 / k[-1], 2_000_001)
    seg = np.clip(np.searchsorted(x, t) - 1, 0, 7)
    lam = np.exp(y[seg] - k[seg] * (t - x[seg]))
    p = norm.cdf((t - math.log(theta)) / beta)
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * (lam[:-1] - lam[1:])))


def run_json(tmp_path: Path, states: list[dict], *extra: str) -> dict:
    path = tmp_path / "fragility.json"
    path.write_text(json.dumps({"im": "pga", "damage_states": states}), encoding="utf-8")
    result = CliRunner().invoke(cli, ["risk", "--fragility", str(path), "--site", SITE,
                                      "--hazard-grid", str(grid_or_skip()), "--format", "json",
                                      *extra])  # fmt: skip
    assert result.exit_code == 0, result.output
    return json.loads(result.output)


def test_the_issues_site(tmp_path: Path) -> None:
    doc = run_json(tmp_path, [{"name": "overturning", "median": 0.30, "beta": 0.35}])
    ag = [h["ag"] for h in doc["hazard"]]
    assert [ag[0], ag[6], ag[7]] == pytest.approx([0.07877, 0.26075, 0.33407], abs=5e-6)
    state = doc["damage_states"][0]
    k = math.log(975 / 475) / math.log(ag[7] / ag[6])
    median_tr = 475 * (0.30 / ag[6]) ** k
    assert median_tr == pytest.approx(714, abs=0.5)
    assert state["median_return_period"] == pytest.approx(median_tr, rel=1e-9)
    rate = direct_rate(ag, 0.30, 0.35)
    assert state["annual_rate"] == pytest.approx(rate, rel=1e-6)
    assert state["annual_rate"] == pytest.approx(2.167e-3, abs=1e-6)
    assert state["return_period"] == pytest.approx(1 / rate, rel=1e-6)
    assert state["p50"] == pytest.approx(1 - math.exp(-50 * rate), rel=1e-6)
    closed = (1 / median_tr) * math.exp(0.5 * k * k * 0.35**2)
    assert state["closed_form_rate"] == pytest.approx(closed, rel=1e-9)
    assert state["closed_form_ratio"] == pytest.approx(closed / rate, rel=1e-6)


def test_a_soft_soil_reads_the_surface_pga(tmp_path: Path) -> None:
    """Soil C: S_S = 1.70 − 0.60·F0·ag in [1, 1.5] (NTC 2018 Tab. 3.2.V) at each point."""
    doc = run_json(tmp_path, [{"name": "s", "median": 0.30, "beta": 0.35}], "--soil", "C",
                   "--reference-period", "75")  # fmt: skip
    for h in doc["hazard"]:
        assert h["S"] == pytest.approx(min(max(1.70 - 0.60 * h["F0"] * h["ag"], 1.0), 1.5))
    rate = direct_rate([h["ag"] * h["S"] for h in doc["hazard"]], 0.30, 0.35)
    state = doc["damage_states"][0]
    assert state["annual_rate"] == pytest.approx(rate, rel=1e-6)
    assert state["p_VR"] == pytest.approx(1 - math.exp(-75 * rate), rel=1e-6)


def test_a_state_without_a_fit_has_no_rate(tmp_path: Path) -> None:
    doc = run_json(tmp_path, [{"name": "a", "median": 0.3, "beta": 0.3},
                              {"name": "b", "median": None, "beta": None}])  # fmt: skip
    assert doc["damage_states"][1]["annual_rate"] is None
    assert any("not fitted" in n and "b" in n for n in doc["notes"])


def bad(tmp_path: Path, text: str, *args: str) -> str:
    path = tmp_path / "f.json"
    path.write_text(text, encoding="utf-8")
    grid = str(GRID_FILE) if GRID_FILE.is_file() else "/nonexistent-grid"
    result = CliRunner().invoke(cli, ["risk", "--fragility", str(path), "--hazard-grid", grid,
                                      *(args or ("--site", SITE))])  # fmt: skip
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    return lines[0]


GOOD = '{"im": "pga", "damage_states": [{"name": "a", "median": 0.3, "beta": 0.3}]}'


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ('{"im": "sa", "damage_states": []}', ("im", "pga")),
        ('{"im": "im", "damage_states": [{"name": "a", "median": 1, "beta": 0.3}]}', ("im",)),
        ('{"im": "pga"}', ("damage_states",)),
        ('{"im": "pga", "damage_states": [{"name": "a", "median": -1, "beta": 0.3}]}',
         ("damage_states[0].median",)),
        ('{"im": "pga", "damage_states": [{"name": "a", "median": 0.3, "beta": NaN}]}',
         ("damage_states[0].beta",)),
        ('{"im": "pga", "damage_states": [{"median": 0.3, "beta": 0.3}]}',
         ("damage_states[0].name",)),
        ("not json", ("not JSON",)),
        (GOOD.replace("0.3,", "1" + "0" * 400 + ",", 1), ("damage_states[0].median",)),
        ('{"im": "pga", "damage_states": [{"name": "a", "median": 0.3}]}',
         ("damage_states[0].beta",)),
        ('{"damage_states": []}', ("no im key",)),
        ("[" * 100_000 + "]" * 100_000, ("not JSON",)),
    ],
)  # fmt: skip
def test_a_bad_fragility_is_one_line(tmp_path: Path, text: str, words: tuple[str, ...]) -> None:
    line = bad(tmp_path, text)
    assert all(w in line for w in words), line


@pytest.mark.parametrize(
    "site",
    ["13.4", "east,north", "200,42", "12.0,60.0", "8.5,40.0"],  # the last: sea, off the grid
)
def test_a_site_off_the_grid_is_one_line(tmp_path: Path, site: str) -> None:
    grid_or_skip()
    assert "--site" in bad(tmp_path, GOOD, "--site", site)


def test_a_deeply_nested_file_under_limits(tmp_path: Path) -> None:
    """A fragility file of 16 MB of nested brackets: refused in one line, in bounded memory
    and time."""
    from tests.limited import run_rock

    grid = grid_or_skip()
    path = tmp_path / "deep.json"
    path.write_text("[" * (8 << 20) + "]" * (8 << 20), encoding="utf-8")
    done = run_rock("risk", "--fragility", str(path), "--site", SITE, "--hazard-grid", str(grid),
                    memory=2 << 30, timeout=60)  # fmt: skip
    assert done.code == 2, done.err
    assert len(done.err.strip().splitlines()) == 1 and "not JSON" in done.err


@pytest.mark.parametrize(
    ("site", "soil"),
    [("14.963,41.676", "D"), ("15.004,37.774", "E")],
)
def test_a_soil_whose_surface_pga_flattens_is_refused(tmp_path: Path, site: str, soil: str) -> None:
    """Where S_S falls almost as fast as ag grows the surface PGA saturates (a segment of
    λ ∝ PGA^−17764 on soil D): no hazard curve to put a fragility on."""
    grid_or_skip()
    line = bad(tmp_path, GOOD, "--site", site, "--soil", soil)
    assert "--soil" in line and "S_S" in line


def test_a_wide_fragility_says_its_rate_rests_on_the_tails(tmp_path: Path) -> None:
    doc = run_json(tmp_path, [{"name": "wide", "median": 0.3, "beta": 4.0},
                              {"name": "far", "median": 9.0, "beta": 0.05}])  # fmt: skip
    wide, far = doc["damage_states"]
    assert 0.5 < wide["tail_share"] <= 1.0 and 0.99 < far["tail_share"] <= 1.0
    assert any("wide" in n and "extrapolated" in n for n in doc["notes"])
    for state in (wide, far):  # finite, valid JSON: the exact sum of the segments
        assert math.isfinite(state["annual_rate"]) and state["annual_rate"] > 0.0
