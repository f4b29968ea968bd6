"""The tolerance check: each polarity integrated again at a tighter tolerance, and whether its
result moved.

Rocking with many small impacts can be chaotic: the impact times depend on the last digits of
the integration, so the peak after dozens of impacts depends on the tolerance
(spec/engine.md, "Sensitivity": small-amplitude, chattering rocking is ill-conditioned,
physically and numerically). A run whose max θ/α moves by more than
:data:`SENSITIVE_CHANGE` (relative), or whose overturning verdict changes, when the
tolerances are divided by :data:`TIGHT_FACTOR` is *tolerance-sensitive*: neither number is
exact, and the reader must know.

Pure and silent: results in, results out.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import replace

import numpy as np

from rockcli.dynamics.result import Assessment, RockingRun, RunStatus, ToleranceCheck
from rockcli.dynamics.settings import SolverSettings
from rockcli.mechanics import Rocker

#: The tight run's tolerances are the run's own divided by this (1e-8 → 1e-11 by default):
#: three digits tighter, where the fast engine still costs about as much (spec/engine.md: cost
#: nearly flat from 1e-6 to 1e-10; measured 1.1 → 1.8 ms on the 40 s NORTHR record).
TIGHT_FACTOR = 1000.0
#: ... but never below the tightest tolerance the engine accepts (model.schema's
#: TIGHTEST_TOLERANCE: below it the step's error estimate is rounding noise).
TIGHTEST = 1e-12
#: Relative change of max θ/α beyond which a run is tolerance-sensitive: 1 %, ten times the
#: agreement of the default tolerance with the reference engine on robust runs (spec/engine.md:
#: "max_ratio agrees with the tight reference to 1e-3 and better"), so robust runs are never
#: flagged (measured: 560 runs of the paper's §3.3 walls on 14 real records moved by at most
#: 2e-5) and a chaotic one is.
SENSITIVE_CHANGE = 0.01
#: Statuses whose max θ/α and verdict mean something (a run stopped at a guard decides
#: nothing: its tolerance sensitivity is not known).
DECIDED = (RunStatus.COMPLETED, RunStatus.OVERTURNED)


def tight_settings(settings: SolverSettings) -> SolverSettings:
    """The settings of the tight run: rtol and atol over TIGHT_FACTOR, at least TIGHTEST."""
    return replace(settings, rtol=tighter(settings.rtol), atol=tighter(settings.atol))


def tighter(tolerance: float) -> float:
    """A tolerance over TIGHT_FACTOR, at least TIGHTEST, rounded to 12 digits (1e-8 gives
    1e-11, not the quotient's 1.0000000000000001e-11)."""
    return max(float(f"{tolerance / TIGHT_FACTOR:.12g}"), TIGHTEST)


def can_tighten(settings: SolverSettings) -> bool:
    """False when rtol and atol are both at TIGHTEST already (the tight run would be the same
    run)."""
    tight = tight_settings(settings)
    return tight.rtol < settings.rtol or tight.atol < settings.atol


def relative_change(a: float, b: float) -> float:
    """|a − b| / max(|a|, |b|), 0 when both are 0 [-]."""
    scale = max(abs(a), abs(b))
    return abs(a - b) / scale if scale > 0.0 else 0.0


def is_sensitive(run: RockingRun, tight: RockingRun) -> bool | None:
    """Whether the tight run tells another story: the overturning verdict changes, or (neither
    overturned) max θ/α moves by more than SENSITIVE_CHANGE relative; None when either run
    ended at a guard."""
    if run.status not in DECIDED or tight.status not in DECIDED:
        return None
    if run.overturned != tight.overturned:
        return True
    if run.overturned:
        return False  # both overturned: max θ/α is overturn angle/α in both
    return relative_change(run.max_ratio, tight.max_ratio) > SENSITIVE_CHANGE


def checked(run: RockingRun, tight: RockingRun) -> RockingRun:
    """``run`` with the tight run's check attached."""
    check = ToleranceCheck(
        rtol=tight.rtol,
        atol=tight.atol,
        max_ratio=tight.max_ratio,
        impacts=tight.impacts,
        overturned=tight.overturned,
        status=tight.status,
        sensitive=is_sensitive(run, tight),
    )
    return replace(run, tolerance=check)


def sensitive(runs: Sequence[RockingRun]) -> bool | None:
    """Whether a result depends on the tolerance (:func:`any_sensitive` of its runs' flags; a
    run not checked counts as not known)."""
    return any_sensitive(r.tolerance.sensitive if r.tolerance is not None else None for r in runs)


def any_sensitive(flags: Iterable[bool | None]) -> bool | None:
    """True when any flag is True; else None when any is not known (None); else False."""
    seen = list(flags)
    if any(f is True for f in seen):
        return True
    return None if any(f is None for f in seen) else False


def check_tolerance(
    block: Rocker,
    time: np.ndarray,
    accel: np.ndarray,
    dt: float,
    settings: SolverSettings,
    result: Assessment,
) -> Assessment:
    """Both polarities of ``result`` with their tolerance check: the same block, ground motion
    and settings through the fast engine at :func:`tight_settings` (a mirror-symmetric block's
    −1 run mirrored as in ``result``); ``result`` unchanged when the tolerances cannot be
    tightened (:func:`can_tighten`).

    Args:
        block: the block as analysed. time, accel, dt: the ground motion it stood on [s, g, s].
        settings: the settings ``result`` was integrated with (fast engine).
        result: both polarities at those settings.
    """
    from rockcli.dynamics.simulate import assess

    if not can_tighten(settings):
        return result
    again = assess(block, time, accel, dt, settings=tight_settings(settings))
    tight = {r.polarity: r for r in again.runs}
    return Assessment(runs=tuple(checked(r, tight[r.polarity]) for r in result.runs))
