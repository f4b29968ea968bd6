"""`rock fragility fit`: the JSON document and the terminal Report of a fitted fragility.

JSON (the contract of `rock fragility`): ``{"schema", "rock_version", "method", "im", "file",
"damage_states": [{"name", "level", "median", "beta", "beta_ddof", "n_records", "n_runs",
"ci_im", "ci"}], "records"}``. ``beta_ddof`` is the divisor's offset of β² for IDA (0: n, the
maximum likelihood; 1: n − 1) and null for MSA (a likelihood fit); ``ci`` is the 95 %
band of the probability, [lo, hi] at each intensity of ``ci_im``; ``level`` is null and
``records`` empty for a data set read from a file (it names no damage level nor records).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from rockcli.studies.fragility.data import FragilityData
from rockcli.studies.fragility.fit import CONFIDENCE, Fit, band_method
from rockcli.terminal.table import Column, Report, Table, key_value
from rockcli.version import __version__

SCHEMA = 1


def fit_document(data: FragilityData, fit: Fit, at: np.ndarray, band: np.ndarray) -> dict[str, Any]:
    """The `rock fragility fit --format json` document."""
    ida = data.method == "ida"
    state = {
        "name": "data",
        "level": None,
        "median": fit.median,
        "beta": fit.beta,
        "beta_ddof": fit.beta_ddof,
        "n_records": int(data.im.size) if ida else None,
        **(
            {"not_reached": int(data.censored.sum()) if data.censored is not None else 0}
            if ida
            else {}
        ),
        "n_runs": fit.n,
        "ci_im": at.tolist(),
        "ci": [[_finite(lo), _finite(hi)] for lo, hi in band.tolist()],
        "probability": fit.probability(at).tolist(),
        "band_method": band_method(
            data.method, bool(ida and data.censored is not None and data.censored.any())
        ),
    }
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "method": data.method,
        "im": "im",
        "file": data.file,
        "damage_states": [state],
        "records": [],
    }


def _finite(x: float) -> float | None:
    return x if np.isfinite(x) else None


BAND_COLUMNS = (
    Column("im", "IM", fmt="{:.4g}"),
    Column("p", "P(DS | IM)", fmt="{:.3f}"),
    Column("lo", f"{CONFIDENCE:.0%} band, low", fmt="{:.3f}", short="low"),
    Column("hi", f"{CONFIDENCE:.0%} band, high", fmt="{:.3f}", short="high"),
)


def fit_report(doc: dict[str, Any]) -> Report:
    """The Report: the fitted median and dispersion, and the curve with its band at the
    data's intensities."""
    state = doc["damage_states"][0]
    ida = doc["method"] == "ida"
    items = [
        ("method", "IDA (collapse intensities)" if ida else "MSA (counts at levels)", "", ""),
        ("median θ", state["median"], "IM", "{:.4g}"),
        ("dispersion β", state["beta"], "", "{:.4g}"),
    ]
    if ida:
        divisor = "n" if state["beta_ddof"] == 0 else "n − 1"
        items.append(("β² divisor", divisor, "", ""))
        items.append(("records", state["n_records"], "", "{}"))
        if state.get("not_reached"):
            items.append(("of which censored", state["not_reached"], "", "{}"))
    else:
        items.append(("runs", state["n_runs"], "", "{}"))
    rows = tuple(
        {"im": x, "p": p, "lo": band[0], "hi": band[1]}
        for x, p, band in zip(state["ci_im"], state["probability"], state["ci"], strict=True)
    )
    return Report(
        title=f"rock fragility fit — {doc['file']}",
        tables=(key_value("Lognormal fragility", items), Table("Curve", BAND_COLUMNS, rows)),
        notes=(
            f"P(DS | IM) = Φ(ln(IM/θ)/β); the band: {state['band_method']}",
            *(
                (
                    "censored records (censored = 1) did not reach the state up to their im: the "
                    "fit is the censored maximum likelihood, β² divided by n",
                )
                if state.get("not_reached")
                else ()
            ),
        ),
    )


def _point_text(point: dict[str, Any] | None) -> str:
    return ", ".join(f"{k} = {v}" for k, v in (point or {}).items())


def study_report(doc: dict[str, Any]) -> Report:
    """The Report of `rock fragility STUDY.toml`: each damage state's median and dispersion
    (each grid point's), then each record's first exceedances (IDA) or errors."""
    ida = doc["method"] == "ida"
    has_points = any("point" in s for s in doc["damage_states"])
    unit = doc["im_label"].rpartition("[")[2].rstrip("]")
    cols = (
        *((Column("point", "point", align="left"),) if has_points else ()),
        Column("name", "damage state"),
        Column("median", "median θ", unit, "{:.4g}"),
        Column("beta", "dispersion β", "", "{:.3f}", short="β"),
        Column("n_records", "records", fmt="{}"),
        *((Column("not_reached", "not reached", fmt="{}", short="not"),) if ida else ()),
        Column("n_runs", "runs", fmt="{}"),
    )
    rows = tuple({**s, "point": _point_text(s.get("point"))} for s in doc["damage_states"])
    tables = [Table(f"Fragility, IM = {doc['im_label']}", cols, rows)]
    if ida:
        names = [s["name"] for s in doc["damage_states"][: _states_per_point(doc)]]
        rec_cols = (
            *((Column("point", "point", align="left"),) if has_points else ()),
            Column("name", "record"),
            *(Column(f"ds{k}", n, unit, "{:.4g}") for k, n in enumerate(names)),
        )
        rec_rows = tuple(
            {
                "point": _point_text(r.get("point")),
                "name": r["name"],
                **{f"ds{k}": (r["first_exceedance"] or {}).get(n) for k, n in enumerate(names)},
            }
            for r in doc["records"]
        )
        tables.append(Table("First exceedance of each damage state", rec_cols, rec_rows))
    return Report(
        title=f"rock fragility — {doc['study']}",
        tables=tuple(tables),
        notes=tuple(_study_notes(doc)),
    )


def _states_per_point(doc: dict[str, Any]) -> int:
    first = doc["damage_states"][0].get("point")
    return sum(1 for s in doc["damage_states"] if s.get("point") == first)


def _study_notes(doc: dict[str, Any]) -> list[str]:
    notes = ["P(DS | IM) = Φ(ln(IM/θ)/β), θ the median, β the dispersion."]
    if doc["method"] == "ida":
        ddof = next((s["beta_ddof"] for s in doc["damage_states"] if s["beta_ddof"] is not None), 0)
        notes.append(
            f"IDA: each record scaled up from {doc['scan_first']:g} in steps of "
            f"{doc['scan_step']:g} to {doc['scan_last']:g}, then bisected to "
            f"{doc['tolerance']:g} inside the first step that reaches each state; a window "
            "narrower than the step can be missed. β² divides by "
            + ("n (maximum likelihood)." if ddof == 0 else "n − 1.")
        )
        if any(s.get("not_reached") for s in doc["damage_states"]):
            notes.append(
                "Records that do not reach a state by the scan's end (not reached) are "
                "right-censored there: that state's θ and β are the censored maximum "
                "likelihood (β² divided by n)."
            )
    else:
        levels = ", ".join(f"{x:g}" for x in doc["levels"])
        notes.append(
            f"MSA: every record at each level ({levels}); θ and β by maximum "
            "likelihood on the binomial counts (Baker 2015)."
        )
    errors = [r for r in doc["records"] if r["error"]]
    for r in errors:
        notes.append(f"record {r['name']} failed: {r['error']}")
    for s in doc["damage_states"]:
        if s.get("note"):
            notes.append(f"{s['name']}: no fit ({s['note']}).")
    run = doc["run"]
    notes.append(
        f"{run['computed_runs']} runs computed ({run['resumed_runs']} read back) in "
        f"{run['wall_time_s']:.1f} s; every run in {run['out']}/cases.csv."
    )
    return notes
