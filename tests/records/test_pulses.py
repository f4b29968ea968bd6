"""Synthetic pulses against their closed forms.

Sources: Makris & Roussos 2000 (one-sine type A ap·sin(ωp t), one-cosine type B ap·cos(ωp t),
0 ≤ t ≤ 2π/ωp), Housner 1963 (rectangular and half-sine pulses), Ricker 1943 (wavelet
ap(1 − 2π²fp²τ²)exp(−π²fp²τ²)). Times are chosen on the sample grid, so the peaks and zeros
are compared to the rounding of sin/cos (ROUND) unless another tolerance is given.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from rockcli.errors import InputError
from rockcli.records.pulses import RICKER_HALF_WIDTH, make_pulse

AP, TP, DT = 0.25, 0.4, 0.001
#: Rounding of sin/cos at a multiple of π/2 computed as ωp·t in floating point.
ROUND = 1e-12


def sample(record_time: np.ndarray, accel: np.ndarray, t: float) -> float:
    """The acceleration at the grid time nearest t."""
    return float(accel[int(np.argmin(np.abs(record_time - t)))])


def test_one_sine_closed_form() -> None:
    """Type A: zero at 0, Tp/2, Tp; +ap at Tp/4; −ap at 3Tp/4; lasts Tp."""
    rec = make_pulse("one-sine", AP, TP, dt=DT)
    assert (rec.format, rec.source, rec.unit) == ("pulse", "generated", "g")
    assert rec.duration == pytest.approx(TP, abs=ROUND)
    for t, expected in [(0, 0), (TP / 4, AP), (TP / 2, 0), (3 * TP / 4, -AP), (TP, 0)]:
        assert sample(rec.time, rec.accel, t) == pytest.approx(expected, abs=ROUND)
    assert rec.pga == pytest.approx(AP, abs=ROUND)


def test_one_sine_integral_is_zero() -> None:
    """∫0^Tp ap sin(ωp t) dt = 0; the trapezoid rule is exact for a full sine period."""
    rec = make_pulse("one-sine", AP, TP, dt=DT)
    assert np.trapezoid(rec.accel, rec.time) == pytest.approx(0.0, abs=ROUND)


def test_one_cosine_closed_form() -> None:
    """Type B: +ap at 0 and Tp, −ap at Tp/2, zeros at Tp/4 and 3Tp/4; integral 0."""
    rec = make_pulse("one-cosine", AP, TP, dt=DT)
    for t, expected in [(0, AP), (TP / 4, 0), (TP / 2, -AP), (3 * TP / 4, 0), (TP, AP)]:
        assert sample(rec.time, rec.accel, t) == pytest.approx(expected, abs=ROUND)
    assert np.trapezoid(rec.accel, rec.time) == pytest.approx(0.0, abs=ROUND)


def test_half_sine_closed_form() -> None:
    """Housner's half-cycle: lasts Tp/2, peak ap at Tp/4, ∫ = ap·Tp/π.

    The trapezoid rule on sin over [0, π] with step h = ωp·dt errs by h²/12 (relative):
    (2π·0.001/0.4)²/12 = 2.1e-5, so the integral is compared to 3e-5.
    """
    rec = make_pulse("half-sine", AP, TP, dt=DT)
    assert rec.duration == pytest.approx(TP / 2, abs=ROUND)
    assert sample(rec.time, rec.accel, TP / 4) == pytest.approx(AP, abs=ROUND)
    assert rec.accel.min() >= -ROUND  # one lobe: sin ≥ 0 on [0, π]
    assert np.trapezoid(rec.accel, rec.time) == pytest.approx(AP * TP / math.pi, rel=3e-5)


def test_rectangular_closed_form() -> None:
    """Housner 1963: ap for 0 ≤ t < td, then 0; td/dt samples at ap, ∑a·dt = ap·td."""
    rec = make_pulse("rectangular", AP, TP, dt=DT)
    at_peak = np.flatnonzero(rec.accel == AP)
    assert at_peak.size == round(TP / DT)
    assert at_peak[0] == 0 and rec.accel[-1] == 0.0
    assert rec.accel.sum() * DT == pytest.approx(AP * TP, rel=ROUND)


def test_ricker_closed_form() -> None:
    """Peak ap at tc = 1.5 Tp; zeros at tc ± Tp/(π√2); troughs −2ap·e^(−3/2) at tc ± √1.5·Tp/π."""
    rec = make_pulse("ricker", AP, TP, dt=DT)
    centre = RICKER_HALF_WIDTH * TP
    assert rec.t_pga == pytest.approx(centre, abs=DT / 2)
    assert rec.pga == pytest.approx(AP, abs=ROUND)
    zero = TP / (math.pi * math.sqrt(2.0))
    crossings = rec.time[:-1][np.diff(np.sign(rec.accel)) != 0]
    assert crossings == pytest.approx([centre - zero, centre + zero], abs=DT)
    assert rec.accel.min() == pytest.approx(-2 * AP * math.exp(-1.5), rel=1e-5)
    # Zero mean (Ricker 1943); the truncated tails beyond ±1.5 Tp are below 1e-8·ap.
    assert np.trapezoid(rec.accel, rec.time) == pytest.approx(0.0, abs=1e-8 * AP * TP)


def test_total_duration_pads_with_zeros() -> None:
    rec = make_pulse("one-sine", AP, TP, dt=DT, total=2.0)
    assert rec.npts == round(2.0 / DT) + 1
    assert rec.duration == pytest.approx(2.0, abs=ROUND)
    assert not rec.accel[rec.time > TP + DT / 2].any()


@pytest.mark.parametrize(
    ("kind", "kwargs", "where"),
    [
        ("one-sine", {"amplitude": 0.0}, "amplitude"),
        ("one-sine", {"period": -1.0}, "period"),
        ("rectangular", {"period": 0.0}, "period"),
        ("ricker", {"dt": 0.0}, "dt"),
        ("half-sine", {"dt": 0.05}, "dt"),
        ("one-cosine", {"total": 0.2}, "duration"),
        ("triangle", {}, "kind"),
    ],
)
def test_bad_pulse_arguments(kind: str, kwargs: dict[str, float], where: str) -> None:
    args = {"amplitude": AP, "period": TP, "dt": DT} | kwargs
    with pytest.raises(InputError) as caught:
        make_pulse(kind, args["amplitude"], args["period"], dt=args["dt"], total=args.get("total"))
    assert caught.value.where == where
