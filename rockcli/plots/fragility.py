"""Fragility curves with their data: P(DS | IM) of each damage state, its 95 % band, and the
points it was fitted to (IDA: each record's first exceedance as the empirical distribution,
(i − ½)/n at the i-th smallest; MSA: the fraction of records reaching the state at each
stripe, labelled k/n). The curves are drawn inside the analysed intensities only, unless
``extrapolate`` (from 0 to twice the last). A study with axes has a panel per grid point."""

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


#: Most panels of one figure (grid points); the others are in fragility.json.
MAX_PANELS = 12
#: Panels per row, and the size of one panel [in].
PANELS_PER_ROW = 3
PANEL_SIZE = (4.6, 3.6)


def grid_points(doc: Mapping[str, Any]) -> list[Any]:
    """The grid points of the document, in order (one [None] for a study without axes)."""
    points: list[Any] = []
    for state in doc["damage_states"]:
        if state.get("point") not in points:
            points.append(state.get("point"))
    return points


def plot_fragility(doc: Mapping[str, Any], path: str | Path, *, extrapolate: bool = False) -> int:
    """Every damage state's curve, its band and its data; a panel per grid point (at most
    MAX_PANELS). Returns the panels drawn."""
    points = grid_points(doc)[:MAX_PANELS]
    lo, hi = analysed_range(doc)
    if extrapolate:
        x = np.linspace(0.0, EXTRAPOLATE_TO * hi, CURVE_POINTS)[1:]
    else:
        x = np.linspace(lo, hi, CURVE_POINTS)
    if len(points) == 1:
        fig = new_figure(path, FIGURE_SIZE)
        axes = [fig.subplots()]
    else:
        cols = min(PANELS_PER_ROW, len(points))
        rows = -(-len(points) // cols)
        size = (PANEL_SIZE[0] * cols, PANEL_SIZE[1] * rows)
        fig = new_figure(path, size)
        axes = list(np.atleast_1d(fig.subplots(rows, cols, squeeze=False)).ravel())
        for ax in axes[len(points) :]:
            ax.set_visible(False)
    method = "IDA" if doc["method"] == "ida" else "MSA"
    for ax, point in zip(axes, points, strict=False):
        states = [s for s in doc["damage_states"] if s.get("point") == point]
        _draw_panel(ax, doc, states, x)
        where = "" if point is None else ", ".join(f"{k} = {v}" for k, v in point.items())
        title = f"{doc['study']}: {method} fragility" if point is None else where
        ax.set_title(title, fontsize="medium")
    if len(points) > 1:
        fig.suptitle(f"{doc['study']}: {method} fragility", fontsize="medium")
    save(fig, path)
    return len(points)


def _draw_panel(ax: Any, doc: Mapping[str, Any], states: list[Any], x: np.ndarray) -> None:
    """One grid point's curves, bands and data."""
    from scipy.special import ndtr

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
