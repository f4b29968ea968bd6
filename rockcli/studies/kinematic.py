"""The kinematic workflow: model file (+ record or site) → mechanism → demand → checks → result.

Composition only: the formulas live in :mod:`rockcli.codecheck`; the settings come from
:mod:`rockcli.model.derive_ntc`. The demand of each limit state is, in this order: the record
given on the command line (its response spectrum), a site given on the command line, the
model's [ntc.demand.*] parameters, the model's [ntc.site] with the hazard grid.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

from rockcli.codecheck import rules2009, rules2019
from rockcli.codecheck.demand import LimitStateDemand, Spectrum, record_demand
from rockcli.codecheck.kinematic import (
    Capacity,
    Mechanism,
    alpha0,
    capacity,
    curve_points,
)
from rockcli.codecheck.position import Position, position
from rockcli.codecheck.restrainer_check import nonlinear_displacement_demand, restrainer_actions
from rockcli.codecheck.result import Check, KinematicResult, Location
from rockcli.errors import InputError
from rockcli.mechanics import Block
from rockcli.model.bounds import MIN_AG
from rockcli.model.derive_ntc import NtcSettings
from rockcli.model.schema import Model
from rockcli.notes import Items, Note
from rockcli.records.record import Record

#: Limit states each edition checks.
LIMIT_STATES = {"2009": ("SLD", "SLV"), "2019": ("SLD", "SLV", "SLC")}
#: Unit mass given to a block without a [mass] table: the kinematic ratios (α0, e*, a0*, d0*)
#: of a block alone do not depend on its mass [kg].
UNIT_MASS = 1.0


def mechanism(block: Block, settings: NtcSettings, side: int) -> Mechanism:
    """The mechanism on one side: the block with its loads and thrusts (the model's own)."""
    if block.mass is None:
        block = replace(block, mass=UNIT_MASS)
    return Mechanism(
        block=block,
        side=side,
        distributed=settings.distributed,
        per_block=settings.edition == "2019",
    )


def governing_capacity(block: Block, settings: NtcSettings) -> Capacity:
    """The capacity of the side the block overturns to most easily.

    One-sided motion: the free side. Two-sided: both sides, the one with the smaller d0*
    (a side without d0*, positive stiffness, is the stronger; ties: θ > 0).
    """
    sides = (block.free_side,) if block.one_sided else (1, -1)
    caps = [capacity(mechanism(block, settings, s), settings.FC) for s in sides]
    return min(caps, key=lambda c: (c.d0_star is None, c.d0_star or 0.0, -c.mech.side))


def code_demand(
    ls: str,
    params: tuple[float, float, float],
    settings: NtcSettings,
    g: float,
    source: str,
    TR: float | None = None,  # noqa: N803 (the code's symbol)
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
    )


def demand_numbers(demand: LimitStateDemand) -> dict[str, object]:
    """The numbers of one limit state's demand, read from the spectrum the checks use.

    A code spectrum (NTC 2018 §3.2.3.2.1): TR [years] (None when the model gives the
    parameters), ag [g], F0, Tc* [s], SS, ST, S, TB, TC, TD [s]. A record: its name and PGA [g].
    Both with the `source` they come from.
    """
    from rockcli.codecheck.spectra import ElasticSpectrum

    spectrum = demand.spectrum
    if demand.record is not None or not isinstance(spectrum, ElasticSpectrum):
        return {"record": demand.record, "PGA": float(demand.ag), "source": demand.source}
    return {
        "TR": None if demand.TR is None else float(demand.TR),
        "ag": float(spectrum.ag),
        "F0": float(spectrum.F0),
        "Tc_star": float(spectrum.Tc_star),
        "SS": float(spectrum.S_S),
        "ST": float(spectrum.S_T),
        "S": float(spectrum.S),
        "TB": float(spectrum.TB),
        "TC": float(spectrum.TC),
        "TD": float(spectrum.TD),
        "source": demand.source,
    }


#: The periods each limit state's checks read a record's spectrum at, beyond T1 at height, by
#: the name of the quantity, with the damping [%] they read it at: Ts of the 2009 non-linear
#: (ULS = SLV) check at 5 %, the secant periods of 2019's SLV (8 %) and SLC (10 %) checks
#: (Circolare 7/2019 §C8.7.1.2.1.8); SLD's checks read accelerations only.
CHECK_PERIODS = {"SLD": (), "SLV": (("Ts", 5.0), ("T_SLV", 8.0)), "SLC": (("T_SLC", 10.0),)}


def with_spectral_values(
    numbers: dict[str, object],
    demand: LimitStateDemand,
    pos: Position,
    values: dict[str, float | None],
    limit_state: str,
    checks: tuple[Check, ...] | list[Check] = (),
) -> dict[str, object]:
    """A record's demand with its spectrum's values where the limit state's checks read it,
    each at the damping the check uses: Se [g] and SDe [m] at the building's T1 (at height, the
    building's damping), at the mechanism's periods (CHECK_PERIODS) and, where a check took
    the maximum over a range of periods (2019), at the period of that maximum."""
    if demand.record is None:
        return numbers
    building = 100.0 * pos.damping
    periods = [("T1", pos.T1, building)] if pos.at_height else []
    periods += [(name, values.get(name), xi) for name, xi in CHECK_PERIODS.get(limit_state, ())]
    periods += [
        (Note("max_over", "max over [{lo:g}, {hi:.4g}] s", lo=float(c.spectral.period_range[0]),
              hi=float(c.spectral.period_range[1])), c.spectral.period, c.spectral.damping)
        for c in checks
        if c.limit_state == limit_state and c.spectral and c.spectral.period_range
        and c.location is Location.GROUND
    ]  # fmt: skip
    spectrum = demand.spectrum
    numbers["spectral_values"] = [
        {"at": name, "T": T, "damping": xi, "Se": spectrum.Se(T, xi), "SDe": spectrum.SDe(T, xi)}
        for name, T, xi in periods
        if T is not None and T > 0
    ]
    return numbers


def site_demands(
    settings: NtcSettings, site: tuple[float, float], grid_file: str | None, g: float
) -> dict[str, LimitStateDemand]:
    """Each limit state's spectrum at a site: TR from VN·CU, (ag, F0, Tc*) from the grid."""
    from rockcli.codecheck.hazard import grid_path, grid_source, read_grid, site_parameters
    from rockcli.codecheck.spectra import LimitState, return_period

    grid = read_grid(grid_path(grid_file))
    out = {}
    for ls in LIMIT_STATES[settings.edition]:
        TR = return_period(settings.VN, settings.CU, LimitState(ls), settings.edition)
        params = site_parameters(grid, site[0], site[1], TR)
        out[ls] = code_demand(ls, params, settings, g, grid_source(site), TR)
    return out


def given_demands(settings: NtcSettings, g: float) -> dict[str, LimitStateDemand]:
    """Each limit state's spectrum from the model's [ntc.demand.*] parameters."""
    out = {}
    for ls in LIMIT_STATES[settings.edition]:
        if ls not in settings.demand:
            raise InputError(
                "missing the spectrum parameters of this limit state",
                where=f"ntc.demand.{ls}",
                allowed="ag [g], F0, Tc_star [s]",
            )
        out[ls] = code_demand(ls, settings.demand[ls], settings, g, f"[ntc.demand.{ls}]")
    return out


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


def analyse(
    block: Block, settings: NtcSettings, dem: dict[str, LimitStateDemand]
) -> KinematicResult:
    """The kinematic analysis and the checks of the settings' edition."""
    cap = governing_capacity(block, settings)
    b = settings.building
    pos = position(b.Z, b.H, b.N, b.T1, b.gamma, b.psi, b.damping)
    by_side = {str(s): alpha0(mechanism(block, settings, s)) for s in (1, -1)}
    return analyse_capacity(cap, settings, dem, pos, by_side)


def analyse_capacity(
    cap: Capacity,
    settings: NtcSettings,
    dem: dict[str, LimitStateDemand],
    pos: Position,
    alpha0_by_side: dict[str, float],
    extra_notes: tuple[str, ...] = (),
) -> KinematicResult:
    """The checks of the settings' edition on one mechanism's capacity at its position."""
    notes = [*pos.notes, *extra_notes]
    if getattr(settings.FC_rule, "key", None) == "fc_lc1":
        notes.append(settings.FC_rule)
    if settings.defaults:
        notes.append(Note("defaults", "defaults (not in the model's [ntc]): {settings}",
                          settings=Items(settings.defaults)))  # fmt: skip
    notes.append(
        Note("capacity_linear", "capacity curve: linear a0*(1 − d*/d0*), constant forces "
             "(Circ. 617/2009 §C8A.4.2.3; Circ. 7/2019 §C8.7.1.2)")
        if cap.linear
        else Note("capacity_curve", "capacity curve: α(θ) with the restrainers that cannot "
                  "fail (an interpretation of rock's: the code's linear curve does not hold "
                  "for restrainers)")
    )  # fmt: skip
    if cap.d0_star is None:
        notes.append(Note("no_d0", "positive global stiffness: α never vanishes, no d0*"))
    notes += [
        Note(
            "tie_slack",
            "{name}: a tie-rod only pulls, so it adds nothing when the mechanism "
            "opens inward (side −1: α0 and the curve without it); the time history keeps its "
            "spring on both sides",
            name=sp.name,
        )  # fmt: skip
        for sp in cap.mech.restrainers
        if sp.slack_side
    ]
    if settings.edition == "2009":
        values, checks = rules2009.check_2009(
            cap, dem["SLD"], dem["SLV"], pos, settings.q, _limit(cap, settings)
        )
    else:
        values, checks, extra = rules2019.check_2019(
            cap, dem, pos, settings.q, _limit(cap, settings)
        )
        notes += extra
        if not cap.free:
            notes.append(Note("rigid", "rigid until activation: not declared free to vibrate "
                              "(the elastic branch of Circ. 7/2019 §C8.7.1.2.1.3, Eqs. "
                              "C8.7.1.6–7, is for elements free to vibrate: [[mechanisms]] "
                              "free = true)"))  # fmt: skip
    actions = restrainer_actions(
        cap, *governing_demand(cap, settings.edition, values, checks, dem, pos)
    )
    return KinematicResult(
        edition=settings.edition,
        side=cap.mech.side,
        alpha0=cap.alpha0,
        e_star=cap.e_star,
        a0_star=cap.a0_star,
        FC=cap.FC,
        d0_star=cap.d0_star,
        linear_curve=cap.linear,
        quantities=values,
        checks=tuple(checks),
        curve=tuple(curve_points(cap)),
        demand={
            ls: with_spectral_values(demand_numbers(d), d, pos, values, ls, checks)
            for ls, d in dem.items()
        },
        notes=tuple(notes),
        alpha0_by_side=alpha0_by_side,
        restrainer_actions=actions,
        FC_rule=str(settings.FC_rule),
    )


def governing_demand(
    cap: Capacity,
    edition: str,
    values: dict[str, float | None],
    checks: list[Check],
    dem: dict[str, LimitStateDemand],
    pos: Position,
) -> tuple[float | None, str]:
    """(d* [m], what it is) at which a spring's force is verified against its strength.

    The displacement demand of the non-linear SLV check when it is computed (2009: the largest
    of SDe(Ts) and the demand at height; 2019: the SLV spectrum's at T_SLV), else the ultimate
    displacement (du*; d_SLV), else none (positive stiffness and no limit: the check reaches no
    displacement, so a spring's force there is not evaluated).
    """
    if edition == "2009":
        demand = nonlinear_displacement_demand(checks)
        ultimate, name = values.get("du_star"), "du*"
    else:
        t0 = cap.T0 if cap.T0 is not None else rules2019.T0_RIGID
        demand = rules2019.slv_displacement_demand(values, dem["SLV"], pos, cap.mech.g, t0)
        ultimate, name = values.get("d_SLV"), "d_SLV"
    if demand is not None:
        return demand, f"SLV displacement demand d* = {demand:.4g} m"
    if ultimate is not None:
        return ultimate, f"{name} = {ultimate:.4g} m"
    return None, f"the check reaches no displacement (no {name})"


def _limit(cap: Capacity, settings: NtcSettings) -> float | None:
    """The local ultimate displacement as a spectral displacement d* [m]."""
    return None if settings.limit is None else settings.limit * cap.factor


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
) -> KinematicResult:
    """The kinematic analysis of a validated model.

    spectrum: the record's response spectrum when the caller already has it (a study reuses
    one per record); record: the record, to compute it otherwise. demand_of: every limit
    state's demand from the settings and g, in place of record, site and the model's own (a
    record suite's target, rockcli.studies.suite.compare).
    """
    from rockcli.model.derive import to_block
    from rockcli.model.derive_wall import is_wall

    settings = check_settings(model, edition)
    if is_wall(model):
        return wall_model(model, settings, record, site, grid_file, spectrum, demand_of)
    block = to_block(model)
    if demand_of is not None:
        dem = demand_of(settings, block.g)
    else:
        dem = demands(settings, block.g, record, site, grid_file, spectrum)
    result = analyse(block, settings, dem)
    return with_block_entry(result, block, settings)


def with_block_entry(result: KinematicResult, block: Block, settings: NtcSettings):
    """Today's block as the catalogue's one mechanism: overturning of the whole wall."""
    from rockcli.codecheck.kinematic import participating_mass
    from rockcli.studies.catalogue import MechanismResult

    m_star = participating_mass(mechanism(block, settings, result.side))
    from rockcli.mechanisms.wall import WHOLE_WALL

    name = WHOLE_WALL
    result = replace(result, mechanism=name)
    entry = MechanismResult(name, "overturning", 0.0, None, m_star, result)
    return replace(result, catalogue=(entry,), governing=name)


def wall_model(model, settings, record, site, grid_file, spectrum, demand_of) -> KinematicResult:
    """The catalogue of a wall: every mechanism, the governing one's result with the rest."""
    from rockcli.model.derive import free_side
    from rockcli.model.derive_wall import to_wall
    from rockcli.model.schema import Sides
    from rockcli.studies.catalogue import analyse_wall

    wall = to_wall(model)
    if demand_of is not None:
        dem = demand_of(settings, wall.g)
    else:
        dem = demands(settings, wall.g, record, site, grid_file, spectrum)
    motion = model.motion
    free = free_side(motion.stopped) if motion.sides is Sides.ONE else None
    results = analyse_wall(wall, settings, dem, free)
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


def run_kinematic(model_path: str, **options: Any) -> KinematicOutput:
    """Load the model file and run :func:`kinematic_model`."""
    from rockcli.model.load import load_model
    from rockcli.model.plausible import model_warnings

    model = load_model(model_path)
    record = options.get("record")
    warnings = (*model_warnings(model), *(record.warnings if record is not None else ()))
    return KinematicOutput(model.name, kinematic_model(model, **options), warnings)
