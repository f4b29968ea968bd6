"""Loads and thrusts in the rocking equation, against statics, Lagrange and an independent solver.

The equation of motion with loads (rules.loaded_angular_acceleration; docs/physics.md, "Loads
and thrusts") is checked here only through closed forms written in this file:

- the uplift acceleration of each side from statics (moment equilibrium about the pivot at
  θ = 0: the Circolare's virtual-work multiplier), and the exact uplift time on a ramp;
- the energy of the same Lagrangian, written here from the geometry in polar form (r, φ), is
  conserved by free rocking with e = 1 (to 1e-8 relative at tolerances 1e-12);
- a rigid load at the top centre makes the block and load one rigid body: its free rocking
  is Housner's equation for the combined centroid and inertia, integrated by scipy's DOP853;
- the same equation with only the block in the point table is paper Eq. (2) (the free path);
- Housner's coefficient of restitution of the combined body, by angular momentum about the
  new pivot.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from rockcli.codecheck.kinematic import Mechanism, alpha0
from rockcli.dynamics import layout as L
from rockcli.dynamics.kernel import integrate
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import (
    extend_with_tail,
    pack_parameters,
    pack_springs,
    simulate,
)
from rockcli.mechanics import (
    Block,
    Load,
    Thrust,
    housner_restitution,
    impact_restitution,
    point_table,
    uplift_accelerations,
)
from rockcli.mechanisms.block import BlockSide

G = 9.81
R_BLOCK = 1.5
ALPHA = 0.2
MASS = 2000.0  # [kg]
B = R_BLOCK * math.sin(ALPHA)
H = R_BLOCK * math.cos(ALPHA)
#: Tight tolerances for the conservation and reference comparisons (the engine's floor).
TIGHT = SolverSettings(rtol=1e-12, atol=1e-12, tail=0.0)
#: Exact crossing times on a ramp (linear ground motion between samples): rounding only [s].
CROSSING_ATOL = 1e-12


def load(weight: float, x: float, z: float, bears: bool = True, moves: bool = True) -> Load:
    """A load of `weight` [N] at x from pivot O (2b − x from O′) and height z."""
    return Load("load", weight, x, 2 * B - x, z, bears, moves)


def thrust(force: float, direction: int, z: float, x: float = B) -> Thrust:
    """A thrust of `force` [N] towards `direction` at height z."""
    return Thrust("thrust", force, direction, x, 2 * B - x, z)


def block(*items: Load | Thrust, e: float = 1.0) -> Block:
    """The test block with the given loads and thrusts."""
    loads = tuple(i for i in items if isinstance(i, Load))
    thrusts = tuple(i for i in items if isinstance(i, Thrust))
    return Block(R=R_BLOCK, alpha=ALPHA, mass=MASS, g=G, e=e, loads=loads, thrusts=thrusts)


W = MASS * G


def statics_uplift(blk: Block, side: int) -> float:
    """Uplift acceleration [g] towards `side` by moment equilibrium about its pivot at θ = 0.

    Weights that bear restore with arm x (distance from the pivot); the inertial forces of the
    masses that move overturn with arm z; a thrust towards the side overturns with arm z.
    """
    restoring = W * B + sum(
        ld.weight * (ld.x_pos if side > 0 else ld.x_neg) for ld in blk.loads if ld.bears
    )
    overturning = W * H + sum(ld.weight * ld.z for ld in blk.loads if ld.moves)
    pushing = sum(side * t.direction * t.force * t.z for t in blk.thrusts)
    return (restoring - pushing) / overturning


CASES = {
    "centred top load": block(load(0.5 * W, B, 2 * H)),
    "eccentric floor at mid-height": block(load(0.8 * W, 0.3 * B, H)),
    "pushing floor (P_j)": block(load(0.4 * W, B, 2 * H, bears=False)),
    "bearing only": block(load(0.4 * W, 1.7 * B, 2 * H, moves=False)),
    "thrust towards θ > 0": block(thrust(0.05 * W, 1, 1.8 * H)),
    "thrust and floor": block(load(0.6 * W, 1.2 * B, 1.5 * H), thrust(0.03 * W, -1, 2 * H)),
}


@pytest.mark.parametrize("name", list(CASES))
def test_uplift_acceleration_of_each_side_is_statics(name: str) -> None:
    # Statics above; the same numbers in a different order of operations: 1e-14 relative.
    blk = CASES[name]
    pos, neg = uplift_accelerations(blk)
    assert pos == pytest.approx(statics_uplift(blk, 1), rel=1e-14)
    assert neg == pytest.approx(statics_uplift(blk, -1), rel=1e-14)


@pytest.mark.parametrize("name", list(CASES))
def test_the_code_checks_alpha0_is_the_uplift_acceleration_bit_for_bit(name: str) -> None:
    # One restoring-moment function (mechanics.point_moments) serves both analyses.
    blk = CASES[name]
    pos, neg = uplift_accelerations(blk)
    assert alpha0(Mechanism(BlockSide(blk, 1))) == pos
    assert alpha0(Mechanism(BlockSide(blk, -1))) == neg


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.parametrize("polarity", [1, -1])
def test_the_engine_uplifts_exactly_at_the_statics_threshold(name: str, polarity: int) -> None:
    # A ramp üg = polarity·k·t [g]: linear between its two samples, so the engine's uplift time
    # is the exact crossing α0_s / k (s = polarity: a positive acceleration drives θ > 0).
    blk = CASES[name]
    k = 0.5  # [g/s]
    run = simulate(
        blk, np.array([0.0, 2.0]), np.array([0.0, polarity * 2.0 * k]), 0.01, settings=TIGHT
    )
    expected = statics_uplift(blk, polarity) / k
    assert run.t_uplift == pytest.approx(expected, abs=CROSSING_ATOL)
    assert (run.theta_max > 0) == (polarity > 0)


weights = st.floats(0.01 * W, 5 * W)
fractions = st.floats(0.0, 1.0)


@st.composite
def loaded_blocks(draw: st.DrawFn) -> Block:
    items: list[Load | Thrust] = []
    for _ in range(draw(st.integers(1, 3))):
        bears, moves = draw(st.sampled_from([(True, True), (True, False), (False, True)]))
        x, z = 2 * B * draw(fractions), 2 * H * draw(fractions)
        items.append(load(draw(weights), x, z, bears, moves))
    if draw(st.booleans()):
        items.append(thrust(draw(st.floats(0.0, 0.02)) * W, draw(st.sampled_from([1, -1])), H))
    return block(*items)


@settings(max_examples=200, deadline=None)
@given(loaded_blocks())
def test_alpha0_equals_the_uplift_acceleration_for_any_loads(blk: Block) -> None:
    # The property of the architecture: the uplift acceleration of each side equals α0 of that
    # side, bit for bit, and both equal statics (1e-12: sums of up to five terms).
    for side, value in zip((1, -1), uplift_accelerations(blk), strict=True):
        assert alpha0(Mechanism(BlockSide(blk, side))) == value
        assert value == pytest.approx(statics_uplift(blk, side), rel=1e-12)


def point_energy(ld: Load, side: int, a: float, om: float) -> tuple[float, float]:
    """(kinetic, potential) of a load after a rotation a about pivot `side`, in polar form."""
    x = ld.x_pos if side > 0 else ld.x_neg
    r, phi = math.hypot(x, ld.z), math.atan2(x, ld.z)
    m = ld.weight / G
    v_hor, v_ver = r * math.cos(phi - a) * om, r * math.sin(phi - a) * om
    kinetic = 0.5 * m * ((v_hor**2 if ld.moves else 0.0) + (v_ver**2 if ld.bears else 0.0))
    potential = ld.weight * r * math.cos(phi - a) if ld.bears else 0.0
    return kinetic, potential


def thrust_energy(t: Thrust, side: int, a: float) -> float:
    """Potential of a constant horizontal force: minus its work since θ = 0."""
    x = t.x_pos if side > 0 else t.x_neg
    r, phi = math.hypot(x, t.z), math.atan2(x, t.z)
    return -side * t.direction * t.force * r * (math.sin(phi) - math.sin(phi - a))


def energy(blk: Block, theta: float, om: float) -> float:
    """Total energy of the Lagrangian: block (Housner), loads and thrusts (polar form)."""
    side = 1 if theta > 0 or (theta == 0 and om >= 0) else -1
    a = abs(theta)
    total = 0.5 * blk.inertia * om**2 + W * R_BLOCK * math.cos(ALPHA - a)
    for ld in blk.loads:
        total += sum(point_energy(ld, side, a, om))
    return total + sum(thrust_energy(t, side, a) for t in blk.thrusts)


SYMMETRIC = {
    "rigid top load": block(load(0.7 * W, B, 2 * H)),
    "pushing floor and bearing roof": block(
        load(0.5 * W, B, 1.6 * H, bears=False), load(0.3 * W, B, 2 * H, moves=False)
    ),
}


@pytest.mark.parametrize("name", list(SYMMETRIC))
def test_free_rocking_with_loads_conserves_the_lagrangian_energy(name: str) -> None:
    # e = 1 and loads on the mid-plane (the same inertia about either pivot): no energy is lost
    # at impacts, so the energy written above is conserved over several impacts. Tolerance
    # 1e-8 relative: the engine's error at rtol = atol = 1e-12 over ~10 s of rocking.
    blk = SYMMETRIC[name]
    theta0 = 0.6 * ALPHA
    run = simulate(
        blk,
        0.01 * np.arange(1001),
        np.zeros(1001),
        0.01,
        theta0=theta0,
        settings=TIGHT,
        history=True,
    )
    assert run.history is not None and run.impacts >= 4
    e0 = energy(blk, theta0, 0.0)
    for th, om in zip(run.history.theta, run.history.omega, strict=True):
        assert energy(blk, float(th), float(om)) == pytest.approx(e0, rel=1e-8)


@pytest.mark.parametrize("name", list(CASES))
def test_one_phase_of_free_rocking_conserves_energy_with_any_load(name: str) -> None:
    # Before the first impact (one pivot) energy is conserved with eccentric loads and thrusts
    # too: this checks the velocity term ½ J′(a) ȧ² of the loads that move one way only.
    blk = CASES[name]
    theta0 = 0.5 * min(uplift_accelerations(blk))  # well inside the static capacity
    run = simulate(
        blk,
        0.001 * np.arange(301),
        np.zeros(301),
        0.001,
        theta0=theta0,
        settings=TIGHT,
        history=True,
    )
    assert run.history is not None
    e0 = energy(blk, theta0, 0.0)
    for th, om in zip(run.history.theta, run.history.omega, strict=True):
        if th <= 0:
            break
        assert energy(blk, float(th), float(om)) == pytest.approx(e0, rel=1e-8)


def combined_body(p: float) -> tuple[float, float, float, float]:
    """(R_c, α_c, total mass, I about a base corner) of the block with a point mass P = p·W at
    the top centre (b, 2h): the polar position of the combined centroid and the inertia."""
    m_p = p * MASS
    m = MASS + m_p
    xc, zc = B, (MASS * H + m_p * 2 * H) / m
    inertia = 4 / 3 * MASS * R_BLOCK**2 + m_p * (B**2 + 4 * H**2)
    return math.hypot(xc, zc), math.atan2(xc, zc), m, inertia


def test_a_rigid_top_load_rocks_as_one_rigid_body() -> None:
    # Housner's equation of the combined body θ̈ = −(m g R_c / I) sin(α_c − θ), integrated by
    # scipy DOP853 at rtol 1e-12 up to the first impact: the engine's impact time and velocity
    # agree to 1e-9 relative (both integrations at 1e-12).
    p = 0.6
    blk = block(load(p * W, B, 2 * H))
    r_c, alpha_c, m, inertia = combined_body(p)
    theta0 = 0.5 * alpha_c

    def rhs(t: float, y: np.ndarray) -> list[float]:
        return [y[1], -(m * G * r_c / inertia) * math.sin(alpha_c - y[0])]

    def impact(t: float, y: np.ndarray) -> float:
        return y[0]

    impact.terminal = True  # type: ignore[attr-defined]
    ref = solve_ivp(
        rhs,
        (0, 20),
        [theta0, 0.0],
        method="DOP853",
        rtol=1e-13,
        atol=1e-14,
        events=impact,
        dense_output=True,
    )
    t_impact = float(ref.t_events[0][0])
    run = simulate(
        blk,
        0.001 * np.arange(1001),
        np.zeros(1001),
        0.001,
        theta0=theta0,
        history=True,
        settings=SolverSettings(rtol=1e-12, atol=1e-12, tail=0.0),
    )
    assert run.history is not None and run.impacts >= 1
    before = run.history.time < t_impact
    assert before.sum() > 100
    expected = ref.sol(run.history.time[before])
    assert run.history.theta[before] == pytest.approx(expected[0], rel=1e-9, abs=1e-12)
    assert run.history.omega[before] == pytest.approx(expected[1], rel=1e-9, abs=1e-12)


def test_housner_restitution_of_the_combined_body() -> None:
    # Angular momentum about the new pivot O′ (Housner 1963): block I0 − 2 m b²; a point mass at
    # (b, 2h) brings m_p((b² + 4h²) − 2b·b); the inertia about O′ is I0 + m_p(b² + 4h²).
    p = 0.6
    blk = block(load(p * W, B, 2 * H))
    m_p = p * MASS
    i0 = 4 / 3 * MASS * R_BLOCK**2
    expected = (i0 - 2 * MASS * B**2 + m_p * (4 * H**2 - B**2)) / (i0 + m_p * (B**2 + 4 * H**2))
    assert impact_restitution(blk, 1) == pytest.approx(expected, rel=1e-14)
    assert impact_restitution(blk, -1) == pytest.approx(expected, rel=1e-14)
    assert impact_restitution(block(), 1) == pytest.approx(housner_restitution(ALPHA), rel=1e-14)


def test_an_eccentric_load_gives_each_side_its_own_restitution() -> None:
    # A load near pivot O: about O′ it is far, so an impact from side +1 (onto O′) loses more.
    blk = block(load(0.8 * W, 0.2 * B, 2 * H))
    assert impact_restitution(blk, 1) != pytest.approx(impact_restitution(blk, -1), rel=1e-3)


def run_kernel(blk: Block, points: np.ndarray, accel: np.ndarray, dt: float) -> np.ndarray:
    """The compiled kernel called directly with the given point table; returns the outputs."""
    settings = SolverSettings()
    times, acc = extend_with_tail(dt * np.arange(accel.size), accel, dt, 2.0)
    par = pack_parameters(blk, settings, settings.rtol, settings.atol)
    par[L.P_UPLIFT_POS] = par[L.P_UPLIFT_NEG] = math.tan(ALPHA)
    out_f = np.zeros(L.N_FLOAT_OUT)
    out_i = np.zeros(L.N_INT_OUT, dtype=np.int64)
    integrate(
        times,
        acc,
        1.0,
        par,
        pack_springs(blk),
        points,
        np.ones(0, dtype=np.int64),
        np.full(1, np.nan),
        np.full(1, np.nan),
        np.zeros((1, 0)),
        out_f,
        out_i,
        np.zeros((0, L.N_SPRING_OUT)),
    )
    return out_f


def test_the_general_equation_without_loads_is_housners() -> None:
    # The block alone in the point table (the general path) against the free path (paper Eq. 2):
    # the same motion, to the integration tolerance (rtol = 1e-8: 1e-6 on the peak).
    blk = block(e=0.9)
    dt = 0.01
    t = dt * np.arange(400)
    accel = 0.4 * np.sin(2 * np.pi * t / 0.8) * (t < 2.0)
    free = run_kernel(blk, np.zeros(0), accel, dt)
    general = run_kernel(blk, np.asarray(point_table(blk)), accel, dt)
    assert free[L.O_MAX_A] > 0.2 * ALPHA
    assert general[L.O_MAX_A] == pytest.approx(free[L.O_MAX_A], rel=1e-6)


def test_fast_and_reference_engines_agree_with_loads_and_thrusts() -> None:
    # Two integrators (DP5(4) compiled, DOP853 at 1e-12) on the same loaded equation: the peak
    # rotation agrees to 1e-6 relative (the fast engine's rtol = 1e-8 over a few impacts).
    blk = block(
        load(0.6 * W, 1.3 * B, 1.5 * H),
        load(0.3 * W, B, 2 * H, bears=False),
        thrust(0.01 * W, 1, 2 * H),
        e=0.85,
    )
    dt = 0.01
    t = dt * np.arange(300)
    accel = 0.35 * np.sin(2 * np.pi * t / 0.6)
    for polarity in (1, -1):
        fast = simulate(blk, t, accel, dt, polarity=polarity, settings=SolverSettings(tail=2.0))
        ref = simulate(
            blk,
            t,
            accel,
            dt,
            polarity=polarity,
            settings=SolverSettings(tail=2.0),
            engine=Engine.REFERENCE,
        )
        assert fast.impacts > 0
        assert fast.max_ratio == pytest.approx(ref.max_ratio, rel=1e-6)
        assert fast.impacts == ref.impacts


def test_the_linearized_frequency_of_a_block_with_a_top_load() -> None:
    # A slender block (α = 0.05) with a rigid top load P at the top centre is one rigid body:
    # linearized about its corner, θ̈ = p_c²(θ − α_c) with p_c² = g·(W h + P·2h)/(g·I) the
    # frequency parameter of the combined body (paper Eq. 2 for the lone block: 3g/4R; Makris
    # & Vassiliou 2013 for a cap mass), so released from θ0 it reaches θ = 0 after
    # t = acosh(α_c/(α_c − θ0))/p_c. The engine integrates the full equation: it agrees to the
    # linearization's error, α²/6 ≈ 4e-4 of the time, plus the history's sampling (1e-4 s of
    # 0.79 s): tolerance 1e-3.
    alpha, radius, mass = 0.05, 2.0, 1000.0
    b, h = radius * math.sin(alpha), radius * math.cos(alpha)
    p_load = 0.8 * mass * G
    top = Load("top", p_load, b, b, 2 * h)
    blk = Block(R=radius, alpha=alpha, mass=mass, g=G, e=1.0, loads=(top,))
    inertia = 4 / 3 * mass * radius**2 + p_load / G * (b**2 + 4 * h**2)
    p_c = math.sqrt((mass * G * h + p_load * 2 * h) / inertia)
    alpha_c = (mass * G * b + p_load * b) / (mass * G * h + p_load * 2 * h)
    theta0 = 0.5 * alpha_c
    expected = math.acosh(alpha_c / (alpha_c - theta0)) / p_c
    dt = 1e-4
    n = int(1.2 * expected / dt)
    run = simulate(
        blk, dt * np.arange(n), np.zeros(n), dt, theta0=theta0, history=True, settings=TIGHT
    )
    assert run.history is not None and run.impacts >= 1
    theta = run.history.theta
    first_zero = int(np.argmax(theta <= 0.0))
    t_impact = float(run.history.time[first_zero])
    assert t_impact == pytest.approx(expected, rel=1e-3)
    # The lone block's p (paper Eq. 2) would be off by far more than the tolerance.
    assert abs(math.sqrt(3 * G / (4 * radius)) / p_c - 1) > 0.05


@pytest.mark.parametrize("name", list(CASES))
def test_the_linear_global_stiffness_with_loads_is_the_slope_of_the_restoring_moment(
    name: str,
) -> None:
    # dM_r/dθ at 0⁺ (paper Eq. 16, the sign of the global stiffness printed by `rock assess`),
    # against a central difference of the restoring moment at h = 1e-6 rad (truncation
    # O(h²)·M‴ and rounding 1e-16·M/h: 1e-6 relative).
    from rockcli.mechanics import linear_global_stiffness, restoring_moment

    blk = CASES[name]
    step = 1e-6
    for side in (1, -1):
        slope = (restoring_moment(blk, side, step) - restoring_moment(blk, side, -step)) / (
            2 * step
        )
        assert linear_global_stiffness(blk, side) == pytest.approx(slope, rel=1e-6)
