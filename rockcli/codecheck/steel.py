"""The tension resistance of a steel tie-rod (NTC 2018 §4.2.4.1.2 and §11.3.4.1).

Pure and silent: only :mod:`math`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: Nominal yield and ultimate strengths [Pa] of hot-rolled structural steel for thicknesses up
#: to 40 mm (NTC 2018 Tab. 11.3.IX; EN 10025-2): (f_yk, f_tk).
GRADES: dict[str, tuple[float, float]] = {
    "S235": (235e6, 360e6),
    "S275": (275e6, 430e6),
    "S355": (355e6, 510e6),
}
#: Minimum percentage elongation after fracture A of the product standard [-], as a fraction of
#: the gauge length (EN 10025-2:2019, Table 7, longitudinal test pieces, nominal thickness 3 to
#: 40 mm): the default elongation at break of a tie-rod of a standard grade in the time history
#: (rockcli.model.derive.rupture_elongation; docs/interpretations.md, "Restrainer laws"). A is
#: measured on a short proportional test piece and includes the local necking: the mean strain
#: of a long bar at rupture is closer to its uniform elongation, which is smaller.
ELONGATION_AT_BREAK: dict[str, float] = {
    "S235": 0.26,
    "S275": 0.23,
    "S355": 0.22,
}
#: Partial factors of steel members in tension (NTC 2018 §4.2.4.1.1, Tab. 4.2.VII):
#: γ_M0 for the resistance of the gross section, γ_M2 for the fracture of the net section.
GAMMA_M0 = 1.05
GAMMA_M2 = 1.25
#: Factor 0.9 on the ultimate resistance of the net section (NTC 2018 Eq. 4.2.7).
NET_SECTION_FACTOR = 0.9
#: The clause of the design tension resistance.
CLAUSE = "NTC 2018 §4.2.4.1.2"


@dataclass(frozen=True)
class TensionResistance:
    """A member's design tension resistance and what governs it.

    Attributes:
        plastic: N_pl,Rd = A·f_yk/γ_M0 [N]. ultimate: N_u,Rd = 0.9·A·f_tk/γ_M2 [N].
        anchor: the anchorage's capacity [N] (inf: not given).
        strength: the lowest of the three [N].
        governs: "plastic", "ultimate" or "anchor".
    """

    plastic: float
    ultimate: float
    anchor: float
    strength: float
    governs: str


def rod_area(diameter: float, count: int = 1) -> float:
    """Gross area of ``count`` round bars of ``diameter`` [m²]: count·π·d²/4."""
    return count * math.pi * diameter**2 / 4.0


def elongation_at_break(grade: str) -> float:
    """The default elongation at break of a bar of a standard grade [-] (fraction of its length).

    Source: EN 10025-2:2019, Table 7 (minimum elongation after fracture A, longitudinal, 3 to
    40 mm): :data:`ELONGATION_AT_BREAK`. A grade outside the table raises KeyError (the model
    schema admits only the tabulated grades).
    """
    return ELONGATION_AT_BREAK[grade]


def tension_resistance(
    area: float, fy: float, fu: float, factor: float = 1.0, anchor: float = math.inf
) -> TensionResistance:
    """N_t,Rd = min(A·f_yk/γ_M0, 0.9·A·f_tk/γ_M2) [N], capped by the anchor's capacity.

    Source: NTC 2018 §4.2.4.1.2, Eq. (4.2.6)–(4.2.7) (N_pl,Rd and N_u,Rd, the net area taken as
    the gross area of a plain bar). ``factor`` divides the strengths: the confidence factor FC
    of an existing member whose f_y and f_u were measured (Circolare 7/2019 §C8.5.4;
    docs/interpretations.md), 1 for a new member of a standard grade.
    """
    plastic = area * fy / (factor * GAMMA_M0)
    ultimate = NET_SECTION_FACTOR * area * fu / (factor * GAMMA_M2)
    candidates = {"plastic": plastic, "ultimate": ultimate, "anchor": anchor}
    governs = min(candidates, key=lambda k: candidates[k])
    return TensionResistance(plastic, ultimate, anchor, candidates[governs], governs)
