"""Metamorphic properties of the rocking engine (hypothesis).

Source: spec/rocking.md, "Closed forms for tests", metamorphic relations, and spec/style.md
("hypothesis property tests (polarity mirror, size scaling, ... energy never grows across an
impact)"):

- polarity mirror: a symmetric block (two-sided, k_pos = k_neg, same r and φ on both pivots)
  gives θ[−üg](t) = −θ[üg](t). The equation is odd in (θ, üg) and the engine holds the side
  s = ±1 as a mode, so every operation of the mirrored run is the exact IEEE negation of the
  original one: the comparison is exact, even for chattering records;
- size scaling: R → λR divides p² by λ; with the record's time axis (and the free tail)
  stretched by √λ the dimensionless equation in τ = p·t is unchanged, so max θ/α is the same and
  every time scales by √λ (no springs: a spring adds K/I0, which does not scale this way). The
  rest threshold is a velocity [rad/s], so it is scaled by 1/√λ too; atol is not (it mixes rad
  and rad/s), which leaves differences at the integration-error level (rtol = 1e-8): 1e-6;
- zeros prepended to a record only shift the response in time: the same peaks (1e-6: the
  times of the steps differ by rounding) and t_uplift shifted by the zeros' duration (1e-9 s);
- energy never grows: in free rocking ½θ̇² + p²[cos(α − |θ|) − cos α] (linearized
  ½θ̇² + ½p²[α² − (α − |θ|)²]) is conserved between impacts and multiplied by e² ≤ 1 (one-sided
  (r_f·e)² ≤ 1) at each impact; the rest rule only removes energy. Checked at every history
  sample against its predecessor, to 1e-6 of the initial energy (integration error).

Records for the scaling and shifting relations are sine pulses (1–4 half cycles, 1.05–4 tan α):
robust responses, as spec/engine.md ("Sensitivity") asks for single-case comparisons; the
mirror is exact and is also tried on band-limited noise.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block, Restrainer, housner_restitution

#: Few examples: each draws whole time histories (spec: keep the suite fast).
EXAMPLES = settings(max_examples=25, deadline=None)
#: Integration-error level of comparisons between runs that differ by rounding (module doc).
RUN_RTOL = 1e-6
#: Exact-time relations (linear interpolation of the uplift crossing): rounding only [s].
TIME_ATOL = 1e-9
#: Free tail in units of 1/p (spec/engine.md: free time ≥ 10–20/p).
TAIL_OVER_P = 20.0

alphas = st.floats(0.05, 0.35)
sizes = st.floats(0.3, 5.0)


def housner_block(R: float, alpha: float, **kwargs: object) -> Block:
    return Block(R=R, alpha=alpha, e=housner_restitution(alpha), **kwargs)  # type: ignore[arg-type]


@st.composite
def sine_pulses(draw, block: Block):  # type: ignore[no-untyped-def]
    """(time, accel, dt): 1–4 half cycles of a sine at ω = (0.5–8)·p, amplitude ±(1.05–4)·tan α."""
    omega = draw(st.floats(0.5, 8.0)) * block.p
    half_cycles = draw(st.integers(1, 4))
    amplitude = draw(st.floats(1.05, 4.0)) * math.tan(block.alpha) * draw(st.sampled_from([-1, 1]))
    dt = half_cycles * math.pi / omega / 200
    time = np.arange(201) * dt
    return time, amplitude * np.sin(omega * time), dt


def noise(seed: int, alpha: float, scale: float, n: int = 1000) -> tuple[np.ndarray, np.ndarray, float]:
    """Band-limited noise (8-sample moving average) with peak scale·tan α, dt = 0.01 s."""
    rng = np.random.default_rng(seed)
    accel = np.convolve(rng.normal(size=n), np.ones(8) / 8, mode="same")
    accel *= scale * math.tan(alpha) / np.abs(accel).max()
    return np.arange(n) * 0.01, accel, 0.01


# --- polarity mirror -------------------------------------------------------------------------


def assert_mirrored(run, mirror) -> None:  # type: ignore[no-untyped-def]
    """`mirror` is the exact mirror image of `run` (module doc: exact, not approximate)."""
    assert mirror.status is run.status
    assert mirror.theta_max == -run.theta_min
    assert mirror.theta_min == -run.theta_max
    assert mirror.max_ratio == run.max_ratio
    assert mirror.max_velocity == run.max_velocity
    assert (mirror.t_uplift, mirror.t_overturn, mirror.t_end) == (run.t_uplift, run.t_overturn, run.t_end)
    assert (mirror.impacts, mirror.uplifts) == (run.impacts, run.uplifts)
    assert mirror.restrainers == run.restrainers


@EXAMPLES
@given(R=sizes, alpha=alphas, seed=st.integers(0, 2**32 - 1), scale=st.floats(0.5, 3.0),
       spring=st.booleans())
def test_polarity_mirror_on_noise(R: float, alpha: float, seed: int, scale: float, spring: bool) -> None:
    """θ[−üg] = −θ[üg] for a symmetric block, with or without a symmetric top spring."""
    springs = (Restrainer("top", 1e5, 1e5, 2 * R, alpha, 2 * R, alpha),) if spring else ()
    block = housner_block(R, alpha, mass=1000.0, restrainers=springs)
    time, accel, dt = noise(seed, alpha, scale)
    run = simulate(block, time, accel, dt)
    assert_mirrored(run, simulate(block, time, -accel, dt))
    # polarity = −1 is the record reversed in sign: the very same run as −üg.
    assert_mirrored(run, simulate(block, time, accel, dt, polarity=-1))


@EXAMPLES
@given(data=st.data(), R=sizes, alpha=alphas, linearized=st.booleans())
def test_polarity_mirror_on_pulses(data, R: float, alpha: float, linearized: bool) -> None:  # type: ignore[no-untyped-def]
    block = housner_block(R, alpha, linearized=linearized)
    time, accel, dt = data.draw(sine_pulses(block))
    assert_mirrored(simulate(block, time, accel, dt), simulate(block, time, -accel, dt))


# --- size scaling ----------------------------------------------------------------------------


@EXAMPLES
@given(data=st.data(), R=sizes, alpha=alphas, lam=st.floats(0.25, 4.0))
def test_size_scaling(data, R: float, alpha: float, lam: float) -> None:  # type: ignore[no-untyped-def]
    """R → λR with the time axis × √λ: the same max θ/α, every time × √λ."""
    block = housner_block(R, alpha)
    big = housner_block(lam * R, alpha)
    time, accel, dt = data.draw(sine_pulses(block))
    stretch = math.sqrt(lam)
    tail = TAIL_OVER_P / block.p
    run = simulate(block, time, accel, dt, settings=SolverSettings(tail=tail))
    scaled_settings = SolverSettings(tail=tail * stretch, rest_velocity=SolverSettings().rest_velocity / stretch)
    scaled = simulate(big, time * stretch, accel, dt * stretch, settings=scaled_settings)
    assert scaled.overturned == run.overturned
    assert run.t_uplift is not None and scaled.t_uplift is not None  # 1.05 tan α or more
    assert scaled.t_uplift == _approx(run.t_uplift * stretch, abs=TIME_ATOL * stretch)
    if run.overturned:
        assert scaled.t_overturn == _approx(run.t_overturn * stretch, rel=RUN_RTOL)
    else:
        assert scaled.max_ratio == _approx(run.max_ratio, rel=RUN_RTOL)


# --- zeros prepended -------------------------------------------------------------------------


@EXAMPLES
@given(data=st.data(), R=sizes, alpha=alphas, n_zeros=st.integers(1, 500))
def test_prepended_zeros_only_shift_the_response(data, R: float, alpha: float, n_zeros: int) -> None:  # type: ignore[no-untyped-def]
    block = housner_block(R, alpha)
    time, accel, dt = data.draw(sine_pulses(block))
    tail = SolverSettings(tail=TAIL_OVER_P / block.p)
    run = simulate(block, time, accel, dt, settings=tail)
    padded_time = np.arange(time.size + n_zeros) * dt
    padded = simulate(block, padded_time, np.concatenate([np.zeros(n_zeros), accel]), dt, settings=tail)
    shift = n_zeros * dt
    assert padded.overturned == run.overturned
    assert run.t_uplift is not None and padded.t_uplift is not None
    assert padded.t_uplift == _approx(run.t_uplift + shift, abs=TIME_ATOL)
    if run.overturned:
        assert padded.t_overturn == _approx(run.t_overturn + shift, rel=RUN_RTOL)
    else:
        assert padded.max_ratio == _approx(run.max_ratio, rel=RUN_RTOL)
        assert padded.theta_max == _approx(run.theta_max, rel=RUN_RTOL, abs=1e-12)
        assert padded.theta_min == _approx(run.theta_min, rel=RUN_RTOL, abs=1e-12)


# --- energy ----------------------------------------------------------------------------------


def rocking_energy(block: Block, theta: np.ndarray, omega: np.ndarray) -> np.ndarray:
    """Mechanical energy per unit I0 above rest [rad²/s²] (module doc)."""
    a = np.abs(theta)
    if block.linearized:
        potential = 0.5 * block.p2 * (block.alpha**2 - (block.alpha - a) ** 2)
    else:
        potential = block.p2 * (np.cos(block.alpha - a) - math.cos(block.alpha))
    return 0.5 * omega**2 + potential


@EXAMPLES
@given(
    R=sizes, alpha=alphas, phi0=st.floats(0.05, 0.9), speed=st.floats(-1.0, 1.0),
    e=st.floats(0.0, 1.0), linearized=st.booleans(), one_sided=st.booleans(),
    rebound=st.floats(0.0, 1.0),
)
def test_energy_never_grows_in_free_rocking(
    R: float, alpha: float, phi0: float, speed: float, e: float, linearized: bool,
    one_sided: bool, rebound: float,
) -> None:
    """From θ0 = φ0·α with θ̇0 = speed × the speed that would just reach α: E(t) never grows."""
    block = Block(R=R, alpha=alpha, e=e, linearized=linearized, one_sided=one_sided, rebound=rebound)
    theta0 = phi0 * alpha
    # θ̇0 bounded so that E0 stays below the energy at θ = α: the block cannot overturn.
    reach = rocking_energy(block, np.array([alpha]), np.zeros(1))[0]
    start = rocking_energy(block, np.array([theta0]), np.zeros(1))[0]
    omega0 = speed * math.sqrt(2.0 * max(reach - start, 0.0)) * 0.99
    run = simulate(
        block, np.array([0.0, 0.005]), np.zeros(2), 0.005, theta0=theta0, omega0=omega0,
        settings=SolverSettings(tail=10.0), history=True,
    )
    assert not run.overturned
    assert run.history is not None
    energy = rocking_energy(block, run.history.theta, run.history.omega)
    e0 = energy[0]
    assert e0 == _approx(rocking_energy(block, np.array([theta0]), np.array([omega0]))[0], rel=1e-12)
    assert np.all(np.diff(energy) <= RUN_RTOL * e0), "energy grew between two samples"
    assert energy.max() <= e0 * (1 + RUN_RTOL)


def _approx(expected: float | None, **tolerance: float):  # type: ignore[no-untyped-def]
    """pytest.approx, imported late so that this module reads as the relations it tests."""
    import pytest

    return pytest.approx(expected, **tolerance)
