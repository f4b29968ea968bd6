"""The `[ntc]` table of the model file: settings of the NTC kinematic check (spec/ntc.md).

Validated here at the edge like every other table (unknown keys are errors, every number has
its unit); :mod:`rockcli.model.derive` turns it into the code check's plain settings.
"""

from __future__ import annotations

from collections.abc import Mapping
from enum import StrEnum
from typing import Annotated, Any

from pydantic import BeforeValidator, Field, model_validator

from rockcli.codecheck.categories import USE_COEFFICIENT, Edition, Soil, Topography, UseClass
from rockcli.model.bounds import (
    MAX_BEHAVIOUR_FACTOR,
    MAX_LENGTH,
    MAX_NOMINAL_LIFE,
    MAX_USE_COEFFICIENT,
    MIN_AG,
    MIN_ELONGATION,
    MIN_TC_STAR,
    MIN_USE_COEFFICIENT,
)
from rockcli.model.schema_base import Table
from rockcli.model.table_rules import choose_group, number, rule_error

#: Confidence factor of each knowledge level (Circolare 617/2009 §C8A.1.A.4, Tab. C8A.1.1;
#: Circolare 7/2019 §C8.5.4, Tab. C8.5.IV): LC1 1.35, LC2 1.20, LC3 1.00.
KNOWLEDGE_LEVEL_FC = {"LC1": 1.35, "LC2": 1.20, "LC3": 1.00}
#: Range of FC accepted: the LC values and, for cultural heritage, 1 + ΣF_Ck (DPCM 9/2/2011).
FC_MIN, FC_MAX = 1.0, 1.35
#: Behaviour factor of the linear kinematic check (Circolare 617/2009 §C8A.4.2.2; C8.7.1.2.1).
DEFAULT_Q = 2.0


#: Where the building's keys went: they describe the element, so both analyses read them.
BUILDING_MOVED = "moved to [building] (the building is shared by both analyses)"
#: Every key that left [ntc]: (problem, what is allowed instead).
MOVED_KEYS = {
    **{
        key: (BUILDING_MOVED, f"[building] {key} = {example}")
        for key, example in (
            ("Z", "height of the base above the foundation [m]"),
            ("H", "height of the building [m]"),
            ("N", "number of storeys"),
            ("T1", "first period of the building [s]"),
            ("gamma", "modal participation factor [-]"),
            ("psi", "first mode shape at Z [-]"),
        )
    },
    "loads": (
        "moved to [[loads]] (the loads are shared by both analyses)",
        "[[loads]] with weight [kN], height [m] or position = 'top', from_pivot [m], bears, moves",
    ),
}


def _new_place(key: str) -> str:
    """The table a key of [ntc] moved to."""
    return "[[loads]]" if key == "loads" else "[building]"


def _scalar(value: Any) -> Any:
    """The value to quote back: a number or text, not a whole table."""
    return value if isinstance(value, int | float | str) else None


#: Other names of the editions: the year of the code (NTC 2008, NTC 2018) for the year of
#: its instructions (Circolare 617/2009, Circolare 7/2019), which rock uses.
EDITION_ALIASES = {"2008": Edition.E2009.value, "2018": Edition.E2019.value}


def edition_name(value: Any) -> Any:
    """rock's name of an edition: an integer year as text, a code year as its circular's.

    Anything else is returned unchanged, for the enum to accept or refuse.
    """
    if isinstance(value, int) and not isinstance(value, bool):
        value = str(value)
    if isinstance(value, str):
        return EDITION_ALIASES.get(value.strip(), value.strip())
    return value


class KnowledgeLevel(StrEnum):
    """Knowledge level of the building (sets FC)."""

    LC1 = "LC1"
    LC2 = "LC2"
    LC3 = "LC3"


class MassDistribution(StrEnum):
    """How the block's mass enters M* and e* (spec/ntc.md: lumped by default, e* = 1)."""

    LUMPED = "lumped"
    DISTRIBUTED = "distributed"


class Site(Table):
    """Site coordinates for the hazard grid (DM 14/01/2008, Allegato B)."""

    lon: float = number("Longitude, east [deg]", ..., ge=-180, le=180)
    lat: float = number("Latitude, north [deg]", ..., ge=-90, le=90)


class SpectrumParameters(Table):
    """Spectrum parameters of one limit state, given directly (NTC §3.2, Allegato B)."""

    ag: float = number("Peak ground acceleration on rock ag [g]", ..., ge=MIN_AG, le=2)
    F0: float = number("Maximum spectral amplification F0 [-]", ..., ge=1.5, le=4)
    Tc_star: float = number(
        "Period Tc* at the start of the constant-velocity branch [s]", ..., ge=MIN_TC_STAR, le=2
    )


class Demand(Table):
    """Spectrum parameters per limit state (SLO, SLD, SLV, SLC), instead of a site."""

    SLO: SpectrumParameters | None = Field(None, description="Operational limit state")
    SLD: SpectrumParameters | None = Field(None, description="Damage limit state (DLS)")
    SLV: SpectrumParameters | None = Field(None, description="Life-safety limit state (ULS)")
    SLC: SpectrumParameters | None = Field(None, description="Collapse limit state")


class Ntc(Table):
    """Settings of the NTC kinematic check (spec/ntc.md)."""

    edition: Annotated[Edition, BeforeValidator(edition_name)] = Field(
        Edition.E2019,
        description="'2009' (NTC 2008 + Circ. 617/2009) or '2019' (NTC 2018 + Circ. 7/2019, "
        "in force); default '2019'. Also accepted: the year of the code, '2008' for '2009' "
        "and '2018' for '2019', and each as a number (edition = 2019)",
    )
    FC: float | None = number(
        "Confidence factor in [1, 1.35] (or knowledge_level); default 1.35 (LC1) [-]",
        ge=FC_MIN,
        le=FC_MAX,
    )
    knowledge_level: KnowledgeLevel | None = Field(
        None, description="'LC1' (FC 1.35), 'LC2' (1.20) or 'LC3' (1.00), instead of FC"
    )
    q: float = number(
        "Behaviour factor of the linear check; default 2.0 [-]",
        DEFAULT_Q,
        ge=1,
        le=MAX_BEHAVIOUR_FACTOR,
    )
    soil: Soil = Field(Soil.A, description="Subsoil category A–E; default A")
    topography: Topography = Field(
        Topography.T1, description="Topographic category T1–T4; default T1"
    )
    VN: float = number("Nominal life VN; default 50 [years]", 50.0, gt=0, le=MAX_NOMINAL_LIFE)
    CU: float = number(
        "Use coefficient CU (class I 0.7, II 1.0, III 1.5, IV 2.0); default 1 [-]",
        1.0,
        ge=MIN_USE_COEFFICIENT,
        le=MAX_USE_COEFFICIENT,
    )
    use_class: UseClass | None = Field(
        None,
        description="Use class 'I'–'IV' (NTC 2018 §2.4.2): sets CU (Tab. 2.4.II) and the limit "
        "states the assessment of an existing building requires (§8.3: the SLV; class IV also "
        "the SLD); default: the class of CU",
    )
    mass_distribution: MassDistribution = Field(
        MassDistribution.LUMPED,
        description="'lumped' (weight at the centroid, e* = 1; default) or 'distributed' "
        "(over the height, e* = 0.75 for a rectangle)",
    )
    ultimate_displacement: float | None = number(
        "Displacement of the control point at which a local incompatibility (or, with a "
        "positive global stiffness, the designer's limit) ends the mechanism; caps du* "
        "(2009), d_SLV and d_SLC (2019) [m]",
        ge=MIN_ELONGATION,
        le=MAX_LENGTH,
    )
    site: Site | None = Field(None, description="Site coordinates, demand from the hazard grid")
    demand: Demand | None = Field(None, description="Spectrum parameters per limit state")

    @model_validator(mode="before")
    @classmethod
    def _moved_keys(cls, data: Any) -> Any:
        """The keys that moved out of [ntc] (0.x: an error naming the new place, no alias).

        One error for the first, naming the others too, so that an old file is fixed in one go.
        """
        if not isinstance(data, Mapping):
            return data
        moved = [key for key in MOVED_KEYS if key in data]
        if moved:
            first, others = moved[0], moved[1:]
            problem, allowed = MOVED_KEYS[first]
            also = "; also moved: " + ", ".join(f"ntc.{k} to {_new_place(k)}" for k in others)
            also = also if others else ""
            raise rule_error(first, problem + also, allowed, _scalar(data[first]))
        return data

    @model_validator(mode="before")
    @classmethod
    def _use_coefficient(cls, data: Any) -> Any:
        """CU from use_class when only the class is given; both given must agree."""
        if not isinstance(data, Mapping) or not isinstance(data.get("use_class"), str):
            return data
        coefficient = USE_COEFFICIENT.get(data["use_class"])
        if coefficient is None:
            return data  # the enum refuses it
        if "CU" not in data:
            return {**data, "CU": coefficient}
        given = data["CU"]
        if isinstance(given, int | float) and abs(given - coefficient) > 1e-12:
            raise rule_error(
                "CU",
                f"does not agree with use_class = '{data['use_class']}' (CU {coefficient:g})",
                f"CU = {coefficient:g} with use class {data['use_class']} (NTC 2018 Tab. 2.4.II), "
                "or only one of the two",
                _scalar(given),
            )
        return data

    @model_validator(mode="after")
    def _consistent(self) -> Ntc:
        """FC or knowledge_level; a site or spectrum parameters, not both."""
        allowed = "FC in [1, 1.35], or knowledge_level = 'LC1' | 'LC2' | 'LC3'"
        choose_group(self.__dict__, [("FC",), ("knowledge_level",)], allowed)
        if self.site is not None and self.demand is not None:
            raise rule_error(
                "demand", "not allowed together with site", "[ntc.site] or [ntc.demand.*]"
            )
        return self

    @property
    def confidence_factor(self) -> float:
        """FC: as given, from the knowledge level, or 1.35 (LC1) by default."""
        if self.FC is not None:
            return self.FC
        if self.knowledge_level is not None:
            return KNOWLEDGE_LEVEL_FC[self.knowledge_level.value]
        return KNOWLEDGE_LEVEL_FC["LC1"]
