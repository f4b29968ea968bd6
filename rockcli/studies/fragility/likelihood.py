"""The two log-likelihoods of the fragility fits (rockcli/studies/fragility/fit.py), and their
maximisation by Newton's method with bounded work whatever the data.

Both are written in the probit's intercept and slope (a, b), P = Φ(a + b·t), on a
standardized log intensity t = (ln IM − m)/s (:func:`standardize`: the data's logs spread over
[−1, 1]), so that an intensity of 1e-300 or of 1e4 is as well scaled as one of 0.3, and
nothing is exponentiated but log-CDFs and Mills ratios:

- binomial counts (MSA): ℓ(a, b) = Σ_j z_j ln Φ(a + b·t_j) + (n_j − z_j) ln Φ(−a − b·t_j),
  concave in (a, b) (probit regression: Φ is log-concave and its argument linear in a, b);
- a lognormal with right-censored records (IDA), with u = b·y − a at each collapse
  intensity y and v = a − b·c at each censoring one c: ℓ(a, b) = Σ_i (ln b − u_i²/2) +
  Σ_k ln Φ(v_k), concave in (a, b) for b > 0 (Olsen 1978, "Note on the uniqueness of the
  maximum likelihood estimator for the Tobit model", Econometrica 46(5):1211–1215). Here
  b = s/β and a = b·(ln θ − m)/s.

:func:`maximise` is Newton's method on such a concave function, each step halved while it
would lower ℓ (a scaled gradient step where the Hessian is not negative definite, e.g. where
its weights underflow), at most NEWTON_ITERATIONS steps of at most HALVINGS halvings: a
search that does not settle stops there and says so (it does not converge only when ℓ has no
maximum, e.g. counts that fall with the intensity, whose ℓ grows as b → −∞).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy import special

#: Newton steps of a search, halvings of a step that would lower ℓ, and the step in (a, b),
#: relative to 1 + |a| + |b|, below which a search has settled: that step is still taken,
#: and near the maximum Newton's method squares its error at each step, so the result is
#: as exact as rounding lets ℓ's sums be (a tolerance much below 1e-9 only makes the
#: search chase that rounding).
NEWTON_ITERATIONS = 100
HALVINGS = 60
NEWTON_TOLERANCE = 1e-9
#: What −ℓ may rise by in a step, relative, as rounding: a sum of many terms is only that
#: exact, and a step at the maximum must not be halved on its noise.
ROUNDING = 1e-13
#: ln of the standard normal density's constant, ln √(2π).
LOG_ROOT_TWO_PI = 0.5 * math.log(2.0 * math.pi)

#: −ℓ and its derivatives at (a, b) for the problems ``rows``: (value, ga, gb, haa, hab, hbb).
Terms = Callable[[np.ndarray, np.ndarray, np.ndarray], tuple[np.ndarray, ...]]
#: −ℓ alone at (a, b) for the problems ``rows``.
Value = Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray]


def standardize(logs: np.ndarray) -> tuple[float, float]:
    """(m, s): the middle and half the range of ``logs`` (s = 1 when they are all equal)."""
    low, high = float(np.min(logs)), float(np.max(logs))
    half = 0.5 * (high - low)
    return 0.5 * (low + high), half if half > 0.0 else 1.0


def maximise(
    terms: Terms, value: Value, a: np.ndarray, b: np.ndarray, tolerance: float = NEWTON_TOLERANCE
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The maximum of K concave functions ℓ_k(a, b) at once (module docstring), from (a, b):
    (a, b) found and whether each search settled. ``terms`` and ``value`` give −ℓ."""
    a, b = np.array(a, dtype=float), np.array(b, dtype=float)
    done = np.zeros(a.size, dtype=bool)
    with np.errstate(all="ignore"):
        for _ in range(NEWTON_ITERATIONS):
            rows = np.flatnonzero(~done)
            if not rows.size:
                break
            da, db, f = _direction(terms, a[rows], b[rows], rows)
            size = np.maximum(np.abs(da), np.abs(db))
            settled = size <= tolerance * (1.0 + np.abs(a[rows]) + np.abs(b[rows]))
            go = ~settled  # a step below the tolerance is taken as it is, and the search ends
            da[go], db[go], stuck = _halve(value, a[rows[go]], b[rows[go]], rows[go], da[go],
                                           db[go], f[go])  # fmt: skip
            a[rows], b[rows] = a[rows] + da, b[rows] + db
            size[go] = np.maximum(np.abs(da[go]), np.abs(db[go]))
            settled = size <= tolerance * (1.0 + np.abs(a[rows]) + np.abs(b[rows]))
            settled[np.flatnonzero(go)[stuck]] = True
            done[rows[settled]] = True
    return a, b, done


def _direction(
    terms: Terms, a: np.ndarray, b: np.ndarray, rows: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Newton's step of each problem, or a gradient step of length at most 1 where the
    Hessian of −ℓ is not positive definite; and −ℓ there."""
    f, ga, gb, haa, hab, hbb = terms(a, b, rows)
    det = haa * hbb - hab * hab
    newton = (haa > 0.0) & (det > 0.0) & np.isfinite(det)
    scale = np.maximum(1.0, np.maximum(np.abs(ga), np.abs(gb)))
    da = np.where(newton, -(hbb * ga - hab * gb) / det, -ga / scale)
    db = np.where(newton, -(haa * gb - hab * ga) / det, -gb / scale)
    bad = ~(np.isfinite(da) & np.isfinite(db))
    return np.where(bad, 0.0, da), np.where(bad, 0.0, db), f


def _halve(
    value: Value, a: np.ndarray, b: np.ndarray, rows: np.ndarray, da: np.ndarray,
    db: np.ndarray, f: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
    """Each step halved until −ℓ does not rise (by more than its rounding, ROUNDING of it),
    at most HALVINGS times; a step that never gets there is 0 and its problem ``stuck`` (at
    its maximum to floating point)."""
    da, db = da.copy(), db.copy()
    pending = np.ones(a.size, dtype=bool)
    if not a.size:
        return da, db, pending
    for _ in range(HALVINGS):
        k = np.flatnonzero(pending)
        trial = value(a[k] + da[k], b[k] + db[k], rows[k])
        pending[k[trial <= f[k] + ROUNDING * np.abs(f[k])]] = False
        if not pending.any():
            break
        da[pending], db[pending] = 0.5 * da[pending], 0.5 * db[pending]
    return np.where(pending, 0.0, da), np.where(pending, 0.0, db), pending


# --- binomial counts (MSA) -----------------------------------------------------------------


def probit_terms(
    eta: np.ndarray, n: np.ndarray, z: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Each stripe's −[z ln Φ(η) + (n − z) ln Φ(−η)] and its first and second derivatives in
    η, through log-CDFs and the Mills ratios λ(±η) = φ(η)/Φ(±η) (no 0·log 0, no overflow):
    −z·λ(η) + (n − z)·λ(−η), and z·λ(η)(η + λ(η)) + (n − z)·λ(−η)(λ(−η) − η) ≥ 0."""
    with np.errstate(all="ignore"):
        up, down = special.log_ndtr(eta), special.log_ndtr(-eta)
        log_pdf = -0.5 * eta * eta - LOG_ROOT_TWO_PI
        rise, fall = np.exp(log_pdf - up), np.exp(log_pdf - down)
        hit, miss = z > 0.0, n - z > 0.0
        value = -(np.where(hit, z * up, 0.0) + np.where(miss, (n - z) * down, 0.0))
        score = np.where(miss, (n - z) * fall, 0.0) - np.where(hit, z * rise, 0.0)
        weight = np.where(hit, z * rise * (eta + rise), 0.0)
        weight = weight + np.where(miss, (n - z) * fall * (fall - eta), 0.0)
    return value, score, np.maximum(weight, 0.0)


def probit_fit(
    t: np.ndarray, n: np.ndarray, z: np.ndarray, tolerance: float = NEWTON_TOLERANCE
) -> tuple[float, float, bool]:
    """The binomial maximum likelihood (a, b) of counts z of n at standardized levels t, from
    the pooled fraction's probit and b = 1, and whether the search settled."""
    start = special.ndtri(float(z.sum() / n.sum()))

    def terms(a: np.ndarray, b: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, ...]:
        value, score, weight = probit_terms(a[0] + b[0] * t, n, z)
        sums = (value, score, score * t, weight, weight * t, weight * t * t)
        return tuple(np.array([s.sum()]) for s in sums)

    def value(a: np.ndarray, b: np.ndarray, rows: np.ndarray) -> np.ndarray:
        return np.array([probit_terms(a[0] + b[0] * t, n, z)[0].sum()] * a.size)

    a, b, done = maximise(terms, value, np.array([start]), np.array([1.0]), tolerance)
    return float(a[0]), float(b[0]), bool(done[0])


# --- a lognormal with right-censored records (IDA) ------------------------------------------


@dataclass(frozen=True)
class CensoredSets:
    """K data sets of standardized ln IM: per set, the collapse intensities' count n, mean ȳ
    and Σ(y − ȳ)² (all the likelihood needs of them: Σ(b·y − a)² = b²·Σ(y − ȳ)² +
    n·(b·ȳ − a)², a sum of two squares that a step near the maximum does not lose to
    rounding), and each censored record's set and value c."""

    count: np.ndarray
    mean: np.ndarray
    spread: np.ndarray
    row: np.ndarray
    limit: np.ndarray

    @classmethod
    def of(cls, y: np.ndarray, reached: np.ndarray) -> CensoredSets:
        """The sets of the rows of ``y`` (K × records), each a collapse intensity where
        ``reached`` and a censoring one elsewhere."""
        count = reached.sum(axis=1).astype(float)
        mean = np.where(reached, y, 0.0).sum(axis=1) / np.maximum(count, 1.0)
        spread = (np.where(reached, y - mean[:, None], 0.0) ** 2).sum(axis=1)
        row, col = np.nonzero(~reached)
        return cls(count, mean, spread, row, y[row, col])


def censored_fit(
    sets: CensoredSets, a: np.ndarray, b: np.ndarray, tolerance: float = NEWTON_TOLERANCE
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The censored maximum likelihood (a, b) of every set of ``sets`` (module docstring),
    from (a, b), and whether each search settled. The sets must each have a maximum
    (:func:`has_maximum`)."""

    def select(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The censored records of the sets ``rows`` (ascending): each one's place among
        ``rows``, and its value."""
        mine = np.zeros(a.size, dtype=bool)
        mine[rows] = True
        keep = mine[sets.row]
        return (np.cumsum(mine) - 1)[sets.row[keep]], sets.limit[keep]

    def value(ar: np.ndarray, br: np.ndarray, rows: np.ndarray) -> np.ndarray:
        row, c = select(rows)
        log_cdf = special.log_ndtr(ar[row] - br[row] * c)
        return _uncensored_value(sets, ar, br, rows) - np.bincount(
            row, weights=log_cdf, minlength=rows.size
        )

    def terms(ar: np.ndarray, br: np.ndarray, rows: np.ndarray) -> tuple[np.ndarray, ...]:
        row, c = select(rows)
        v = ar[row] - br[row] * c
        log_cdf = special.log_ndtr(v)
        ratio = np.exp(-0.5 * v * v - LOG_ROOT_TWO_PI - log_cdf)  # λ(v) = φ(v)/Φ(v)
        w = ratio * (v + ratio)

        def per(x: np.ndarray) -> np.ndarray:
            return np.bincount(row, weights=x, minlength=rows.size)

        n, mean, spread = sets.count[rows], sets.mean[rows], sets.spread[rows]
        f = _uncensored_value(sets, ar, br, rows) - per(log_cdf)
        ga = n * (ar - br * mean) - per(ratio)
        gb = br * spread + n * mean * (br * mean - ar) - n / br + per(c * ratio)
        hbb = spread + n * (mean * mean + 1.0 / (br * br)) + per(c * c * w)
        return f, ga, gb, n + per(w), -n * mean - per(c * w), hbb

    return maximise(terms, value, a, b, tolerance)


def _uncensored_value(
    sets: CensoredSets, a: np.ndarray, b: np.ndarray, rows: np.ndarray
) -> np.ndarray:
    """Σ_i (u_i²/2 − ln b) of each set's collapse intensities, u = b·y − a (+∞ where b ≤ 0)."""
    n, mean, spread = sets.count[rows], sets.mean[rows], sets.spread[rows]
    with np.errstate(all="ignore"):
        f = 0.5 * (b * b * spread + n * (b * mean - a) ** 2) - n * np.log(b)
    return np.where(b > 0.0, f, np.inf)


def has_maximum(y: np.ndarray, reached: np.ndarray) -> np.ndarray:
    """Whether each row's censored likelihood has a finite maximum: two or more distinct
    collapse intensities, or one or more below some censored record's intensity (else it
    grows without bound as β → 0, or, with no collapse, as θ → ∞)."""
    count = reached.sum(axis=1)
    top = np.max(y, axis=1, where=reached, initial=-math.inf)
    bottom = np.min(y, axis=1, where=reached, initial=math.inf)
    censored_top = np.max(y, axis=1, where=~reached, initial=-math.inf)
    return ((count >= 2) & (top > bottom)) | ((count >= 1) & (censored_top > top))
