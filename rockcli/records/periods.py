"""The oscillator periods of a response spectrum: the default grid and the ``--periods`` text.

Two forms, one per value of the option:

- a list ``0.1,0.2,0.5`` (periods in seconds, any order; sorted, duplicates dropped);
- a range ``START:STOP:N``: N periods log-spaced from START to STOP inclusive
  (``0.05:4:100``), like ``numpy.geomspace``.

Every period lies in [MIN_PERIOD, MAX_PERIOD]; anything else is one InputError naming
``--periods``, the value and the two forms. No click; numpy is imported inside the functions,
so that the help of ``rock record spectrum`` reads the grid's constants without it.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from rockcli.errors import InputError
from rockcli.numbers import ascii_float

if TYPE_CHECKING:
    import numpy as np

#: The default grid: GRID_COUNT periods log-spaced from GRID_FIRST to GRID_LAST [s] …
GRID_FIRST = 0.01
GRID_LAST = 4.0
GRID_COUNT = 100
#: … plus the round periods one reads a spectrum at [s] (merged into the grid, sorted).
ROUND_PERIODS = (0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0)

#: Shortest period accepted [s]: a 1 ms oscillator is already rigid for any recorded motion
#: (Sa = PGA), and far below it ω² = (2π/T)² overflows.
MIN_PERIOD = 0.001
#: Longest period accepted [s]: the exact-step coefficients cancel terms of order 1/(ω·dt),
#: losing about log10(1/(ω·dt)²) digits; at 100 s and dt = 0.005 s, 7 of 16.
MAX_PERIOD = 100.0
#: Most periods one spectrum may ask for (each costs a pass over the record).
MAX_PERIODS = 2000
#: At least this many periods in a range START:STOP:N.
MIN_RANGE_COUNT = 2

OPTION = "--periods"
ALLOWED = (
    f"periods in seconds, {MIN_PERIOD:g} to {MAX_PERIOD:g}: a list like 0.1,0.2,0.5, "
    f"or START:STOP:N for N (2 to {MAX_PERIODS}) log-spaced periods like 0.05:4:100"
)


def default_periods() -> np.ndarray:
    """The default grid [s]: 100 log-spaced periods 0.01–4 s and the round ones, sorted."""
    import numpy as np

    grid = np.geomspace(GRID_FIRST, GRID_LAST, GRID_COUNT)
    return np.unique(np.concatenate([grid, ROUND_PERIODS]))


def parse_periods(text: str | None) -> np.ndarray:
    """The periods [s] of ``--periods`` (the default grid for None), sorted, no duplicates.

    Raises:
        InputError: empty, unparsable, non-finite, out of range, or too many periods.
    """
    import numpy as np

    if text is None:
        return default_periods()
    body = text.strip()
    periods = _parse_range(body, text) if ":" in body else _parse_list(body, text)
    if not all(MIN_PERIOD <= p <= MAX_PERIOD for p in periods):
        raise _error("period out of range", text)
    return np.unique(np.array(periods, dtype=float))


def _parse_list(body: str, text: str) -> list[float]:
    """``0.1,0.2,0.5`` → the floats (InputError if any item is not a finite number)."""
    items = body.split(",")
    if len(items) > MAX_PERIODS:
        raise _error("too many periods", text)
    return [_number(item, text) for item in items]


def _parse_range(body: str, text: str) -> list[float]:
    """``START:STOP:N`` → N log-spaced periods from START to STOP (START < STOP)."""
    parts = body.split(":")
    if len(parts) != 3:
        raise _error("not a range START:STOP:N", text)
    start, stop = _number(parts[0], text), _number(parts[1], text)
    count = parts[2].strip()
    if not (count.isascii() and count.isdigit()):
        raise _error("the count N of START:STOP:N is not a whole number", text)
    n = int(count)
    if not MIN_RANGE_COUNT <= n <= MAX_PERIODS:
        raise _error("the count N of START:STOP:N is out of range", text)
    if not MIN_PERIOD <= start < stop <= MAX_PERIOD:
        raise _error("the range START:STOP:N needs START < STOP, both in range", text)
    import numpy as np

    return [float(p) for p in np.geomspace(start, stop, n)]


def _number(item: str, text: str) -> float:
    """One finite number (InputError otherwise, e.g. an empty item or 'nan')."""
    try:
        value = ascii_float(item.strip())
    except ValueError:
        raise _error(f"not a number: {item.strip()!r}", text) from None
    if not math.isfinite(value):
        raise _error(f"not a finite number: {item.strip()!r}", text)
    return value


def _error(problem: str, text: str) -> InputError:
    return InputError(problem, where=OPTION, value=text, allowed=ALLOWED)
