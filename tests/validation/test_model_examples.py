"""The shipped examples load and hold the paper's numbers (spec/paper-cases.md)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from rockcli.mechanics import POSITIVE
from rockcli.model.derive import describe, to_block
from rockcli.model.load import load_model

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_the_three_examples_are_there() -> None:
    names = {p.name for p in EXAMPLES.glob("*.toml")}
    assert {"altar.toml", "facade.toml", "wall.toml"} <= names


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.toml")), ids=lambda p: p.name)
def test_every_example_loads(path: Path) -> None:
    # Every model derives its catalogue: a wall's mechanisms, a block file's block.
    from rockcli.model.catalogue import catalogue

    model = load_model(path)
    assert catalogue(model)


def test_altar_example_is_the_papers_altar() -> None:
    # Paper §3.2: R = 1.499 m, α = 0.163 rad, width 2.40 m, Housner e not reduced, two-sided.
    model = load_model(EXAMPLES / "altar.toml")
    block = to_block(model)
    assert (block.R, block.alpha, model.geometry.width) == (1.499, 0.163, 2.40)
    assert block.e == 1 - 1.5 * math.sin(0.163) ** 2
    assert not block.one_sided and block.restrainers == ()


def test_facade_example_is_the_papers_facade() -> None:
    # Paper §4.2: W = 1755 kN, R = 5.04 m, α = 0.05 rad; vault K_v = 4E6 N/m and tie-rod
    # Ø20 L = 3.00 m (K = 22.0E6 N/m, 3 significant digits) at 7.00 m, 0.072 rad; one-sided,
    # outward (positive) rotation free, rebound without additional damping (r_f = 1).
    block = to_block(load_model(EXAMPLES / "facade.toml"))
    assert (block.R, block.alpha, block.weight) == pytest.approx((5.04, 0.05, 1755e3))
    assert (block.one_sided, block.free_side, block.rebound) == (True, POSITIVE, 1.0)
    vault, tie = block.restrainers
    assert (vault.k_pos, vault.r_pos, vault.phi_pos) == (4e6, 7.0, 0.072)
    assert float(f"{tie.k_pos:.2e}") == 2.20e7
    assert (tie.r_pos, tie.phi_pos) == (vault.r_pos, vault.phi_pos)


def test_wall_example() -> None:
    # 0.5 × 4.0 × 3.0 m at 18 kN/m³ = 108 kN; restitution 0.9 × Housner (paper §3.3).
    d = describe(load_model(EXAMPLES / "wall.toml"))
    assert d.weight == pytest.approx(108e3)
    assert d.e == pytest.approx(0.9 * (1 - 1.5 * math.sin(math.atan(0.25 / 2.0)) ** 2))
