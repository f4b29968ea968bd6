"""A chain's capacity curve is scanned for its zero SCAN_CHUNK rotations at a time (its
functions of an array of rotations): the same zero as the scan rotation by rotation, on every
side of every wall mechanism of the examples (ties that hold, ties lost on the way)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from rockcli.codecheck.kinematic import (
    BRACKET_POINTS,
    Mechanism,
    load_multiplier,
    zero_rotation,
)
from rockcli.searches import brent_root

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
WALLS = ["two-storey-facade.toml", "top-storey-wall.toml"]


def one_by_one(mech: Mechanism) -> float | None:
    """The scan rotation by rotation (the block's path), then Brent's search."""

    def f(t: float) -> float:
        return load_multiplier(mech, t)

    prev, f_prev = 0.0, math.inf
    for k in range(1, BRACKET_POINTS + 1):
        t = mech.view.limit * k / BRACKET_POINTS
        if (f_t := f(t)) <= 0.0:
            return brent_root(f, prev, t, f_prev, f_t)
        prev, f_prev = t, f_t
    return None


def sides(name: str) -> list[tuple[str, Mechanism]]:
    from rockcli.analyses.catalogue import side_check
    from rockcli.analyses.kinematic import check_settings
    from rockcli.model.catalogue import catalogue
    from rockcli.model.load import load_model

    model = load_model(EXAMPLES / name)
    settings = check_settings(model, None)
    return [(f"{m.name} {s:+d}", side_check(m, s, settings)) for m in catalogue(model)
            for s in m.sides]  # fmt: skip


@pytest.mark.parametrize("name", WALLS)
def test_the_chunked_scan_finds_the_zero_of_the_scan_one_by_one(name: str) -> None:
    checked = 0
    for label, mech in sides(name):
        want, got = one_by_one(mech), zero_rotation(mech)
        if want is None:
            assert got is None, label
            continue
        checked += 1
        assert got is not None and math.isclose(got, want, rel_tol=1e-13), (label, got, want)
    assert checked >= 2
