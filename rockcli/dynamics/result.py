"""Results of rocking runs: data, rendered elsewhere (spec/style.md, "Output is data first")."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum

import numpy as np

#: Runs whose peak amplitude ratio stays below this while impacts happen are flagged as
#: chattering-dominated (engine.md, "Sensitivity": small-amplitude rocking is ill-conditioned).
CHATTER_RATIO = 0.05

#: Two polarities' amplitude ratios within this share of each other are a tie (far below
#: the engine's tolerance, rtol 1e-8): the history written is the record's as given.
TIE_RATIO = 1e-9


class RunStatus(StrEnum):
    """How a run ended. NONFINITE: a NaN or an infinity (θ, θ̇, θ̈, the ground acceleration,
    the error estimate or a restrainer's force) stopped it; its numbers decide nothing."""

    COMPLETED = "completed"
    OVERTURNED = "overturned"
    EVENT_LIMIT = "event-limit"
    STEP_LIMIT = "step-limit"
    NONFINITE = "non-finite"


@dataclass(frozen=True)
class ToleranceCheck:
    """A run integrated again at tighter tolerances.

    Attributes:
        rtol, atol: the tight run's tolerances [-], [rad and rad/s].
        max_ratio: its max|θ|/α [-] (overturn angle/α when it overturned).
        impacts: its impacts.
        overturned: True when it overturned.
        status: how it ended.
        sensitive: True when the run's max θ/α differs from this one's by more than
            SENSITIVE_CHANGE (rockcli.dynamics.tolerance) relative, or one overturned and the
            other not; None when either ended at a guard (step or event limit, a non-finite
            value): not known.
    """

    rtol: float
    atol: float
    max_ratio: float
    impacts: int
    overturned: bool
    status: RunStatus
    sensitive: bool | None


class Verdict(StrEnum):
    """Envelope verdict over both polarities."""

    SURVIVES = "survives"
    OVERTURNS = "overturns"
    UNDECIDED = "undecided"


@dataclass(frozen=True)
class RestrainerPeak:
    """Demand on one restrainer during a run.

    Attributes:
        name: restrainer label.
        max_displacement: peak spring elongation [m].
        max_force: peak force of its law [N] (K·u for an elastic spring).
        t_fail: time the restrainer was lost (ruptured, or its anchor gave way) [s], None if it
            held.
        t_yield: time it first yielded [s], None if it never did.
        plastic_elongation: its permanent elongation at the end of the run [m].
        energy_dissipated: plastic work, plus the energy released when it was lost [J].
    """

    name: str
    max_displacement: float
    max_force: float
    t_fail: float | None = None
    t_yield: float | None = None
    plastic_elongation: float = 0.0
    energy_dissipated: float = 0.0

    @property
    def yielded(self) -> bool:
        """True when the member reached its yield force."""
        return self.t_yield is not None

    @property
    def ruptured(self) -> bool:
        """True when the member was lost during the run."""
        return self.t_fail is not None


@dataclass(frozen=True, eq=False)
class History:
    """θ(t), θ̇(t) and each restrainer's force at the sample times (tail included) up to the
    end of the run (forces: shape (restrainers, samples) [N]), and its elongation there
    (elongations, the same shape [m]; None: not computed)."""

    time: np.ndarray
    theta: np.ndarray
    omega: np.ndarray
    forces: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))
    elongations: np.ndarray | None = None


@dataclass(frozen=True)
class RockingRun:
    """One time-history run for one polarity.

    Attributes:
        polarity: +1 as recorded, −1 reversed.
        status: how the run ended. message: one sentence about it.
        max_ratio: max|θ|/α, the paper's amplitude ratio [-].
        theta_max, theta_min: signed extremes of θ [rad].
        max_velocity: max|θ̇| seen at step ends and events [rad/s].
        t_overturn: time of overturning [s] or None. t_uplift: first uplift [s] or None.
        impacts: impacts counted (with rest threshold rest_velocity). uplifts: starts from rest.
        steps, rejected: accepted and rejected integration steps.
        t_end: time the run ended [s].
        engine, rtol, atol, rest_velocity: how it was integrated.
        restrainers: demand on each restrainer.
        warnings: remarks for the reader (chattering, event limit, …).
        history: θ(t), θ̇(t) when asked for.
        impact_loss: kinetic energy lost in impacts and at rest [J] (0 without a mass).
        mirror_of: the polarity this run is the mirror image of (a mirror-symmetric block:
            not integrated, θ → −θ of that run), None when it was integrated.
        tolerance: the same run at tighter tolerances (dynamics.tolerance), None when not
            checked.
    """

    polarity: int
    status: RunStatus
    message: str
    max_ratio: float
    theta_max: float
    theta_min: float
    max_velocity: float
    t_overturn: float | None
    t_uplift: float | None
    impacts: int
    uplifts: int
    steps: int
    rejected: int
    t_end: float
    engine: str
    rtol: float
    atol: float
    rest_velocity: float
    restrainers: tuple[RestrainerPeak, ...] = ()
    warnings: tuple[str, ...] = ()
    history: History | None = field(default=None, compare=False, repr=False)
    impact_loss: float = 0.0
    mirror_of: int | None = None
    tolerance: ToleranceCheck | None = None

    @property
    def overturned(self) -> bool:
        """True when the block overturned in this run."""
        return self.status is RunStatus.OVERTURNED

    @property
    def chattering(self) -> bool:
        """True for small-amplitude runs dominated by impacts (read their peak with care)."""
        return self.impacts > 0 and self.max_ratio < CHATTER_RATIO


@dataclass(frozen=True)
class Assessment:
    """Both polarities of one block under one record, and their envelope.

    Attributes:
        runs: the run with the record as given (+1) and reversed (−1).
    """

    runs: tuple[RockingRun, ...]

    @property
    def worst(self) -> RockingRun:
        """The run that decides the verdict: an overturn first, else the largest ratio; two
        ratios within TIE_RATIO of each other are a tie, kept by the record as given (the
        first run), so that the last bits of a sum do not choose (a one-sided wedge rocks
        alike under both polarities)."""
        best = self.runs[0]
        for run in self.runs[1:]:
            if run.overturned != best.overturned:
                best = run if run.overturned else best
            elif run.max_ratio > best.max_ratio * (1.0 + TIE_RATIO):
                best = run
        return best

    @property
    def verdict(self) -> Verdict:
        """`overturns` if either polarity overturns, else `survives` (spec/rocking.md).

        A run that met a non-finite number (NaN or ±inf) decides nothing, not even an overturn
        of the other polarity: the model or the record holds an absurd magnitude.
        """
        if any(r.status is RunStatus.NONFINITE for r in self.runs):
            return Verdict.UNDECIDED
        if any(r.overturned for r in self.runs):
            return Verdict.OVERTURNS
        if any(r.status is not RunStatus.COMPLETED for r in self.runs):
            return Verdict.UNDECIDED
        return Verdict.SURVIVES

    @property
    def max_ratio(self) -> float:
        """Envelope amplitude ratio max over both polarities [-]."""
        return max(r.max_ratio for r in self.runs)
