"""Overturning spectra: the lowest overturning intensity against ωp/p or the block's size."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from rockcli.plots.files import new_figure, save

FIGURE_SIZE = (6.4, 4.4)
#: Marker size of a point of the spectrum [points].
MARKER = 4.0


def plot_overturning(doc: Mapping[str, Any], path: str | Path) -> None:
    """The threshold against x, a line per record; points without a threshold are left out
    (a gap in the line)."""
    fig = new_figure(path, FIGURE_SIZE)
    ax = fig.subplots()
    x = doc["x"]
    if "pulse" in doc:
        series = [(f"{doc['pulse']} pulse", doc["threshold"])]
        ax.set_xlabel("ωp/p")
        ax.set_ylabel(f"lowest overturning {doc['threshold_name']}")
        title = f"Overturning spectrum, {doc['pulse']} pulse"
    else:
        series = [(r["name"], t) for r, t in zip(doc["records"], doc["threshold"], strict=True)]
        from rockcli.terminal.overturning import SIZE_UNITS

        ax.set_xlabel(f"{doc['x_name']} [{SIZE_UNITS[doc['x_name']]}]")
        ax.set_ylabel("lowest overturning scale of the record")
        title = "Overturning spectrum of records"
    for label, values in series:
        ys = [float("nan") if v is None else v for v in values]
        ax.plot(x, ys, marker="o", ms=MARKER, lw=1.2, label=label)
    ax.set_ylim(bottom=0.0)
    ax.set_xlim(min(x) - 0.05 * _span(x), max(x) + 0.05 * _span(x))  # a gap shows at the end
    ax.grid(True, lw=0.3)
    ax.legend(fontsize="small")
    ax.set_title(f"{title} (scan step {doc['scan_step']:g})", fontsize="medium")
    save(fig, path)


def _span(x: list[float]) -> float:
    return (max(x) - min(x)) or 1.0
