"""From the `[ntc]` and `[building]` tables to the code check's plain settings.

SI units, frozen dataclasses.

Pure: no numpy, scipy or numba (model validation starts fast; spec/engine.md "Speed").
"""

from __future__ import annotations

from dataclasses import dataclass

from rockcli.codecheck.existing import use_class_of
from rockcli.errors import InputError
from rockcli.model.ntc import KNOWLEDGE_LEVEL_FC, Ntc
from rockcli.model.schema import Model
from rockcli.notes import Note

#: The confidence factor of knowledge level LC1 (Circolare 7/2019 §C8.5.4).
LC1_FC = KNOWLEDGE_LEVEL_FC["LC1"]
#: The clause that asks for LC1's FC when α ignores the masonry's compressive strength.
LC1_CLAUSE = "Circolare 7/2019 §C8.7.1.2.1.3"


@dataclass(frozen=True)
class BuildingSettings:
    """Where the element stands in the building (the [building] table, defaults applied).

    Attributes:
        Z: height of the base of the mechanism above the foundation [m] (0: on the ground).
        H: building height [m]. N: storeys. T1: first period [s]. gamma, psi: first-mode
        participation factor and shape at Z [-] (None: the code's default).
        damping: first-mode damping of the building, fraction of critical [-].
    """

    Z: float
    H: float | None
    N: int | None
    T1: float | None
    gamma: float | None
    psi: float | None
    damping: float


def building_settings(model: Model) -> BuildingSettings:
    """The [building] table of a model (an absent table means on the ground)."""
    b = model.building
    return BuildingSettings(
        Z=b.Z, H=b.H, N=b.N, T1=b.T1, gamma=b.gamma, psi=b.psi, damping=b.damping
    )


@dataclass(frozen=True)
class NtcSettings:
    """Everything the kinematic check needs from the model file (defaults applied).

    Attributes:
        edition: "2009" or "2019". FC, q: as in the code (FC the factor used). FC_rule: why
        that FC (a note). soil, topography: category names.
        VN [years], CU [-]. use_class: "I"–"IV" or None. building: the element's place in
        the building ([building]).
        distributed: mass spread over the height for M*, e*. limit: local ultimate
        displacement of the control point [m]. site: (lon, lat) or None. demand: per limit
        state (ag [g], F0, Tc* [s]). defaults: which settings were not given (shown with the
        result).
    """

    edition: str
    FC: float
    FC_rule: str
    q: float
    soil: str
    topography: str
    VN: float
    CU: float
    building: BuildingSettings
    distributed: bool
    limit: float | None
    site: tuple[float, float] | None
    demand: dict[str, tuple[float, float, float]]
    defaults: tuple[Note, ...]
    #: The use class (NTC 2018 §2.4.2): as given, else CU's (Tab. 2.4.II); None: CU is not
    #: one of the table's.
    use_class: str | None = None


def ntc_settings(model: Model, edition: str | None = None) -> NtcSettings:
    """The [ntc] settings of a model (an absent table means every default); ``edition``: the
    command line's, in place of the model's."""
    ntc = model.ntc if model.ntc is not None else Ntc.model_validate({})
    given = ntc.model_fields_set
    demand = {}
    if ntc.demand is not None:
        for ls in ("SLO", "SLD", "SLV", "SLC"):
            p = getattr(ntc.demand, ls)
            if p is not None:
                demand[ls] = (p.ag, p.F0, p.Tc_star)
    edition = ntc.edition.value if edition is None else edition
    FC, rule = confidence_factor(ntc, edition, uses_strength(model))
    return NtcSettings(
        edition=edition,
        FC=FC,
        FC_rule=rule,
        q=ntc.q,
        soil=ntc.soil.value,
        topography=ntc.topography.value,
        VN=ntc.VN,
        CU=ntc.CU,
        building=building_settings(model),
        distributed=ntc.mass_distribution.value == "distributed",
        limit=ntc.ultimate_displacement,
        site=None if ntc.site is None else (ntc.site.lon, ntc.site.lat),
        demand=demand,
        defaults=_defaults(ntc, given),
        use_class=ntc.use_class.value if ntc.use_class is not None else use_class_of(ntc.CU),
    )


def uses_strength(model: Model) -> bool:
    """True when α0 takes the masonry's compressive strength into account: ``[masonry] f_m``
    given (the hinges of every mechanism set back by the stress block; a block file with it
    is refused, rockcli.model.derive.refuse_unrockable)."""
    return model.masonry is not None and model.masonry.f_m is not None


def confidence_factor(ntc: Ntc, edition: str, strength: bool) -> tuple[float, str]:
    """(FC, why): the factor the check divides the capacity by, and its rule as a note.

    Circolare 7/2019 §C8.7.1.2.1.3: "nel caso in cui, per la valutazione del moltiplicatore α,
    non si tenga conto della resistenza a compressione della muratura, il fattore di
    confidenza da utilizzare sarà comunque quello relativo al livello di conoscenza LC1". So
    for the 2019 edition without the strength in α0 a knowledge level's lower FC is raised to
    LC1's (with the note), and a lower FC given as a number is refused: it would be ignored,
    or silently unconservative. The 2009 edition keeps the FC given (docs/interpretations.md).

    Raises:
        InputError: an FC below LC1's for the 2019 edition where α0 ignores the strength.
    """
    FC = ntc.confidence_factor
    if ntc.FC is not None:
        source = Note("fc_given", "FC = {FC:g} as given", FC=FC)
    elif ntc.knowledge_level is not None:
        source = Note("fc_level", "FC = {FC:g} of knowledge level {level}", FC=FC,
                      level=ntc.knowledge_level.value)  # fmt: skip
    else:
        source = Note("fc_default", "FC = {FC:g} (LC1), by default", FC=FC)
    if edition != "2019" or strength or FC >= LC1_FC:
        return FC, source
    if ntc.FC is not None:
        raise InputError(
            f"below the FC of LC1 ({LC1_FC:g}), which {LC1_CLAUSE} requires when α0 does not "
            "use the masonry's compressive strength",
            where="ntc.FC",
            value=FC,
            allowed=f"FC = {LC1_FC:g} (or knowledge_level = 'LC1'); a lower FC needs [masonry] "
            "f_m on a wall of storeys, whose hinges then use it",
        )
    return LC1_FC, Note(
        "fc_lc1", "FC = {FC:g} of LC1 in place of {level}'s {given:g}: α0 does not use the "
        "masonry's compressive strength ({clause})", FC=LC1_FC, level=str(ntc.knowledge_level),
        given=FC, clause=LC1_CLAUSE)  # fmt: skip


def _defaults(ntc: Ntc, given: set[str]) -> tuple[Note, ...]:
    """The settings the model's [ntc] does not give, as the notes say them (only those: a
    kinematic check per case of a study makes them)."""
    values: dict[str, str | float] = {
        "edition": ntc.edition.value, "q": float(ntc.q), "soil": ntc.soil.value,
        "topography": ntc.topography.value, "VN": float(ntc.VN), "CU": float(ntc.CU),
    }  # fmt: skip
    out = [
        Note("setting_number", "{key} = {value:g}", key=key, value=value)
        if isinstance(value, float)
        else Note("setting", "{key} = {value}", key=key, value=value)
        for key, value in values.items()
        if key not in given
    ]
    if "FC" not in given and ntc.FC is None and ntc.knowledge_level is None:
        out.append(Note("setting_fc", "FC = {value:g} (LC1)", value=1.35))
    return tuple(out)
