"""The verification of a yielding tie-rod: its ductility and its anchorage's capacity design.

A rod of an elastic-plastic steel never carries more than its yield force, so its force check
alone cannot fail once it yields. Two more checks make the verification real:

- **ductility**: the bar's largest elongation against the elongation it can take, its
  elongation at break ε_u over its length L divided by a partial factor γ_ε
  (docs/interpretations.md, "Tie-rods: ductility and anchorage");
- **anchorage (capacity design)**: the anchor must be stronger than the bar can become, its
  over-strength γ_ov·A·f_y (NTC 2018 §7.5.1, γ_ov = 1.25 for S235, S275 and S355), so that the
  bar yields and the anchor does not give way first; otherwise the anchor governs and the
  check fails.

Pure and silent: only :mod:`math`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: Over-strength factor of the material for capacity design (NTC 2018 §7.5.1): 1.25 for the
#: grades S235, S275 and S355, 1.15 for S420 and S460.
GAMMA_OV = {"S235": 1.25, "S275": 1.25, "S355": 1.25, "S420": 1.15, "S460": 1.15}
#: γ_ov of a bar of measured f_y (no grade): that of the grades up to S355.
MEASURED_OV = 1.25
#: The clause of γ_ov.
OVERSTRENGTH_CLAUSE = "NTC 2018 §7.5.1"
#: Partial factor on the elongation at break of a long bar (docs/interpretations.md): 0.9 of
#: NTC 2018 §4.1.2.1.2.3 (ε_ud = 0.9·ε_uk) on the scatter, and about one half from the gauge
#: length: the elongation at break A is measured on 5.65·√S0 (≈ 5 diameters) and includes the
#: necking, which over a bar many diameters long stays local; only the uniform elongation
#: spreads over the length.
GAMMA_ELONGATION = 2.0
#: The clause of the elongation at break of the standard grades.
ELONGATION_CLAUSE = "EN 10025-2 Tab. 7"


@dataclass(frozen=True)
class Verification:
    """One verification of a member: demand against capacity (SI units).

    Attributes:
        demand, capacity: [m] for ductility, [N] for the anchor; capacity None when not known.
        passed: demand ≤ capacity (None: not verified, the capacity is not known).
        rule: how the capacity is obtained, with its clause.
    """

    demand: float
    capacity: float | None
    passed: bool | None
    rule: str


def overstrength_force(area: float, fy: float, gamma_ov: float) -> float:
    """γ_ov·A·f_y [N]: the largest force the bar can bring to its anchor (NTC 2018 §7.5.1).

    Args:
        area: the bars' gross area [m²]. fy: their yield strength [Pa] (nominal f_yk of the
            grade, or the measured mean). gamma_ov: the over-strength factor.
    """
    return gamma_ov * area * fy


def elongation_capacity(eps_u: float, length: float, gamma: float = GAMMA_ELONGATION) -> float:
    """ε_u·L/γ_ε [m]: the elongation the bar can take, from its unstressed length.

    Args:
        eps_u: elongation at break, a fraction (0.23 = 23 %). length: the bar's length [m].
        gamma: partial factor γ_ε on it (GAMMA_ELONGATION).
    """
    return eps_u * length / gamma


def ductility(elongation: float, capacity: float, rule: str) -> Verification:
    """The bar's largest elongation [m] against its capacity [m] (inf: not a bar: None)."""
    if not math.isfinite(capacity):
        return Verification(elongation, None, None, rule)
    return Verification(elongation, capacity, elongation <= capacity, rule)


def anchorage(overstrength: float, anchor: float) -> Verification:
    """The anchor's capacity [N] against the bar's over-strength γ_ov·A·f_y [N] (capacity
    design, NTC 2018 §7.5.1): it must be larger, or the anchor governs (inf: not given, the
    anchorage is to be designed for the over-strength; not verified)."""
    rule = f"γ_ov·A·f_y ({OVERSTRENGTH_CLAUSE}) against the anchor's capacity"
    if not math.isfinite(anchor):
        return Verification(overstrength, None, None, rule)
    return Verification(overstrength, anchor, anchor >= overstrength, rule)
