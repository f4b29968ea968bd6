"""`rock risk --fragility`: the JSON document and the terminal Report of the annual rate of
each damage state of a fragility at a site.

JSON: ``{"schema", "rock_version", "fragility", "site": {"lon", "lat", "soil",
"topography"}, "reference_period", "hazard": [{"TR", "ag", "F0", "S", "pga"}],
"damage_states": [{"name", "point", "median", "beta", "annual_rate", "return_period", "p50",
"p_VR", "closed_form_rate", "closed_form_ratio", "k0", "k", "median_return_period",
"tail_share"}], "notes"}`` (a state the fragility did not fit: its numbers null).
"""

from __future__ import annotations

from typing import Any

from rockcli.risk.curve import DamageRate, SitePoint
from rockcli.risk.fragility import FragilityState
from rockcli.terminal.table import Column, Report, Table, key_value
from rockcli.version import __version__

SCHEMA = 1
#: Years of the probability every document gives (NTC's nominal life of an ordinary building).
FIFTY = 50.0

NOTES = (
    "λ = ∫ P(DS | PGA)·|dλ(PGA)|: the hazard curve of the surface PGA through the grid's nine "
    "return periods (30–2475 years), log–log between them as DM 14/01/2008 Allegato A "
    "interpolates ag, and beyond them the power law of the end segment (30–50 and 975–2475 "
    "years); tail share: the part of λ from intensities beyond the grid's points",
    "closed form k0·θ^−k·exp(k²β²/2) (Cornell et al. 2002) with k0, k of the grid segment "
    "that holds the median; its ratio to λ says how far the hazard curve bends there",
    "P in t years = 1 − exp(−λ·t) (Poisson)",
)


def state_entry(state: FragilityState, rate: DamageRate | None, vr: float) -> dict[str, Any]:
    """One damage state's rates (None where the fragility gave no median)."""
    entry: dict[str, Any] = {"name": state.name, "point": state.point or None,
                             "median": state.median, "beta": state.beta}  # fmt: skip
    if rate is None:
        keys = ("annual_rate", "return_period", "p50", "p_VR", "closed_form_rate",
                "closed_form_ratio", "k0", "k", "median_return_period", "tail_share")  # fmt: skip
        return entry | dict.fromkeys(keys)
    return entry | {
        "annual_rate": rate.rate,
        "return_period": rate.return_period,
        "p50": rate.probability_in(FIFTY),
        "p_VR": rate.probability_in(vr),
        "closed_form_rate": rate.closed_form,
        "closed_form_ratio": None if rate.closed_form is None else rate.closed_form / rate.rate,
        "k0": rate.k0,
        "k": rate.k,
        "median_return_period": 1.0 / rate.median_rate,
        "tail_share": rate.tails,
    }


def risk_document(path: str, site: tuple[float, float], soil: str, topography: str, vr: float,
                  points: tuple[SitePoint, ...], states: list[dict[str, Any]],
                  notes: tuple[str, ...]) -> dict[str, Any]:  # fmt: skip
    """The `rock risk --fragility --format json` document."""
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "fragility": path,
        "site": {"lon": site[0], "lat": site[1], "soil": soil, "topography": topography},
        "reference_period": vr,
        "hazard": [{"TR": p.TR, "ag": p.ag, "F0": p.F0, "S": p.S, "pga": p.pga} for p in points],
        "damage_states": states,
        "notes": [*NOTES, *notes],
    }


HAZARD_COLUMNS = (
    Column("TR", "TR", "years", "{:g}"),
    Column("ag", "ag", "g", "{:.5f}"),
    Column("S", "S", "", "{:.3f}"),
    Column("pga", "PGA = ag·S", "g", "{:.5f}", short="PGA"),
)


def state_columns(vr: float) -> tuple[Column, ...]:
    """The damage states' table: the fragility, then its rates (V_R's column when it is not
    50 years)."""
    return tuple(
        c
        for c in (
            Column("name", "damage state"),
            Column("median", "median θ", "g", "{:.4g}", short="θ"),
            Column("beta", "β", "", "{:.3f}"),
            Column("annual_rate", "λ", "1/year", "{:.4g}"),
            Column("return_period", "1/λ", "years", "{:.4g}"),
            Column("p50", "P in 50 years", "", "{:.4f}", short="P50"),
            Column("p_VR", f"P in V_R = {vr:g} years", "", "{:.4f}", short="P_VR"),
            Column("closed_form_rate", "closed form", "1/year", "{:.4g}"),
            Column("closed_form_ratio", "closed/λ", "", "{:.3f}"),
            Column("median_return_period", "TR of θ", "years", "{:.4g}"),
        )
        if c.key != "p_VR" or vr != FIFTY
    )


def risk_report(doc: dict[str, Any]) -> Report:
    """The Report: the site, its hazard points, each damage state's rates."""
    site = doc["site"]
    items = [
        ("fragility", doc["fragility"], "", ""),
        ("site", f"{site['lon']:.4f} E, {site['lat']:.4f} N", "", ""),
        ("soil, topography", f"{site['soil']}, {site['topography']}", "", ""),
        ("reference period V_R", doc["reference_period"], "years", "{:g}"),
    ]
    rows = tuple(
        {**s, "name": s["name"] + (f" ({s['point']})" if s.get("point") else "")}
        for s in doc["damage_states"]
    )
    return Report(
        title="rock risk — annual rate of each damage state",
        tables=(
            key_value("Site", items),
            Table(
                "Hazard at the site (grid return periods)", HAZARD_COLUMNS, tuple(doc["hazard"])
            ),  # fmt: skip
            Table("Damage states", state_columns(doc["reference_period"]), rows),
        ),
        notes=tuple(doc["notes"]),
    )
