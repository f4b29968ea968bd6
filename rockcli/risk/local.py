"""The risk class of a building from its local mechanisms (rockcli.risk.classification on the
code check of a model's catalogue): each mechanism's own class, and the building's from the
lowest T_Rc of each limit state and the lowest IS-V over the mechanisms (the building
reaches a limit state when its first mechanism does).

A local mechanism has no operational limit state in the Circolare (§C8.7.1.2.1 checks the
SLD, SLV and SLC): its T_Rc(SLO) is read as its T_Rc(SLD), the action that first sets it in
motion (a rigid block does not move, and so loses nothing, below it; docs/interpretations.md).

Pure and silent.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Protocol

from rockcli.codecheck.hazard_curve import HazardCurve
from rockcli.risk.classification import RiskClass, classify

#: The limit states the code check of a local mechanism gives T_Rc for.
CHECKED = ("SLD", "SLV", "SLC")


class Checked(Protocol):
    """What the class reads of one mechanism's code check (analyses.catalogue.MechanismResult)."""

    name: str
    T_Rc: dict[str, float] | None
    pga_SLV: tuple[float, float] | None
    hazard: HazardCurve | None


@dataclass(frozen=True)
class MechanismRisk:
    """One mechanism's class (None: its check gives no T_Rc of a state, or no IS-V)."""

    name: str
    T_Rc: dict[str, float] | None
    IS_V: float | None
    risk: RiskClass | None


@dataclass(frozen=True)
class BuildingRisk:
    """The building's class from its mechanisms.

    Attributes:
        T_Rc: the lowest T_Rc of each of SLD, SLV, SLC over the mechanisms that have it
            [years].
        governing: the mechanism that gives each (and "IS_V": the lowest IS-V's).
        IS_V: the lowest IS-V (None: no mechanism has one).
        risk: the class (classification.classify with SLO read as SLD); None when a mechanism
            lacks the T_Rc of a state or its IS-V (its check not evaluated there): the class
            of the others could be better than the building's.
        mechanisms: each mechanism's own class, in the catalogue's order.
        missing: the mechanisms without a T_Rc of every state or an IS-V, and what they lack.
        hazard: the hazard curve the T_Rc were read on (the mechanisms share it).
    """

    T_Rc: dict[str, float]
    governing: dict[str, str]
    IS_V: float | None
    risk: RiskClass | None
    mechanisms: tuple[MechanismRisk, ...]
    missing: tuple[str, ...]
    hazard: HazardCurve


def with_slo(T_Rc: dict[str, float]) -> dict[str, float]:  # noqa: N803
    """The four states of the curve, SLO read as SLD (the module's reading)."""
    return {"SLO": T_Rc["SLD"], **{ls: T_Rc[ls] for ls in CHECKED}}


def mechanism_risk(m: Checked) -> MechanismRisk:
    """One mechanism's T_Rc, IS-V and class."""
    periods = m.T_Rc if m.T_Rc and all(ls in m.T_Rc for ls in CHECKED) else None
    isv = None if m.pga_SLV is None else m.pga_SLV[0] / m.pga_SLV[1]
    risk = None if periods is None or isv is None else classify(with_slo(periods), isv)
    return MechanismRisk(m.name, m.T_Rc, isv, risk)


def lacks(r: MechanismRisk) -> str:
    """What a mechanism without a class lacks, in words."""
    states = [ls for ls in CHECKED if not r.T_Rc or ls not in r.T_Rc]
    parts = [f"T_Rc of {', '.join(states)}"] if states else []
    return f"{r.name} ({', '.join(parts + ([] if r.IS_V is not None else ['IS-V']))})"


def building_risk(catalogue: Sequence[Checked]) -> BuildingRisk | None:
    """The building's class (None: no mechanism has any T_Rc, the demand gives no hazard)."""
    own = tuple(mechanism_risk(m) for m in catalogue)
    if not any(r.T_Rc for r in own):
        return None
    governing: dict[str, str] = {}
    periods: dict[str, float] = {}
    for ls in CHECKED:
        known = [r for r in own if r.T_Rc and ls in r.T_Rc]
        if known:
            first = min(known, key=lambda r: r.T_Rc[ls])  # type: ignore[index]
            governing[ls], periods[ls] = first.name, first.T_Rc[ls]  # type: ignore[index]
    with_isv = [r for r in own if r.IS_V is not None]
    isv = None
    if with_isv:
        weakest = min(with_isv, key=lambda r: r.IS_V)  # type: ignore[arg-type,return-value]
        governing["IS_V"], isv = weakest.name, float(weakest.IS_V)  # type: ignore[arg-type]
    missing = tuple(lacks(r) for r in own if r.risk is None)
    risk = None if missing or isv is None else classify(with_slo(periods), isv)
    hazard = next(m.hazard for m in catalogue if m.T_Rc)
    assert hazard is not None  # a T_Rc is read on a curve
    return BuildingRisk(periods, governing, isv, risk, own, missing, hazard)
