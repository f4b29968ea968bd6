"""Response spectra: Sa against T, one line per record, their mean in bold when several."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from rockcli.plots.files import new_figure, save

FIGURE_SIZE = (6.4, 4.4)
#: Line width of the mean of several records, against 1.0 for each record.
MEAN_WIDTH = 2.5


def plot_spectra(doc: Mapping[str, Any], path: str | Path) -> None:
    """Sa [g] against T [s] on a logarithmic period axis (the records' common grid)."""
    records = doc["records"]
    fig = new_figure(path, FIGURE_SIZE)
    ax = fig.subplots()
    periods = records[0]["periods"]
    for rec in records:
        ax.plot(periods, rec["Sa_g"], lw=1.0, label=rec["name"])
    if len(records) > 1:
        mean = [
            sum(values) / len(records) for values in zip(*(r["Sa_g"] for r in records), strict=True)
        ]
        ax.plot(periods, mean, color="k", lw=MEAN_WIDTH, label=f"mean of {len(records)}")
    ax.set_xscale("log")
    ax.set_xlabel("period T [s]")
    ax.set_ylabel("pseudo-acceleration Sa [g]")
    ax.set_ylim(bottom=0.0)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize="small")
    ax.set_title(
        f"Elastic response spectra, damping {records[0]['damping']:.4g}", fontsize="medium"
    )
    save(fig, path)
