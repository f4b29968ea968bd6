"""The risk class of DM 58/2017 Allegato A (text of DM 65/2017), conventional method, from a
model's local mechanisms (rock risk MODEL), against numbers written here from the decree:

- the decree's own check (note to Tab. 1): a new building at the minimum of the NTC, T_R of
  SLO, SLD, SLV, SLC 30, 50, 475 and 975 years, has PAM 1.13 %, class B:
  |1/30 − 1/10|·(0 + 7)/2 + |1/50 − 1/30|·(7 + 15)/2 + |1/475 − 1/50|·(15 + 50)/2
  + |1/975 − 1/475|·(50 + 80)/2 + 1/975·100 = 1.134 %;
- the bounds of Tab. 1 (PAM ≤ 0.5, 1.0, 1.5, 2.5, 3.5, 4.5, 7.5 %) and Tab. 2 (IS-V > 100 %,
  ≥ 80, 60, 45, 30, 15 %), the worse of the two, step 3's cap of SLO and SLD at the SLV;
- the model's class: each mechanism's T_Rc from its capacity ag on the hazard through the
  model's [ntc.demand] (as test_return_period.py), IS-V = ag_C·S(ag_C)/(ag_D·S(ag_D)) with
  S_S = 1.40 − 0.40·F0·ag/g in [1, 1.2] for soil B (NTC 2018 Tab. 3.2.IV), SLO read as SLD.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.risk.classification import classes_gained, classify, isv_class, pam_class, worse

ROOT = Path(__file__).resolve().parents[2]
FACADE = ROOT / "examples" / "two-storey-facade.toml"
GRID_FILE = ROOT.parent / "shared" / "ntc" / "AllegatoB.txt"
CR = {"SLID": 0.0, "SLO": 0.07, "SLD": 0.15, "SLV": 0.50, "SLC": 0.80}
ORDER = ("SLID", "SLO", "SLD", "SLV", "SLC")


def pam_by_hand(tr: dict[str, float]) -> float:
    """The decree's step 7 with step 3's cap, written out."""
    tr = dict(tr)
    for ls in ("SLO", "SLD"):
        tr[ls] = min(tr[ls], tr["SLV"])
    lam = {"SLID": 0.1, **{ls: 1.0 / tr[ls] for ls in ("SLO", "SLD", "SLV", "SLC")}}
    pairs = zip(ORDER[:-1], ORDER[1:], strict=True)
    area = sum(abs(lam[b] - lam[a]) * (CR[a] + CR[b]) / 2 for a, b in pairs)
    return area + lam["SLC"] * 1.0


def test_the_decree_s_own_new_building_is_pam_1_13_percent_class_b() -> None:
    tr = {"SLO": 30.0, "SLD": 50.0, "SLV": 475.0, "SLC": 975.0}
    by_hand = (
        abs(1 / 30 - 1 / 10) * 0.035 + abs(1 / 50 - 1 / 30) * 0.11
        + abs(1 / 475 - 1 / 50) * 0.325 + abs(1 / 975 - 1 / 475) * 0.65 + 1 / 975
    )  # fmt: skip
    result = classify(tr, 1.0)
    assert result.PAM == pytest.approx(by_hand, rel=1e-12)
    assert round(100 * result.PAM, 2) == 1.13
    assert (result.pam_class, result.isv_class, result.risk_class) == ("B", "A", "B")
    assert result.capped == ()


@pytest.mark.parametrize(("pam", "expected"), [
    (0.005, "A+"), (0.00501, "A"), (0.010, "A"), (0.0101, "B"), (0.015, "B"), (0.025, "C"),
    (0.035, "D"), (0.045, "E"), (0.0451, "F"), (0.0749, "F"), (0.075, "G"), (0.0751, "G"),
    (0.5, "G"),
])  # fmt: skip
def test_pam_classes_follow_table_1(pam: float, expected: str) -> None:
    assert pam_class(pam) == expected


@pytest.mark.parametrize(("isv", "expected"), [
    (1.0001, "A+"), (1.0, "A"), (0.8, "A"), (0.7999, "B"), (0.6, "B"), (0.45, "C"),
    (0.4499, "D"), (0.30, "D"), (0.2999, "E"), (0.1501, "E"), (0.15, "F"), (0.0, "F"),
])  # fmt: skip
def test_is_v_classes_follow_table_2(isv: float, expected: str) -> None:
    assert isv_class(isv) == expected


def test_the_class_is_the_worse_and_gains_count_classes() -> None:
    assert worse("A+", "C") == "C" and worse("G", "F") == "G"
    assert classes_gained("G", "C") == 4 and classes_gained("B", "B") == 0
    assert classes_gained("A", "B") == -1


def test_serviceability_states_are_capped_at_the_slv() -> None:
    """Step 3: the SLV cannot come before SLO and SLD."""
    result = classify({"SLO": 700.0, "SLD": 600.0, "SLV": 475.0, "SLC": 975.0}, 1.0)
    assert result.capped == ("SLO", "SLD")
    assert result.T_Rc["SLO"] == result.T_Rc["SLD"] == 475.0
    assert result.PAM == pytest.approx(pam_by_hand({"SLO": 700, "SLD": 600, "SLV": 475,
                                                     "SLC": 975}), rel=1e-12)  # fmt: skip


def run_json(*args: str, env: dict[str, str] | None = None) -> dict:
    result = CliRunner().invoke(cli, ["risk", *args, "--format", "json"], env=env)
    assert result.exit_code == 0, result.output
    return json.loads(result.output)


def soil_b_pga(ag: float, F0: float) -> float:  # noqa: N803
    return ag * min(1.2, max(1.0, 1.40 - 0.40 * F0 * ag))


def test_the_model_s_class_from_its_mechanisms() -> None:
    doc = run_json(str(FACADE))
    kin = json.loads(CliRunner().invoke(cli, ["kinematic", str(FACADE), "--format",
                                              "json"]).output)  # fmt: skip
    lowest = {ls: min(m["T_Rc"][ls] for m in kin["mechanisms"]) for ls in ("SLD", "SLV", "SLC")}
    assert doc["T_Rc"] == pytest.approx(lowest, rel=1e-12)
    tr = {"SLO": lowest["SLD"], **lowest}
    assert doc["PAM"] == pytest.approx(pam_by_hand(tr), rel=1e-12)
    F0, ag_d = 2.5, 0.15  # [ntc.demand.SLV]  # noqa: N806
    isv = []
    for m in kin["mechanisms"]:
        slv = [c for c in m["checks"] if c["limit_state"] == "SLV"]
        cap = min(c["capacity"] for c in ([c for c in slv if c["method"] == "nonlinear"] or slv))
        isv.append(soil_b_pga(cap, F0) / soil_b_pga(ag_d, F0))
    assert doc["IS_V"] == pytest.approx(min(isv), rel=1e-12)
    assert doc["PAM_class"] == pam_class(doc["PAM"]) and doc["IS_V_class"] == isv_class(min(isv))
    assert doc["class"] == worse(doc["PAM_class"], doc["IS_V_class"])
    assert any("upper bound" in n and "global behaviour" in n for n in doc["notes"])
    assert "after" not in doc


def test_a_site_reads_the_grid(tmp_path: Path) -> None:
    if not GRID_FILE.is_file():
        pytest.skip(f"NTC hazard grid not available: {GRID_FILE} is absent (rock does not ship it)")
    env = {"ROCK_HAZARD_GRID": str(GRID_FILE)}
    doc = run_json(str(FACADE), "--site", "13.40,42.35", env=env)
    kin = json.loads(CliRunner().invoke(cli, ["kinematic", str(FACADE), "--site", "13.40,42.35",
                                              "--format", "json"], env=env).output)  # fmt: skip
    lowest = {ls: min(m["T_Rc"][ls] for m in kin["mechanisms"]) for ls in ("SLD", "SLV", "SLC")}
    assert doc["T_Rc"] == pytest.approx(lowest, rel=1e-12)
    assert doc["hazard"]["source"] == "grid" and len(doc["hazard"]["TR"]) == 9


def model_with_rod(tmp_path: Path, diameter_m: float | None) -> Path:
    """The façade with its tie-rod of this diameter (None: without the rod)."""
    text = FACADE.read_text(encoding="utf-8")
    start = text.index("[[restrainers]]")
    end = text.index("\n\n", start)
    block = text[start:end]
    if diameter_m is None:
        text = text[:start] + text[end + 2 :]
    else:
        text = text[:start] + block.replace("diameter = 0.020", f"diameter = {diameter_m!r}") \
            + text[end:]  # fmt: skip
    path = tmp_path / f"facade-{diameter_m}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_retrofit_gives_the_class_without_and_with_the_sized_rod(tmp_path: Path) -> None:
    doc = run_json(str(FACADE), "--retrofit")
    chosen = doc["retrofit"]["diameter_mm"]
    assert chosen is not None and doc["retrofit"]["rod"] == "tie-rod"
    bare = run_json(str(model_with_rod(tmp_path, None)))
    tied = run_json(str(model_with_rod(tmp_path, chosen / 1000.0)))
    for key in ("T_Rc", "PAM", "IS_V", "class"):
        assert doc[key] == bare[key], key
        assert doc["after"][key] == tied[key], key
    assert doc["after"]["classes_gained"] == classes_gained(bare["class"], tied["class"])
    assert doc["state"] == "without its tie-rod 'tie-rod'"
    # The rod restrains the storey's overturning: its SLV return period grows.
    assert doc["after"]["T_Rc"]["SLV"] > doc["T_Rc"]["SLV"]


def refused(*args: str) -> str:
    result = CliRunner().invoke(cli, ["risk", *args])
    assert result.exit_code == 2, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and "Traceback" not in result.output, result.output
    return lines[0]


def test_bad_input_is_one_line_and_exit_2(tmp_path: Path) -> None:
    assert "--edition" in refused(str(FACADE), "--edition", "2009")
    old = tmp_path / "old.toml"
    old.write_text(FACADE.read_text(encoding="utf-8").replace('edition = "2019"',
                                                              'edition = "2009"'),
                   encoding="utf-8")  # fmt: skip
    assert "ntc.edition" in refused(str(old))
    assert "MODEL" in refused()
    assert "--soil" in refused(str(FACADE), "--soil", "B")
    assert "--record" in refused(str(FACADE), "--record", str(FACADE))
    assert "--site" in refused(str(FACADE), "--retrofit", "--site", "13.4,42.35")
    assert "--retrofit" in refused("--fragility", str(FACADE), "--site", "13.4,42.35",
                                   "--retrofit")  # fmt: skip
    flat = tmp_path / "flat.toml"
    flat.write_text(FACADE.read_text(encoding="utf-8").replace("ag = 0.19", "ag = 0.14"),
                    encoding="utf-8")  # fmt: skip
    assert "ntc.demand" in refused(str(flat))
    no_rod = ROOT / "examples" / "palazzo-facade.toml"
    assert "0 tie-rods" in refused(str(no_rod), "--retrofit")
    assert "MODEL and --fragility" in refused(str(FACADE), "--fragility", str(FACADE))


def edited(tmp_path: Path, name: str, *changes: tuple[str, str]) -> Path:
    """The façade with these text replacements (each must apply)."""
    text = FACADE.read_text(encoding="utf-8")
    for old, new in changes:
        assert old in text, old
        text = text.replace(old, new)
    path = tmp_path / f"{name}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def test_a_near_flat_demand_gives_no_hazard_curve(tmp_path: Path) -> None:
    """ag 0.1499 g at 50 years and 0.15 g at 475: λ ∝ ag^−3400 between them, no curve (a
    capacity a hair above 0.15 g would come back in 10^-3000 years)."""
    flat = edited(tmp_path, "flat-low", ("ag = 0.06", "ag = 0.1499"))
    assert "ntc.demand" in refused(str(flat))
    top = edited(tmp_path, "flat-top", ("ag = 0.19", "ag = 0.1501"))
    assert "ntc.demand" in refused(str(top))
    kin = CliRunner().invoke(cli, ["kinematic", str(top), "--format", "json"])
    assert kin.exit_code == 0, kin.output
    assert json.loads(kin.output)["T_Rc"] is None


def test_t_rc_far_beyond_the_curve_is_bounded(tmp_path: Path) -> None:
    """A capacity far below the first point (SLD ag 0.14 g at 50 years, 0.15 at 475: k = 32.6,
    just above the steepest allowed) is refused; at k = 10 (SLD ag 0.12 g: still steep) the
    gable's SLD comes back in 1 year or less: taken as 1, and said."""
    path = edited(tmp_path, "steep", ("ag = 0.06", "ag = 0.1199"))
    doc = run_json(str(path))
    assert doc["T_Rc"]["SLD"] == 1.0
    assert any("1 year or less, taken as 1" in n for n in doc["notes"])
    assert all(math.isfinite(m["PAM"]) for m in doc["mechanisms"] if m["PAM"] is not None)


def test_a_mechanism_not_evaluated_leaves_no_class(tmp_path: Path) -> None:
    """A stiff spring in place of the rod: the whole wall's SLV and SLC checks are not evaluated
    (positive stiffness, no limit displacement); the class of the others would be better than
    the building's, so there is none, and the mechanism is named."""
    rod = FACADE.read_text(encoding="utf-8")
    start = rod.index("[[restrainers]]")
    block = rod[start : rod.index("\n\n", start)]
    path = edited(
        tmp_path,
        "spring",
        (
            block,
            '[[restrainers]]\nname = "stiff spring"\nk = 1.0e8\nheight = 7.5\nfrom_pivot = 0.30',
        ),
    )
    doc = run_json(str(path))
    assert doc["class"] is None and doc["PAM"] is None
    assert any("whole wall" in m for m in doc["not_evaluated"])
    assert doc["T_Rc"]["SLD"] > 0  # the states the mechanisms give are still there


def test_options_name_what_rock_risk_takes(tmp_path: Path) -> None:
    assert "--edition" in refused(str(FACADE), "--edition", "2008")  # 2008 is 2009's code
    nodemand = ROOT / "examples" / "facade.toml"
    line = refused(str(nodemand), "--retrofit")
    assert "ntc" in line and "--record" not in line
    two = edited(tmp_path, "two", ('name = "tie-rod"', 'name = "tie-rod"'))
    text = two.read_text(encoding="utf-8")
    start = text.index("[[restrainers]]")
    block = text[start : text.index("\n\n", start)]
    two.write_text(text.replace(block, block + "\n\n" + block.replace('"tie-rod"\nkind',
                                                                    '"second"\nkind')),
                   encoding="utf-8")  # fmt: skip
    line = refused(str(two), "--retrofit")
    assert "2 tie-rods" in line and "rock retrofit --name" not in line
