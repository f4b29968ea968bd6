"""Lognormal fragility functions fitted to collapse intensities (IDA) or to counts of
exceedances at intensity levels (MSA), and their bootstrap confidence bands.

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

Pure and silent: numpy and scipy; a data set that defines no fit is a ValueError that says why.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize, special

#: The divisor of β² in an IDA fit: n (maximum likelihood), not n − 1.
BETA_DDOF = 0
#: Bootstrap resamples of a confidence band, and its two-sided level.
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
    return Fit(float(math.exp(ln_theta)), float(math.exp(ln_beta)), None, int(n.sum()))


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


def msa_band(
    im: np.ndarray,
    runs: np.ndarray,
    exceedances: np.ndarray,
    at: np.ndarray,
    samples: int = BOOTSTRAP_SAMPLES,
    seed: int = 0,
) -> np.ndarray:
    """The bootstrap confidence band of an MSA fragility at the intensities ``at``, shape
    (len(at), 2): at each level, z*_j ~ Binomial(n_j, z_j/n_j) is drawn again, the
    fragility refitted, and the band is the (1 ∓ CONFIDENCE)/2 quantiles of the refitted
    probabilities (resamples that define no fit are left out). ``seed`` fixes the draws; each
    refit starts from the data's own fit, to BAND_TOLERANCE in ln θ and ln β."""
    n = np.asarray(runs, dtype=int)
    p = np.asarray(exceedances, dtype=float) / n
    whole = msa_fit(im, n, exceedances)
    rng = np.random.default_rng(seed)
    draws = np.array([rng.binomial(n, p) for _ in range(samples)])
    logs = np.log(np.asarray(im, dtype=float))
    theta, beta, done = probit_refits(logs, n, draws, whole)
    curves = []
    for k, z in enumerate(draws):
        if not (z.sum() > 0 and (n - z).sum() > 0):
            continue  # the resample defines no fit (msa_fit's ValueError)
        if done[k]:
            curves.append(Fit(float(theta[k]), float(beta[k]), None, 0).probability(at))
            continue
        refit = msa_fit(im, n, z, (whole.median, whole.beta), BAND_TOLERANCE)
        curves.append(refit.probability(at))
    return _quantiles(np.array(curves), len(at))


#: Fisher-scoring iterations of the bootstrap's refits, and their convergence in (a, b).
SCORING_ITERATIONS = 100
SCORING_TOLERANCE = 1e-12


def probit_refits(
    logs: np.ndarray, n: np.ndarray, draws: np.ndarray, start: Fit
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The binomial maximum likelihood of every resample ``draws`` (K × levels) at once: θ, β
    and whether each converged. With p = Φ(a + b·ln x), b = 1/β and a = −ln θ/β, the fit is a
    probit regression, solved by Fisher scoring (McCullagh & Nelder 1989, Generalized Linear
    Models, §4.4: the binomial score and expected information, here with the probit link),
    vectorised over the resamples, from the data's own fit. A resample whose data are
    separated (no finite maximum), or that does not converge, is left to the Nelder–Mead
    search of msa_fit (``converged`` False)."""
    k = draws.shape[0]
    z = draws.astype(float)
    a = np.full(k, -math.log(start.median) / start.beta)
    b = np.full(k, 1.0 / start.beta)
    converged = np.zeros(k, dtype=bool)
    with np.errstate(all="ignore"):
        for _ in range(SCORING_ITERATIONS):
            eta = a[:, None] + b[:, None] * logs[None, :]
            log_pdf = -0.5 * eta * eta - 0.5 * math.log(2.0 * math.pi)
            up, down = special.log_ndtr(eta), special.log_ndtr(-eta)
            score = z * np.exp(log_pdf - up) - (n - z) * np.exp(log_pdf - down)
            weight = n * np.exp(2.0 * log_pdf - up - down)
            s0, s1 = score.sum(axis=1), (score * logs).sum(axis=1)
            w0, w1, w2 = (
                weight.sum(axis=1),
                (weight * logs).sum(axis=1),
                (weight * logs * logs).sum(axis=1),
            )
            det = w0 * w2 - w1 * w1
            da, db = (w2 * s0 - w1 * s1) / det, (w0 * s1 - w1 * s0) / det
            a, b = a + da, b + db
            step = np.maximum(np.abs(da), np.abs(db))
            converged = np.isfinite(step) & (step < SCORING_TOLERANCE * (1.0 + np.abs(b)))
            if converged.all():
                break
    ok = converged & np.isfinite(a) & np.isfinite(b) & (b > 0.0)
    with np.errstate(all="ignore"):
        beta = np.where(ok, 1.0 / b, np.nan)
        theta = np.where(ok, np.exp(-a / b), np.nan)
    return theta, beta, ok


def ida_band(
    im: np.ndarray, at: np.ndarray, samples: int = BOOTSTRAP_SAMPLES, seed: int = 0,
    ddof: int = BETA_DDOF,
) -> np.ndarray:  # fmt: skip
    """The bootstrap confidence band of an IDA fragility at ``at``, shape (len(at), 2): the
    records' collapse intensities drawn again with replacement, refitted (module docstring
    of msa_band for the quantiles)."""
    x = np.asarray(im, dtype=float)
    rng = np.random.default_rng(seed)
    curves = []
    for _ in range(samples):
        try:
            curves.append(ida_fit(rng.choice(x, x.size), ddof).probability(at))
        except ValueError:
            continue
    return _quantiles(np.array(curves), len(at))


def ida_censored_band(
    im: np.ndarray, censored: np.ndarray, at: np.ndarray, samples: int = BOOTSTRAP_SAMPLES,
    seed: int = 0,
) -> np.ndarray:  # fmt: skip
    """The bootstrap band of :func:`ida_censored_fit`: the records (collapse intensities and
    censored ones together) drawn again with replacement, refitted (all at once by Newton's
    method, :func:`censored_refits`; a resample it does not settle by Nelder–Mead, as
    ida_censored_fit); quantiles as msa_band's."""
    x = np.asarray(im, dtype=float)
    c = np.asarray(censored, dtype=float)
    whole = ida_censored_fit(x, c)
    rng = np.random.default_rng(seed)
    picks = rng.integers(0, x.size + c.size, (samples, x.size + c.size))
    counts = np.stack([np.bincount(p, minlength=x.size + c.size) for p in picks])
    theta, beta, done = censored_refits(np.log(x), np.log(c), counts, whole)
    every = np.concatenate([x, c])
    reached = np.arange(every.size) < x.size
    curves = []
    for k, pick in enumerate(picks):
        xs, cs = every[pick][reached[pick]], every[pick][~reached[pick]]
        try:
            refit = (
                Fit(float(theta[k]), float(beta[k]), 0, pick.size)
                if done[k] and cs.size and _defines_fit(xs)
                else _refit_censored(xs, cs, whole)
            )
        except ValueError:
            continue
        curves.append(refit.probability(at))
    return _quantiles(np.array(curves), len(at))


def _refit_censored(x: np.ndarray, c: np.ndarray, whole: Fit) -> Fit:
    """A bootstrap refit by Nelder–Mead, from the whole data's fit, to BAND_TOLERANCE."""
    if c.size == 0:
        return ida_fit(x, 0)
    ida_fit(x, 0)  # the same checks as the whole data's
    found = optimize.minimize(
        _censored_negative_log_likelihood, np.log([whole.median, whole.beta]),
        args=(np.log(x), np.log(c)), method="Nelder-Mead",
        options={"xatol": BAND_TOLERANCE, "fatol": BAND_TOLERANCE * 1e-2, "maxiter": 20_000},
    )  # fmt: skip
    return Fit(float(math.exp(found.x[0])), float(math.exp(found.x[1])), 0, x.size + c.size)


def _defines_fit(x: np.ndarray) -> bool:
    """Two or more collapse intensities, not all equal (ida_fit's own conditions)."""
    return x.size >= 2 and bool(np.ptp(x) > 0.0)


#: Newton iterations of the censored refits, and their convergence in (ln θ, ln β).
NEWTON_ITERATIONS = 100
NEWTON_TOLERANCE = 1e-12
#: Halvings of a Newton step that would lower the likelihood (a damped Newton's method).
HALVINGS = 30


def censored_refits(
    logs: np.ndarray, censored_logs: np.ndarray, counts: np.ndarray, start: Fit
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The censored maximum likelihood of every resample at once: θ, β and whether each
    converged. ``counts`` (K × records) is how many times each record (the collapse
    intensities ``logs``, then the censored ``censored_logs``) is drawn. Newton's method on
    μ = ln θ and τ = ln β with the exact gradient and Hessian of the log-likelihood of the
    module docstring (for a censored record, with h = φ(v)/Φ(−v), v = (ln c − μ)/β:
    ∂ℓ/∂μ = h/β, ∂ℓ/∂τ = h·v, and h' = h(h − v)), from the data's own fit, each step halved
    while it would lower the likelihood (and a gradient step where the Hessian is not
    negative definite)."""
    nx = logs.size
    mx, mc = counts[:, :nx].astype(float), counts[:, nx:].astype(float)
    k = counts.shape[0]
    mu = np.full(k, math.log(start.median))
    tau = np.full(k, math.log(start.beta))
    converged = np.zeros(k, dtype=bool)

    def likelihood(mu: np.ndarray, tau: np.ndarray) -> np.ndarray:
        sigma = np.exp(tau)[:, None]
        u = (logs[None, :] - mu[:, None]) / sigma
        v = (censored_logs[None, :] - mu[:, None]) / sigma
        return (mx * (-0.5 * u * u - tau[:, None])).sum(1) + (mc * special.log_ndtr(-v)).sum(1)

    with np.errstate(all="ignore"):
        for _ in range(NEWTON_ITERATIONS):
            sigma = np.exp(tau)[:, None]
            u = (logs[None, :] - mu[:, None]) / sigma
            v = (censored_logs[None, :] - mu[:, None]) / sigma
            h = np.exp(-0.5 * v * v - 0.5 * math.log(2.0 * math.pi) - special.log_ndtr(-v))
            dh = h * (h - v)
            g_mu = (mx * u / sigma).sum(1) + (mc * h / sigma).sum(1)
            g_tau = (mx * (u * u - 1.0)).sum(1) + (mc * h * v).sum(1)
            h_mumu = -(mx / sigma**2).sum(1) - (mc * dh / sigma**2).sum(1)
            h_mutau = -(mx * 2.0 * u / sigma).sum(1) - (mc * (dh * v + h) / sigma).sum(1)
            h_tautau = -(mx * 2.0 * u * u).sum(1) - (mc * (dh * v * v + h * v)).sum(1)
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
    return np.where(ok, np.exp(mu), np.nan), np.where(ok, np.exp(tau), np.nan), ok


def ida_curve(
    im: np.ndarray, censored: np.ndarray, at: np.ndarray, ddof: int = BETA_DDOF
) -> tuple[Fit, np.ndarray]:
    """An IDA fragility and its band at ``at``: the censored maximum likelihood when some
    records are censored (β² over n whatever ddof), else the closed form with ``ddof``."""
    if np.asarray(censored).size:
        return ida_censored_fit(im, censored), ida_censored_band(im, censored, at)
    return ida_fit(im, ddof), ida_band(im, at, ddof=ddof)


def msa_curve(
    im: np.ndarray, runs: np.ndarray, exceedances: np.ndarray, at: np.ndarray
) -> tuple[Fit, np.ndarray]:
    """An MSA fragility and its band at ``at``."""
    return msa_fit(im, runs, exceedances), msa_band(im, runs, exceedances, at)


def _quantiles(curves: np.ndarray, size: int) -> np.ndarray:
    if not curves.size:
        return np.full((size, 2), np.nan)
    tail = (1.0 - CONFIDENCE) / 2.0
    return np.quantile(curves, [tail, 1.0 - tail], axis=0).T
