"""The kinematic workflow: model file (+ record or site) → mechanism → demand → checks → result.

Composition only: the formulas live in :mod:`rockcli.codecheck`; the settings come from
:mod:`rockcli.model.derive_ntc`. The demand of each limit state is, in this order: the record
given on the command line (its response spectrum), a site given on the command line, the
model's [ntc.demand.*] parameters, the model's [ntc.site] with the hazard grid.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from dataclasses import dataclass, replace

from rockcli.codecheck.demand import LimitStateDemand, Spectrum, record_demand
from rockcli.codecheck.hazard_curve import HazardCurve
from rockcli.codecheck.result import KinematicResult
from rockcli.errors import InputError
from rockcli.model.bounds import MIN_AG
from rockcli.model.catalogue import Mechanism as CatalogueMechanism
from rockcli.model.derive_ntc import NtcSettings
from rockcli.model.schema import Model
from rockcli.records.record import Record

#: Limit states each edition checks.
LIMIT_STATES = {"2009": ("SLD", "SLV"), "2019": ("SLD", "SLV", "SLC")}


def code_demand(
    ls: str,
    params: tuple[float, float, float],
    settings: NtcSettings,
    g: float,
    source: str,
    TR: float | None = None,  # noqa: N803 (the code's symbol)
    hazard: HazardCurve | None = None,
) -> LimitStateDemand:
    """The code's elastic spectrum of one limit state, for any ag with F0 and Tc* fixed."""
    from rockcli.codecheck.spectra import ElasticSpectrum, Soil, Topography

    ag, F0, Tc = params
    soil, topo = Soil(settings.soil), Topography(settings.topography)
    return LimitStateDemand(
        limit_state=ls,
        ag=ag,
        parameters=params,
        source=source,
        at_ag=lambda a: ElasticSpectrum(ag=a, F0=F0, Tc_star=Tc, soil=soil, topography=topo, g=g),
        TR=TR,
        hazard=hazard,
    )


def site_demands(
    settings: NtcSettings, site: tuple[float, float], grid_file: str | None, g: float
) -> dict[str, LimitStateDemand]:
    """Each limit state's spectrum at a site: TR from VN·CU, (ag, F0, Tc*) from the grid."""
    from rockcli.codecheck.hazard import grid_path, grid_source, read_grid, site_parameters
    from rockcli.codecheck.spectra import LimitState, return_period

    grid = read_grid(grid_path(grid_file))
    hazard = rock_hazard(grid, site[0], site[1])
    out = {}
    for ls in LIMIT_STATES[settings.edition]:
        TR = return_period(settings.VN, settings.CU, LimitState(ls), settings.edition)
        params = site_parameters(grid, site[0], site[1], TR)
        out[ls] = code_demand(ls, params, settings, g, grid_source(site), TR, hazard)
    return out


@functools.lru_cache(maxsize=64)
def rock_hazard(grid, lon: float, lat: float) -> HazardCurve | None:
    """The site's hazard curve of ag on rock through the grid's return periods (None when its
    ag does not grow with TR: no curve to read a return period from); kept for the grid
    (read once per process) and site, as a study's cases share them (nine interpolations,
    ≈ 4 ms)."""
    from rockcli.codecheck.hazard import site_parameters
    from rockcli.codecheck.hazard_curve import rising

    periods = [float(TR) for TR in grid.return_periods]
    ag = [site_parameters(grid, lon, lat, TR).ag for TR in periods]
    if not rising(ag, periods):
        return None
    return HazardCurve(tuple(ag), tuple(1.0 / TR for TR in periods))


def given_demands(settings: NtcSettings, g: float) -> dict[str, LimitStateDemand]:
    """Each limit state's spectrum from the model's [ntc.demand.*] parameters, with the hazard
    curve through them (:func:`given_hazard`)."""
    hazard = given_hazard(settings)
    out = {}
    for ls in LIMIT_STATES[settings.edition]:
        if ls not in settings.demand:
            raise InputError(
                "missing the spectrum parameters of this limit state",
                where=f"ntc.demand.{ls}",
                allowed="ag [g], F0, Tc_star [s]",
            )
        source = f"[ntc.demand.{ls}]"
        out[ls] = code_demand(ls, settings.demand[ls], settings, g, source, hazard=hazard)
    return out


def given_hazard(settings: NtcSettings) -> HazardCurve | None:
    """The hazard curve of ag through the model's own [ntc.demand.*]: each limit state's ag
    at its return period TR = −V_R/ln(1 − P_VR) (NTC 2018 §3.2.1, Tab. 3.2.I; V_R = VN·CU),
    the points of the site's hazard the model's author read them from (the T_Rc of a
    capacity, log–log between them as Allegato A interpolates). None for the 2009 edition
    (its checks are not in ag), with fewer than two limit states, or where ag does not grow
    with TR, or grows so little that a segment is steeper than λ ∝ ag^−30:
    rockcli.codecheck.hazard_curve.rising; docs/interpretations.md)."""
    from rockcli.codecheck.hazard_curve import rising
    from rockcli.codecheck.spectra import LimitState, return_period

    if settings.edition != "2019":
        return None
    points = sorted(
        (return_period(settings.VN, settings.CU, LimitState(ls), settings.edition), p[0])
        for ls, p in settings.demand.items()
    )
    if not rising([ag for _, ag in points], [TR for TR, _ in points]):
        return None
    return HazardCurve(tuple(ag for _, ag in points), tuple(1.0 / TR for TR, _ in points),
                       "model")  # fmt: skip


def demands(
    settings: NtcSettings,
    g: float,
    record: Record | None,
    site: tuple[float, float] | None,
    grid_file: str | None,
    spectrum: Spectrum | None = None,
) -> dict[str, LimitStateDemand]:
    """The demand of every limit state the edition checks (order: record, site, model)."""
    if record is not None:
        if spectrum is None:
            from rockcli.codecheck.response import RecordSpectrum

            spectrum = RecordSpectrum.from_record(record, g=g)
        if not spectrum.pga_ground >= MIN_AG:  # 1e-310 g made capacity/demand infinite
            raise InputError(
                "the record barely moves: its spectrum cannot be the code demand",
                file=record.source,
                value=f"PGA {spectrum.pga_ground:g} g",
                allowed=f"a record whose PGA is at least {MIN_AG:g} g, as a spectrum's ag",
            )
        states = LIMIT_STATES[settings.edition]
        return {ls: record_demand(ls, spectrum, record.name) for ls in states}
    if site is not None:
        return site_demands(settings, site, grid_file, g)
    if settings.demand:
        return given_demands(settings, g)
    if settings.site is not None:
        return site_demands(settings, settings.site, grid_file, g)
    raise InputError(
        "no seismic demand",
        where="ntc",
        allowed="[ntc.site] with a hazard grid, [ntc.demand.SLD/SLV/SLC], --site LON,LAT "
        "or --record FILE",
    )


@dataclass(frozen=True)
class KinematicOutput:
    """The kinematic analysis of a model: its name, the result and the warnings on its inputs
    (magnitudes that look like unit slips), as data, no document."""

    name: str
    result: KinematicResult
    warnings: tuple[str, ...] = ()


def kinematic_model(
    model: Model,
    *,
    edition: str | None = None,
    record: Record | None = None,
    site: tuple[float, float] | None = None,
    grid_file: str | None = None,
    spectrum: Spectrum | None = None,
    demand_of: Callable[[NtcSettings, float], dict[str, LimitStateDemand]] | None = None,
    mechanisms: tuple[CatalogueMechanism, ...] | None = None,
) -> KinematicResult:
    """The kinematic analysis of a validated model.

    spectrum: the record's response spectrum when the caller already has it (a study reuses
    one per record); record: the record, to compute it otherwise. demand_of: every limit
    state's demand from the settings and g, in place of record, site and the model's own (a
    record suite's target, rockcli.studies.suite_run.compare). mechanisms: the model's catalogue
    when the caller already has it (rockcli.model.catalogue.catalogue).
    """
    from rockcli.analyses.catalogue import analyse_catalogue
    from rockcli.model.catalogue import catalogue

    settings = check_settings(model, edition)
    if mechanisms is None:
        mechanisms = catalogue(model)
    g = model.analysis.g
    if demand_of is not None:
        dem = demand_of(settings, g)
    else:
        dem = demands(settings, g, record, site, grid_file, spectrum)
    results = analyse_catalogue(mechanisms, settings, dem)
    return replace(results[0].result, catalogue=results, governing=results[0].name)


def check_settings(model: Model, edition: str | None = None) -> NtcSettings:
    """The model's code-check settings, with the edition of the command line when given."""
    from rockcli.model.derive_ntc import ntc_settings

    settings = ntc_settings(model, edition)
    if edition is None:
        return settings
    return replace(
        settings, defaults=tuple(d for d in settings.defaults if not d.startswith("edition"))
    )


def run_kinematic(
    model_path: str,
    *,
    edition: str | None = None,
    record: Record | None = None,
    site: tuple[float, float] | None = None,
    grid_file: str | None = None,
) -> KinematicOutput:
    """Load the model file and run :func:`kinematic_model`, with the warnings on its inputs."""
    from rockcli.model.load import load_model
    from rockcli.model.plausible import model_warnings

    model = load_model(model_path)
    warnings = (*model_warnings(model), *(record.warnings if record is not None else ()))
    result = kinematic_model(model, edition=edition, record=record, site=site, grid_file=grid_file)
    return KinematicOutput(model.name, result, warnings)
