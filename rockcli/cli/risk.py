"""`rock risk`: the risk class of MODEL's local mechanisms (DM 58/2017 Allegato A, before and
after the tie-rod `rock retrofit` sizes), or with --fragility the annual rate of each damage
state of a fragility on a site's hazard (rockcli.risk)."""

from __future__ import annotations

import math

import click

from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import (
    ASCII_FLOAT,
    SITE_ALLOWED,
    check_record_options,
    edition_option,
    hazard_grid,
    load_record,
    output_format,
    parse_site,
    with_record_options,
)

#: The options of the fragility form only (the model's [ntc] sets them for MODEL).
FRAGILITY_ONLY = ("--soil", "--topography", "--reference-period")


@click.command(
    "risk", cls=RockCommand,
    short_help="Risk class of MODEL (DM 58/2017), or a fragility's annual rates.",
)  # fmt: skip
@click.argument("model_path", metavar="[MODEL]", type=InputPath(), required=False)
@click.option("--fragility", "fragility_path", type=InputPath("file"), default=None,
              help="The JSON of `rock fragility` on PGA: the annual rate of each damage state "
              "at --site (instead of MODEL).")  # fmt: skip
@click.option("--site", default=None, metavar="LON,LAT",
              help="The site on the NTC hazard grid [deg east, deg north] (MODEL: instead of "
              "its own demand).")  # fmt: skip
@hazard_grid("NTC Allegato B grid file (default: $ROCK_HAZARD_GRID).")
@click.option("--soil", type=click.Choice(["A", "B", "C", "D", "E"]), default=None,
              help="--fragility: subsoil category (NTC 2018 Tab. 3.2.II): the fragility's PGA "
              "is read at the surface, ag·S [default: A].")  # fmt: skip
@click.option("--topography", type=click.Choice(["T1", "T2", "T3", "T4"]), default=None,
              help="--fragility: topographic category (NTC 2018 Tab. 3.2.III) "
              "[default: T1].")  # fmt: skip
@click.option("--reference-period", "vr", type=ASCII_FLOAT, default=None,
              help="--fragility: V_R = V_N·C_U [years]: the probability is given in 50 years "
              "and in V_R [default: 50].")  # fmt: skip
@click.option("--retrofit", is_flag=True,
              help="MODEL: the class without its tie-rod and with the diameter `rock "
              "retrofit` sizes on the model's own spectra (rocked under --record when given), "
              "and the classes gained.")  # fmt: skip
@with_record_options(required=False,
                     optional_help=" for --retrofit: the rod's time history (none: the code "
                     "check alone).")  # fmt: skip
@edition_option
@output_format
def risk(model_path, fragility_path, site, grid_file, soil, topography, vr, retrofit,
         record_path, record_format, dt, units, scale, pga, edition, output):  # fmt: skip
    """The seismic risk class of MODEL from its local mechanisms (DM 58/2017 Allegato A,
    conventional method): the return period T_Rc of the action that brings each mechanism
    to SLD, SLV and SLC on the site's hazard, PAM, IS-V, the class; with --retrofit the class
    without the model's tie-rod and with the diameter `rock retrofit` chooses. The class from
    local mechanisms is an upper bound of the building's: its global behaviour must be
    checked too.

    With --fragility F.json --site LON,LAT instead of MODEL: the mean annual rate λ at which
    each damage state of a fragility is reached at the site (the total probability theorem on
    the hazard curve of the surface PGA through the grid's nine return periods), its return
    period, the probability in 50 years and in V_R, and the closed form
    k0·θ^−k·exp(k²β²/2) beside it."""
    from rockcli.errors import InputError

    if (model_path is None) == (fragility_path is None):
        raise InputError("give one of MODEL and --fragility" if model_path is None else
                         "MODEL and --fragility together", where="risk",
                         allowed="rock risk MODEL, or rock risk --fragility F.json --site "
                         "LON,LAT")  # fmt: skip
    check_record_options(record_path, record_format, dt, units, scale, pga)
    if fragility_path is not None:
        given = dict(zip(("--retrofit", "--record", "--edition"),
                         (retrofit or None, record_path, edition), strict=True))  # fmt: skip
        refuse_given(given, "applies to MODEL, not to --fragility", "rock risk MODEL with it")
        fragility_risk(fragility_path, site, grid_file, soil or "A", topography or "T1",
                       50.0 if vr is None else vr, output)  # fmt: skip
        return
    given = dict(zip(FRAGILITY_ONLY, (soil, topography, vr), strict=True))
    refuse_given(given, "applies to --fragility; the model's [ntc] sets it for MODEL",
                 "the model's [ntc] soil, topography, VN and CU")  # fmt: skip
    if record_path is not None and not retrofit:
        raise InputError("applies to --retrofit (the rod's time history)", where="--record",
                         value=record_path, allowed="--retrofit --record FILE")  # fmt: skip
    if retrofit and site is not None:
        raise InputError("not with --retrofit: the rod is sized on the model's own spectra",
                         where="--site", value=site,
                         allowed="the site in the model's [ntc.site], or no "
                         "--retrofit")  # fmt: skip
    model_class(model_path, site, grid_file, retrofit, edition, output,
                (record_path, record_format, dt, units, scale, pga))  # fmt: skip


def refuse_given(given: dict, problem: str, allowed: str) -> None:
    """InputError naming the first option given that this form of the command does not take."""
    from rockcli.errors import InputError

    for option, value in given.items():
        if value is not None:
            raise InputError(problem, where=option, value=value, allowed=allowed)


def model_class(model_path, site, grid_file, retrofit, edition, output, record_args) -> None:
    """`rock risk MODEL [--retrofit]`: the class of the model's local mechanisms."""
    from rockcli.analyses.choices import Analyses
    from rockcli.model.load import load_model
    from rockcli.risk.model import model_risk, retrofit_risk
    from rockcli.terminal.risk_class import risk_class_document, risk_class_report
    from rockcli.terminal.table import show

    lon_lat = None if site is None else parse_site(site)
    analyses = Analyses(edition=edition)
    name = load_model(model_path).name
    if not retrofit:
        state = model_risk(model_path, analyses, lon_lat, grid_file)
        doc = risk_class_document(name, model_path, state)
    else:
        record = None if record_args[0] is None else load_record(*record_args)
        before, rod, after = retrofit_risk(model_path, record, analyses, grid_file)
        doc = risk_class_document(name, model_path, before, (rod, after))
    show(doc, output, risk_class_report)


def fragility_risk(fragility_path, site, grid_file, soil, topography, vr, output) -> None:
    """The annual rate of each damage state of a fragility at a site (rockcli.risk.curve)."""
    from rockcli.codecheck.hazard import grid_path, read_grid
    from rockcli.errors import InputError
    from rockcli.risk.curve import curve_of, damage_rate, site_points
    from rockcli.risk.fragility import read_fragility
    from rockcli.terminal.risk import risk_document, risk_report, state_entry
    from rockcli.terminal.table import show

    if site is None:
        raise InputError("--fragility needs the site", where="--site",
                         allowed=SITE_ALLOWED + ", inside the NTC grid")  # fmt: skip
    lon, lat = parse_site(site)
    if not (math.isfinite(vr) and 1.0 <= vr <= 1e4):
        raise InputError("not a reference period", where="--reference-period", value=vr,
                         allowed="V_R in [1, 10000] years")  # fmt: skip
    states = read_fragility(fragility_path)
    grid = read_grid(grid_path(grid_file))
    try:
        points = site_points(grid, lon, lat, soil, topography)
    except InputError as exc:
        raise InputError(exc.problem, where="--site", value=site,
                         allowed=SITE_ALLOWED + ", inside the NTC grid") from None  # fmt: skip
    check_rising(points, soil)
    curve = curve_of(points)
    rates = [damage_rate(curve, s.median, s.beta) if s.median and s.beta else None
             for s in states]  # fmt: skip
    entries = [state_entry(s, r, vr) for s, r in zip(states, rates, strict=True)]
    notes = state_notes(states, rates)
    doc = risk_document(fragility_path, (lon, lat), soil, topography, vr, points, entries, notes)
    show(doc, output, risk_report)


def check_rising(points, soil: str) -> None:
    """The surface PGA must grow with the return period, by more than a power law of
    STEEPEST (a soft soil's S_S can fall as fast as ag grows at high hazard)."""
    from rockcli.codecheck.hazard_curve import STEEPEST
    from rockcli.errors import InputError

    for a, b in zip(points[:-1], points[1:], strict=True):
        if not (b.pga > a.pga and math.log(b.TR / a.TR) <= STEEPEST * math.log(b.pga / a.pga)):
            raise InputError(
                f"the surface PGA ag·S goes from {a.pga:.4g} g at {a.TR:g} years to "
                f"{b.pga:.4g} g at {b.TR:g} years (S_S falls as fast as ag grows)",
                where="--soil", value=soil,
                allowed="a soil whose surface PGA grows with the return period at this site",
            )  # fmt: skip


def state_notes(states, rates) -> tuple[str, ...]:
    """What each state's rate rests on: the tails beyond the grid's points, or nothing."""
    notes = []
    for state, rate in zip(states, rates, strict=True):
        if rate is not None and rate.tails > 0.5:
            notes.append(f"{state.name}: {rate.tails:.1%} of λ from PGAs beyond the grid's "
                         "points: the rate rests on the extrapolated hazard curve")  # fmt: skip
        elif rate is not None:
            notes.append(f"{state.name}: {rate.tails:.1%} of λ from PGAs beyond the grid's points")
        elif state.fitted:
            notes.append(f"{state.name}: no usable rate (beyond e^±700 a year)")
    unfitted = [s.name for s in states if not s.fitted]
    if unfitted:
        notes.append(f"not fitted by the fragility, no rate: {', '.join(unfitted)}")
    return tuple(notes)
