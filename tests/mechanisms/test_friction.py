"""The toothed return walls' friction on an overturning (issue 38, item 1).

Circolare 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.2: F = 0.4·n(n+1)·Φ·μ·l²·t_s·W per return wall,
n = h/h_b the courses the vertical crack crosses, Φ = h_b/l, applied at h/3; "l'altezza h
... dovrebbe essere identificata attraverso un processo di minimizzazione del moltiplicatore
α0". Every expected number here is written from the clause by hand, not read from the code:

- the issue's façade, 0.5 × 6 m, 5 m wide, γ = 18 kN/m³, two return walls 0.45 m thick,
  h_b = l = 0.25 m, μ = 0.577: n = 24, Φ = 1, F = 0.4·24·25·0.577·0.0625·0.45·18 = 70.1055 kN
  per wall at h/3 = 2 m; W = 270 kN; α0 = (W·t/2 + 2·F·h/3)/(W·h/2) = 347.922/810 = 0.429533
  (0.083333 without);
- the part of height H' above a hinge at 6 − H': α(H') = [11.25·H' + 2·F(H')·H'/3]/(22.5·H'²)
  with F(H') = 0.1168425·n(n+1), n = 4H' (kN, m), minimised over H' by a dense scan here;
- along the rotation θ about the outer base edge (no stress block), a course at height z on
  the interface (x = t/2) slides z·sin θ + (t/2)(1 − cos θ) and resists until that reaches
  the overlap l; the friction per unit height q(z) = 2F(h − z)/h² (resultant F at h/3) does
  the work ∫ q(z)·(−(t/2)·sin θ − z·cos θ) dz over the courses still engaged.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
import tomli_w
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.codecheck.kinematic import Mechanism as SideCheck
from rockcli.codecheck.kinematic import load_multiplier
from rockcli.model.catalogue import catalogue, named
from rockcli.model.load import load_model

DEMAND = {
    state: {"ag": ag, "F0": 2.5, "Tc_star": tc}
    for state, ag, tc in (("SLD", 0.06, 0.27), ("SLV", 0.15, 0.29), ("SLC", 0.19, 0.30))
}

#: The issue's façade with toothed return walls, its overturnings with and without friction.
FACADE: dict[str, Any] = {
    "name": "toothed façade",
    "kind": "wall",
    "geometry": {"width": 5.0, "storeys": [{"height": 6.0, "thickness": 0.5}]},
    "mass": {"unit_weight": 18.0},
    "return_walls": {
        "thickness": 0.45,
        "toothed": True,
        "mu": 0.577,
        "course_height": 0.25,
        "overlap": 0.25,
        "sides": 2,
    },  # fmt: skip
    "mechanisms": [
        {"type": "overturning"},
        {"type": "overturning", "name": "free", "friction": False},
        {"type": "overturning", "name": "optimal", "hinge_height": "optimal"},
    ],
    "ntc": {"edition": "2019", "q": 2.0, "soil": "B", "demand": DEMAND},
}

#: kN, m: the clause's numbers for the issue's façade.
GAMMA, T, H, B = 18.0, 0.5, 6.0, 5.0
MU, HB, L, TS = 0.577, 0.25, 0.25, 0.45


def F_hand(h: float) -> float:
    """Eq. C8.7.1.2 for one return wall toothed over h [kN]."""
    n = h / HB
    return 0.4 * n * (n + 1.0) * (HB / L) * MU * L**2 * TS * GAMMA


def alpha_hand(h: float) -> float:
    """α0 of the part of height h above a hinge, both walls' friction at h/3."""
    W = GAMMA * T * B * h
    return (W * T / 2 + 2 * F_hand(h) * h / 3) / (W * h / 2)


def write(tmp_path: Path, model: dict[str, Any]) -> Path:
    path = tmp_path / "wall.toml"
    path.write_text(tomli_w.dumps(model), encoding="utf-8")
    return path


def kinematic_json(path: Path) -> dict[str, Any]:
    import json

    result = CliRunner().invoke(cli, ["kinematic", str(path), "--format", "json"])
    assert result.exit_code == 0, result.output
    return {m["name"]: m for m in json.loads(result.stdout)["mechanisms"]}


def test_the_clause_numbers_by_hand() -> None:
    assert F_hand(6.0) == pytest.approx(70.1055, abs=5e-5)
    assert alpha_hand(6.0) == pytest.approx(0.429533, abs=5e-7)


def test_the_whole_wall_with_and_without_friction(tmp_path: Path) -> None:
    found = kinematic_json(write(tmp_path, FACADE))
    whole = found["overturning, whole wall"]
    assert whole["alpha0"] == pytest.approx(347.922 / 810.0, rel=1e-6)
    assert whole["friction"]["F_kN"] == pytest.approx(70.1055, rel=1e-9)
    assert whole["friction"]["lever"] == pytest.approx(2.0, rel=1e-12)
    assert whole["friction"]["walls"] == 2
    assert found["free"]["alpha0"] == pytest.approx(T / H, rel=1e-12)
    assert found["free"]["friction"] is None
    # the virtual work's table: the friction's resultant at h/3 resists with 2·F·h/3
    terms = {t["kind"]: t for t in whole["virtual_work"]}
    assert terms["friction"]["resisting_kNm"] == pytest.approx(2 * 70.1055 * 2.0, rel=1e-9)
    assert terms["friction"]["z"] == pytest.approx(2.0)


def test_one_toothed_wall_resists_half(tmp_path: Path) -> None:
    model = {**FACADE, "return_walls": {**FACADE["return_walls"], "sides": 1}}
    whole = kinematic_json(write(tmp_path, model))["overturning, whole wall"]
    W = GAMMA * T * B * H
    assert whole["alpha0"] == pytest.approx((W * T / 2 + F_hand(H) * H / 3) / (W * H / 2))
    assert whole["friction"]["walls"] == 1


def test_the_optimal_hinge_minimises_alpha0_as_the_clause_asks(tmp_path: Path) -> None:
    # a dense scan of the part's height H' = 6 − hinge over the search range [0.6, 6] m
    heights = [0.6 + 5.4 * k / 200000 for k in range(200001)]
    best = min(heights, key=alpha_hand)
    optimal = kinematic_json(write(tmp_path, FACADE))["optimal"]
    assert optimal["alpha0"] == pytest.approx(alpha_hand(best), rel=1e-9)
    assert optimal["alpha0"] == pytest.approx(0.34669, abs=5e-6)
    assert optimal["hinge_height"] == pytest.approx(H - best, abs=1e-3)
    assert optimal["friction"]["height"] == pytest.approx(best, abs=1e-3)


def engaged_work(theta: float, F: float, h: float) -> float:
    """∫ q·dX/dθ over the engaged courses, by the closed form of the polynomial [kN·m]."""
    c, s = math.cos(theta), math.sin(theta)
    x = T / 2
    top = h if s == 0.0 else min(h, max(0.0, (L - x * (1 - c)) / s))
    k = 2 * F / h**2  # q(z) = k (h − z)

    def primitive(z: float) -> float:  # ∫ k(h − z)(−x s − z c) dz
        return k * (-x * s * (h * z - z * z / 2) - c * (h * z * z / 2 - z**3 / 3))

    return primitive(top) - primitive(0.0)


@pytest.mark.parametrize("theta", [0.0, 0.01, 0.03, 0.05, 0.08, 0.12, 0.6, 1.2])
def test_the_capacity_curve_loses_the_courses_that_slid_past_their_overlap(
    tmp_path: Path, theta: float
) -> None:
    mech = named(catalogue(load_model(write(tmp_path, FACADE))), "overturning, whole wall")
    check = SideCheck(mech.view(1))
    W = GAMMA * T * B * H
    c, s = math.cos(theta), math.sin(theta)
    g = W * (T / 2 * c - H / 2 * s)  # the weight's dZ/dθ at its centroid
    h_terms = W * (T / 2 * s + H / 2 * c)  # −dX/dθ
    t = 2 * engaged_work(theta, F_hand(H), H)
    expected = (g - t) / h_terms
    assert load_multiplier(check, theta) == pytest.approx(expected, rel=1e-9, abs=1e-12)


def test_only_the_courses_near_the_hinge_still_resist_at_large_rotations(
    tmp_path: Path,
) -> None:
    # at θ = 0.6 rad only the courses below (l − (t/2)(1 − cos θ))/sin θ = 0.365 m are
    # engaged: what is left of the friction is a few per cent of its moment at rest
    mech = named(catalogue(load_model(write(tmp_path, FACADE))), "overturning, whole wall")
    free = named(catalogue(load_model(write(tmp_path, FACADE))), "free")
    a = load_multiplier(SideCheck(mech.view(1)), 0.6)
    b = load_multiplier(SideCheck(free.view(1)), 0.6)
    W = GAMMA * T * B * H
    left = (a - b) * W * (T / 2 * math.sin(0.6) + H / 2 * math.cos(0.6))
    assert left == pytest.approx(-2 * engaged_work(0.6, F_hand(H), H), rel=1e-9)
    assert 0.0 < left < 0.05 * 2 * F_hand(H) * H / 3


@pytest.mark.parametrize("side", [1, -1])
def test_the_engines_friction_is_the_capacity_curves(tmp_path: Path, side: int) -> None:
    """The time history's friction moment (mechanics.friction_moment, for a rigid body) is
    the code check's SideFriction.work with the sign turned, at every rotation."""
    from rockcli.mechanics import friction_moment

    mech = named(catalogue(load_model(write(tmp_path, FACADE))), "overturning, whole wall")
    view = mech.view(side)
    fr = view.frictions[0]
    for a in (0.0, 0.003, 0.02, 0.041, 0.09, 0.3, 0.7):
        work = fr.work(view.states(a)[fr.link])
        moment = friction_moment(fr.force, fr.x, fr.z0, fr.height, fr.overlap, a,
                                 math.sin(a), math.cos(a))  # fmt: skip
        assert moment == pytest.approx(-work, rel=1e-12, abs=1e-9)


def test_time_history_uplifts_where_the_friction_lets_it(tmp_path: Path) -> None:
    """The time history carries the friction (tests/dynamics/test_coulomb_friction.py): the façade
    leaves rest at the code check's α0 with it, 0.4295 g, not at t/h = 0.08333 g."""
    record = Path(__file__).resolve().parents[2] / "records" / "ricker_Tp0.5s_0.5g.txt"
    path = write(tmp_path, FACADE)
    result = CliRunner().invoke(
        cli,
        ["assess", str(path), "--record", str(record), "--mechanism",
         "overturning, whole wall", "--format", "json"],
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    doc = json.loads(result.output)
    alpha0 = (GAMMA * T * B * H * T / 2 + 2 * F_hand(H) * H / 3) / (GAMMA * T * B * H * H / 2)
    assert doc["model"]["uplift_acceleration_g"] == pytest.approx(alpha0, rel=1e-9)
    assert alpha0 == pytest.approx(0.42953, abs=1e-5)
    assert not any("friction" in w for w in doc.get("warnings", []))


BAD = [
    ({"mu": 0.0}, "return_walls.mu"),
    ({"mu": 1.6}, "return_walls.mu"),
    ({"course_height": 0.0}, "return_walls.course_height"),
    ({"course_height": 7.0}, "return_walls.course_height"),
    ({"overlap": -0.1}, "return_walls.overlap"),
    ({"overlap": 5.5}, "return_walls.overlap"),
    ({"sides": 3}, "return_walls.sides"),
]


@pytest.mark.parametrize(("change", "key"), BAD)
def test_a_bad_toothing_is_one_line_naming_the_key(
    tmp_path: Path, change: dict[str, Any], key: str
) -> None:
    model = {**FACADE, "return_walls": {**FACADE["return_walls"], **change}}
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, model))])
    assert result.exit_code == 2
    assert result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and key in lines[0], result.stderr


def test_friction_without_a_toothing_is_refused(tmp_path: Path) -> None:
    walls = {"thickness": 0.45}
    model = {**FACADE, "return_walls": walls,
             "mechanisms": [{"type": "overturning", "friction": True}]}  # fmt: skip
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, model))])
    assert result.exit_code == 2
    assert "mechanisms[0].friction" in result.stderr or "mechanisms.0.friction" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_a_toothing_key_without_toothed_is_refused(tmp_path: Path) -> None:
    model = {**FACADE, "return_walls": {"thickness": 0.45, "mu": 0.6}}
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, model))])
    assert result.exit_code == 2 and "return_walls.mu" in result.stderr


def test_toothed_without_its_courses_is_refused(tmp_path: Path) -> None:
    model = {**FACADE, "return_walls": {"thickness": 0.45, "toothed": True}}
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, model))])
    assert result.exit_code == 2 and "return_walls.course_height" in result.stderr


def test_friction_is_the_default_of_a_toothed_wall_and_the_reference_mu(tmp_path: Path) -> None:
    walls = {k: v for k, v in FACADE["return_walls"].items() if k not in ("mu", "sides")}
    model = {**FACADE, "return_walls": walls, "mechanisms": [{"type": "overturning"}]}
    whole = kinematic_json(write(tmp_path, model))["overturning, whole wall"]
    assert whole["friction"]["F_kN"] == pytest.approx(70.1055, rel=1e-9)  # μ = 0.577
    assert whole["friction"]["walls"] == 2


def test_an_optimal_hinge_needs_a_range_to_search(tmp_path: Path) -> None:
    # a wall 0.4 m high and 0.5 m thick: base to top less max(0.5, 0.04) is empty
    model = {**FACADE, "geometry": {"width": 5.0, "storeys": [{"height": 0.4,
                                                                "thickness": 0.5}]},
             "return_walls": {**FACADE["return_walls"], "course_height": 0.1},
             "mechanisms": [{"type": "overturning", "hinge_height": "optimal"}]}  # fmt: skip
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, model))])
    assert result.exit_code == 2 and result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "mechanisms[0].hinge_height" in lines[0], result.stderr


def test_a_block_file_with_a_toothing_is_refused(tmp_path: Path) -> None:
    model = {k: v for k, v in FACADE.items() if k != "mechanisms"}
    model["geometry"] = {"thickness": 0.5, "height": 6.0, "width": 5.0}
    result = CliRunner().invoke(cli, ["kinematic", str(write(tmp_path, model))])
    assert result.exit_code == 2 and result.stdout == ""
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "return_walls.toothed" in lines[0], result.stderr


def test_the_toothing_holds_the_base_from_sliding_too(tmp_path: Path) -> None:
    # μ = 0.4: without the toothing α_s = 0.4 < α0 = 0.4295 would slide first; the courses
    # hold it: α_s = (0.4·270 + 2·70.1055)/270 = 0.91930 above α0
    from rockcli.analyses.sliding import alpha0_of, slides_first, sliding_multiplier

    model = {**FACADE, "base": {"mu": 0.4}}
    mech = named(catalogue(load_model(write(tmp_path, model))), "overturning, whole wall")
    W = GAMMA * T * B * H
    assert sliding_multiplier(mech.view(1), 0.4) == pytest.approx(
        (0.4 * W + 2 * F_hand(H)) / W, rel=1e-12
    )
    assert slides_first(mech, 0.4, alpha0_of(mech)) is None


def test_the_friction_on_the_inward_side_and_with_a_stress_block(tmp_path: Path) -> None:
    # side −1 turns about the inner edge: the interface at t/2 is again t/2 from the pivot,
    # so the same closed form holds; with f_m the pivot moves in by a/2, a = W/(f_m·B)
    mech = named(catalogue(load_model(write(tmp_path, FACADE))), "overturning, whole wall")
    W = GAMMA * T * B * H
    for theta in (0.0, 0.03, 0.08):
        c, s = math.cos(theta), math.sin(theta)
        expected = (W * (T / 2 * c - H / 2 * s) - 2 * engaged_work(theta, F_hand(H), H)) / (
            W * (T / 2 * s + H / 2 * c)
        )
        got = load_multiplier(SideCheck(mech.view(-1)), theta)
        assert got == pytest.approx(expected, rel=1e-9, abs=1e-12)
    f_m = 1.0e3  # kN/m² (1 MPa): a = 270/(1000·5) = 0.054 m
    model = {**FACADE, "masonry": {"f_m": 1.0e6}}
    mech = named(catalogue(load_model(write(tmp_path, model))), "overturning, whole wall")
    a = W / (f_m * B)
    lever = T / 2 - a / 2  # the centroid's and the interface's x from the set-back pivot
    alpha0 = (W * lever + 2 * F_hand(H) * H / 3) / (W * H / 2)
    assert load_multiplier(SideCheck(mech.view(1)), 0.0) == pytest.approx(alpha0, rel=1e-12)
