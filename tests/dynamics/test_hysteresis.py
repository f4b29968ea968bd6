"""Restrainers with strength in the time history: the elastic-plastic law with memory.

The law (rules.member_force and the state changes beside it; docs/physics.md, "Restrainers
with strength") is checked here against closed forms and conservation written in this file:

- with a yield force too large to reach, every output equals the elastic spring's bit for bit;
- the force never exceeds the yield force (round-off aside), at the peaks and at every sample;
- the energy balance of free rocking from a tilted state: the initial energy equals the final
  kinetic, potential and elastic energy plus the plastic work, the energy released at rupture
  and the impact losses, to 1e-6 relative (tolerances 1e-12), in both engines;
- a slow cycle of the ground: the energy the engine reports dissipated equals the area of the
  force–elongation loop of the sampled history, and the ideal loop's F_y·(u_max − F_y/K);
- a pretension P0 at height z raises the uplift acceleration by statics: (W·b + P0·z)/(W·h);
- a yielded member is slack at rest: the second uplift needs tan α again;
- rupture at the elongation at break and at the anchor's capacity;
- the fast engine and the reference engine (scipy DOP853) agree on a yielding run.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from rockcli.dynamics.result import RockingRun
from rockcli.dynamics.settings import Engine, SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block, Restrainer, spring_elongation

G = 9.81
R_BLOCK = 3.0
ALPHA = 0.1
MASS = 10_000.0  # [kg]
B = R_BLOCK * math.sin(ALPHA)
H = R_BLOCK * math.cos(ALPHA)
W = MASS * G
I0 = 4.0 / 3.0 * MASS * R_BLOCK**2
#: A tie at the top corner: r = 2R, φ = α (paper Eq. 4); z = 2h.
K = 2e6  # [N/m]
#: Tight tolerances for conservation (the engine's floor, rtol = atol = 1e-12).
TIGHT = SolverSettings(rtol=1e-12, atol=1e-12, tail=0.0)
#: The energy balance holds to the integration and event-location error (issue 9: 1e-6).
ENERGY_RTOL = 1e-6
#: The bundled Ricker pulse (examples use it; ships with the repository).
RICKER = Path(__file__).resolve().parents[2] / "records" / "ricker_Tp0.5s_0.5g.txt"


def tie(**law: float | str) -> Restrainer:
    """A restrainer at the top corner acting while θ > 0 only, with the given law fields."""
    return Restrainer(
        "tie",
        K,
        0.0,
        2 * R_BLOCK,
        ALPHA,
        2 * R_BLOCK,
        ALPHA,
        **law,  # type: ignore[arg-type]
    )


def block(*restrainers: Restrainer, e: float = 0.9) -> Block:
    """The test block (R = 3 m, α = 0.1, 10 t) with the given restrainers."""
    return Block(R=R_BLOCK, alpha=ALPHA, mass=MASS, g=G, e=e, restrainers=restrainers)


def ricker() -> tuple[np.ndarray, np.ndarray, float]:
    """(time, accel [g], dt) of the bundled Ricker record (two columns: t, a)."""
    data = np.loadtxt(RICKER, comments="#")
    return data[:, 0], data[:, 1], float(data[1, 0] - data[0, 0])


def free(blk: Block, theta0: float, omega0: float, duration: float, engine=Engine.FAST):
    """Free rocking (no ground motion) from (θ0, θ̇0) for `duration` seconds, history kept."""
    dt = 0.01
    time = np.arange(0.0, duration, dt)
    return simulate(
        blk,
        time,
        np.zeros(time.size),
        dt,
        settings=TIGHT,
        engine=engine,
        history=True,
        theta0=theta0,
        omega0=omega0,
    )


def yield_u(f_yield: float) -> float:
    """Elongation at first yield without pretension [m]."""
    return f_yield / K


# --- bit-identity with the elastic spring --------------------------------------------------


def test_unreachable_yield_is_the_elastic_spring_bit_for_bit() -> None:
    """A yield force of 1e300 N takes the member-law path (COL_MEMORY = 1, levels computed,
    events scanned) but is never reached: every output and the whole history equal the
    elastic spring's exactly (issue 9: "with an infinite yield force the results equal the
    elastic ones bit for bit")."""
    time, accel, dt = ricker()
    both = Restrainer("top", 4e6, 4e6, 2 * R_BLOCK, ALPHA, 2 * R_BLOCK, ALPHA)
    plastic = replace(both, law="elastic-plastic", yield_pos=1e300, yield_neg=1e300)
    assert plastic.has_memory and not both.has_memory
    for pol in (1, -1):
        runs = [
            simulate(block(sp), time, 2.0 * accel, dt, polarity=pol, history=True)
            for sp in (both, plastic)
        ]
        a, b = runs
        assert a.max_ratio > 0.01 and a.restrainers[0].max_force > 0.0  # it rocks, springs work
        assert replace(a, history=None) == replace(b, history=None)
        for name in ("time", "theta", "omega", "forces"):
            np.testing.assert_array_equal(getattr(a.history, name), getattr(b.history, name))


# --- the yield force bounds the force --------------------------------------------------------


def test_force_never_exceeds_the_yield_force() -> None:
    """On a record that stretches the tie far past yield, the peak force and every sampled
    force stay at or below F_y (1e-12 relative: the force is F_y exactly on the plateau and
    K·(u − c) ≤ F_y in the elastic range, up to the rounding of c)."""
    time, accel, dt = ricker()
    f_yield = 30e3
    sp = tie(law="elastic-plastic", yield_pos=f_yield, yield_neg=f_yield)
    for pol in (1, -1):
        run = simulate(block(sp), time, 2.0 * accel, dt, polarity=pol, history=True)
        peak = run.restrainers[0]
        if pol == 1:
            assert peak.yielded and peak.plastic_elongation > 0.0
        assert peak.max_force <= f_yield * (1 + 1e-12)
        assert run.history is not None
        assert np.max(run.history.forces) <= f_yield * (1 + 1e-12)
        assert np.min(run.history.forces) >= 0.0  # a tie cannot push


# --- the energy balance ----------------------------------------------------------------------


def potential(a: float) -> float:
    """Potential energy of the tilted free block about its pivot [J]: m g R [cos(α − a) − cos α]
    (the centre of mass rises; paper Eq. 1 integrated)."""
    return W * R_BLOCK * (math.cos(ALPHA - a) - math.cos(ALPHA))


def elastic_energy(sp: Restrainer, a: float, c: float, side_active: bool) -> float:
    """Elastic energy stored in the one-sided member [J]: ½K(u − c)² above its slack point
    (u = 0 while the block rocks on the other pivot)."""
    u = spring_elongation(sp.r_pos, sp.phi_pos, a) if side_active else 0.0
    return 0.5 * K * (u - c) ** 2 if u > c else 0.0


def energy_terms(sp: Restrainer, run: RockingRun, theta0: float, omega0: float) -> dict:
    """The terms of the balance: initial energy, and final kinetic + potential + elastic,
    plastic work (with rupture release) and impact losses [J]."""
    assert run.history is not None
    c0 = -sp.pretension / K
    peak = run.restrainers[0]
    c_end = c0 + peak.plastic_elongation
    th, om = float(run.history.theta[-1]), float(run.history.omega[-1])
    alive = not peak.ruptured
    initial = 0.5 * I0 * omega0**2 + potential(theta0) + elastic_energy(sp, theta0, c0, True)
    final = 0.5 * I0 * om**2 + potential(abs(th))
    if alive:
        final += elastic_energy(sp, abs(th), c_end, th > 0)
    return {
        "initial": initial,
        "final": final,
        "dissipated": peak.energy_dissipated,
        "impacts": run.impact_loss,
    }


@pytest.mark.parametrize(
    ("law", "theta0", "omega0"),
    [
        # 3750 J of kinetic energy; the tie yields at u = 10 mm
        ({"law": "elastic-plastic", "yield_pos": 20e3, "yield_neg": 20e3}, 0.0, 0.25),
        # tilted 0.5 mrad (u = 3 mm, below the yield at c0 + F_y/K = 6 mm)
        (
            {"law": "elastic-plastic", "yield_pos": 20e3, "yield_neg": 20e3, "pretension": 8e3},
            0.0005,
            0.3,
        ),
        # 1734 J: the tie takes 700 J to its rupture at 40 mm, 1034 J < 1470 J to overturn
        (
            {"law": "elastic-plastic", "yield_pos": 20e3, "yield_neg": 20e3, "fails_at": 0.04},
            0,
            0.17,
        ),
        # 600 J: 150 J stored when the anchor gives way at 25 kN
        ({"rupture_force": 25e3, "pretension": 5e3}, 0.0, 0.1),
    ],
    ids=["yield", "pretension", "rupture-elongation", "anchor-rupture"],
)
@pytest.mark.parametrize("engine", [Engine.FAST, Engine.REFERENCE])
def test_energy_balance_of_free_rocking(law: dict, theta0: float, omega0: float, engine) -> None:
    """Initial energy = final kinetic + potential + elastic + dissipated + impact losses, to
    ENERGY_RTOL of the initial energy (issue 9's invariant; no ground motion: no input)."""
    sp = tie(**law)
    run = free(block(sp, e=0.9), theta0, omega0, 6.0, engine)
    terms = energy_terms(sp, run, theta0, omega0)
    peak = run.restrainers[0]
    assert peak.yielded or peak.ruptured  # the law acted
    assert terms["dissipated"] > 0.0 and terms["impacts"] > 0.0
    balance = terms["final"] + terms["dissipated"] + terms["impacts"]
    assert balance == pytest.approx(terms["initial"], rel=ENERGY_RTOL)


# --- a slow cycle: the loop area -------------------------------------------------------------


def test_slow_cycle_reproduces_the_elastic_plastic_loop() -> None:
    """A slow half-sine of the ground (40 s, peak 0.5 g) tilts the block quasi-statically
    against an elastic spring and a yielding tie in parallel (the elastic spring keeps the
    stiffness positive past yield: a rocking block alone would run away on the plateau),
    stretches the tie past yield and releases it.

    The energy the engine reports dissipated equals the ideal elastic–perfectly plastic loop
    F_y·(u_max − F_y/K) (closed form: a tension member's slack point ends at u_max − F_y/K
    whatever the small cycles; 1e-9 relative, the event location's accuracy) and the area
    ∮F du of the sampled force–elongation history (trapezoids over 1 ms samples, the loop
    closed at F = 0: 1e-3 relative).
    """
    dt = 0.001
    time = np.arange(0.0, 40.0 + dt / 2, dt)
    accel = 0.5 * np.sin(math.pi * time / 40.0)
    f_yield = 5e3
    sp = tie(law="elastic-plastic", yield_pos=f_yield, yield_neg=f_yield)
    spring = replace(tie(), name="spring")
    run = simulate(block(sp, spring, e=0.9), time, accel, dt, settings=TIGHT, history=True)
    peak = run.restrainers[0]
    assert peak.yielded and run.status.value == "completed"
    assert peak.plastic_elongation > f_yield / K  # a loop, not a corner
    hist = run.history
    assert hist is not None
    u = np.array([spring_elongation(2 * R_BLOCK, ALPHA, max(t, 0.0)) for t in hist.theta])
    force = hist.forces[0]
    assert force[-1] == 0.0  # slack at the end: the loop is closed
    loop = float(np.sum(0.5 * (force[1:] + force[:-1]) * np.diff(u)))
    ideal = f_yield * (peak.max_displacement - f_yield / K)
    assert peak.energy_dissipated == pytest.approx(ideal, rel=1e-9)
    assert loop == pytest.approx(peak.energy_dissipated, rel=1e-3)


# --- pretension and slack at rest ------------------------------------------------------------


def ramp_uplift(blk: Block, slope: float = 0.05) -> float:
    """Ground acceleration [g] at the first uplift on a ramp a(t) = slope·t (exact crossing:
    the ground is linear between samples)."""
    dt = 0.01
    time = np.arange(0.0, 20.0, dt)
    run = simulate(blk, time, slope * time, dt, settings=SolverSettings(tail=0.0))
    assert run.t_uplift is not None
    return slope * run.t_uplift


def test_pretension_raises_the_uplift_acceleration_as_statics_says() -> None:
    """Moment equilibrium about the pivot at θ = 0 with the tie pulling P0 at z = 2h:
    üg·W·h = W·b + P0·z ⇒ üg = (W·b + P0·2h)/(W·h) (issue 9's closed form). 1e-12 relative:
    the crossing on a linear ramp is exact up to rounding."""
    p0 = 6e3
    sp = tie(law="elastic-plastic", yield_pos=50e3, yield_neg=50e3, pretension=p0)
    expected = (W * B + p0 * 2 * H) / (W * H)
    assert ramp_uplift(block(sp)) == pytest.approx(expected, rel=1e-12)
    assert ramp_uplift(block(tie())) == pytest.approx(math.tan(ALPHA), rel=1e-12)


def test_a_member_stretched_past_yield_is_slack_at_rest() -> None:
    """After a free rocking that yields the pretensioned tie beyond its pretension's stretch,
    the member is slack at rest (plastic elongation > P0/K): the force at the end is zero."""
    p0 = 6e3
    sp = tie(law="elastic-plastic", yield_pos=20e3, yield_neg=20e3, pretension=p0)
    run = free(block(sp, e=0.8), 0.0, 0.4, 8.0)
    peak = run.restrainers[0]
    assert peak.plastic_elongation > p0 / K
    assert run.history is not None and run.history.forces[0, -1] == 0.0


# --- rupture ---------------------------------------------------------------------------------


def test_anchor_rupture_loses_the_member_at_its_capacity() -> None:
    """An elastic tie with an anchor capacity of 25 kN is lost when its force reaches it: the
    peak force is the capacity (1e-9: the event's location) and the loss time is kept."""
    sp = tie(rupture_force=25e3)
    run = free(block(sp), 0.0, 0.4, 3.0)
    peak = run.restrainers[0]
    assert peak.ruptured and not peak.yielded
    assert peak.max_force == pytest.approx(25e3, rel=1e-9)


def test_a_yield_below_the_anchor_capacity_yields_instead() -> None:
    """With F_y < anchor capacity the member yields and the anchor never sees more than F_y."""
    sp = tie(law="elastic-plastic", yield_pos=20e3, yield_neg=20e3, rupture_force=25e3)
    run = free(block(sp), 0.0, 0.4, 3.0)
    peak = run.restrainers[0]
    assert peak.yielded and not peak.ruptured
    assert peak.max_force == pytest.approx(20e3, rel=1e-12)


# --- the two engines -------------------------------------------------------------------------


def test_fast_and_reference_engines_agree_on_a_yielding_run() -> None:
    """The compiled DP5 engine (rtol 1e-10) and scipy's DOP853 (the reference's 1e-12) on a
    record that yields the tie: peak ratio, first yield time and plastic elongation agree to
    1e-6 relative (the fast engine's tolerance, amplified by the impacts' sensitivity)."""
    time, accel, dt = ricker()
    sp = tie(law="elastic-plastic", yield_pos=30e3, yield_neg=30e3, pretension=3e3)
    settings = SolverSettings(rtol=1e-10, atol=1e-10)
    fast, ref = (
        simulate(block(sp), time, 2.0 * accel, dt, settings=settings, engine=engine)
        for engine in (Engine.FAST, Engine.REFERENCE)
    )
    assert fast.restrainers[0].yielded
    assert fast.max_ratio == pytest.approx(ref.max_ratio, rel=1e-6)
    a, b = fast.restrainers[0], ref.restrainers[0]
    assert a.t_yield == pytest.approx(b.t_yield, rel=1e-9)
    assert a.plastic_elongation == pytest.approx(b.plastic_elongation, rel=1e-6)
    assert a.energy_dissipated == pytest.approx(b.energy_dissipated, rel=1e-6)
