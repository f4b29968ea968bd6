"""From the `[ntc]` table to the code check's plain settings (SI units, frozen dataclasses).

Pure: no numpy, scipy or numba (model validation starts fast; spec/engine.md "Speed").
"""

from __future__ import annotations

from dataclasses import dataclass

from rockcli.model.ntc import Ntc
from rockcli.model.schema import Model

#: kN → N.
NEWTONS_PER_KILONEWTON = 1e3


@dataclass(frozen=True)
class LoadSettings:
    """An extra weight: name, weight [N], x from the pivot [m], z above it [m], bears."""

    name: str
    weight: float
    x: float | None
    z: float
    bears: bool


@dataclass(frozen=True)
class NtcSettings:
    """Everything the kinematic check needs from the model file (defaults applied).

    Attributes:
        edition: "2009" or "2019". FC, q: as in the code. soil, topography: category names.
        VN [years], CU [-]. Z, H [m], N, T1 [s], gamma, psi: position (None: default).
        distributed: mass spread over the height for M*, e*. limit: local ultimate
        displacement of the control point [m]. site: (lon, lat) or None. demand: per limit
        state (ag [g], F0, Tc* [s]). loads: extra weights. defaults: which settings were not
        given (shown with the result).
    """

    edition: str
    FC: float
    q: float
    soil: str
    topography: str
    VN: float
    CU: float
    Z: float
    H: float | None
    N: int | None
    T1: float | None
    gamma: float | None
    psi: float | None
    distributed: bool
    limit: float | None
    site: tuple[float, float] | None
    demand: dict[str, tuple[float, float, float]]
    loads: tuple[LoadSettings, ...]
    defaults: tuple[str, ...]


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
        Z=ntc.Z,
        H=ntc.H,
        N=ntc.N,
        T1=ntc.T1,
        gamma=ntc.gamma,
        psi=ntc.psi,
        distributed=ntc.mass_distribution.value == "distributed",
        limit=ntc.ultimate_displacement,
        site=None if ntc.site is None else (ntc.site.lon, ntc.site.lat),
        demand=demand,
        loads=tuple(
            LoadSettings(
                name=ld.name or f"load {i + 1}",
                weight=ld.weight * NEWTONS_PER_KILONEWTON,
                x=ld.from_pivot,
                z=ld.height,
                bears=ld.bears,
            )
            for i, ld in enumerate(ntc.loads)
        ),
        defaults=tuple(
            f"{key} = {value}" for key, value in _defaults(ntc).items() if key not in given
        ),
    )


def _defaults(ntc: Ntc) -> dict[str, str]:
    fc = "1.35 (LC1)" if ntc.FC is None and ntc.knowledge_level is None else None
    out = {
        "edition": ntc.edition.value,
        "q": f"{ntc.q:g}",
        "soil": ntc.soil.value,
        "topography": ntc.topography.value,
        "VN": f"{ntc.VN:g}",
        "CU": f"{ntc.CU:g}",
    }
    if fc:
        out["FC"] = fc
    return out
