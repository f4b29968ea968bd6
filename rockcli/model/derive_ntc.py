"""From the `[ntc]` and `[building]` tables to the code check's plain settings.

SI units, frozen dataclasses.

Pure: no numpy, scipy or numba (model validation starts fast; spec/engine.md "Speed").
"""

from __future__ import annotations

from dataclasses import dataclass

from rockcli.model.ntc import Ntc
from rockcli.model.schema import Model
from rockcli.notes import Note


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
        edition: "2009" or "2019". FC, q: as in the code. soil, topography: category names.
        VN [years], CU [-]. building: the element's place in the building ([building]).
        distributed: mass spread over the height for M*, e*. limit: local ultimate
        displacement of the control point [m]. site: (lon, lat) or None. demand: per limit
        state (ag [g], F0, Tc* [s]). defaults: which settings were not given (shown with the
        result).
    """

    edition: str
    FC: float
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


def ntc_settings(model: Model) -> NtcSettings:
    """The [ntc] settings of a model (an absent table means every default)."""
    ntc = model.ntc if model.ntc is not None else Ntc.model_validate({})
    given = ntc.model_fields_set
    demand = {}
    if ntc.demand is not None:
        for ls in ("SLO", "SLD", "SLV", "SLC"):
            p = getattr(ntc.demand, ls)
            if p is not None:
                demand[ls] = (p.ag, p.F0, p.Tc_star)
    return NtcSettings(
        edition=ntc.edition.value,
        FC=ntc.confidence_factor,
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
    )


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
