"""The toothed return walls' friction in the time history, against closed forms written here.

The friction (Circolare 7/2019 §C8.7.1.2.1.1, Eq. C8.7.1.2) is a horizontal force F spread
over the toothed height h as q(ζ) = 2F(h − ζ)/h² (its resultant at h/3), each course resisting
while its slide is at most the overlap l. In the equation of motion it is a Coulomb moment
against the sense of the motion; at a standstill the body sticks while the other moments are
within it. Checked here without the engine's own formulas:

- its moment at a rotation a, integrated over the engaged courses by scipy's quad from the
  definition (and equal to the code check's SideFriction.work, the same law on a chain);
- the uplift from rest at α0 = (W·b + F·h/3)/(W·h_G), the Circolare's multiplier with the
  friction, on a ramp (the crossing time exact);
- the energy it dissipates: a body released from a tilt reaches the impact with
  ½·I_O·ω² = W·ΔY_G − ∫ M_F da, every course engaged (closed form) or some let go (quad);
- sticking: released where the weight's moment is within the friction's it stays there; held
  at a tilt, it moves again when üg·H = G ± M_F on a ramp, not before;
- the two engines agree on a record, and a symmetric body's response to −üg is the mirror.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import (
    Friction,
    Restrainer,
    RigidBody,
    friction_moment,
    uplift_accelerations,
)

G = 9.81
B, HG = 0.25, 3.0  # half thickness and centroid height of a 0.5 × 6 m wall [m]
WIDTH = 5.0
GAMMA = 18e3  # [N/m³]
W = GAMMA * 2 * B * 2 * HG * WIDTH  # 270 kN
MASS = W / G
I_G = MASS * ((2 * B) ** 2 + (2 * HG) ** 2) / 12.0
I_O = I_G + MASS * (B * B + HG * HG)
TIGHT = SolverSettings(rtol=1e-12, atol=1e-12, tail=0.0)
ENGINES = (Engine.FAST, Engine.REFERENCE)
RECORDS = Path(__file__).resolve().parents[3] / "shared" / "records"


def wall(force: float, overlap: float = 0.25, height: float = 2 * HG, e: float = 0.9,
         **fields):  # fmt: skip
    """The wall as a rigid body turning about either base edge, the friction's interface at
    mid-thickness (x = b from either pivot), toothed from the base over ``height``."""
    fr = Friction("toothing", force, B, B, 0.0, height, overlap)
    return RigidBody(R=math.hypot(B, HG), alpha=math.atan2(B, HG), mass=MASS, g=G, e=e,
                     shape=(B, B, HG, I_G), frictions=(fr,), **fields)  # fmt: skip


def moment_by_quad(force: float, overlap: float, height: float, a: float) -> float:
    """∫ q(ζ)·(b·sin a + ζ·cos a) dζ over the courses whose slide b(1 − cos a) + ζ sin a is
    at most the overlap: the friction's moment from its definition."""

    def integrand(z: float) -> float:
        slide = B * (1.0 - math.cos(a)) + z * math.sin(a)
        if slide > overlap:
            return 0.0
        return 2.0 * force * (height - z) / height**2 * (B * math.sin(a) + z * math.cos(a))

    top = (
        height
        if a == 0.0
        else min(height, max(0.0, (overlap - B * (1 - math.cos(a))) / math.sin(a)))
    )
    return quad(integrand, 0.0, top, epsabs=0.0, epsrel=1e-13)[0] if top > 0 else 0.0


def still(seconds: float = 2.0, dt: float = 1e-3):
    """A ground at rest."""
    t = np.arange(0.0, seconds + dt / 2, dt)
    return t, np.zeros_like(t), dt


def ramp(rate: float, seconds: float, dt: float = 1e-3):
    """üg = rate·t [g]."""
    t = np.arange(0.0, seconds + dt / 2, dt)
    return t, rate * t, dt


@pytest.mark.parametrize("a", [0.0, 1e-4, 0.01, 0.02, 0.05, 0.2, 0.8])
@pytest.mark.parametrize("overlap", [0.25, 0.06])
def test_moment_is_the_integral_over_the_engaged_courses(a: float, overlap: float) -> None:
    got = friction_moment(40e3, B, 0.0, 2 * HG, overlap, a, math.sin(a), math.cos(a))
    assert got == pytest.approx(moment_by_quad(40e3, overlap, 2 * HG, a), rel=1e-10, abs=1e-6)


def test_moment_at_rest_is_the_force_at_a_third_of_the_height() -> None:
    assert friction_moment(70e3, B, 0.0, 6.0, 0.25, 0.0, 0.0, 1.0) == pytest.approx(70e3 * 2.0)


def test_uplift_is_the_multiplier_with_the_friction() -> None:
    """The issue's façade: two walls of F = 70.1055 kN at h/3 = 2 m, α0 = 0.42953."""
    block = wall(2 * 70.1055e3)
    expected = (W * B + 2 * 70.1055e3 * 2.0) / (W * HG)
    assert expected == pytest.approx(0.42953, abs=1e-5)
    assert uplift_accelerations(block) == pytest.approx((expected, expected), rel=1e-12)


@pytest.mark.parametrize("engine", ENGINES)
def test_uplift_on_a_ramp_at_the_multiplier(engine: Engine) -> None:
    block = wall(2 * 70.1055e3)
    alpha0 = (W * B + 2 * 70.1055e3 * 2.0) / (W * HG)
    t, ag, dt = ramp(0.5, 1.0)
    run = simulate(block, t, ag, dt, settings=TIGHT, engine=engine)
    assert run.t_uplift == pytest.approx(alpha0 / 0.5, abs=1e-9)


def impact_velocity_by_energy(force: float, overlap: float, a0: float) -> float:
    """ω at the impact of the wall released from a0: ½·I_O·ω² = W·(Y_G(a0) − Y_G(0)) −
    ∫₀^a0 M_F(a) da (the friction's work, by quad of its definition)."""
    lift = W * (HG * math.cos(a0) + B * math.sin(a0) - HG)
    work = quad(lambda a: moment_by_quad(force, overlap, 2 * HG, a), 0.0, a0, epsrel=1e-12)[0]
    return math.sqrt(2.0 * (lift - work) / I_O)


@pytest.mark.parametrize("engine", ENGINES)
def test_energy_dissipated_with_every_course_engaged(engine: Engine) -> None:
    """F = 20 kN, l = 0.25: at a0 = 0.02 the top course slides 0.12 m, all engaged, so the
    friction's work is F·(b(1 − cos a0) + h/3·sin a0) in closed form."""
    force, a0 = 20e3, 0.02
    work = force * (B * (1 - math.cos(a0)) + 2.0 * math.sin(a0))
    lift = W * (HG * math.cos(a0) + B * math.sin(a0) - HG)
    expected = math.sqrt(2.0 * (lift - work) / I_O)
    assert expected == pytest.approx(impact_velocity_by_energy(force, 0.25, a0), rel=1e-9)
    t, ag, dt = still()
    run = simulate(wall(force), t, ag, dt, settings=TIGHT, engine=engine, theta0=a0)
    assert run.impacts >= 1
    assert run.max_velocity == pytest.approx(expected, rel=1e-8)
    free = math.sqrt(2.0 * lift / I_O)  # without the friction: faster
    assert run.max_velocity < 0.9 * free


@pytest.mark.parametrize("engine", ENGINES)
def test_energy_dissipated_with_the_top_courses_let_go(engine: Engine) -> None:
    """l = 0.06 m: at a0 = 0.02 the courses above ≈ 3 m have left their teeth."""
    force, overlap, a0 = 30e3, 0.06, 0.02
    t, ag, dt = still()
    block = wall(force, overlap=overlap)
    run = simulate(block, t, ag, dt, settings=TIGHT, engine=engine, theta0=a0)
    expected = impact_velocity_by_energy(force, overlap, a0)
    assert run.max_velocity == pytest.approx(expected, rel=1e-8)


@pytest.mark.parametrize("engine", ENGINES)
def test_released_within_the_friction_it_stays(engine: Engine) -> None:
    """The issue's toothing (F = 140 kN at 2 m) holds the wall at any small tilt: the
    weight's moment W(b cos a − h_G sin a) < 67.5 kN·m is within the friction's ≥ 280."""
    a0 = 0.01
    t, ag, dt = still()
    run = simulate(wall(2 * 70.1055e3), t, ag, dt, settings=TIGHT, engine=engine, theta0=a0,
                   history=True)  # fmt: skip
    assert run.status.value == "completed"
    assert run.impacts == 0
    assert run.theta_max == a0
    assert np.all(run.history.theta == a0)


def held_breakaway(force: float, a_s: float, sense: int) -> float:
    """The ground acceleration [g] that moves the wall held at a_s: üg·H = G + M_F opening
    (sense +1), üg·H = G − M_F closing (−1), H = W·Y_G(a_s), G = W·X_G(a_s)."""
    big_h = W * (HG * math.cos(a_s) + B * math.sin(a_s))
    big_g = W * (B * math.cos(a_s) - HG * math.sin(a_s))
    m_f = moment_by_quad(force, 0.25, 2 * HG, a_s)
    return (big_g + sense * m_f) / big_h


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("sense", [1, -1])
def test_held_at_a_tilt_it_moves_when_the_ground_overcomes_the_friction(
    engine: Engine, sense: int
) -> None:
    force, a_s, rate = 2 * 70.1055e3, 0.01, 0.4
    threshold = held_breakaway(force, a_s, sense)
    t, ag, dt = ramp(sense * rate, 3.0)
    run = simulate(wall(force), t, ag, dt, settings=TIGHT, engine=engine, theta0=a_s,
                   history=True)  # fmt: skip
    t_star = abs(threshold) / rate if threshold * sense > 0 else 0.0
    t, theta = run.history.time, run.history.theta
    assert t_star > 0.5  # held a while
    before = t < t_star - 1e-9
    assert np.all(theta[before] == a_s)
    after = t > t_star + 0.05
    assert np.all(sense * (theta[after][:10] - a_s) > 0.0)


@pytest.mark.parametrize("polarity", [1, -1])
def test_the_engines_agree_on_a_record(polarity: int) -> None:
    path = RECORDS / "ELC180.AT2"
    if not path.is_file():
        pytest.skip(f"the shared records are not beside the project ({path} absent)")
    from rockcli.records.at2 import parse_at2

    rec = parse_at2(path.read_text())
    block = wall(2 * 30e3, overlap=0.1)
    runs = [simulate(block, rec.time[:2500], 2.5 * rec.accel[:2500], rec.dt, polarity=polarity,
                     engine=engine) for engine in ENGINES]  # fmt: skip
    fast, ref = runs
    assert fast.impacts > 0
    assert fast.status == ref.status
    assert fast.theta_max == pytest.approx(ref.theta_max, rel=1e-6, abs=1e-9)
    assert fast.theta_min == pytest.approx(ref.theta_min, rel=1e-6, abs=1e-9)
    assert fast.impacts == ref.impacts


def test_a_symmetric_body_mirrors() -> None:
    t = np.arange(0.0, 4.0, 0.005)
    ag = 0.6 * np.sin(2 * math.pi * 1.5 * t) * np.exp(-0.3 * t)
    block = wall(2 * 30e3, overlap=0.1)
    plus = simulate(block, t, ag, 0.005, settings=TIGHT, history=True)
    minus = simulate(block, t, -ag, 0.005, settings=TIGHT, history=True)
    assert plus.impacts > 0
    assert plus.theta_max == pytest.approx(-minus.theta_min, rel=1e-9)
    np.testing.assert_allclose(plus.history.theta, -minus.history.theta, atol=1e-10)


def top_tie(law: str = "elastic", yield_force: float = math.inf) -> Restrainer:
    """A tie at the wall's top inner corner, K = 5 MN/m (yielding at ``yield_force``)."""
    r, phi = math.hypot(B, 2 * HG), math.atan2(B, 2 * HG)
    if law == "elastic":
        return Restrainer("tie", 5e6, 0.0, r, phi, r, phi)
    return Restrainer("tie", 5e6, 0.0, r, phi, r, phi, law=law, yield_pos=yield_force,
                      yield_neg=yield_force)  # fmt: skip


@pytest.mark.parametrize("engine", ENGINES)
def test_a_yielding_tie_stays_at_its_yield_force_while_the_wall_is_held(engine: Engine) -> None:
    """The wall sticks at a peak while its tie yields (20 kN), then the ground pushes it open
    again: the tie goes on along its plateau, never above its yield force, and both engines
    tell the same story (a review's reproducer: the tie was unloaded at the standstill and
    then carried 35.7 kN)."""
    block = wall(140.211e3, restrainers=(top_tie("elastic-plastic", 20e3),))
    a0 = block.uplifts()[0]
    dt = 0.01
    t = np.arange(0.0, 4.0, dt)
    level = 1.25 * a0
    ag = np.interp(t, [0, 0.5, 1.0, 1.3, 1.6, 2.2, 2.6, 4],
                   [0, level, level, 0.9 * level, 0.9 * level, 1.3 * level, 0, 0])  # fmt: skip
    run = simulate(block, t, ag, dt, engine=engine, settings=SolverSettings(tail=0.0))
    other = simulate(block, t, ag, dt, engine=ENGINES[1 - ENGINES.index(engine)],
                     settings=SolverSettings(tail=0.0))  # fmt: skip
    tie = run.restrainers[0]
    assert tie.max_force <= 20e3 * (1 + 1e-9)
    assert tie.energy_dissipated > 0.0
    assert run.theta_max == pytest.approx(other.theta_max, rel=1e-5)


@pytest.mark.parametrize("one_sided", [False, True])
def test_the_engines_agree_with_a_tie_and_one_sided(one_sided: bool) -> None:
    t = np.arange(0.0, 5.0, 0.005)
    ag = 0.9 * np.sin(2 * math.pi * 1.2 * t) * np.exp(-0.4 * t)
    block = wall(2 * 30e3, overlap=0.1, restrainers=(top_tie(),), one_sided=one_sided)
    fast, ref = (simulate(block, t, ag, 0.005, engine=engine) for engine in ENGINES)
    assert fast.status == ref.status
    assert fast.uplifts > 0
    assert fast.theta_max == pytest.approx(ref.theta_max, rel=1e-6, abs=1e-10)
    assert fast.theta_min == pytest.approx(ref.theta_min, rel=1e-6, abs=1e-10)
    assert fast.restrainers[0].max_force == pytest.approx(ref.restrainers[0].max_force, rel=1e-6)
