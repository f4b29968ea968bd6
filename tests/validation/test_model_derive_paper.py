"""The model's derived quantities against the source paper and the closed forms they come from.

Each test names its source (paper section, table or equation; spec/rocking.md) and its
tolerance. Paper numbers are compared to the digits the paper prints.
"""

from __future__ import annotations

import math
from typing import Any

import pytest

from rockcli.mechanics import NEGATIVE, POSITIVE, point_polar, stiffness_coefficient
from rockcli.model.derive import (
    AnalysisOptions,
    block_mass,
    describe,
    solver_options,
    to_block,
)
from rockcli.model.load import validate_model
from rockcli.model.schema import Model

#: Paper §4.2: the façade, weight 1755 kN, R = 5.04 m, α = 0.05 rad.
FACADE_GEOMETRY = {"R": 5.04, "alpha": 0.05}


def model(geometry: dict[str, Any], **tables: Any) -> Model:
    """A valid model of the given geometry and extra tables."""
    return validate_model({"name": "t", "kind": "wall", "geometry": geometry, **tables})


def with_restrainer(geometry: dict[str, Any], **keys: Any) -> Model:
    """A model with one restrainer (and a weight, which restrainers require)."""
    return model(geometry, mass={"weight": 100.0}, restrainers=[keys])


def sig(x: float, digits: int) -> float:
    """x rounded to ``digits`` significant digits."""
    return float(f"{x:.{digits - 1}e}")


# --- geometry ------------------------------------------------------------------------------------


def test_altar_thickness_and_height_give_the_papers_R_and_alpha() -> None:
    # Paper §3.2: equivalent prism 0.487 m thick, 2.96 m high → R = 1.499 m, α = 0.163 rad
    # (9.34°). The paper prints 3 decimals (R exact 1.49990, truncated to 1.499 by the paper):
    # tolerance one unit of the last printed digit.
    block = to_block(model({"thickness": 0.487, "height": 2.96}))
    assert block.R == pytest.approx(1.499, abs=1e-3)
    assert block.alpha == pytest.approx(0.163, abs=1e-3)
    assert math.degrees(block.alpha) == pytest.approx(9.34, abs=0.01)


def test_R_alpha_and_thickness_height_describe_the_same_block() -> None:
    # spec/rocking.md, notation: b = R sin α, h = R cos α; exact inverse to rounding.
    d = describe(model({"R": 1.499, "alpha": 0.163}))
    back = describe(model({"thickness": d.thickness, "height": d.height}))
    assert (back.R, back.alpha) == pytest.approx((1.499, 0.163), rel=1e-12)
    assert (d.b, d.h) == pytest.approx((1.499 * math.sin(0.163), 1.499 * math.cos(0.163)))


@pytest.mark.parametrize(("R", "p"), [(3.0, 1.566), (1.839, 2.0)])
def test_frequency_parameter_of_the_validation_blocks(R: float, p: float) -> None:
    # Paper §3.1: R = 3 m → p = 1.566 rad/s (Sorrentino); R = 1.839 m → p = 2.0 rad/s (Makris &
    # Konstantinidis), p = √(3g/4R) with g = 9.81; tolerance: half a unit of the printed digit.
    digits = {1.566: 5e-4, 2.0: 5e-2}[p]
    assert describe(model({"R": R, "alpha": 0.2})).p == pytest.approx(p, abs=digits)


# --- mass ---------------------------------------------------------------------------------------


def test_weight_in_kN_gives_the_mass_in_kg() -> None:
    # Block.mass = W·1e3/g [kg]: 1755 kN / 9.81 m/s² (paper §4.2 weight; §4.3 "175-tons façade").
    m = block_mass(model(FACADE_GEOMETRY, mass={"weight": 1755.0}))
    assert m == pytest.approx(1755e3 / 9.81, rel=1e-12)
    assert m / 1e3 == pytest.approx(175, rel=0.03)


def test_unit_weight_times_volume() -> None:
    # W = γ·2b·2h·width: 18 kN/m³ × 0.5 × 4 × 3 m³ = 108 kN (paper §4.4 values).
    d = describe(model({"thickness": 0.5, "height": 4.0, "width": 3.0}, mass={"unit_weight": 18.0}))
    assert d.weight == pytest.approx(108e3, rel=1e-12)
    assert d.mass == pytest.approx(108e3 / 9.81, rel=1e-12)


def test_gravity_of_the_model_sets_the_mass() -> None:
    m = model(FACADE_GEOMETRY, mass={"weight": 100.0}, analysis={"g": 10.0})
    assert block_mass(m) == pytest.approx(1e4)
    assert to_block(m).g == 10.0


def test_no_mass_table_gives_no_mass() -> None:
    d = describe(model(FACADE_GEOMETRY))
    assert (d.mass, d.weight) == (None, None)
    assert to_block(model(FACADE_GEOMETRY)).mass is None


def test_stiffness_terms_of_the_facade_match_the_paper() -> None:
    # Paper §4.3, same façade: c_K = 4KR²/I0 = 167.7 for K = 1e7 N/m and 0.002 for K = 100 N/m,
    # c_E = p² = 1.46 (printed to 4, 1 and 3 significant digits). Checks the mass derivation
    # (W = 1755 kN, g = 9.81) against the paper.
    block = to_block(model(FACADE_GEOMETRY, mass={"weight": 1755.0}))
    assert sig(stiffness_coefficient(1e7, block.R, block.inertia), 4) == 167.7
    assert sig(stiffness_coefficient(100.0, block.R, block.inertia), 1) == 0.002
    assert sig(block.p2, 3) == 1.46


# --- restitution -------------------------------------------------------------------------------


def test_housner_restitution_of_the_altar() -> None:
    # Paper Eq. (3): e = 1 − 1.5 sin²α; α = 0.163 → 0.96050 (closed form, to rounding).
    block = to_block(model({"R": 1.499, "alpha": 0.163}))
    assert block.e == pytest.approx(1 - 1.5 * math.sin(0.163) ** 2, rel=1e-12)
    assert block.e == pytest.approx(0.9605, abs=5e-5)


def test_housner_factor_of_the_systemic_study() -> None:
    # Paper §3.3: "restitution coefficient taken equal to 90 % of the theoretical one".
    m = model({"R": 3.5, "alpha": 0.1}, restitution={"factor": 0.9})
    d = describe(m)
    assert d.e == pytest.approx(0.9 * (1 - 1.5 * math.sin(0.1) ** 2), rel=1e-12)
    assert d.e_rule == "0.9 × Housner (1 − 1.5 sin²α)"


def test_housner_restitution_is_zero_for_squat_blocks() -> None:
    # spec/rocking.md: for α ≥ 54.74° (sin²α ≥ 2/3) Housner's e ≤ 0 → no rocking after impact.
    squat = math.asin(math.sqrt(2 / 3)) + 0.1
    assert to_block(model({"R": 1.0, "alpha": squat})).e == 0.0
    assert to_block(model({"R": 1.0, "alpha": squat}, restitution={"factor": 0.5})).e == 0.0


def test_explicit_restitution() -> None:
    for table in ({"e": 0.7}, {"model": "explicit", "e": 0.7}):
        d = describe(model({"R": 1.0, "alpha": 0.2}, restitution=table))
        assert (d.e, d.e_rule) == (0.7, "explicit")


# --- restrainers --------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("diameter_mm", "k_paper"),
    [(2, 2.2e5), (5, 1.4e6), (10, 5.5e6), (20, 2.2e7), (30, 4.9e7), (40, 8.8e7), (50, 1.4e8)],
)
def test_tie_rod_stiffness_of_paper_table_2(diameter_mm: int, k_paper: float) -> None:
    # Paper Table 2: steel tie-rod, L = 3 m, E = 210 GPa; K printed to 2 significant digits.
    m = with_restrainer(
        FACADE_GEOMETRY, kind="tie-rod", diameter=diameter_mm / 1e3, length=3.0, position="top"
    )
    spring = to_block(m).restrainers[0]
    assert sig(spring.k_pos, 2) == k_paper
    assert spring.k_neg == spring.k_pos


def test_tie_rod_of_the_facade_case() -> None:
    # Paper §4.2: Ø 20 mm, 3.00 m → K_tie = 22.0E6 N/m (3 significant digits).
    m = with_restrainer(
        FACADE_GEOMETRY, kind="tie-rod", diameter=0.020, length=3.0, radius=7.0, angle=0.072
    )
    assert sig(to_block(m).restrainers[0].k_pos, 3) == 22.0e6


def test_tie_rod_modulus_and_acting_side() -> None:
    # K = E·π·d²/4 / L (spec/README.md); acts = "positive" → no stiffness while θ < 0.
    m = with_restrainer(
        FACADE_GEOMETRY,
        kind="tie-rod",
        diameter=0.02,
        length=2.0,
        E=200e9,
        acts="positive",
        position="top",
    )
    spring = to_block(m).restrainers[0]
    assert spring.k_pos == pytest.approx(200e9 * math.pi * 0.02**2 / 4 / 2.0, rel=1e-12)
    assert spring.k_neg == 0.0
    negative = with_restrainer(
        FACADE_GEOMETRY, kind="tie-rod", diameter=0.02, length=2.0, acts="negative", position="top"
    )
    assert to_block(negative).restrainers[0].k_pos == 0.0


def test_stiffness_forms() -> None:
    both = to_block(with_restrainer(FACADE_GEOMETRY, k=4e6, position="top")).restrainers[0]
    assert (both.k_pos, both.k_neg) == (4e6, 4e6)
    split = with_restrainer(FACADE_GEOMETRY, k_pos=4e6, k_neg=0.0, position="top")
    assert to_block(split).restrainers[0].side(NEGATIVE)[0] == 0.0


@pytest.mark.parametrize("geometry", [FACADE_GEOMETRY, {"thickness": 0.487, "height": 2.96}])
def test_top_position_is_the_papers_top_corner(geometry: dict[str, float]) -> None:
    # Paper Eq. (4)–(6), spec/rocking.md: the spring at the top corner has r = 2R, φ = α,
    # for both pivots; it follows the geometry whichever form gives it.
    block = to_block(with_restrainer(geometry, k=1e6, position="top"))
    spring = block.restrainers[0]
    for s in (POSITIVE, NEGATIVE):
        _, r, phi = spring.side(s)
        assert r == pytest.approx(2 * block.R, rel=1e-12)
        assert phi == pytest.approx(block.alpha, rel=1e-12)


def test_radius_and_angle_are_the_same_for_both_pivots() -> None:
    # Paper §4.2: the vault at R_vault = 7.00 m, α_vault = 0.072 rad from the pivot.
    spring = to_block(with_restrainer(FACADE_GEOMETRY, k=4e6, radius=7.0, angle=0.072)).restrainers[
        0
    ]
    assert (spring.r_pos, spring.phi_pos, spring.r_neg, spring.phi_neg) == (7.0, 0.072, 7.0, 0.072)


def test_point_on_the_mid_plane_is_symmetric() -> None:
    # spec/rocking.md: x differs for θ > 0 and θ < 0 unless the point lies on the mid-plane
    # (x = b): there r = √(b² + z²), φ = atan(b/z) for both pivots.
    geometry = {"thickness": 0.5, "height": 4.0}
    spring = to_block(with_restrainer(geometry, k=1e6, height=3.0, from_pivot=0.25)).restrainers[0]
    assert (spring.r_pos, spring.phi_pos) == (spring.r_neg, spring.phi_neg)
    assert spring.r_pos == pytest.approx(math.hypot(0.25, 3.0), rel=1e-12)
    assert spring.phi_pos == pytest.approx(math.atan(0.25 / 3.0), rel=1e-12)


def test_point_on_the_pivot_face_is_2b_from_the_other_pivot() -> None:
    # spec/rocking.md: a point on the pivot face (x = 0) at height z has r = z, φ = 0 about O;
    # about O′ it is 2b away horizontally.
    geometry = {"thickness": 0.5, "height": 4.0}
    spring = to_block(with_restrainer(geometry, k=1e6, height=3.0, from_pivot=0.0)).restrainers[0]
    assert (spring.r_pos, spring.phi_pos) == (3.0, 0.0)
    assert (spring.r_neg, spring.phi_neg) == pytest.approx(point_polar(0.5, 3.0), rel=1e-12)


def test_point_on_the_top_corner_by_coordinates_equals_position_top() -> None:
    # x = 2b, z = 2h about O is the paper's top corner (r = 2R, φ = α).
    geometry = {"thickness": 0.5, "height": 4.0}
    by_xy = to_block(with_restrainer(geometry, k=1.0, height=4.0, from_pivot=0.5)).restrainers[0]
    top = to_block(with_restrainer(geometry, k=1.0, position="top")).restrainers[0]
    assert (by_xy.r_pos, by_xy.phi_pos) == pytest.approx((top.r_pos, top.phi_pos), rel=1e-12)


def test_failure_elongation_and_default_names() -> None:
    m = model(
        FACADE_GEOMETRY,
        mass={"weight": 100.0},
        restrainers=[
            {"k": 4e6, "radius": 7.0, "angle": 0.072, "fails_at": 0.001},
            {"name": "tie", "k": 1.0, "position": "top"},
            {"k": 1.0, "position": "top"},
        ],
    )
    springs = to_block(m).restrainers
    assert [s.name for s in springs] == ["restrainer 1", "tie", "restrainer 3"]
    assert springs[0].fails_at == 0.001 and springs[0].can_fail
    assert springs[1].fails_at == math.inf and not springs[1].can_fail


# --- motion and analysis ------------------------------------------------------------------------


def test_one_sided_motion_frees_the_side_opposite_the_stopped_one() -> None:
    # spec/rocking.md, one-sided motion; model contract: stopped defaults to "negative".
    default = to_block(model(FACADE_GEOMETRY, motion={"sides": "one"}))
    assert (default.one_sided, default.free_side, default.rebound) == (True, POSITIVE, 1.0)
    stopped_pos = to_block(
        model(FACADE_GEOMETRY, motion={"sides": "one", "stopped": "positive", "rebound": 0.6})
    )
    assert (stopped_pos.free_side, stopped_pos.rebound) == (NEGATIVE, 0.6)
    assert to_block(model(FACADE_GEOMETRY)).one_sided is False


def test_solver_options_defaults_and_values() -> None:
    # Defaults of spec/engine.md: rtol = atol = 1e-8, ω_rest = 1e-4 rad/s, overturn at π/2.
    assert solver_options(model(FACADE_GEOMETRY)) == AnalysisOptions(
        tail=None, overturn_angle=math.pi / 2, rtol=1e-8, atol=1e-8, rest_velocity=1e-4
    )
    given = model(
        FACADE_GEOMETRY,
        analysis={
            "tail": 20,
            "overturn_angle": 1.0,
            "rtol": 1e-6,
            "atol": 1e-7,
            "rest_velocity": 1e-5,
            "linearized": True,
        },
    )
    assert solver_options(given) == AnalysisOptions(20.0, 1.0, 1e-6, 1e-7, 1e-5)
    assert to_block(given).linearized is True
