"""Results of the kinematic check: data, rendered elsewhere (spec/style.md, principle 6)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rockcli.codecheck.position import Position
    from rockcli.mechanics import WorkItem


class Method(StrEnum):
    """Linear (acceleration) or non-linear (displacement) kinematic analysis."""

    LINEAR = "linear"
    NONLINEAR = "nonlinear"


class Location(StrEnum):
    """Where the demand is taken: at the ground, or at the height of the mechanism."""

    GROUND = "ground"
    HEIGHT = "height"


@dataclass(frozen=True)
class WorkTerm:
    """One body, load, thrust or restrainer in α0's virtual work (Circ. 7/2019 §C8.7.1.2.1.1,
    Eq. C8.7.1.1; Circ. 617/2009 §C8A.4.1), per unit virtual rotation about the hinge.

    Attributes:
        item: what it is and where (rockcli.mechanics.WorkItem: its name, kind — "body",
            "load", "thrust" or "restrainer" —, its weight P or horizontal force F [N], its
            point x inward from the hinge and z above it [m], its virtual displacement δx
            outward and δy upward [m/rad]).
        resisting: its term of α0's numerator [N·m]: P·δy of a weight that bears, −F·δx of
            a thrust pushing the mechanism open (+ when it pushes it shut), F·δx of a
            restrainer.
        overturning: its term of the denominator [N·m]: P·δx of a weight whose mass moves.
    α0 = Σ resisting / Σ overturning.
    """

    item: WorkItem
    resisting: float
    overturning: float


@dataclass(frozen=True)
class SpectralDemand:
    """Where a displacement check read its demand on the spectrum, so that it can be redone by
    hand: the damping, the period (or the range searched and the period of its maximum) and the
    spectral displacement at the limit state's own ag.

    Attributes:
        damping: the mechanism's damping in the spectrum [%] (5, or 8 at SLV / 10 at SLC in 2019).
        period: the period at which the demand is read [s] (the maximum's, over a range).
        value: the spectral displacement demand there, at the limit state's own ag [m].
        period_range: [T_lo, T_hi] [s] over which the maximum was taken (Circ. 7/2019
            §C8.7.1.2.1.8, a record or a suite as the demand); None: read at one period.
        rule: the rule in words, with its clause.
        at_secant: the demand at the secant period itself [m] (T_hi of the range).
    """

    damping: float
    period: float
    value: float
    period_range: tuple[float, float] | None = None
    rule: str = ""
    at_secant: float | None = None


@dataclass(frozen=True)
class Check:
    """One verification: demand against capacity, the clause, any interpretation made.

    Attributes:
        limit_state: "DLS"/"ULS" (2009) or "SLD"/"SLV"/"SLC" (2019).
        method, location: which check.
        demand, capacity: in `unit`; capacity None when it cannot be computed (see note).
        unit: "m/s²", "m" or "g".
        passed: capacity ≥ demand; None when not evaluated.
        clause: the article of the Circolare.
        note: an interpretation or a reason it was not evaluated.
        spectral: where a displacement check read the spectrum (None: an acceleration check,
            or not evaluated).
    """

    limit_state: str
    method: Method
    location: Location
    demand: float | None
    capacity: float | None
    unit: str
    clause: str
    note: str = ""
    spectral: SpectralDemand | None = None

    @property
    def passed(self) -> bool | None:
        """capacity ≥ demand (None when either is missing)."""
        if self.capacity is None or self.demand is None:
            return None
        return bool(self.capacity >= self.demand)

    @property
    def ratio(self) -> float | None:
        """ζ = capacity / demand (≥ 1 passes)."""
        if self.capacity is None or not self.demand:
            return None
        return float(self.capacity / self.demand)


@dataclass(frozen=True)
class KinematicResult:
    """The whole kinematic analysis of one mechanism under one demand.

    Attributes:
        edition: "2009" or "2019".
        side: the side of overturning analysed (+1 or −1).
        alpha0, e_star, a0_star [m/s²], FC, d0_star [m] (None: positive global stiffness),
        linear_curve: which capacity curve the code's rules used.
        quantities: the edition's derived quantities (du_star, ds_star, as_star, Ts; or d_SLV,
            T_SLV, d_SLC, T_SLC …), by name, SI units.
        checks: every verification.
        curve: the capacity curve as rows (θ, d_k, d*, α, α sure, a*).
        demand: per limit state, the demand's numbers and their source (TR, ag, F0, Tc*, SS,
            ST, S, TB, TC, TD; or a record's name and PGA).
        notes: interpretations and warnings to show with the result.
        alpha0_by_side: α0 towards each side, keys "1" (θ > 0) and "-1" (θ < 0): loads off the
            mid-plane and thrusts make them differ.
        restrainer_actions: how each restrainer entered the check, and its verification.
        catalogue: every mechanism of the model with its own result, the governing one
            first (rockcli.analyses.catalogue.MechanismResult); this result is the governing
            mechanism's. governing: its name. mechanism: the name of the mechanism this
            result describes (None: the block, outside a catalogue).
        FC_rule: why the check used that FC (given, a knowledge level's, LC1's by
            Circolare 7/2019 §C8.7.1.2.1.3).
        position: where the check put the mechanism (codecheck.position.Position: its
            height, the building's T1, ψ, γ), whose floor spectra it read.
        activation_by_side: α0's virtual work term by term on each side of
            ``alpha0_by_side`` and the side analysed (codecheck.kinematic.activation_terms),
            keys as ``alpha0_by_side``.
    """

    edition: str
    side: int
    alpha0: float
    e_star: float
    a0_star: float
    FC: float
    d0_star: float | None
    linear_curve: bool
    quantities: dict[str, float | None]
    checks: tuple[Check, ...]
    #: A sequence of rows (a codecheck.kinematic.CapacityCurve computes them when read).
    curve: Sequence[dict[str, float]]
    demand: dict[str, object]
    notes: tuple[str, ...] = field(default_factory=tuple)
    alpha0_by_side: dict[str, float] = field(default_factory=dict)
    restrainer_actions: tuple[RestrainerAction, ...] = ()
    catalogue: tuple[Any, ...] = ()
    governing: str | None = None
    mechanism: str | None = None
    FC_rule: str = ""
    position: Position | None = None
    activation_by_side: dict[str, dict[str, float]] = field(default_factory=dict)
    #: α0's virtual work per body, load, thrust and restrainer on each side of
    #: ``activation_by_side`` (codecheck.kinematic.activation_work), whose sums are its terms.
    work_by_side: dict[str, tuple[WorkTerm, ...]] = field(default_factory=dict)

    def verdict(self) -> dict[str, bool | None]:
        """DLS and ULS satisfied? (None: not evaluated).

        DLS: every damage check. ULS: the non-linear checks (the more refined method, the
        paper's §3.3 choice; not evaluated when they cannot be: see :func:`deciding`). 2019
        also gives each limit state (SLD, SLV, SLC) by the same rule.
        """
        out: dict[str, bool | None] = {
            "DLS": _all(deciding(self.checks, ("DLS", "SLD"))),
            "ULS": _all(deciding(self.checks, ("ULS", "SLV", "SLC"))),
        }
        if self.edition == "2019":
            for ls in ("SLD", "SLV", "SLC"):
                out[ls] = _all(deciding(self.checks, (ls,)))
        return out


def deciding(checks: tuple[Check, ...], states: tuple[str, ...]) -> list[Check]:
    """The checks that decide the verdict of these limit states: the non-linear ones when the
    analysis has them, else the linear ones.

    A non-linear check that could not be evaluated (positive global stiffness and no limit
    displacement) leaves the verdict not evaluated: the linear checks ignore the restrainers
    (α0 does not see them), so falling back on them would call a restrained block unsafe for
    a reason the code's own non-linear analysis does not give (docs/interpretations.md).
    """
    mine = [c for c in checks if c.limit_state in states]
    nonlinear = [c for c in mine if c.method is Method.NONLINEAR]
    return nonlinear if nonlinear else mine


def _all(checks: list[Check]) -> bool | None:
    """All passed (None when there are none or one is not evaluated)."""
    results = [c.passed for c in checks]
    if not results or any(r is None for r in results):
        return None
    return all(results)


@dataclass(frozen=True)
class RestrainerAction:
    """How one restrainer entered the kinematic check, and its own verification.

    Attributes:
        name: the restrainer's label.
        code_action: "force" (a constant stabilising force) or "spring" (P0 + K·u, capped).
        force: the force it gives α0 [N] (0 for a spring without pretension).
        strength: its strength [N] (None: not known).
        demand: the force the check relies on [N]: the force, or the spring's force at
            ``demand_at`` (None: no displacement of the check to read it at).
        demand_at: where the spring's force is read (or "constant force").
        utilisation: demand / strength (None: strength not known).
        lost: True when the member is lost (rupture) before the rotation of ``demand_at``.
        passed: demand ≤ strength and not lost (None: strength not known and not lost).
        clause: the clause of its strength.
        lost_at_d_star: the spectral displacement d* at which the member is lost in the
            check [m] (None: never): its fails_at, a bar's ε_u·L/γ_ε, an anchor giving way.
        slack: True on the side where a tie-rod would push: it adds nothing there.
    """

    name: str
    code_action: str
    force: float
    strength: float | None
    demand: float | None
    demand_at: str
    utilisation: float | None
    lost: bool
    passed: bool | None
    clause: str
    lost_at_d_star: float | None = None
    slack: bool = False
