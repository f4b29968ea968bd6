"""Settings of a rocking run: tolerances, thresholds, durations (spec/engine.md defaults)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

#: Default relative and absolute tolerance of the fast engine (engine.md: cost nearly flat
#: from 1e-6 to 1e-10; max_ratio agrees with the tight reference to 1e-3 and better).
DEFAULT_RTOL = 1e-8
DEFAULT_ATOL = 1e-8
#: Rest rule: after an impact, |θ̇⁺| below this is rest [rad/s] (engine.md, trap 5: peaks are
#: identical for 1e-4, 1e-5, 1e-6 rad/s; the impact count depends on it).
DEFAULT_REST_VELOCITY = 1e-4
#: Overturning angle |θ| [rad] (paper §3.1: π/2; a block past θ = α can still come back).
DEFAULT_OVERTURN_ANGLE = math.pi / 2
#: Free-vibration tail after the record: at least this many seconds, and at least
#: TAIL_PERIODS/p (engine.md: "free time after the record ≥ 10–20/p").
DEFAULT_TAIL_MIN = 10.0
TAIL_PERIODS = 20.0
#: Guards: a run stops with a status (never hangs) past these counts.
DEFAULT_MAX_EVENTS = 1_000_000
DEFAULT_MAX_STEPS = 50_000_000
#: Tolerances of the reference engine (engine.md: DOP853 at 1e-10, one sample interval at a time).
REFERENCE_RTOL = 1e-10
REFERENCE_ATOL = 1e-12


class Engine(StrEnum):
    """Which integrator runs the time history."""

    FAST = "fast"
    REFERENCE = "reference"


@dataclass(frozen=True)
class SolverSettings:
    """How a rocking run is integrated.

    Attributes:
        rtol, atol: tolerances of the fast engine's error control [-], [rad and rad/s].
        rest_velocity: rest rule threshold ω_rest [rad/s].
        overturn_angle: |θ| at which the block is declared overturned [rad].
        tail: free time after the record [s]; None → max(DEFAULT_TAIL_MIN, TAIL_PERIODS/p).
        max_events: impacts after which the run stops with status "event-limit".
        max_steps: steps after which the run stops with status "step-limit" (at most; the
            run's work budget, tied to the record's length, can stop it sooner:
            simulate.STEPS_PER_SAMPLE).
        free_tail: after the record, let the error controller alone choose the steps (the
            ground is at rest: no sample to align with; the history is interpolated at the
            tail's samples); False clips every step at every sample, as during the record.
    """

    rtol: float = DEFAULT_RTOL
    atol: float = DEFAULT_ATOL
    rest_velocity: float = DEFAULT_REST_VELOCITY
    overturn_angle: float = DEFAULT_OVERTURN_ANGLE
    tail: float | None = None
    max_events: int = DEFAULT_MAX_EVENTS
    max_steps: int = DEFAULT_MAX_STEPS
    free_tail: bool = True

    def tail_for(self, p: float) -> float:
        """The free-vibration tail [s] for a block of frequency parameter p [rad/s]."""
        if self.tail is not None:
            return self.tail
        return max(DEFAULT_TAIL_MIN, TAIL_PERIODS / p)
