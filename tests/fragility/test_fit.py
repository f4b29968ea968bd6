"""The fragility fits (rockcli/fragility/fit.py) against independent computations.

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

from rockcli.fragility.fit import BETA_DDOF, ida_band, ida_fit, msa_band, msa_fit

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


def test_the_bootstrap_bands_hold_the_fit_and_repeat_with_their_seed() -> None:
    at = np.array([0.2, 0.4, 0.8])
    for band, fit in (
        (msa_band(LEVELS, RUNS, EXCEEDANCES, at, samples=300), msa_fit(LEVELS, RUNS, EXCEEDANCES)),
        (ida_band(COLLAPSES, at, samples=300), ida_fit(COLLAPSES)),
    ):
        assert band.shape == (3, 2) and np.all(band[:, 0] <= band[:, 1])
        p = fit.probability(at)
        assert np.all((band[:, 0] <= p) & (p <= band[:, 1]))
    again = msa_band(LEVELS, RUNS, EXCEEDANCES, at, samples=300)
    assert np.array_equal(again, msa_band(LEVELS, RUNS, EXCEEDANCES, at, samples=300))


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
    from rockcli.fragility.fit import ida_censored_fit

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
    from rockcli.fragility.fit import ida_censored_fit

    assert ida_censored_fit(COLLAPSES, np.array([])) == ida_fit(COLLAPSES)


def test_the_censored_band_holds_its_fit() -> None:
    from rockcli.fragility.fit import ida_censored_band, ida_censored_fit

    at = np.array([0.2, 0.4, 0.8])
    band = ida_censored_band(COLLAPSES, CENSORED, at, samples=200)
    p = ida_censored_fit(COLLAPSES, CENSORED).probability(at)
    assert band.shape == (3, 2) and np.all((band[:, 0] <= p) & (p <= band[:, 1]))


def test_the_bands_refits_are_the_maximum_likelihood_of_each_resample() -> None:
    """The band refits every resample by Fisher scoring at once (fit.probit_refits): each
    equals msa_fit's Nelder–Mead search on that resample (to 1e-6, the search's own
    tolerance); a separated resample (no finite maximum) is left to msa_fit."""
    from rockcli.fragility.fit import probit_refits

    whole = msa_fit(LEVELS, RUNS, EXCEEDANCES)
    rng = np.random.default_rng(7)
    draws = np.array([rng.binomial(RUNS, EXCEEDANCES / RUNS) for _ in range(50)])
    separated = np.array([0, 0, 0, 20, 20, 20, 20])
    theta, beta, ok = probit_refits(np.log(LEVELS), RUNS, np.vstack([draws, separated]), whole)
    assert ok[:-1].all() and not ok[-1]
    for k, z in enumerate(draws):
        fit = msa_fit(LEVELS, RUNS, z, (whole.median, whole.beta), 1e-12)
        assert theta[k] == pytest.approx(fit.median, rel=1e-6)
        assert beta[k] == pytest.approx(fit.beta, rel=1e-6)


def test_the_censored_refits_are_the_censored_maximum_likelihood_of_each_resample() -> None:
    """fit.censored_refits (Newton's method, every resample at once) against
    ida_censored_fit's Nelder–Mead search on each resample, to 1e-6 (the search's)."""
    from rockcli.fragility.fit import censored_refits, ida_censored_fit

    whole = ida_censored_fit(COLLAPSES, CENSORED)
    every = np.concatenate([COLLAPSES, CENSORED])
    reached = np.arange(every.size) < COLLAPSES.size
    rng = np.random.default_rng(11)
    picks = rng.integers(0, every.size, (60, every.size))
    counts = np.stack([np.bincount(p, minlength=every.size) for p in picks])
    theta, beta, ok = censored_refits(np.log(COLLAPSES), np.log(CENSORED), counts, whole)
    checked = 0
    for k, pick in enumerate(picks):
        xs, cs = every[pick][reached[pick]], every[pick][~reached[pick]]
        if not cs.size or np.ptp(xs) == 0.0:
            continue
        fit = ida_censored_fit(xs, cs, 1e-12)
        assert ok[k]
        assert theta[k] == pytest.approx(fit.median, rel=1e-6)
        assert beta[k] == pytest.approx(fit.beta, rel=1e-6)
        checked += 1
    assert checked > 40
