"""Fragility curves with their data: P(DS | IM) of each damage state, its 95 % band, and the
points it was fitted to (IDA: each record's first exceedance as the empirical distribution,
(i − ½)/n at the i-th smallest; MSA: the fraction of records reaching the state at each
stripe, labelled k/n). The curves are drawn inside the analysed intensities only, unless
``extrapolate`` (from 0 to twice the last)."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from rockcli.plots.files import new_figure, save

FIGURE_SIZE = (6.4, 4.6)
#: Points of a drawn curve.
CURVE_POINTS = 200
#: How far --extrapolate draws, as a multiple of the last analysed intensity.
EXTRAPOLATE_TO = 2.0


def analysed_range(doc: Mapping[str, Any]) -> tuple[float, float]:
    """The intensities the study ran: IDA's scan, MSA's levels."""
    if doc["method"] == "ida":
        return float(doc["scan_first"]), float(doc["scan_last"])
    return float(doc["levels"][0]), float(doc["levels"][-1])


def plot_fragility(doc: Mapping[str, Any], path: str | Path, *, extrapolate: bool = False) -> None:
    """Every damage state's curve (of the first grid point), its band and its data."""
    from scipy.special import ndtr

    lo, hi = analysed_range(doc)
    if extrapolate:
        x = np.linspace(0.0, EXTRAPOLATE_TO * hi, CURVE_POINTS)[1:]
    else:
        x = np.linspace(lo, hi, CURVE_POINTS)
    fig = new_figure(path, FIGURE_SIZE)
    ax = fig.subplots()
    first = doc["damage_states"][0].get("point")
    states = [s for s in doc["damage_states"] if s.get("point") == first]
    for k, state in enumerate(states):
        color = f"C{k}"
        label = state["name"]
        if state["median"] is not None:
            p = ndtr(np.log(x / state["median"]) / state["beta"])
            ax.plot(
                x,
                p,
                color=color,
                lw=1.8,
                label=f"{label}: θ = {state['median']:.3g}, β = {state['beta']:.2f}",
            )
            band = [
                (a, b[0], b[1])
                for a, b in zip(state["ci_im"], state["ci"], strict=True)
                if b[0] is not None and b[1] is not None
            ]
            if band:
                xs, los, his = zip(*band, strict=True)
                ax.fill_between(xs, los, his, color=color, alpha=0.15, lw=0)
        else:
            label = f"{label}: no fit"
        _draw_data(ax, doc, state, color, label if state["median"] is None else None)
    ax.set_xlabel(f"intensity measure {doc['im_label']}")
    ax.set_ylabel("P(damage state | IM)")
    ax.set_ylim(-0.02, 1.02)
    ax.set_xlim(left=0.0)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize="small", loc="lower right")
    where = "" if first is None else " (" + ", ".join(f"{k} = {v}" for k, v in first.items()) + ")"
    method = "IDA" if doc["method"] == "ida" else "MSA"
    ax.set_title(f"{doc['study']}: {method} fragility{where}", fontsize="medium")
    save(fig, path)


def _draw_data(
    ax: Any, doc: Mapping[str, Any], state: Mapping[str, Any], color: str, label: str | None
) -> None:
    """IDA: the empirical distribution of the first exceedances; MSA: the stripes' fractions
    with their counts."""
    if doc["method"] == "ida":
        values = np.sort(np.asarray(state.get("collapse_im", []), dtype=float))
        if values.size:
            n = values.size
            ax.plot(values, (np.arange(1, n + 1) - 0.5) / n, "o", color=color, ms=4, label=label)
        return
    for stripe in state.get("stripes", []):
        if not stripe["runs"]:
            continue
        frac = stripe["exceedances"] / stripe["runs"]
        ax.plot([stripe["im"]], [frac], "s", color=color, ms=4, label=label)
        label = None
        ax.annotate(
            f"{stripe['exceedances']}/{stripe['runs']}",
            (stripe["im"], frac),
            textcoords="offset points",
            xytext=(4, 4),
            fontsize="x-small",
            color=color,
        )
