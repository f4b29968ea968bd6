"""One damage measure for every mechanism: max |θ|/θc, θc the collapse rotation of the side of θ.

θc of side s is where the restoring moment of the weights, loads and thrusts about that
side's pivot vanishes (mechanics.collapse_rotations): the rectangle's α, a loaded block's
statics, a chain's instability rotation. Expected values from the statics by hand, or from
the code check's own configuration function (rockcli.mechanisms.side) for the chain.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from rockcli.analyses.rocked import mechanism_block, named_spec
from rockcli.codecheck.kinematic import Mechanism
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import assess
from rockcli.mechanics import Block, Load, Thrust, collapse_rotations
from rockcli.mechanisms.catalogue import build
from rockcli.model.derive_wall import to_wall
from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
FACADE = ROOT / "examples" / "two-storey-facade.toml"
B, H, MASS, G = 0.25, 2.0, 1000.0, 9.81


def rectangle(**kw) -> Block:
    return Block(R=math.hypot(B, H), alpha=math.atan2(B, H), mass=MASS, g=G, **kw)


def test_the_rectangle_is_alpha_on_both_sides() -> None:
    block = rectangle()
    assert collapse_rotations(block) == (block.alpha, block.alpha)


def test_an_off_centre_load_moves_each_side_its_own_way() -> None:
    """A bearing load P at 0.1 m from O (0.4 m from O′), 4 m up: the weights' centre stands
    above each pivot at tan θc = Σ P·x / Σ P·z."""
    W, P = MASS * G, 5000.0
    block = rectangle(loads=(Load("floor", P, 0.1, 0.4, 4.0),))
    pos, neg = collapse_rotations(block)
    assert pos == pytest.approx(math.atan((W * B + P * 0.1) / (W * H + P * 4.0)), rel=1e-13)
    assert neg == pytest.approx(math.atan((W * B + P * 0.4) / (W * H + P * 4.0)), rel=1e-13)


def test_a_thrust_lowers_the_side_it_pushes_to() -> None:
    """A thrust F towards θ > 0 at height 2 m, on the block's faces: about O it opens with the
    arm Y = z cos a + x sin a (x = 0 at O's face, 2b at O′'s), about O′ it closes. Restoring
    moment W(b cos a − h sin a) ∓ F(z cos a + x sin a) = 0 ⇒ tan a = (W b ∓ F z)/(W h ± F x)."""
    W, F = MASS * G, 1000.0
    block = rectangle(thrusts=(Thrust("roof", F, 1, 0.0, 2 * B, 2.0),))
    pos, neg = collapse_rotations(block)
    assert pos == pytest.approx(math.atan2(W * B - F * 2.0, W * H + F * 0.0), rel=1e-13)
    assert neg == pytest.approx(math.atan2(W * B + F * 2.0, W * H - F * 2 * B), rel=1e-13)


def restoring_zero(mech: Mechanism) -> float:
    """The zero of G − T of the code check's configuration function, by bisection."""

    def f(t: float) -> float:
        g, thrust, _ = mech.view.work_terms(t)
        return g - thrust

    lo, hi = 0.0, mech.view.limit * 0.999
    assert f(hi) < 0.0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


@pytest.mark.parametrize("name", ["vertical flexure, storey 2", "overturning, storey 2", "gable"])
def test_each_mechanism_s_sides_match_the_code_check_statics(name: str) -> None:
    """The engine's θc of each side (from its table or its body) is the zero of the code
    check's restoring moment (the catalogue's configuration function), side by side."""
    model = load_model(str(FACADE))
    wall = to_wall(model)
    spec = named_spec(wall, name)
    block = mechanism_block(model, wall, spec)
    if spec.hinge_height == "optimal":
        from rockcli.model.catalogue import resolved

        spec, _ = resolved(wall, spec, (1, -1))
    got = collapse_rotations(block)
    for k, s in enumerate((1, -1)):
        expected = restoring_zero(Mechanism(build(wall, spec, s)))
        assert got[k] == pytest.approx(expected, rel=1e-6), (name, s)


def test_storey_2_has_two_different_sides() -> None:
    """The issue's case: storey 2's sides differ (a set-back storey, off-centre loads)."""
    model = load_model(str(FACADE))
    wall = to_wall(model)
    block = mechanism_block(model, wall, named_spec(wall, "overturning, storey 2"))
    pos, neg = collapse_rotations(block)
    assert abs(pos - neg) > 0.01


def test_max_ratio_reads_the_side_of_each_extreme() -> None:
    """A run's max_ratio is max(θmax/θc⁺, −θmin/θc⁻) (a one-sine pulse rocks both sides)."""
    P = 5000.0
    block = rectangle(loads=(Load("floor", P, 0.1, 0.4, 4.0),))
    t = np.linspace(0.0, 3.0, 3001)
    accel = np.where(t < 0.5, 0.4 * np.sin(2 * math.pi * t / 0.5), 0.0)
    runs = assess(block, t, accel, 0.001, settings=SolverSettings()).runs
    pos, neg = collapse_rotations(block)
    for run in runs:
        expected = max(run.theta_max / pos, -run.theta_min / neg)
        assert run.max_ratio == pytest.approx(expected, rel=1e-15)
    assert any(r.theta_min < 0 for r in runs)
