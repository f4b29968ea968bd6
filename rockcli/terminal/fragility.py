"""`rock fragility fit`: the JSON document and the terminal Report of a fitted fragility.

JSON (the contract of `rock fragility`): ``{"schema", "rock_version", "method", "im", "file",
"damage_states": [{"name", "level", "median", "beta", "beta_ddof", "n_records", "n_runs",
"ci_im", "ci"}], "records"}``. ``beta_ddof`` is the divisor's offset of β² for IDA (0: n, the
maximum likelihood; 1: n − 1) and null for MSA (a likelihood fit); ``ci`` is the bootstrap
band of the probability, [lo, hi] at each intensity of ``ci_im``; ``level`` is null and
``records`` empty for a data set read from a file (it names no damage level nor records).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from rockcli import __version__
from rockcli.fragility.data import FragilityData
from rockcli.fragility.fit import CONFIDENCE, Fit
from rockcli.terminal.table import Column, Report, Table, key_value

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
        "n_runs": fit.n,
        "ci_im": at.tolist(),
        "ci": [[_finite(lo), _finite(hi)] for lo, hi in band.tolist()],
        "probability": fit.probability(at).tolist(),
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
            "P(DS | IM) = Φ(ln(IM/θ)/β); the band: bootstrap, "
            + ("the records drawn again" if ida else "each level's counts drawn again"),
        ),
    )
