"""The rigid mechanisms of the catalogue rock as bodies of their own shape (issue 22, first part).

A gable, a wall with its wedge, the storey above a floor: each turns as one rigid body about
its hinge, and the engine's loaded equation of motion takes it as its centroid's point mass
plus I_G (rockcli.mechanisms.rigid). Checked here against closed forms written from the body's
own mass properties, not from the code:

- free rocking with e = 1 conserves ½·I_O·θ̇² + m·g·Z_G(θ): released from θ0 it reaches
  θ = 0 with θ̇² = 2·m·g·r·[cos(α − θ0) − cos α]/I_O (Housner 1963, for any rigid body about
  its pivot, I_O = I_G + m·r² by parallel axes, r and α its centroid's polar coordinates);
- a rectangle given as a body of its own shape is the paper's block (the same motion);
- the fast engine agrees with the reference integration (scipy DOP853) on the same body;
- Housner's e of a body about the new pivot (angular momentum) for the rectangle is 1 − 1.5 sin²α.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block, RigidBody, impact_restitution
from rockcli.mechanisms.catalogue import build
from rockcli.mechanisms.catalogue import rigid_parts as parts
from rockcli.mechanisms.rigid import composite, rigid_block
from rockcli.mechanisms.wall import MechanismSpec, MechanismType, Storey, Wall

G = 9.81
WALL = Wall(
    storeys=(Storey(4.0, 0.6), Storey(3.5, 0.45)),
    width=6.0,
    unit_weight=20e3,
    g=G,
    gable_height=2.5,
    return_wall_thickness=0.45,
)
#: The settings a model of e = 1, two-sided, gives the block the mechanism keeps.
BASE = Block(R=1.0, alpha=0.1, mass=1.0, g=G, e=1.0)
GABLE = MechanismSpec("gable", MechanismType.GABLE)
STOREY_2 = MechanismSpec("overturning, storey 2", MechanismType.OVERTURNING, 4.0)
WEDGE = MechanismSpec("wedge", MechanismType.WEDGE, angle=math.radians(30.0), sides=2)


def rigid_of(wall: Wall, spec: MechanismSpec, base: Block) -> RigidBody:
    """The mechanism as the engine rocks it, from its placement about each pivot."""
    wedge = spec.type is MechanismType.WEDGE
    return rigid_block(build(wall, spec, 1), build(wall, spec, -1), base, wedge)


def at_rest(seconds: float = 6.0, dt: float = 0.01) -> tuple[np.ndarray, np.ndarray]:
    """A record of no motion [s, g]."""
    time = np.arange(0.0, seconds + dt / 2, dt)
    return time, np.zeros_like(time)


@pytest.mark.parametrize("spec", [GABLE, STOREY_2], ids=lambda s: s.name)
def test_free_rocking_conserves_the_energy_of_the_bodys_own_mass_properties(spec) -> None:
    block = rigid_of(WALL, spec, BASE)
    bodies, hinge, thickness = parts(WALL, spec)
    body = composite(bodies)
    # Closed form from the mass properties (not from the block): pivot O at the hinge
    # section's outer edge (no f_m: no set-back).
    x, z = body.x, body.z - hinge
    r, alpha = math.hypot(x, z), math.atan2(x, z)
    i_o = body.inertia + body.mass * r * r
    theta0 = 0.5 * alpha
    expected = math.sqrt(
        2.0 * body.mass * G * r * (math.cos(alpha - theta0) - math.cos(alpha)) / i_o
    )
    time, accel = at_rest()
    run = simulate(block, time, accel, 0.01, theta0=theta0, settings=SolverSettings(tail=0.0))
    # Tolerance: the engine's rtol 1e-8 on the state; the peak speed is read at the impact
    # event (the root of θ on the dense output), so 1e-6 relative is ample.
    assert run.max_velocity == pytest.approx(expected, rel=1e-6)
    # e = 1: it comes back to θ0 after each impact (no energy lost): max θ/α stays θ0/α.
    assert run.max_ratio == pytest.approx(theta0 / block.alpha, rel=1e-6)


def test_a_rectangle_as_a_body_of_its_own_shape_is_the_papers_block() -> None:
    # One storey 4 m × 0.5 m: its overturning about the base as a composite body against
    # Block(R, α) of the paper, under a half-sine pulse of 0.3 g (both run by the engine).
    wall = Wall(storeys=(Storey(4.0, 0.5),), width=1.0, unit_weight=18e3, g=G)
    spec = MechanismSpec("o", MechanismType.OVERTURNING, 0.0)
    b, h = 0.25, 2.0
    mass = 18e3 * 0.5 * 4.0 / G
    e = 1.0 - 1.5 * math.sin(math.atan2(b, h)) ** 2
    paper = Block(R=math.hypot(b, h), alpha=math.atan2(b, h), mass=mass, g=G, e=e)
    body = replace(rigid_of(wall, spec, paper), e=e, e_neg=None)
    time = np.arange(0.0, 3.0, 0.005)
    accel = np.where(time < 0.5, 0.3 * np.sin(2 * math.pi * time), 0.0)
    one = simulate(paper, time, accel, 0.005)
    other = simulate(body, time, accel, 0.005)
    # The two differ only in how I0 is summed (4/3·m·R² against I_G + m·R²): to the engine's
    # tolerance (rtol 1e-8; a robust, non-chattering pulse response).
    assert other.max_ratio == pytest.approx(one.max_ratio, rel=1e-6)
    assert other.impacts == one.impacts


def test_housner_restitution_of_a_body_is_the_rectangles() -> None:
    # e = (I_G + m(z² − x·x′))/(I_G + m(x′² + z²)) for the rectangle: 1 − 1.5 sin²α
    # (Housner 1963; paper Eq. 3).
    b, h, m = 0.3, 1.5, 1000.0
    i_g = m * (4 * b * b + 4 * h * h) / 12.0
    body = RigidBody(R=math.hypot(b, h), alpha=math.atan2(b, h), mass=m, shape=(b, b, h, i_g))
    expected = 1.0 - 1.5 * math.sin(math.atan2(b, h)) ** 2
    assert impact_restitution(body, 1) == pytest.approx(expected, rel=1e-13)


@pytest.mark.parametrize("spec", [GABLE, WEDGE], ids=lambda s: s.name)
def test_the_fast_engine_agrees_with_the_reference_on_a_body(spec) -> None:
    block = rigid_of(WALL, spec, replace(BASE, e=0.9))
    time = np.arange(0.0, 3.0, 0.005)
    accel = np.where(time < 1.0, 0.6 * np.sin(2 * math.pi * time), 0.0)
    fast = simulate(block, time, accel, 0.005, engine=Engine.FAST)
    ref = simulate(block, time, accel, 0.005, engine=Engine.REFERENCE)
    # Engine agreement of the block (docs/physics.md): 1e-3 relative on a robust pulse.
    assert fast.overturned == ref.overturned
    assert fast.max_ratio == pytest.approx(ref.max_ratio, rel=1e-3)


def projection_restitution(
    cells: list[tuple[float, float, float]], x_old: float, x_new: float
) -> float:
    """e = Σ v⁻·v⁺ m / Σ |v⁺|² m over mass cells (m, x, z) of a body: v⁻ = ω × (r − O) with
    O at x = x_old, v⁺ = ω × (r − O′) with O′ at x = x_new, both at z = 0 (per unit ω²,
    v⁻·v⁺ = (r − O)·(r − O′))."""
    num = sum(m * ((x - x_old) * (x - x_new) + z * z) for m, x, z in cells)
    den = sum(m * ((x - x_new) ** 2 + z * z) for m, x, z in cells)
    return num / den


def gable_cells(t: float, hg: float, width: float, n: int) -> list[tuple[float, float, float]]:
    """The gable (thickness t, height hg, base width) as n × n cells of mass ∝ its width at
    their height (a triangle in the wall's plane), x from its outer base edge, z from its base."""
    cells = []
    for i in range(n):
        for j in range(n):
            x, z = (i + 0.5) * t / n, (j + 0.5) * hg / n
            cells.append((width * (1.0 - z / hg) * (t / n) * (hg / n), x, z))
    return cells


def test_momentum_and_projection_restitution_are_one_number_for_one_body() -> None:
    # docs/physics.md, "Momentum or projection": for one rigid body ∫v⁻·v⁺dm/∫|v⁺|²dm is
    # the angular momentum balance about the new pivot, term by term. Summed over a 400 × 400
    # grid of the gable's mass (midpoint rule, error O(1/n²) ≈ 1e-6 of the moments), against
    # mechanics.impact_restitution of the gable as a body (its centroid and I_G in closed form).
    block = rigid_of(WALL, GABLE, BASE)
    t, hg = WALL.storeys[-1].thickness, WALL.gable_height or 0.0
    cells = gable_cells(t, hg, WALL.width, 400)
    for s, (x_old, x_new) in ((1, (0.0, t)), (-1, (t, 0.0))):
        assert impact_restitution(block, s) == pytest.approx(
            projection_restitution(cells, x_old, x_new), rel=1e-5
        )
