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

Pure and silent: numpy and scipy; a data set that defines no fit is a ValueError that says why.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize, special

#: The divisor of β² in an IDA fit: n (maximum likelihood), not n − 1.
BETA_DDOF = 0
#: Resamples of the censored IDA band's parametric bootstrap, and every band's two-sided level.
BOOTSTRAP_SAMPLES = 1000
CONFIDENCE = 0.95
#: Tolerance of a bootstrap refit in ln θ and ln β (1e-6: far below the band's own spread).
BAND_TOLERANCE = 1e-6


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
        with np.errstate(divide="ignore"):
            return np.asarray(special.ndtr(np.log(x / self.median) / self.beta))


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
    return Fit(float(np.exp(np.mean(logs))), beta, ddof, int(x.size))


def ida_censored_fit(im: np.ndarray, censored: np.ndarray, tolerance: float = 1e-10) -> Fit:
    """The maximum-likelihood lognormal of collapse intensities ``im`` and of records
    right-censored at ``censored`` (each the intensity below which such a record was seen
    not to reach the state; module docstring), searched (Nelder–Mead) over ln θ and ln β to
    ``tolerance`` from the uncensored intensities' own fit. Without censored records: ida_fit
    with ddof 0, in closed form."""
    x = np.asarray(im, dtype=float)
    c = np.asarray(censored, dtype=float)
    if c.size == 0:
        return ida_fit(x, 0)
    if np.any(c <= 0.0) or not np.all(np.isfinite(c)):
        raise ValueError("censoring intensities must be finite and > 0")
    first = ida_fit(x, 0)  # the checks of the collapse intensities, and the start
    start = np.array([math.log(first.median), math.log(first.beta)])
    found = optimize.minimize(
        _censored_negative_log_likelihood, start, args=(np.log(x), np.log(c)),
        method="Nelder-Mead",
        options={"xatol": tolerance, "fatol": tolerance * 1e-2, "maxiter": 20_000,
                 "maxfev": 40_000},
    )  # fmt: skip
    ln_theta, ln_beta = found.x
    return Fit(float(math.exp(ln_theta)), float(math.exp(ln_beta)), 0, int(x.size + c.size))


def _censored_negative_log_likelihood(
    params: np.ndarray, logs: np.ndarray, censored_logs: np.ndarray
) -> float:
    """−(Σ ln φ(u_i) − n ln β + Σ ln(1 − Φ(u_k))), u = (ln x − ln θ)/β (the Σ ln x_i of the
    density does not depend on θ, β and is left out)."""
    ln_theta, ln_beta = params
    beta = math.exp(ln_beta)
    u = (logs - ln_theta) / beta
    v = (censored_logs - ln_theta) / beta
    density = -0.5 * u * u - ln_beta
    return float(-(density.sum() + special.log_ndtr(-v).sum()))


def msa_fit(
    im: np.ndarray,
    runs: np.ndarray,
    exceedances: np.ndarray,
    start: tuple[float, float] | None = None,
    tolerance: float = 1e-10,
) -> Fit:
    """The maximum-likelihood lognormal fit of exceedance counts at intensity levels (MSA):
    θ, β maximising the binomial log-likelihood (module docstring), searched (Nelder–Mead)
    over ln θ and ln β to ``tolerance``, from ``start`` (θ, β) or else from the moments of the
    levels weighted by their exceedances."""
    x, n, z = (np.asarray(a, dtype=float) for a in (im, runs, exceedances))
    if not (x.shape == n.shape == z.shape) or x.size < 2:
        raise ValueError("an MSA fit needs two or more intensity levels, each with its runs "
                         "and exceedances")  # fmt: skip
    if np.any(x <= 0.0) or not np.all(np.isfinite(x)) or np.any(n < 1) or np.any(z < 0):
        raise ValueError("intensity levels must be finite and > 0, runs ≥ 1, exceedances ≥ 0")
    if np.any(z > n) or np.any(z != np.round(z)) or np.any(n != np.round(n)):
        raise ValueError("exceedances must be whole numbers, at most the runs of their level")
    if not (z.sum() > 0 and (n - z).sum() > 0):
        raise ValueError("every run exceeds, or none does: the data set defines no median")
    logs = np.log(x)
    first = _start(logs, n, z) if start is None else np.log(np.array(start, dtype=float))
    found = optimize.minimize(
        _negative_log_likelihood, first, args=(logs, n, z), method="Nelder-Mead",
        options={"xatol": tolerance, "fatol": tolerance * 1e-2, "maxiter": 20_000,
                 "maxfev": 40_000},
    )  # fmt: skip
    ln_theta, ln_beta = found.x
    if not (abs(ln_theta) < LOG_LIMIT and abs(ln_beta) < LOG_LIMIT):
        raise ValueError("the exceedances do not rise with the intensity: no finite median "
                         "and dispersion fit them")  # fmt: skip
    return Fit(float(math.exp(ln_theta)), float(math.exp(ln_beta)), None, int(n.sum()))


#: |ln θ|, |ln β| beyond which an MSA search has run off (counts that do not rise with the
#: intensity have their likelihood's supremum at β → ∞) rather than found a fit: e^700 ≈ 1e304.
LOG_LIMIT = 700.0


def _start(logs: np.ndarray, n: np.ndarray, z: np.ndarray) -> np.ndarray:
    """(ln θ, ln β) to start the search from: the levels' mean and spread, weighted by the
    exceedances' increments (a rough median and dispersion)."""
    fraction = z / n
    weights = np.clip(np.diff(np.concatenate([[0.0], np.maximum.accumulate(fraction)])), 0, None)
    if weights.sum() <= 0.0:
        weights = np.ones_like(logs)
    mean = float(np.average(logs, weights=weights))
    spread = float(np.sqrt(np.average((logs - mean) ** 2, weights=weights)))
    return np.array([mean, math.log(max(spread, 0.1))])


def _negative_log_likelihood(
    params: np.ndarray, logs: np.ndarray, n: np.ndarray, z: np.ndarray
) -> float:
    """−Σ [z ln p + (n − z) ln(1 − p)], p = Φ((ln x − ln θ)/β), by log-CDFs (no 0·log 0)."""
    ln_theta, ln_beta = params
    u = (logs - ln_theta) / math.exp(ln_beta)
    return float(-(z * special.log_ndtr(u) + (n - z) * special.log_ndtr(-u)).sum())


#: The profile-likelihood band's search: the slope b = 1/β kept in [0, PROFILE_SLOPE_MAX]
#: (b = 0 a flat curve, the limit of counts that do not rise; 1e4, β = 1e-4, a step for any
#: data), η = Φ⁻¹(P) searched out to PROFILE_EDGE from the fit and from 0 (Φ(±40) is 0 and 1 in
#: double precision), each search at most PROFILE_ITERATIONS steps to PROFILE_TOLERANCE.
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
    Theoretical Statistics, §9.3). With p = Φ(a + b·ln x) (b = 1/β, a = −ln θ/β), at each x0
    of ``at`` the band is the P(x0) = Φ(η0) whose profile deviance, 2·[ℓ(fit) − max over b ≥ 0
    of ℓ with a = η0 − b·ln x0], is at most the χ²₁ quantile of CONFIDENCE (3.84). At the
    true median (η0 = 0) it is the likelihood-ratio interval of θ. The binomial log-likelihood
    is concave in (a, b), so the deviance is convex in η0 and each end is its one root on that
    side (:func:`_profile_end`). A stripe of 0/n or n/n exceedances weighs in as it is; where
    the data do not bound P on a side, the band reaches 0 or 1 there."""
    whole = msa_fit(im, runs, exceedances)
    logs = np.log(np.asarray(im, dtype=float))
    n, z = np.asarray(runs, dtype=float), np.asarray(exceedances, dtype=float)
    x0 = np.log(np.asarray(at, dtype=float))
    with np.errstate(divide="ignore"):
        a, b = -float(np.log(whole.median)) / whole.beta, 1.0 / whole.beta
    if not (math.isfinite(a) and math.isfinite(b)):
        return np.full((x0.size, 2), np.nan)  # θ or β out of floating point: no band
    level = _negative_log_likelihood(np.log([whole.median, whole.beta]), logs, n, z)
    level += 0.5 * float(special.chdtri(1, 1.0 - CONFIDENCE))
    eta, start = a + b * x0, np.full(x0.size, min(b, PROFILE_SLOPE_MAX))
    low = _profile_end(logs, n, z, x0, eta, start, level, -1.0)
    high = _profile_end(logs, n, z, x0, eta, start, level, 1.0)
    return np.stack([special.ndtr(low), special.ndtr(high)], axis=1)


def _profile_end(
    logs: np.ndarray, n: np.ndarray, z: np.ndarray, x0: np.ndarray, eta: np.ndarray,
    slope: np.ndarray, level: float, side: float,
) -> np.ndarray:  # fmt: skip
    """Where the profile's −ℓ (:func:`_profile`) reaches ``level`` beyond the fit's η at each
    x0, on ``side`` (+1 up, −1 down): Newton's method from the far end of the bracket from η
    to PROFILE_EDGE beyond both η and 0, which for a convex function converges from outside
    the root without passing it (a step that would leave the bracket is a bisection, as a
    safeguard). Where the far end is still below ``level``, the end is the far end."""
    inside = eta.copy()
    point = side * np.maximum(side * eta, 0.0) + side * PROFILE_EDGE
    outside = point.copy()
    for _ in range(PROFILE_ITERATIONS):
        value, rate, slope = _profile(logs, n, z, x0, point, slope)
        excess = value - level
        above = excess >= 0.0
        inside, outside = np.where(above, inside, point), np.where(above, point, outside)
        with np.errstate(all="ignore"):
            step = point - excess / rate
        kept = (np.minimum(inside, outside) <= step) & (step <= np.maximum(inside, outside))
        step = np.where(kept, step, 0.5 * (inside + outside))
        done = np.abs(step - point) <= PROFILE_TOLERANCE * (1.0 + np.abs(point))
        point = step
        if done.all():
            break
    return point


def _profile(
    logs: np.ndarray, n: np.ndarray, z: np.ndarray, x0: np.ndarray, eta: np.ndarray,
    slope: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
    """The binomial −ℓ minimised over the slope b ∈ [0, PROFILE_SLOPE_MAX] with the probit at
    x0 held at ``eta`` (η_j = eta + b·(ln x_j − x0)), for each element; returns that minimum,
    its derivative in eta (the score at the minimiser: the envelope theorem) and the
    minimiser. −ℓ is convex in b, so its minimiser is the root of the derivative in b, found
    by Newton's method from ``slope`` inside a bracket that every step narrows (a step out of
    it is a bisection), or an end of [0, PROFILE_SLOPE_MAX] where the derivative does not
    change sign."""
    d = logs[None, :] - x0[:, None]
    low, high = np.zeros(eta.size), np.full(eta.size, PROFILE_SLOPE_MAX)
    for end in (low, high):
        _, score, _ = _probit_terms(eta[:, None] + end[:, None] * d, n, z)
        rising = (d * score).sum(axis=1) >= 0.0
        low, high = (np.where(rising, low, end), np.where(rising, end, high))
    b = np.clip(slope, low, high)
    for _ in range(PROFILE_ITERATIONS):
        _, score, weight = _probit_terms(eta[:, None] + b[:, None] * d, n, z)
        gradient, curvature = (d * score).sum(axis=1), (d * d * weight).sum(axis=1)
        low, high = np.where(gradient < 0.0, b, low), np.where(gradient < 0.0, high, b)
        with np.errstate(all="ignore"):
            step = b - gradient / curvature
        kept = np.isfinite(step) & (step >= low) & (step <= high)
        step = np.where(kept, step, 0.5 * (low + high))
        done = np.abs(step - b) <= PROFILE_TOLERANCE * (1.0 + b)
        b = step
        if done.all():
            break
    value, score, _ = _probit_terms(eta[:, None] + b[:, None] * d, n, z)
    return value.sum(axis=1), score.sum(axis=1), b


def _probit_terms(
    eta: np.ndarray, n: np.ndarray, z: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each stripe's −[z ln Φ(η) + (n − z) ln Φ(−η)], its first and second derivatives in η,
    through log-CDFs and the Mills ratios λ(±η) = φ(η)/Φ(±η) (no 0·log 0, no overflow):
    −z·λ(η) + (n − z)·λ(−η), and z·λ(η)(η + λ(η)) + (n − z)·λ(−η)(λ(−η) − η) ≥ 0."""
    up, down = special.log_ndtr(eta), special.log_ndtr(-eta)
    log_pdf = -0.5 * eta * eta - 0.5 * math.log(2.0 * math.pi)
    rise, fall = np.exp(log_pdf - up), np.exp(log_pdf - down)
    value = -(z * up + (n - z) * down)
    score = -z * rise + (n - z) * fall
    weight = z * rise * (eta + rise) + (n - z) * fall * (fall - eta)
    return value, score, np.maximum(weight, 0.0)


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
    t = root_n * (math.log(fit.median) - np.log(np.asarray(at, dtype=float))) / fit.beta
    t = np.clip(t, -T_LIMIT, T_LIMIT)
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
    records (its β̂* are biased low as β̂ is). The resamples are refitted all at once
    (:func:`censored_refits`), one that Newton's method does not settle by Nelder–Mead as
    ida_censored_fit. A resample whose likelihood has no maximum (no record reaches the state,
    and its θ runs off upwards; or, in a data file, one record does, above every censored
    one) counts as P = 1 at every intensity: its records were drawn high, and dropping it
    would leave the band short on that side."""
    x = np.asarray(im, dtype=float)
    c = np.asarray(censored, dtype=float)
    whole = ida_censored_fit(x, c)
    mu, sigma = math.log(whole.median), whole.beta
    limits = np.log(censoring_points(x, c))
    rng = np.random.default_rng(seed)
    drawn = mu + sigma * rng.standard_normal((samples, limits.size))
    reached = drawn <= limits
    logs = np.where(reached, drawn, limits)
    theta, beta, done = censored_refits(logs, reached, whole)
    fits = _has_maximum(logs, reached)
    for k in np.flatnonzero(fits & ~done):
        refit = _refit_censored(np.exp(logs[k][reached[k]]), np.exp(logs[k][~reached[k]]), whole)
        theta[k], beta[k] = refit.median, refit.beta
    q1, q2 = (np.log(theta[fits]) - mu) / beta[fits], beta[fits] / sigma
    u = (np.log(np.asarray(at, dtype=float)) - mu) / sigma
    curves = np.ones((samples, u.size))
    curves[fits] = special.ndtr((u[None, :] + q1[:, None]) * q2[:, None])
    return _quantiles(curves, u.size)


def _has_maximum(logs: np.ndarray, reached: np.ndarray) -> np.ndarray:
    """Whether each resample's censored likelihood has a finite maximum: two or more distinct
    collapse intensities, or one below some censored record's intensity (with none, or one
    above every censored record, it grows without bound)."""
    count = reached.sum(axis=1)
    top = np.max(logs, axis=1, where=reached, initial=-math.inf)
    bottom = np.min(logs, axis=1, where=reached, initial=math.inf)
    censored_top = np.max(logs, axis=1, where=~reached, initial=-math.inf)
    return ((count >= 2) & (top > bottom)) | ((count == 1) & (censored_top > top))


def censoring_points(im: np.ndarray, censored: np.ndarray) -> np.ndarray:
    """Where each record's scan ended, for redrawing the data as they were censored: a
    censored record at its own intensity; a record that reached the state at the highest
    censoring intensity (a study's scan ends at one intensity for every record), or at its own
    intensity if higher (its scan went at least that far). Records in the order (im, censored)."""
    top = float(np.max(censored)) if np.size(censored) else math.inf
    return np.concatenate([np.maximum(np.asarray(im, dtype=float), top), censored])


def _refit_censored(x: np.ndarray, c: np.ndarray, whole: Fit) -> Fit:
    """A bootstrap refit by Nelder–Mead, from the whole data's fit, to BAND_TOLERANCE, at most
    20 000 iterations (a resample with a finite maximum: :func:`_has_maximum`)."""
    if c.size == 0:
        return ida_fit(x, 0)
    found = optimize.minimize(
        _censored_negative_log_likelihood, np.log([whole.median, whole.beta]),
        args=(np.log(x), np.log(c)), method="Nelder-Mead",
        options={"xatol": BAND_TOLERANCE, "fatol": BAND_TOLERANCE * 1e-2, "maxiter": 20_000},
    )  # fmt: skip
    return Fit(float(math.exp(found.x[0])), float(math.exp(found.x[1])), 0, x.size + c.size)


#: Newton iterations of the censored refits, and their convergence in (ln θ, ln β).
NEWTON_ITERATIONS = 100
NEWTON_TOLERANCE = 1e-12
#: Halvings of a Newton step that would lower the likelihood (a damped Newton's method).
HALVINGS = 30


def censored_refits(
    logs: np.ndarray, reached: np.ndarray, start: Fit
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The censored maximum likelihood of every resample at once: θ, β and whether each
    converged. Row k of ``logs`` (K × records) holds resample k's ln IM, a collapse intensity
    where ``reached`` and else a censoring one. Newton's method on μ = ln θ and τ = ln β with
    the exact gradient and Hessian of the log-likelihood of the module docstring (for a
    censored record, with h = φ(v)/Φ(−v), v = (ln c − μ)/β: ∂ℓ/∂μ = h/β, ∂ℓ/∂τ = h·v, and
    h' = h(h − v)), from ``start``, each step halved while it would lower the likelihood (and
    a gradient step where the Hessian is not negative definite). A resample without a finite
    maximum (:func:`_has_maximum`) does not converge."""
    mx, mc = reached.astype(float), (~reached).astype(float)
    k = logs.shape[0]
    mu = np.full(k, math.log(start.median))
    tau = np.full(k, math.log(start.beta))
    converged = np.zeros(k, dtype=bool)

    def likelihood(mu: np.ndarray, tau: np.ndarray) -> np.ndarray:
        u = (logs - mu[:, None]) / np.exp(tau)[:, None]
        return (mx * (-0.5 * u * u - tau[:, None])).sum(1) + (mc * special.log_ndtr(-u)).sum(1)

    with np.errstate(all="ignore"):
        for _ in range(NEWTON_ITERATIONS):
            sigma = np.exp(tau)[:, None]
            u = (logs - mu[:, None]) / sigma  # v of the censored records
            h = np.exp(-0.5 * u * u - 0.5 * math.log(2.0 * math.pi) - special.log_ndtr(-u))
            dh = h * (h - u)
            g_mu = (mx * u / sigma).sum(1) + (mc * h / sigma).sum(1)
            g_tau = (mx * (u * u - 1.0)).sum(1) + (mc * h * u).sum(1)
            h_mumu = -(mx / sigma**2).sum(1) - (mc * dh / sigma**2).sum(1)
            h_mutau = -(mx * 2.0 * u / sigma).sum(1) - (mc * (dh * u + h) / sigma).sum(1)
            h_tautau = -(mx * 2.0 * u * u).sum(1) - (mc * (dh * u * u + h * u)).sum(1)
            det = h_mumu * h_tautau - h_mutau * h_mutau
            d_mu = -(h_tautau * g_mu - h_mutau * g_tau) / det
            d_tau = -(h_mumu * g_tau - h_mutau * g_mu) / det
            uphill = (h_mumu < 0.0) & (det > 0.0)  # the Hessian negative definite
            d_mu = np.where(uphill, d_mu, g_mu * 1e-2)  # else a short gradient step
            d_tau = np.where(uphill, d_tau, g_tau * 1e-2)
            before = likelihood(mu, tau)
            for _ in range(HALVINGS):  # halve the step until the likelihood does not drop
                worse = ~(likelihood(mu + d_mu, tau + d_tau) >= before - 1e-12 * np.abs(before))
                if not worse.any():
                    break
                d_mu, d_tau = np.where(worse, d_mu / 2, d_mu), np.where(worse, d_tau / 2, d_tau)
            mu, tau = mu + d_mu, tau + d_tau
            step = np.maximum(np.abs(d_mu), np.abs(d_tau))
            converged = np.isfinite(step) & (step < NEWTON_TOLERANCE * (1.0 + np.abs(mu)))
            if converged.all():
                break
    ok = converged & np.isfinite(mu) & np.isfinite(tau)
    with np.errstate(over="ignore"):  # a resample that ran off, not ok
        return np.where(ok, np.exp(mu), np.nan), np.where(ok, np.exp(tau), np.nan), ok


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
