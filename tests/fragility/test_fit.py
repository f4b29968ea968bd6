"""The fragility fits (rockcli/studies/fragility/fit.py) against independent computations.

- IDA: θ and β against numpy on the logs of the collapse intensities, and against
  scipy.stats.lognorm.fit with its location at 0 (the maximum likelihood, divisor n); with
  ddof = 1 against numpy's std with divisor n − 1 (Baker 2015's β). Tolerance 1e-12 relative:
  the same closed form evaluated in another order.
- MSA: θ and β against the optimum of the binomial log-likelihood found by brute force on a
  fine grid of (θ, β), for a hand-made data set (seven stripes of 20 runs); the fit must be
  within two grid steps of it and its likelihood at least the grid's best.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from rockcli.studies.fragility.fit import BETA_DDOF, ida_band, ida_fit, msa_band, msa_fit

#: Collapse intensities of ten records [g] (hand-made).
COLLAPSES = np.array([0.21, 0.34, 0.29, 0.45, 0.18, 0.52, 0.39, 0.27, 0.61, 0.33])
#: Seven stripes: intensity [g], runs, exceedances (hand-made, increasing as a fragility).
LEVELS = np.array([0.1, 0.2, 0.3, 0.4, 0.6, 0.8, 1.0])
RUNS = np.full(7, 20)
EXCEEDANCES = np.array([0, 1, 4, 9, 14, 18, 19])


def test_ida_is_the_lognormal_of_the_logs() -> None:
    fit = ida_fit(COLLAPSES)
    logs = np.log(COLLAPSES)
    assert fit.median == pytest.approx(np.exp(logs.mean()), rel=1e-12)
    assert fit.beta == pytest.approx(logs.std(ddof=0), rel=1e-12)
    assert fit.beta_ddof == BETA_DDOF == 0 and fit.n == 10
    shape, loc, scale = stats.lognorm.fit(COLLAPSES, floc=0)
    assert loc == 0 and fit.beta == pytest.approx(shape, rel=1e-9)
    assert fit.median == pytest.approx(scale, rel=1e-9)
    baker = ida_fit(COLLAPSES, ddof=1)
    assert baker.beta == pytest.approx(logs.std(ddof=1), rel=1e-12)
    assert baker.median == fit.median


def log_likelihood(theta: np.ndarray, beta: np.ndarray) -> np.ndarray:
    """The binomial log-likelihood of LEVELS, RUNS, EXCEEDANCES at every (θ, β) of a grid,
    written here from the definition (Baker 2015), with the binomial coefficients."""
    from scipy.special import gammaln

    u = (np.log(LEVELS)[None, None, :] - np.log(theta)[:, None, None]) / beta[None, :, None]
    z, n = EXCEEDANCES, RUNS
    coefficient = gammaln(n + 1) - gammaln(z + 1) - gammaln(n - z + 1)
    terms = coefficient + z * stats.norm.logcdf(u) + (n - z) * stats.norm.logcdf(-u)
    return terms.sum(axis=2)


def test_msa_is_the_binomial_maximum_likelihood() -> None:
    fit = msa_fit(LEVELS, RUNS, EXCEEDANCES)
    theta = np.linspace(0.3, 0.6, 601)  # steps of 5e-4 g
    beta = np.linspace(0.2, 0.9, 701)  # steps of 1e-3
    grid = log_likelihood(theta, beta)
    i, j = np.unravel_index(np.argmax(grid), grid.shape)
    assert fit.median == pytest.approx(theta[i], abs=2 * (theta[1] - theta[0]))
    assert fit.beta == pytest.approx(beta[j], abs=2 * (beta[1] - beta[0]))
    at_fit = log_likelihood(np.array([fit.median]), np.array([fit.beta]))[0, 0]
    assert at_fit >= grid.max() - 1e-9
    assert fit.beta_ddof is None and fit.n == 140


@pytest.mark.parametrize(
    ("z", "why"),
    [
        (np.zeros(7), "none exceeds"),
        (RUNS.copy(), "every run exceeds"),
        (np.array([0, 1, 4, 9, 14, 18, 21]), "more exceedances than runs"),
        (np.array([0, 1, 4, 9.5, 14, 18, 19]), "half an exceedance"),
    ],
)
def test_an_msa_data_set_that_defines_no_fit_says_why(z: np.ndarray, why: str) -> None:
    with pytest.raises(ValueError):
        msa_fit(LEVELS, RUNS, z)


@pytest.mark.parametrize("im", [[0.3], [0.3, 0.3, 0.3], [0.3, -0.1], [0.3, np.nan]])
def test_an_ida_data_set_that_defines_no_fit_says_why(im: list[float]) -> None:
    with pytest.raises(ValueError):
        ida_fit(np.array(im))


def test_the_bands_hold_the_fit() -> None:
    """The MSA band (profile likelihood) and the IDA band (noncentral t) are intervals that
    hold the fit's own probability: the profile deviance is 0 at the fit, and the exact IDA
    band holds it with either divisor of β (n or n − 1)."""
    at = np.array([0.2, 0.4, 0.8])
    for band, fits in (
        (msa_band(LEVELS, RUNS, EXCEEDANCES, at), [msa_fit(LEVELS, RUNS, EXCEEDANCES)]),
        (ida_band(COLLAPSES, at), [ida_fit(COLLAPSES), ida_fit(COLLAPSES, ddof=1)]),
    ):
        assert band.shape == (3, 2) and np.all(band[:, 0] <= band[:, 1])
        for fit in fits:
            p = fit.probability(at)
            assert np.all((band[:, 0] <= p) & (p <= band[:, 1]))


#: Three records of COLLAPSES' study that did not reach the state by the scan's end, 0.7 g.
CENSORED = np.full(3, 0.7)


def censored_log_likelihood(theta: np.ndarray, beta: np.ndarray) -> np.ndarray:
    """The log-likelihood of COLLAPSES with CENSORED right-censored, at every (θ, β) of a grid,
    from the definition: Σ ln pdf_lognormal(x_i) + Σ ln(1 − CDF(c_k)) (scipy.stats.lognorm)."""
    s, scale = beta[None, :, None], theta[:, None, None]
    density = stats.lognorm.logpdf(COLLAPSES[None, None, :], s, scale=scale).sum(axis=2)
    survival = stats.lognorm.logsf(CENSORED[None, None, :], s, scale=scale).sum(axis=2)
    return density + survival


def test_censored_ida_is_the_censored_maximum_likelihood() -> None:
    """Against a brute-force grid (within two steps; its likelihood at least the grid's best)
    and against scipy's own censored fit, stats.lognorm.fit(CensoredData, floc=0), whose
    optimiser stops earlier (agreement 1e-3; rock's likelihood at least scipy's)."""
    from rockcli.studies.fragility.fit import ida_censored_fit

    fit = ida_censored_fit(COLLAPSES, CENSORED)
    theta = np.linspace(0.3, 0.7, 801)  # steps of 5e-4 g
    beta = np.linspace(0.3, 1.0, 701)  # steps of 1e-3
    grid = censored_log_likelihood(theta, beta)
    i, j = np.unravel_index(np.argmax(grid), grid.shape)
    assert fit.median == pytest.approx(theta[i], abs=2 * (theta[1] - theta[0]))
    assert fit.beta == pytest.approx(beta[j], abs=2 * (beta[1] - beta[0]))
    at_fit = censored_log_likelihood(np.array([fit.median]), np.array([fit.beta]))[0, 0]
    assert at_fit >= grid.max() - 1e-9
    data = stats.CensoredData(uncensored=COLLAPSES, right=CENSORED)
    shape, _, scale = stats.lognorm.fit(data, floc=0)
    assert fit.median == pytest.approx(scale, rel=1e-3)
    assert fit.beta == pytest.approx(shape, rel=1e-3)
    at_scipy = censored_log_likelihood(np.array([scale]), np.array([shape]))[0, 0]
    assert at_fit >= at_scipy - 1e-12
    # Censored records pull the median up: they lie above every collapse but one.
    assert fit.median > ida_fit(COLLAPSES).median and fit.n == 13


def test_censored_ida_without_censored_records_is_the_closed_form() -> None:
    from rockcli.studies.fragility.fit import ida_censored_fit

    assert ida_censored_fit(COLLAPSES, np.array([])) == ida_fit(COLLAPSES)


def test_the_censored_band_holds_its_fit_and_repeats_with_its_seed() -> None:
    from rockcli.studies.fragility.fit import ida_censored_band, ida_censored_fit

    at = np.array([0.2, 0.4, 0.8])
    band = ida_censored_band(COLLAPSES, CENSORED, at, samples=200)
    p = ida_censored_fit(COLLAPSES, CENSORED).probability(at)
    assert band.shape == (3, 2) and np.all((band[:, 0] <= p) & (p <= band[:, 1]))
    assert np.array_equal(band, ida_censored_band(COLLAPSES, CENSORED, at, samples=200))


def test_the_msa_band_is_the_range_of_p_over_the_likelihood_region() -> None:
    """The MSA band at x is the range of P(x) over the (θ, β) whose deviance from the fit is
    at most χ²₁(0.95) = 3.84 (the profile likelihood; Venzon & Moolgavkar 1988), checked two
    independent ways. (1) By brute force on a grid of (θ, β) with the log-likelihood written
    from the definition (log_likelihood above): every grid point inside the region is a
    candidate, so the band holds the grid's range, and it exceeds it by at most what one grid
    step moves P (θ steps of 1.25e-3 g and β steps of 0.5 % move P by < 3e-3 here; 5e-3
    allowed). (2) At each end η = Φ⁻¹(P), the deviance maximised over β by scipy's bounded
    scalar search (scipy.stats' log-CDFs) is 3.84, to 1e-6."""
    from scipy import optimize, special

    at = np.array([0.2, 0.4, 0.8])
    fit = msa_fit(LEVELS, RUNS, EXCEEDANCES)
    band = msa_band(LEVELS, RUNS, EXCEEDANCES, at)
    theta, beta = np.linspace(0.25, 0.75, 401), np.geomspace(0.2, 1.6, 401)
    best = log_likelihood(np.array([fit.median]), np.array([fit.beta]))[0, 0]
    region = 2.0 * (best - log_likelihood(theta, beta)) <= stats.chi2.ppf(0.95, 1)
    assert not (region[0].any() or region[-1].any() or region[:, 0].any() or region[:, -1].any())
    p = special.ndtr(np.log(at / theta[:, None, None]) / beta[None, :, None])[region]
    assert np.all(band[:, 0] <= p.min(axis=0) + 1e-9) and np.all(band[:, 1] >= p.max(axis=0) - 1e-9)
    assert np.all(p.min(axis=0) - band[:, 0] < 5e-3) and np.all(band[:, 1] - p.max(axis=0) < 5e-3)

    def minus_log_likelihood(u: np.ndarray) -> float:  # u_j = Φ⁻¹(p_j) at each level
        n, z = RUNS, EXCEEDANCES
        return -float((z * stats.norm.logcdf(u) + (n - z) * stats.norm.logcdf(-u)).sum())

    at_fit = minus_log_likelihood(np.log(LEVELS / fit.median) / fit.beta)
    for x, ends in zip(at, band, strict=True):
        for end in ends:  # Φ⁻¹(P(x)) held at the end, maximised over b = 1/β
            eta = float(stats.norm.ppf(end))
            found = optimize.minimize_scalar(
                lambda b, x=x, eta=eta: minus_log_likelihood(eta + b * np.log(LEVELS / x)),
                bounds=(1e-6, 50.0), method="bounded", options={"xatol": 1e-10},
            )  # fmt: skip
            deviance = 2.0 * (found.fun - at_fit)
            assert deviance == pytest.approx(stats.chi2.ppf(0.95, 1), abs=1e-6)


def test_the_censored_refits_are_the_censored_maximum_likelihood_of_each_resample() -> None:
    """fit.censored_refits (Newton's method, every resample at once) against scipy's
    Nelder–Mead search of each resample's censored log-likelihood, written here with
    scipy.stats' log-density and log-survival, from the resample's own moments: rock's
    likelihood at least scipy's best − 1e-9, θ and β within 1e-5 (the search's)."""
    from scipy import optimize

    from rockcli.studies.fragility.fit import censored_refits, ida_censored_fit

    whole = ida_censored_fit(COLLAPSES, CENSORED)
    every = np.concatenate([COLLAPSES, CENSORED])
    reached = np.arange(every.size) < COLLAPSES.size
    rng = np.random.default_rng(11)
    picks = rng.integers(0, every.size, (60, every.size))
    theta, beta, ok = censored_refits(np.log(every[picks]), reached[picks], whole)
    checked = 0
    for k, pick in enumerate(picks):
        xs, cs = every[pick][reached[pick]], every[pick][~reached[pick]]
        if not cs.size or np.ptp(xs) == 0.0:
            continue

        def minus(p: np.ndarray, xs: np.ndarray = xs, cs: np.ndarray = cs) -> float:
            s = np.exp(p[1])
            return -float(stats.norm.logpdf(np.log(xs), p[0], s).sum()
                          + stats.norm.logsf(np.log(cs), p[0], s).sum())  # fmt: skip

        start = [np.log(xs).mean(), np.log(np.log(xs).std())]
        options = {"xatol": 1e-10, "fatol": 1e-13, "maxiter": 20_000}
        found = optimize.minimize(minus, start, method="Nelder-Mead", options=options)
        assert ok[k]
        assert minus(np.log([theta[k], beta[k]])) <= found.fun + 1e-9
        assert theta[k] == pytest.approx(np.exp(found.x[0]), rel=1e-5)
        assert beta[k] == pytest.approx(np.exp(found.x[1]), rel=1e-5)
        checked += 1
    assert checked > 40
