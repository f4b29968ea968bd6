"""The return period each mechanism bears (issue 39, item 1), against a hand-written inverse
of the site's hazard: T_Rc of a limit state is the return period at which the site's ag
(the grid's nine return periods, log ag linear in log TR between them: DM 14/01/2008
Allegato A, Eq. 3; the end segments' line beyond) equals the capacity ag of the limit
state's deciding checks (the non-linear ones when there are, else the linear; the lowest).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.codecheck.hazard import read_grid, site_parameters

ROOT = Path(__file__).resolve().parents[2]
GRID_FILE = ROOT.parent / "shared" / "ntc" / "AllegatoB.txt"
FACADE = ROOT / "examples" / "two-storey-facade.toml"
GRID_TR = (30.0, 50.0, 72.0, 101.0, 140.0, 201.0, 475.0, 975.0, 2475.0)
#: The checks' limit states of each demand's.
STATES = {"SLD": ("SLD",), "SLV": ("SLV",), "SLC": ("SLC",)}


def grid_or_skip() -> Path:
    if not GRID_FILE.is_file():
        pytest.skip(f"NTC hazard grid not available: {GRID_FILE} is absent (rock does not ship it)")
    return GRID_FILE


def inverse(ag_site: list[float], capacity: float) -> float:
    """TR with ag(TR) = capacity: log TR linear in log ag on the segment that holds it."""
    k = next((j for j in range(8) if capacity <= ag_site[j + 1]), 7)
    k = 0 if capacity < ag_site[0] else k
    a1, a2, t1, t2 = ag_site[k], ag_site[k + 1], GRID_TR[k], GRID_TR[k + 1]
    return bounded(t1 * (t2 / t1) ** (math.log(capacity / a1) / math.log(a2 / a1)))


def bounded(years: float) -> float:
    """T_Rc is read within 1 and 10^6 years (the power law beyond the points has no support
    further out: docs/risk.md)."""
    return min(max(years, 1.0), 1e6)


def deciding_capacity(checks: list[dict], states: tuple[str, ...]) -> float | None:
    mine = [c for c in checks if c["limit_state"] in states]
    nonlinear = [c for c in mine if c["method"] == "nonlinear"]
    caps = [c["capacity"] for c in (nonlinear or mine) if c["unit"] == "g"]
    return min(caps) if caps else None


@pytest.mark.parametrize("edition", ["2019"])
def test_each_mechanism_bears_the_return_period_of_its_capacity(edition: str) -> None:
    grid = grid_or_skip()
    result = CliRunner().invoke(cli, ["kinematic", str(FACADE), "--site", "13.40,42.35",
                                      "--edition", edition, "--format", "json"],
                                env={"ROCK_HAZARD_GRID": str(grid)})  # fmt: skip
    assert result.exit_code == 0, result.output
    doc = json.loads(result.output)
    g = read_grid(grid)
    ag_site = [site_parameters(g, 13.40, 42.35, tr).ag for tr in GRID_TR]
    assert [ag_site[0], ag_site[6], ag_site[7]] == pytest.approx([0.07877, 0.26075, 0.33407],
                                                                 abs=5e-6)  # fmt: skip
    seen = 0
    for m in doc["mechanisms"]:
        for ls, years in m["T_Rc"].items():
            capacity = deciding_capacity(m["checks"], STATES[ls])
            assert capacity is not None
            assert years == pytest.approx(inverse(ag_site, capacity), rel=1e-9), (m["name"], ls)
            seen += 1
    assert seen >= 2 * len(doc["mechanisms"])
    governing = next(m for m in doc["mechanisms"] if m["name"] == doc["mechanism"])
    assert doc["T_Rc"] == governing["T_Rc"]


def test_the_2009_checks_give_no_capacity_ag_so_no_return_period() -> None:
    """Circ. 617/2009's checks compare accelerations [m/s²] and displacements [m], not ag."""
    grid = grid_or_skip()
    result = CliRunner().invoke(cli, ["kinematic", str(FACADE), "--site", "13.40,42.35",
                                      "--edition", "2009", "--format", "json"],
                                env={"ROCK_HAZARD_GRID": str(grid)})  # fmt: skip
    assert result.exit_code == 0, result.output
    doc = json.loads(result.output)
    assert doc["T_Rc"] is None and all(m["T_Rc"] is None for m in doc["mechanisms"])


def test_without_a_site_the_model_s_own_demand_is_the_hazard() -> None:
    """[ntc.demand]'s ag at each limit state's return period, TR = −V_R/ln(1 − P_VR) (NTC 2018
    Tab. 3.2.I, V_R = 50 years: SLD 63 %, SLV 10 %, SLC 5 %), are three points of the site's
    hazard: T_Rc of a capacity ag is read log–log between them, the end segments beyond."""
    result = CliRunner().invoke(cli, ["kinematic", str(FACADE), "--format", "json"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.output)
    periods = [-50.0 / math.log(1.0 - p) for p in (0.63, 0.10, 0.05)]
    ag = [0.06, 0.15, 0.19]  # the model's [ntc.demand.SLD/SLV/SLC]
    assert doc["T_Rc_hazard"] == {"source": "model", "TR": pytest.approx(periods, rel=1e-12),
                                  "ag": ag}  # fmt: skip

    def inverse3(capacity: float) -> float:
        k = 0 if capacity <= ag[1] else 1
        return bounded(
            periods[k]
            * (periods[k + 1] / periods[k])
            ** (math.log(capacity / ag[k]) / math.log(ag[k + 1] / ag[k]))
        )

    for m in doc["mechanisms"]:
        for ls, years in m["T_Rc"].items():
            capacity = deciding_capacity(m["checks"], STATES[ls])
            assert years == pytest.approx(inverse3(capacity), rel=1e-9), (m["name"], ls)


def test_a_record_s_demand_has_no_return_period() -> None:
    record = ROOT.parent / "shared" / "records"
    files = sorted(record.glob("*.AT2")) if record.is_dir() else []
    if not files:
        pytest.skip(f"no PEER AT2 record in {record} (the shared records are absent)")
    result = CliRunner().invoke(cli, ["kinematic", str(FACADE), "--record", str(files[0]),
                                      "--format", "json"])  # fmt: skip
    assert result.exit_code == 0, result.output
    doc = json.loads(result.output)
    assert doc["T_Rc"] is None and doc["T_Rc_hazard"] is None
    assert all(m["T_Rc"] is None for m in doc["mechanisms"])
