"""The lowest intensity at which a response first reaches each damage state: hunt and fill.

A rocking block's response is not monotonic in the intensity: a block overturned by a pulse
can survive a stronger one (the "safe region" of Makris & Konstantinidis 2003, EESD
32:265–289), so a bisection between a surviving and an overturning intensity can converge to
any boundary between them, not to the lowest one. The search here (the hunt-and-fill of IDA,
Vamvatsikos & Cornell 2002, EESD 31:491–514, "hunt" step) first scans the scales upwards at a
fixed step until the damage state is reached, then bisects inside that first step only:
the result is the first exceedance, up to the bisection's tolerance, unless the response
reaches and leaves the damage state inside one step of the scan (a window narrower than the
step, which the scan cannot see: the step is reported with the result).

Damage states are levels of a response measure (max θ/α; an overturn as +inf), in
increasing order: a scale below the first exceedance of one level cannot reach a higher one,
so each level's scan starts where the previous one's bracket starts, and every response is
computed once (cached by scale).

Pure and silent: the response is the caller's function.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

#: Most scales a scan may try ((last − first)/step + 1): a bound on a typo (a step of 1e-9
#: would list 10⁹ intensities), for `rock fragility` and `rock spectrum overturning` alike.
MAX_SCAN_POINTS = 100_000
#: The narrowest bisection bracket asked for, as a share of the scan's last scale: a float
#: carries 16 digits, so a tolerance below last·1e-12 cannot be met (the bracket stops
#: shrinking), and the search would never end.
MIN_TOLERANCE_SHARE = 1e-12
#: Most bisection steps of one bracket: a step of the scan halved 200 times is far below any
#: tolerance a float can tell, so the loop ends whatever it is given.
MAX_BISECTIONS = 200


def scan_problem(first: float, step: float, last: float, tolerance: float) -> str | None:
    """What makes a scan unbounded (too many scales, or a tolerance narrower than the float
    spacing at ``last`` allows), None when it is bounded."""
    if (last - first) / step + 1.0 > MAX_SCAN_POINTS:
        return f"more than {MAX_SCAN_POINTS} scales: raise the step to at least " \
               f"{(last - first) / (MAX_SCAN_POINTS - 1):.3g}"  # fmt: skip
    if tolerance < MIN_TOLERANCE_SHARE * last:
        return f"a tolerance below {MIN_TOLERANCE_SHARE:g} of the last intensity " \
               f"({MIN_TOLERANCE_SHARE * last:.3g}), which a float cannot resolve"  # fmt: skip
    return None


@dataclass(frozen=True)
class Exceedance:
    """The first exceedance of one level.

    Attributes:
        level: the damage state's level of the response.
        scale: the lowest scale found at which the response reaches it (the upper end of the
            last bracket), None when no scale up to the last one does.
        below: the highest scale known below it (the lower end of the bracket; None when it
            is reached at the first scale, or never).
    """

    level: float
    scale: float | None
    below: float | None


def scan_points(first: float, step: float, last: float) -> list[float]:
    """The scan's scales: first, first + step, … up to last (to 1e-9 of a step)."""
    count = int(math.floor((last - first) / step + 1e-9)) + 1
    return [first + k * step for k in range(count)]


def first_exceedances(
    response: Callable[[float], float],
    levels: Sequence[float],
    *,
    first: float,
    step: float,
    last: float,
    tolerance: float,
) -> tuple[list[Exceedance], int]:
    """Each level's first exceedance by the response, scanning scales first, first + step,
    … up to last, then bisecting the first step that reaches it down to ``tolerance``; and
    the number of responses computed. Levels must increase; scales and steps be > 0."""
    if not (first > 0.0 and step > 0.0 and last >= first and tolerance > 0.0):
        raise ValueError("the scan needs first > 0, step > 0, last ≥ first, tolerance > 0")
    if any(b <= a for a, b in zip(levels, levels[1:], strict=False)):
        raise ValueError("the damage states' levels must increase")
    known: dict[float, float] = {}

    def measure(scale: float) -> float:
        if scale not in known:
            known[scale] = response(scale)
        return known[scale]

    scales = scan_points(first, step, last)
    count = len(scales)
    found, start = [], 0
    for level in levels:
        hit = next((k for k in range(start, count) if measure(scales[k]) >= level), None)
        if hit is None:
            found.append(Exceedance(level, None, None))
            start = count
            continue
        if hit == 0:
            found.append(Exceedance(level, scales[0], None))
            continue
        lo, hi = scales[hit - 1], scales[hit]
        for _ in range(MAX_BISECTIONS):
            mid = 0.5 * (lo + hi)
            if hi - lo <= tolerance or not lo < mid < hi:  # met, or the floats ran out
                break
            if measure(mid) >= level:
                hi = mid
            else:
                lo = mid
        found.append(Exceedance(level, hi, lo))
        start = hit - 1
    return found, len(known)
