"""`rock risk --fragility F.json --site LON,LAT`: the annual rate of each damage state of a
fragility on a site's hazard (rockcli.risk), its return period and its probability in 50
years and in the reference period."""

from __future__ import annotations

import math

import click

from rockcli.cli.inputs import InputPath, RockCommand
from rockcli.cli.options import ASCII_FLOAT, SITE_ALLOWED, hazard_grid, output_format, parse_site


@click.command(
    "risk", cls=RockCommand,
    short_help="Annual rate of each damage state of a fragility at a site.",
)  # fmt: skip
@click.option("--fragility", "fragility_path", type=InputPath("file"), required=True,
              help="The JSON of `rock fragility` on PGA.")  # fmt: skip
@click.option("--site", required=True, metavar="LON,LAT",
              help="The site on the NTC hazard grid [deg east, deg north].")  # fmt: skip
@hazard_grid("NTC Allegato B grid file (default: $ROCK_HAZARD_GRID).")
@click.option("--soil", type=click.Choice(["A", "B", "C", "D", "E"]), default="A",
              show_default=True,
              help="Subsoil category (NTC 2018 Tab. 3.2.II): the fragility's PGA is read at the "
              "surface, ag·S.")  # fmt: skip
@click.option("--topography", type=click.Choice(["T1", "T2", "T3", "T4"]), default="T1",
              show_default=True, help="Topographic category (NTC 2018 Tab. 3.2.III).")  # fmt: skip
@click.option("--reference-period", "vr", type=ASCII_FLOAT, default=50.0, show_default=True,
              help="V_R = V_N·C_U [years]: the probability is given in 50 years and "
              "in V_R.")  # fmt: skip
@output_format
def risk(fragility_path, site, grid_file, soil, topography, vr, output):
    """The mean annual rate λ at which each damage state of a fragility is reached at a site,
    by the total probability theorem on the site's hazard curve of the surface PGA (the NTC
    grid's nine return periods, 30–2475 years): λ, its return period 1/λ, the probability
    in 50 years and in V_R, and beside it the closed form k0·θ^−k·exp(k²β²/2) with their
    ratio. The return period of the median alone overstates how rarely the state comes."""
    from rockcli.codecheck.hazard import grid_path, read_grid
    from rockcli.errors import InputError
    from rockcli.risk.curve import curve_of, damage_rate, site_points
    from rockcli.risk.fragility import read_fragility
    from rockcli.terminal.risk import risk_document, risk_report, state_entry
    from rockcli.terminal.table import show

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


#: The steepest hazard segment taken as a hazard curve, λ ∝ PGA^−k (the grid's rock curves:
#: k ≈ 1.5–4; a soft soil's S_S falling almost as fast as ag grows flattens the surface PGA,
#: so that λ would vanish just above it: no curve to integrate a fragility on).
STEEPEST = 30.0


def check_rising(points, soil: str) -> None:
    """The surface PGA must grow with the return period, by more than a power law of
    STEEPEST (a soft soil's S_S can fall as fast as ag grows at high hazard)."""
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
