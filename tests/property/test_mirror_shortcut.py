"""The mirror shortcut (rockcli.dynamics.simulate.assess): a mirror-symmetric block is
integrated for +üg only and its −üg run is the mirror image. The decision
(rockcli.mechanics.mirror_symmetric) is kept honest both ways (hypothesis):

- on random symmetric blocks (two-sided; restrainers of any law with the same stiffness,
  arm, angle and yield from either pivot; loads on the mid-plane) the shortcut is taken, and
  the mirrored run equals the −üg run integrated in full, field by field, exactly (the
  equation is odd in (θ, üg) and the engine negates exactly: test_rocking_metamorphic);
- on the same blocks with one asymmetry (one side's stiffness, arm, angle or yield; a load off
  the mid-plane; a thrust; one-sided motion; another restitution on one side) the shortcut is
  never taken: both runs are integrated.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.dynamics.result import RockingRun
from rockcli.dynamics.simulate import assess
from rockcli.mechanics import Block, Load, Restrainer, Thrust, mirror_symmetric, mirrored

#: Few examples: each integrates whole time histories.
EXAMPLES = settings(max_examples=30, deadline=None)
DT = 0.005


@st.composite
def restrainers(draw: st.DrawFn, R: float, alpha: float) -> Restrainer:
    """A restrainer the same from either pivot, elastic or elastic-plastic, maybe fragile."""
    k = draw(st.floats(1e3, 1e6))
    r = draw(st.floats(0.3, 2.0)) * R
    phi = draw(st.floats(0.05, 1.2))  # any angle into the block [rad]
    yield_force = draw(st.one_of(st.just(math.inf), st.floats(50.0, 5e3)))
    fails_at = draw(st.one_of(st.just(math.inf), st.floats(0.005, 0.05)))
    law = "elastic" if math.isinf(yield_force) else "elastic-plastic"
    return Restrainer("tie", k, k, r, phi, r, phi, fails_at=fails_at, law=law,
                      yield_pos=yield_force, yield_neg=yield_force)  # fmt: skip


@st.composite
def symmetric_blocks(draw: st.DrawFn) -> Block:
    R = draw(st.floats(0.5, 3.0))
    alpha = draw(st.floats(0.08, 0.3))
    mass = draw(st.floats(200.0, 5000.0))
    block = Block(R=R, alpha=alpha, mass=mass, e=draw(st.floats(0.7, 1.0)))
    springs = tuple(draw(st.lists(restrainers(R, alpha), max_size=2)))
    b, h = block.b, block.h
    loads = tuple(
        Load(
            f"load{i}",
            draw(st.floats(100.0, 5e3)),
            b,
            b,
            draw(st.floats(0.0, 2.0)) * h,
            bears=draw(st.booleans()),
            moves=True,
        )  # fmt: skip
        for i in range(draw(st.integers(0, 2)))
    )
    return replace(block, restrainers=springs, loads=loads)


def pulse(amplitude: float, period: float) -> tuple[np.ndarray, np.ndarray]:
    """One full sine of the given amplitude [g] and period [s], then 1 s at rest."""
    t = np.arange(0.0, period + 1.0, DT)
    return t, np.where(t < period, amplitude * np.sin(2 * np.pi * t / period), 0.0)


PULSES = st.tuples(st.floats(1.2, 4.0), st.floats(0.2, 1.5))


def fields(run: RockingRun) -> dict:
    return {k: v for k, v in vars(run).items() if k not in ("mirror_of", "history")}


@EXAMPLES
@given(symmetric_blocks(), PULSES)
def test_symmetric_blocks_take_the_shortcut_and_it_is_exact(block: Block, shape) -> None:
    assert mirror_symmetric(block) and mirrored(block) == block
    t, a = pulse(shape[0] * math.tan(block.alpha), shape[1])
    short = assess(block, t, a, DT, history=True)
    full = assess(block, t, a, DT, history=True, mirror=False)
    assert [r.mirror_of for r in short.runs] == [None, 1]
    assert [r.mirror_of for r in full.runs] == [None, None]
    for mine, theirs in zip(short.runs, full.runs, strict=True):
        assert fields(mine) == fields(theirs)
        assert np.array_equal(mine.history.theta, theirs.history.theta)
        assert np.array_equal(mine.history.omega, theirs.history.omega)
        assert np.array_equal(mine.history.forces, theirs.history.forces)


def break_symmetry(block: Block, how: str, amount: float) -> Block:
    """The block with one asymmetry (``amount`` in (0.05, 0.5): a relative change)."""
    b = block.b
    if how == "one-sided":
        return replace(block, one_sided=True)
    if how == "restitution":
        return replace(block, e_neg=block.e * (1 - amount))
    if how == "thrust":
        return replace(block, thrusts=(Thrust("arch", 1e3, 1, b, b, block.h),))
    if how == "load":
        x = b * (1 - amount)
        return replace(block, loads=(*block.loads, Load("off", 500.0, x, 2 * b - x, block.h)))
    if not block.restrainers:
        return replace(block, one_sided=True)
    r = block.restrainers[0]
    changed = {
        "stiffness": {"k_neg": r.k_neg * (1 + amount)},
        "arm": {"r_neg": r.r_neg * (1 + amount)},
        "angle": {"phi_neg": r.phi_neg * (1 + amount)},
        "yield": {
            "yield_neg": r.yield_neg * (1 + amount) if math.isfinite(r.yield_neg) else 1e3,
            "law": "elastic-plastic",
            "yield_pos": r.yield_pos if math.isfinite(r.yield_pos) else 2e3,
        },
    }[how]
    return replace(block, restrainers=(replace(r, **changed), *block.restrainers[1:]))


@EXAMPLES
@given(
    symmetric_blocks(),
    st.sampled_from(["one-sided", "restitution", "thrust", "load", "stiffness", "arm", "angle",
                     "yield"]),
    st.floats(0.05, 0.5),
    PULSES,
)  # fmt: skip
def test_asymmetric_blocks_never_take_the_shortcut(block: Block, how, amount, shape) -> None:
    broken = break_symmetry(block, how, amount)
    assert not mirror_symmetric(broken)
    # The field-by-field test is the definition: a block equal to its mirror, two-sided,
    # without thrusts (a thrust's mirror pushes the other way).
    assert mirrored(broken) != broken or broken.one_sided or broken.thrusts
    t, a = pulse(shape[0] * math.tan(block.alpha), shape[1])
    assert [r.mirror_of for r in assess(broken, t, a, DT).runs] == [None, None]
