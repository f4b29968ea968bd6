"""Brent's methods: the root of a function that changes sign, the minimum of a function in
a bracket — each a bounded number of evaluations, in pure Python.

R. P. Brent, *Algorithms for Minimization without Derivatives* (Prentice-Hall, 1973),
ch. 4 (``zero``: inverse quadratic interpolation and secant steps, with bisection whenever
they do not shrink the bracket fast enough) and ch. 5 (``localmin``: parabolic interpolation
with golden-section steps); the same procedures as W. H. Press et al., *Numerical Recipes*,
3rd ed., §9.3 and §10.3, and as scipy.optimize's ``brentq`` and ``fminbound``. Written here
rather than imported: ``scipy.optimize`` takes over half a second to import, more than a
whole ``rock kinematic`` run, whose searches (a capacity curve's zero, a capacity's ag, a
flexure's optimal hinge) each need a handful of evaluations of a plain function.

Pure and silent: only :mod:`math`.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Callable

#: The spacing of doubles at 1.
EPS = sys.float_info.epsilon
#: The golden section's smaller share, (3 − √5)/2.
GOLDEN_SHARE = 0.5 * (3.0 - math.sqrt(5.0))
#: Evaluations allowed to a search: Brent's methods need about a dozen on a smooth function
#: (a root to within 8 ulps, a minimum to √ε); the cap bounds any other, which returns the best
#: point found.
MAX_EVALUATIONS = 200


def brent_root(
    f: Callable[[float], float], lo: float, hi: float, f_lo: float, f_hi: float
) -> float:
    """The point in [lo, hi] where f changes sign, to within 8 ulps (Brent's ``zero``).

    Given f(lo) > 0 ≥ f(hi) (or the reverse): where f passes from one class to the other, as
    a bisection that keeps ``lo`` where f > 0 finds it — a zero of a continuous f, the jump of
    one that drops through zero, the start of an interval where f is zero (zero counts with
    the non-positive side: from a point where f is zero the search bisects). ``f_lo`` may be
    ``inf`` (not evaluated, known positive): the first step then bisects. On a smooth f about
    a dozen evaluations; on a jump more than a bisection's (up to about 140 from a bracket of
    1e-3 to 4 ulps); at most MAX_EVALUATIONS, after which the best point found is returned.
    """
    a, fa, b, fb = lo, f_lo, hi, f_hi
    c, fc = a, fa
    d = e = b - a
    for _ in range(MAX_EVALUATIONS):
        if (fb > 0.0) == (fc > 0.0):  # b and c on one side: c goes back to a
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):  # b the best guess
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 2.0 * EPS * abs(b) + 0.5 * math.ulp(0.0)
        m = 0.5 * (c - b)
        if abs(m) <= tol:
            break
        if abs(e) >= tol and abs(fa) > abs(fb) and fb != 0.0:
            s = fb / fa
            if a == c:  # secant
                p, q = 2.0 * m * s, 1.0 - s
            else:  # inverse quadratic interpolation
                q, r = fa / fc, fb / fc
                p = s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0))
                q = (q - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0.0:
                q = -q
            else:
                p = -p
            if 2.0 * p < min(3.0 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:  # bisection
                d = e = m
        else:
            d = e = m
        a, fa = b, fb
        b += d if abs(d) > tol else math.copysign(tol, m)
        fb = f(b)
    return b


def brent_minimum(
    f: Callable[[float], float], a: float, b: float, xtol: float
) -> tuple[float, float]:
    """(x, f(x)): a local minimum of f in [a, b] (Brent's ``localmin``), x resolved to
    about √ε·|x| + ``xtol`` (below that, values of f near a minimum differ by rounding)."""
    x = w = v = a + GOLDEN_SHARE * (b - a)
    fx = fw = fv = f(x)
    d = e = 0.0
    for _ in range(MAX_EVALUATIONS):
        m = 0.5 * (a + b)
        tol = math.sqrt(EPS) * abs(x) + xtol / 3.0
        if abs(x - m) <= 2.0 * tol - 0.5 * (b - a):
            break
        p = q = r = 0.0
        if abs(e) > tol:  # a parabola through x, w, v
            r = (x - w) * (fx - fv)
            q = (x - v) * (fx - fw)
            p = (x - v) * q - (x - w) * r
            q = 2.0 * (q - r)
            if q > 0.0:
                p = -p
            else:
                q = -q
            r, e = e, d
        if abs(p) < abs(0.5 * q * r) and q * (a - x) < p < q * (b - x):
            d = p / q
            if (x + d) - a < 2.0 * tol or b - (x + d) < 2.0 * tol:
                d = tol if x < m else -tol
        else:  # a golden-section step into the larger part
            e = (b if x < m else a) - x
            d = GOLDEN_SHARE * e
        u = x + (d if abs(d) >= tol else math.copysign(tol, d))
        fu = f(u)
        if fu <= fx:
            if u < x:
                b = x
            else:
                a = x
            v, fv, w, fw, x, fx = w, fw, x, fx, u, fu
        else:
            if u < x:
                a = u
            else:
                b = u
            if fu <= fw or w == x:
                v, fv, w, fw = w, fw, u, fu
            elif fu <= fv or v in (x, w):
                v, fv = u, fu
    return x, fx
