"""Lognormal fragility functions fitted to collapse intensities (IDA) or to counts of
exceedances at intensity levels (MSA), and their confidence bands.

P(DS reached | IM = x) = Φ(ln(x/θ)/β), with θ the median intensity and β the dispersion
(Baker 2015, "Efficient analytical fragility function fitting using dynamic structural
analysis", Earthquake Spectra 31(1):579–599, the lognormal fragility function).

- IDA: each record gives the intensity at which the damage state is first reached. The fit
  is the lognormal's maximum likelihood: ln θ = mean of ln IM_i and β² = the mean of
  (ln IM_i − ln θ)², dividing by n (``BETA_DDOF = 0``), as ``scipy.stats.lognorm.fit`` with
  its location at 0 does. Baker (2015) writes β with n − 1 (the unbiased variance of ln IM);
  :func:`ida_fit` gives that one with ``ddof=1``.
- IDA with records that do not reach the damage state by the end of their scan: those are
  right-censored at the scan's end c_k (the state lies above it), and θ, β maximise the
  censored log-likelihood Σ_i ln[φ(u_i)/(β x_i)] + Σ_k ln[1 − Φ(u_k)], u = (ln x − ln θ)/β
  (the lognormal with right-censored observations; scipy.stats.CensoredData with
  lognorm.fit gives the same). Without censored records it is the maximum likelihood above.
- MSA: at each intensity level x_j, z_j of n_j runs reach the damage state; θ and β
  maximise the binomial likelihood Σ_j [z_j ln p_j + (n_j − z_j) ln(1 − p_j)],
  p_j = Φ(ln(x_j/θ)/β) (Baker 2015, the maximum-likelihood fit to MSA data).

The bands are CONFIDENCE (95 %) intervals of P at each intensity, chosen to hold the true P
that often with a handful of records (tests/fragility/test_band_coverage.py): MSA, the
profile likelihood (:func:`msa_band`); IDA, the exact noncentral-t band (:func:`ida_band`),
or with censored records a parametric bootstrap read through the lognormal's pivots
(:func:`ida_censored_band`). :func:`band_method` names each in words.

Every likelihood is maximised in log space by Newton's method with bounded work
(rockcli/studies/fragility/likelihood.py), so a fit and its band end in seconds whatever the data:
intensities of 1e-300 and 1e4 alike, counts of a million runs. A level repeated in MSA data is
one stripe (the binomial likelihood is the same: its runs and exceedances add up).

Pure and silent: numpy and scipy; a data set that defines no fit is a ValueError that says why
(all runs or none exceed; the counts do not rise with the intensity; they jump from none to
all, whose likelihood is greatest for a step, β → 0; a fitted median beyond floating point).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import special

from rockcli.studies.fragility.likelihood import (
    NEWTON_TOLERANCE,
    CensoredSets,
    censored_fit,
    has_maximum,
    probit_fit,
    probit_terms,
    standardize,
)

#: The divisor of β² in an IDA fit: n (maximum likelihood), not n − 1.
BETA_DDOF = 0
#: Resamples of the censored IDA band's parametric bootstrap, and every band's two-sided level.
BOOTSTRAP_SAMPLES = 1000
CONFIDENCE = 0.95
#: |ln θ| and |ln β| beyond which a fitted value is not a double (e^708 ≈ 3e307).
LOG_LIMIT = 708.0
#: The most intensities :func:`band_points` gives a band at; for MSA, also at most BAND_WORK
#: divided by the stripes (the profile likelihood's every step costs band intensities ×
#: stripes: 10 000 distinct levels get 10 intensities and take about a second), but never
#: fewer than MIN_BAND_POINTS.
BAND_POINTS = 100
BAND_WORK = 100_000
MIN_BAND_POINTS = 10
#: Elements (intensities × stripes, or resamples × records) a band computes at once: its
#: arrays stay near 2 MB each whatever the data's size.
CHUNK_ELEMENTS = 1 << 18


@dataclass(frozen=True)
class Fit:
    """A lognormal fragility function: median θ (the intensity's unit), dispersion β (-),
    the divisor of β² for an IDA fit (``beta_ddof``; None for a likelihood fit), the data's
    size (records for IDA, runs for MSA)."""

    median: float
    beta: float
    beta_ddof: int | None
    n: int

    def probability(self, im: np.ndarray | float) -> np.ndarray:
        """P(damage state reached | IM = im) = Φ(ln(im/θ)/β)."""
        x = np.asarray(im, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.asarray(special.ndtr((np.log(x) - math.log(self.median)) / self.beta))


def _lognormal(ln_theta: float, beta: float, ddof: int | None, n: int) -> Fit:
    """The Fit of ln θ and β, or a ValueError where either is beyond floating point."""
    if not (abs(ln_theta) <= LOG_LIMIT and 0.0 < beta and abs(math.log(beta)) <= LOG_LIMIT):
        raise ValueError(
            "the fitted median or dispersion lies beyond floating point (the data hardly "
            "rise with the intensity)"
        )
    return Fit(math.exp(ln_theta), beta, ddof, n)


def _positive(values: np.ndarray, what: str) -> np.ndarray:
    """``values`` as floats, each finite and > 0 (a ValueError naming ``what`` otherwise)."""
    x = np.asarray(values, dtype=float)
    if not (np.all(np.isfinite(x)) and np.all(x > 0.0)):
        raise ValueError(f"{what} must be finite and > 0")
    return x


def ida_fit(im: np.ndarray, ddof: int = BETA_DDOF) -> Fit:
    """The lognormal fit of collapse intensities (IDA): ln θ = mean(ln im), β = the standard
    deviation of ln im with divisor n − ddof (module docstring)."""
    x = np.asarray(im, dtype=float)
    if x.size < 2 or not np.all(np.isfinite(x)) or np.any(x <= 0.0):
        raise ValueError("an IDA fit needs two or more finite collapse intensities > 0")
    logs = np.log(x)
    beta = float(np.std(logs, ddof=ddof))
    if not beta > 0.0:
        raise ValueError("the collapse intensities are all equal: no dispersion to fit")
    return _lognormal(float(np.mean(logs)), beta, ddof, int(x.size))


def ida_censored_fit(
    im: np.ndarray, censored: np.ndarray, tolerance: float = NEWTON_TOLERANCE
) -> Fit:
    """The maximum-likelihood lognormal of collapse intensities ``im`` and of records
    right-censored at ``censored`` (each the intensity below which such a record was seen
    not to reach the state; module docstring), by Newton's method to ``tolerance``
    (rockcli.studies.fragility.likelihood.censored_fit). Without censored records: ida_fit with ddof
    0, in closed form."""
    c = np.asarray(censored, dtype=float)
    if c.size == 0:
        return ida_fit(im, 0)
    x = _positive(im, "collapse intensities")
    m, s, a, b = _censored_search(np.log(x), np.log(_positive(c, "censoring intensities")),
                                  tolerance)  # fmt: skip
    return _lognormal(m + s * a / b, s / b, 0, int(x.size + c.size))


def _censored_search(
    logs: np.ndarray, censored_logs: np.ndarray, tolerance: float = NEWTON_TOLERANCE
) -> tuple[float, float, float, float]:
    """(m, s, a, b) of the censored maximum likelihood: the standardization of the records'
    logs and the probit's intercept and slope on it (rockcli.studies.fragility.likelihood)."""
    every = np.concatenate([logs, censored_logs])
    m, s = standardize(every)
    y = ((every - m) / s)[None, :]
    reached = (np.arange(every.size) < logs.size)[None, :]
    if not has_maximum(y, reached)[0]:
        raise ValueError(
            "the records define no fit: it needs two or more distinct collapse intensities, "
            "or one below a censored record's intensity"
        )
    found = y[reached]
    mean, spread = float(found.mean()), float(found.std())
    b0 = 1.0 / spread if spread > 0.0 else 1.0
    a, b, done = censored_fit(CensoredSets.of(y, reached), np.array([mean * b0]),
                              np.array([b0]), tolerance)  # fmt: skip
    if not done[0]:
        raise ValueError("the censored likelihood's search did not settle")
    return m, s, float(a[0]), float(b[0])


def msa_stripes(
    im: np.ndarray, runs: np.ndarray, exceedances: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The MSA data checked, one stripe a level (a level repeated: its runs and exceedances
    added up), levels increasing: (ln x, n, z)."""
    x, n, z = (np.asarray(a, dtype=float) for a in (im, runs, exceedances))
    if not (x.shape == n.shape == z.shape) or x.size < 2:
        raise ValueError("an MSA fit needs two or more intensity levels, each with its runs "
                         "and exceedances")  # fmt: skip
    _positive(x, "intensity levels")
    if not (np.all(np.isfinite(n)) and np.all(n >= 1) and np.all(z >= 0)):
        raise ValueError("runs must be ≥ 1 and exceedances ≥ 0")
    if np.any(z > n) or np.any(z != np.round(z)) or np.any(n != np.round(n)):
        raise ValueError("exceedances must be whole numbers, at most the runs of their level")
    levels, which = np.unique(x, return_inverse=True)
    if levels.size < 2:
        raise ValueError("every stripe is at one intensity level: an MSA fit needs two or more")
    return np.log(levels), np.bincount(which, weights=n), np.bincount(which, weights=z)


def _msa_search(
    logs: np.ndarray, n: np.ndarray, z: np.ndarray, tolerance: float = NEWTON_TOLERANCE
) -> tuple[float, float, float, float]:
    """(m, s, a, b) of the binomial maximum likelihood of stripes (ln x increasing, n, z):
    the standardization of the levels' logs and the probit's intercept and slope on it."""
    if not (z.sum() > 0 and (n - z).sum() > 0):
        raise ValueError("every run exceeds, or none does: the data set defines no median")
    _refuse_a_step(logs, n, z)
    m, s = standardize(logs)
    a, b, done = probit_fit((logs - m) / s, n, z, tolerance)
    if not b > 0.0:
        raise ValueError("the exceedances do not rise with the intensity: no finite median "
                         "and dispersion fit them")  # fmt: skip
    if not done:
        raise ValueError("the binomial likelihood's search did not settle")
    return m, s, a, b


def _refuse_a_step(logs: np.ndarray, n: np.ndarray, z: np.ndarray) -> None:
    """A ValueError where no level has exceedances below some level and every level above it
    has nothing but: the likelihood then grows without bound towards a step (β → 0)."""
    first = int(np.argmax(z > 0))  # the lowest level with an exceedance
    last = int(n.size - 1 - np.argmax((n - z > 0)[::-1]))  # the highest with a run that does not
    if last > first:
        return
    low, high = (f"{math.exp(v):.4g}" for v in (logs[last], logs[first]))
    where = f"at {high}" if last == first else f"between {low} and {high}"
    raise ValueError(
        f"the exceedances go from none to all runs {where}: the likelihood is greatest for a "
        "step there (β → 0), no lognormal fits; runs at more levels around it would"
    )


def msa_fit(
    im: np.ndarray,
    runs: np.ndarray,
    exceedances: np.ndarray,
    tolerance: float = NEWTON_TOLERANCE,
) -> Fit:
    """The maximum-likelihood lognormal fit of exceedance counts at intensity levels (MSA):
    θ, β maximising the binomial log-likelihood (module docstring), by Newton's method on
    the probit's intercept and slope over the standardized log levels (a concave problem:
    rockcli.studies.fragility.likelihood) to ``tolerance``."""
    logs, n, z = msa_stripes(im, runs, exceedances)
    m, s, a, b = _msa_search(logs, n, z, tolerance)
    return _lognormal(m - s * a / b, s / b, None, int(n.sum()))


#: The profile-likelihood band's search: the slope b of the standardized log levels kept in
#: [0, max(PROFILE_SLOPE_MAX, 10 b̂)] (b = 0 a flat curve, the limit of counts that do not
#: rise; b = 1e4 a step for any data), η = Φ⁻¹(P) searched out to PROFILE_EDGE from the fit
#: and from 0 (Φ(±40) is 0 and 1 in double precision), each search at most PROFILE_ITERATIONS
#: steps to PROFILE_TOLERANCE.
PROFILE_SLOPE_MAX = 1e4
PROFILE_EDGE = 40.0
PROFILE_ITERATIONS = 100
PROFILE_TOLERANCE = 1e-10


def msa_band(
    im: np.ndarray, runs: np.ndarray, exceedances: np.ndarray, at: np.ndarray
) -> np.ndarray:
    """The profile-likelihood confidence band of an MSA fragility at the intensities ``at``,
    shape (len(at), 2) (Venzon & Moolgavkar 1988, "A method for computing profile-likelihood-
    based confidence intervals", Applied Statistics 37(1):87–94; Cox & Hinkley 1974,
    Theoretical Statistics, §9.3). With p = Φ(a + b·t) (t the standardized ln x), at each t0
    of ``at`` the band is the P(x0) = Φ(η0) whose profile deviance, 2·[ℓ(fit) − max over b ≥ 0
    of ℓ with a = η0 − b·t0], is at most the χ²₁ quantile of CONFIDENCE (3.84). At the
    true median (η0 = 0) it is the likelihood-ratio interval of θ. The binomial log-likelihood
    is concave in (a, b), so the deviance is convex in η0 and each end is its one root on that
    side (:func:`_profile_end`). A stripe of 0/n or n/n exceedances weighs in as it is; where
    the data do not bound P on a side, the band reaches 0 or 1 there. Computed CHUNK_ELEMENTS
    at a time."""
    logs, n, z = msa_stripes(im, runs, exceedances)
    m, s, a, b = _msa_search(logs, n, z)
    _lognormal(m - s * a / b, s / b, None, int(n.sum()))  # the fit's own checks
    t = (logs - m) / s
    x0 = (np.log(_positive(at, "band intensities")) - m) / s
    value, _, weight = probit_terms(a + b * t, n, z)
    level = float(value.sum()) + 0.5 * float(special.chdtri(1, 1.0 - CONFIDENCE))
    cap = max(PROFILE_SLOPE_MAX, 10.0 * b)
    band = np.empty((x0.size, 2))
    step = max(1, CHUNK_ELEMENTS // t.size)
    for i in range(0, x0.size, step):
        part = x0[i : i + step]
        eta, spread = a + b * part, _wald_spread(weight, t, part)
        ends = [_profile_end(t, n, z, part, eta, np.full(part.size, b), level, side, cap,
                             spread) for side in (-1, 1)]  # fmt: skip
        band[i : i + step] = special.ndtr(np.stack(ends, axis=1))
    return band


def _wald_spread(weight: np.ndarray, t: np.ndarray, x0: np.ndarray) -> np.ndarray:
    """The standard error of the fit's η at each x0 from the binomial Hessian in (a, b), the
    stripes' ``weight`` (:func:`probit_terms`): √([1, x0]·H⁻¹·[1, x0]ᵀ); PROFILE_EDGE where
    H is singular. Only a start for the profile's search."""
    haa, hab, hbb = weight.sum(), (weight * t).sum(), (weight * t * t).sum()
    det = haa * hbb - hab * hab
    with np.errstate(all="ignore"):
        spread = np.sqrt((hbb - 2.0 * x0 * hab + x0 * x0 * haa) / det)
    return np.where(np.isfinite(spread) & (det > 0.0), spread, PROFILE_EDGE)


#: Steps of the inner search at the bracket's far end: enough to find −ℓ below the level
#: there when it is (the minimum is at most any value found), else the search from inside
#: still ends there.
PROFILE_CHECK = 20
#: The profile's search starts this many Wald standard errors from the fit (1.96 of them
#: for a quadratic deviance), so that Newton's method is near the end from its first step.
WALD_START = 2.0


def _profile_end(
    t: np.ndarray, n: np.ndarray, z: np.ndarray, x0: np.ndarray, eta: np.ndarray,
    slope: np.ndarray, level: float, side: float, cap: float, spread: np.ndarray,
) -> np.ndarray:  # fmt: skip
    """Where the profile's −ℓ (:func:`_profile`) reaches ``level`` beyond the fit's η at each
    x0, on ``side`` (+1 up, −1 down), inside the bracket from η to PROFILE_EDGE beyond both η
    and 0: where −ℓ is still below ``level`` at the bracket's far end, the end is the far end;
    elsewhere Newton's method from WALD_START standard errors (``spread``) out, keeping the
    bracket [inside, outside] of the root (−ℓ is convex in η, so a step from outside the
    root does not pass it, and one from inside lands outside; a step that would leave the
    bracket is a bisection, as a safeguard)."""
    far = side * np.maximum(side * eta, 0.0) + side * PROFILE_EDGE
    open_end = _profile(t, n, z, x0, far, slope, cap, PROFILE_CHECK)[0] < level
    point = np.where(open_end, far, eta + side * np.minimum(WALD_START * spread, np.abs(far - eta)))
    inside, outside = np.where(open_end, far, eta), far.copy()
    with np.errstate(all="ignore"):
        for _ in range(PROFILE_ITERATIONS):
            value, rate, slope = _profile(t, n, z, x0, point, slope, cap)
            excess = value - level
            above = excess >= 0.0
            inside, outside = np.where(above, inside, point), np.where(above, point, outside)
            step = point - excess / rate
            kept = (np.minimum(inside, outside) <= step) & (step <= np.maximum(inside, outside))
            step = np.where(kept, step, 0.5 * (inside + outside))
            done = np.abs(step - point) <= PROFILE_TOLERANCE * (1.0 + np.abs(point))
            point = step
            if done.all():
                break
    return point


def _profile(
    t: np.ndarray, n: np.ndarray, z: np.ndarray, x0: np.ndarray, eta: np.ndarray,
    slope: np.ndarray, cap: float, iterations: int = PROFILE_ITERATIONS,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
    """The binomial −ℓ minimised over the slope b ∈ [0, cap] with the probit at x0 held at
    ``eta`` (η_j = eta + b·(t_j − x0)), for each element; returns that minimum, its
    derivative in eta (the score at the minimiser: the envelope theorem) and the minimiser.
    −ℓ is convex in b, so its minimiser is the root of the derivative in b, found by Newton's
    method from ``slope`` inside a bracket that every step narrows (a step out of it is a
    bisection), or an end of [0, cap] where the derivative does not change sign; at most
    ``iterations`` steps."""
    d = t[None, :] - x0[:, None]
    low, high = np.zeros(eta.size), np.full(eta.size, cap)
    for end in (low, high):
        _, score, _ = probit_terms(eta[:, None] + end[:, None] * d, n, z)
        rising = (d * score).sum(axis=1) >= 0.0
        low, high = (np.where(rising, low, end), np.where(rising, end, high))
    b = np.clip(slope, low, high)
    for _ in range(iterations):
        _, score, weight = probit_terms(eta[:, None] + b[:, None] * d, n, z)
        gradient, curvature = (d * score).sum(axis=1), (d * d * weight).sum(axis=1)
        low, high = np.where(gradient < 0.0, b, low), np.where(gradient < 0.0, high, b)
        with np.errstate(all="ignore"):  # 0/0 where the weights underflow: a bisection
            step = b - gradient / curvature
        kept = np.isfinite(step) & (step >= low) & (step <= high)
        step = np.where(kept, step, 0.5 * (low + high))
        done = np.abs(step - b) <= PROFILE_TOLERANCE * (1.0 + b)
        b = step
        if done.all():
            break
    value, score, _ = probit_terms(eta[:, None] + b[:, None] * d, n, z)
    return value.sum(axis=1), score.sum(axis=1), b


#: |t| beyond which the noncentral t is not inverted: scipy's search slows without bound as
#: |t| grows (|t| = 1e6 does not return); at |t| = 1e3 both ends of the band lie below
#: Φ(−22) ≈ 1e-107 (or above 1 minus that) for any n ≥ 2, so the clip moves P by less.
T_LIMIT = 1e3


def ida_band(im: np.ndarray, at: np.ndarray) -> np.ndarray:
    """The exact confidence band of a lognormal fragility fitted to n collapse intensities,
    at ``at``, shape (len(at), 2): with m and s the mean and standard deviation (divisor
    n − 1) of ln IM, t = √n·(m − ln x)/s is noncentral t with n − 1 degrees of freedom and
    noncentrality √n·δ, δ = (ln θ − ln x)/β; the band of P(x) = Φ(−δ) is the δ that put t at
    its (1 ± CONFIDENCE)/2 quantiles (the confidence interval of a normal proportion: Owen
    1968, "A survey of properties and applications of the noncentral t-distribution",
    Technometrics 10(3):445–478; Hahn & Meeker 1991, Statistical Intervals). At the true
    median (δ = 0) it is ln θ̂ ± t_{n−1}·s/√n. It does not depend on the divisor of the fit's
    β."""
    x = np.asarray(im, dtype=float)
    fit = ida_fit(x, 1)  # the checks, and m, s
    root_n = math.sqrt(x.size)
    logs = np.log(_positive(at, "band intensities"))
    t = np.clip(root_n * (math.log(fit.median) - logs) / fit.beta, -T_LIMIT, T_LIMIT)
    tail = (1.0 - CONFIDENCE) / 2.0
    above = special.nctdtrinc(x.size - 1, tail, t) / root_n  # the largest δ
    below = special.nctdtrinc(x.size - 1, 1.0 - tail, t) / root_n
    return np.stack([special.ndtr(-above), special.ndtr(-below)], axis=1)


def ida_censored_band(
    im: np.ndarray, censored: np.ndarray, at: np.ndarray, samples: int = BOOTSTRAP_SAMPLES,
    seed: int = 0,
) -> np.ndarray:  # fmt: skip
    """The band of :func:`ida_censored_fit` at ``at``, shape (len(at), 2): a parametric
    bootstrap of the fitted censored lognormal (Meeker & Escobar 1998, Statistical Methods for
    Reliability Data, ch. 9: each resample drawn from the fit and censored as the data were,
    :func:`censoring_points`), read through the pivots of a location-scale family, Q1 =
    (μ̂ − μ)/σ̂ and Q2 = σ̂/σ (μ = ln θ, σ = β: exact pivots for complete data, nearly so under
    censoring; Lawless 2003, Statistical Models and Methods for Lifetime Data, ch. 5). With
    their resampled values (μ̂* − μ̂)/σ̂* and σ̂*/σ̂, the band of u = (ln x − μ)/σ is the
    (1 ± CONFIDENCE)/2 quantiles of ((ln x − μ̂)/σ̂ + Q1*)·Q2*, and P = Φ(u) (the generalized
    pivotal quantity, Weerahandi 1993, JASA 88:899–905; without censoring it is
    :func:`ida_band`'s exact band). A plain percentile bootstrap is short for a handful of
    records (its β̂* are biased low as β̂ is). The resamples are refitted by Newton's method
    all at once, CHUNK_ELEMENTS at a time, in the standardized logs of the data
    (rockcli.studies.fragility.likelihood.censored_fit). A resample whose likelihood has no maximum
    (no record reaches the state, and its θ runs off upwards; or the records that do are all
    at one intensity, above every censored one) counts as P = 1 at every intensity: its
    records were drawn high, and dropping it would leave the band short on that side."""
    x = _positive(im, "collapse intensities")
    c = _positive(censored, "censoring intensities")
    m, s, a, b = _censored_search(np.log(x), np.log(c))
    limits = (np.log(censoring_points(x, c)) - m) / s
    u = b * (np.log(_positive(at, "band intensities")) - m) / s - a  # (ln x − μ̂)/σ̂
    rng = np.random.default_rng(seed)
    curves = np.ones((samples, u.size))
    block = max(1, CHUNK_ELEMENTS // limits.size)
    for i in range(0, samples, block):
        drawn = (a + rng.standard_normal((min(block, samples - i), limits.size))) / b
        reached = drawn <= limits
        y = np.where(reached, drawn, limits)
        fits = has_maximum(y, reached)
        k = int(fits.sum())
        ak, bk, _ = censored_fit(CensoredSets.of(y[fits], reached[fits]), np.full(k, a),
                                 np.full(k, b))  # fmt: skip
        q1, q2 = ak - a * bk / b, b / bk
        part = curves[i : i + drawn.shape[0]]
        part[fits] = special.ndtr((u[None, :] + q1[:, None]) * q2[:, None])
    return _quantiles(curves, u.size)


def censoring_points(im: np.ndarray, censored: np.ndarray) -> np.ndarray:
    """Where each record's scan ended, for redrawing the data as they were censored: a
    censored record at its own intensity; a record that reached the state at the highest
    censoring intensity (a study's scan ends at one intensity for every record), or at its own
    intensity if higher (its scan went at least that far). Records in the order (im, censored)."""
    top = float(np.max(censored)) if np.size(censored) else math.inf
    return np.concatenate([np.maximum(np.asarray(im, dtype=float), top), censored])


def censored_refits(
    logs: np.ndarray, reached: np.ndarray, start: Fit
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The censored maximum likelihood of every resample at once: θ, β and whether each
    converged. Row k of ``logs`` (K × records) holds resample k's ln IM, a collapse intensity
    where ``reached`` and else a censoring one; each is searched from ``start``
    (rockcli.studies.fragility.likelihood.censored_fit, on the logs standardized by start's ln θ and
    β). A resample without a finite maximum (rockcli.studies.fragility.likelihood.has_maximum) does
    not converge: NaN."""
    m, s = math.log(start.median), start.beta
    y = (np.asarray(logs, dtype=float) - m) / s
    fits = has_maximum(y, reached)
    k = int(fits.sum())
    a, b, done = censored_fit(CensoredSets.of(y[fits], reached[fits]), np.zeros(k), np.ones(k))
    theta, beta = np.full(y.shape[0], np.nan), np.full(y.shape[0], np.nan)
    with np.errstate(over="ignore"):
        theta[fits], beta[fits] = np.exp(m + s * a / b), s / b
    ok = np.zeros(y.shape[0], dtype=bool)
    ok[fits] = done & np.isfinite(theta[fits])
    return theta, beta, ok


def ida_curve(
    im: np.ndarray, censored: np.ndarray, at: np.ndarray, ddof: int = BETA_DDOF
) -> tuple[Fit, np.ndarray]:
    """An IDA fragility and its band at ``at``: the censored maximum likelihood when some
    records are censored (β² over n whatever ddof), else the closed form with ``ddof``."""
    if np.asarray(censored).size:
        return ida_censored_fit(im, censored), ida_censored_band(im, censored, at)
    return ida_fit(im, ddof), ida_band(im, at)


def msa_curve(
    im: np.ndarray, runs: np.ndarray, exceedances: np.ndarray, at: np.ndarray
) -> tuple[Fit, np.ndarray]:
    """An MSA fragility and its band at ``at``."""
    return msa_fit(im, runs, exceedances), msa_band(im, runs, exceedances, at)


def band_points(im: np.ndarray, msa: bool = False) -> np.ndarray:
    """The intensities to give a band at: the data's own, each once and increasing, or as
    many of them as BAND_POINTS allows (``msa``: BAND_WORK too, ``im`` being the levels),
    evenly spread in rank (the first and the last among them), when there are more."""
    distinct = np.unique(np.asarray(im, dtype=float))
    limit = BAND_POINTS
    if msa:
        limit = max(MIN_BAND_POINTS, min(limit, BAND_WORK // max(distinct.size, 1)))
    if distinct.size <= limit:
        return distinct
    return distinct[np.unique(np.round(np.linspace(0, distinct.size - 1, limit)).astype(int))]


def band_method(method: str, censored: bool = False) -> str:
    """What the band of an ``ida`` or ``msa`` fit is, in words (the output's ``band_method``)."""
    level = f"{CONFIDENCE * 100:g} %"
    if method == "msa":
        return f"profile likelihood of the binomial counts, {level} at each intensity"
    if censored:
        return (
            f"parametric bootstrap of the fitted censored lognormal through its pivots, {level} "
            f"at each intensity, {BOOTSTRAP_SAMPLES} resamples"
        )
    return f"exact for a lognormal (noncentral t of ln IM), {level} at each intensity"


def _quantiles(curves: np.ndarray, size: int) -> np.ndarray:
    if not curves.size:
        return np.full((size, 2), np.nan)
    tail = (1.0 - CONFIDENCE) / 2.0
    return np.quantile(curves, [tail, 1.0 - tail], axis=0).T
