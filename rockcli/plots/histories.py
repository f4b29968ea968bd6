"""θ/α of both polarities against time over the record (paper Fig. 7, 11, 12)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rockcli.plots.colors import POLARITY_COLORS
from rockcli.plots.files import new_figure, save
from rockcli.plots.phrases import Say, english

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from rockcli.dynamics.result import History, RockingRun
    from rockcli.records.record import Record

#: |θ| at which a run counts as overturned unless the model sets it [rad] (paper §3.1; the
#: value of rockcli.dynamics.settings.DEFAULT_OVERTURN_ANGLE, not imported to keep numpy out).
OVERTURN_ANGLE = math.pi / 2
#: Vertical room above the largest |θ|/α, and the smallest half-range so that ±1 shows [-].
HEADROOM = 1.1
MIN_RATIO_RANGE = 1.2


def _history(run: RockingRun) -> History:
    if run.history is None:
        raise ValueError("the run has no history: run the assessment with history=True")
    return run.history


def _run_label(run: RockingRun, say: Say) -> str:
    sign = "+" if run.polarity > 0 else "−"
    if run.t_overturn is not None:
        # Not its max θ/α: an overturned run's is the overturning angle over α, a number
        # that says nothing (issue 19).
        return say("run_overturns", sign=sign, t=run.t_overturn)
    return say("run", sign=sign, ratio=run.max_ratio)


def _ratio_limits(peak: float, level: float | None, free_side: int | None) -> tuple[float, float]:
    """y range of θ/α: the data with headroom, ±1 always, the overturning level if drawn."""
    top = max(MIN_RATIO_RANGE, HEADROOM * peak, HEADROOM * (level or 0.0))
    if free_side is None:
        return -top, top
    return (-0.15 * top, top) if free_side > 0 else (-top, 0.15 * top)


def _plot_runs(ax: Axes, runs: Sequence[RockingRun], alpha: float, say: Say) -> float:
    """θ/α of each run, a cross where it overturns; returns the peak |θ|/α drawn."""
    peak = 0.0
    for run in runs:
        hist = _history(run)
        ratio = hist.theta / alpha
        peak = max(peak, float(abs(ratio).max(initial=0.0)))
        color = POLARITY_COLORS.get(run.polarity, "k")
        ax.plot(hist.time, ratio, color=color, lw=1.0, label=_run_label(run, say))
        if run.overturned:
            ax.plot(hist.time[-1], ratio[-1], "x", color=color, ms=9, mew=2, clip_on=False)
    return peak


def _mark_levels(
    ax: Axes, sides: tuple[int, ...], level: float | None, angle: float, say: Say
) -> None:
    """θ = ±α, and the overturning level |θ| = angle when it is drawn (level: in θ/α)."""
    for k, side in enumerate(sides):
        ax.axhline(side, color="k", ls="--", lw=0.8, label=say("alpha_level") if k == 0 else None)
        if level is not None:
            label = say("overturn_level", angle=angle) if k == 0 else None
            ax.axhline(side * level, color="tab:red", ls=":", lw=1.2, label=label)
    ax.axhline(0.0, color="0.6", lw=0.5)


def draw_histories(
    ax: Axes,
    model: Mapping[str, Any],
    runs: Sequence[RockingRun],
    overturn_angle: float,
    verdict: str,
    say: Say = english,
) -> None:
    """θ/α of both polarities against time, ±1 (θ = ±α) and the overturning level (drawn
    only when a run overturns or comes near it: a survivor's figure carries no overturning
    mark), the legend above the axes; say: the figure's words (rockcli.plots.phrases)."""
    alpha = model["alpha"]
    free_side = model["free_side"] if model["sides"] == "one" else None
    peak = _plot_runs(ax, runs, alpha, say)
    level = overturn_angle / alpha
    shown = level if any(r.overturned for r in runs) or peak >= level else None
    _mark_levels(ax, (free_side,) if free_side else (1, -1), shown, overturn_angle, say)
    ax.set_ylim(*_ratio_limits(peak, shown, free_side))
    ax.set_ylabel("amplitude ratio θ/α [-]")
    word = say(f"verdict_{verdict}")
    title = (
        say("histories_one_sided", verdict=word, sign="<" if free_side > 0 else ">")
        if free_side
        else say("histories_title", verdict=word)
    )
    ax.legend(
        loc="lower left", bbox_to_anchor=(0.0, 1.0), ncols=2, fontsize="small", frameon=False,
        title=title, alignment="left",
    )  # fmt: skip
    ax.grid(alpha=0.3)


def draw_record(
    ax: Axes, record: Record, t_end: float, floor: bool = False, say: Say = english
) -> None:
    """The acceleration that shook the block [g] (polarity +1), to the end of the runs: the
    record at the base, or its floor motion for a block at height (``floor``)."""
    ax.plot(
        record.time, record.accel, color="0.25", lw=0.8, label=say("record", record=record.name)
    )
    ax.axhline(0.0, color="0.6", lw=0.5)
    ax.set_xlim(float(record.time[0]), max(t_end, float(record.time[-1])))
    ax.set_xlabel("time t [s]")
    ax.set_ylabel(say("floor_acc") if floor else say("ground_acc"))
    ax.legend(loc="upper right", fontsize="small", title=say("pga", pga=record.pga))
    ax.grid(alpha=0.3)


def draw_time_panels(
    fig: Figure,
    spec: Any,
    doc: Mapping[str, Any],
    runs: Sequence[RockingRun],
    record: Record,
    overturn_angle: float,
    say: Say = english,
) -> None:
    """θ/α above, the record below, on a shared time axis, in a gridspec cell pair."""
    top = fig.add_subplot(spec[0])
    bottom = fig.add_subplot(spec[1], sharex=top)
    draw_histories(top, doc["model"], runs, overturn_angle, doc["verdict"], say)
    top.tick_params(labelbottom=False)
    floor = doc.get("record", {}).get("input") == "floor"
    draw_record(bottom, record, max(r.t_end for r in runs), floor, say)


def plot_assessment(
    doc: Mapping[str, Any],
    runs: Sequence[RockingRun],
    path: str | Path,
    *,
    record: Record,
    overturn_angle: float = OVERTURN_ANGLE,
) -> None:
    """θ/α of both polarities against time over the record's acceleration (paper Fig. 7, 11);
    below them, the force–elongation loop of each restrainer that yielded or was lost.

    Args:
        doc: the `rock assess` JSON document.
        runs: both polarities, with their history (assess with history=True).
        path: the file to write, .png or .svg.
        record: the record the runs were computed with (acceleration [g]).
        overturn_angle: |θ| at which a run counts as overturned [rad].
    """
    from rockcli.plots.loops import acted, draw_loops  # numpy: loaded only to draw

    loops = acted(runs)
    if not loops:
        fig = new_figure(path, (10.0, 6.0))
        spec = fig.add_gridspec(2, 1, height_ratios=(3, 1))
        draw_time_panels(fig, [spec[0], spec[1]], doc, runs, record, overturn_angle)
    else:
        fig = new_figure(path, (10.0, 10.0))
        outer = fig.add_gridspec(2, 1, height_ratios=(4, 2.6), hspace=0.25)
        time_spec = outer[0].subgridspec(2, 1, height_ratios=(3, 1), hspace=0.08)
        draw_time_panels(fig, [time_spec[0], time_spec[1]], doc, runs, record, overturn_angle)
        loop_spec = outer[1].subgridspec(1, len(loops), wspace=0.25)
        for k, row in enumerate(loops):
            draw_loops(fig.add_subplot(loop_spec[k]), doc["model"], runs, row)
    fig.suptitle(f"rock assess — {doc['model']['name']} under {record.name}")
    save(fig, path)
