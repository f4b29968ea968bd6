"""A record suite's spectra: each record thin, the mean bold, the target and its band."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from rockcli.plots.files import new_figure, save
from rockcli.plots.phrases import Say, english

#: Colours of the records: matplotlib's tab10 without its red, which marks the target.
RECORD_COLORS = tuple(
    f"tab:{c}"
    for c in ("blue", "orange", "green", "purple", "brown", "pink", "gray", "olive", "cyan")
)
#: Period ticks labelled on the log axis [s].
PERIOD_TICKS = (0.05, 0.1, 0.15, 0.2, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 7.0, 10.0)


def plot_suite(doc: Mapping[str, Any], path: str | Path) -> None:
    """Sa of each scaled record (thin), their mean (bold), the target Se and its tolerance band
    over the checked periods (NTC §3.2.3.6), periods on a log axis.

    Args:
        doc: the `rock suite check` JSON document.
        path: the file to write, .png or .svg.
    """
    fig = new_figure(path, (9.0, 6.0))
    draw_suite(fig.add_subplot(), doc)
    fig.suptitle("rock suite check")
    save(fig, path)


def draw_suite(ax: Any, doc: Mapping[str, Any], say: Say = english) -> None:
    """The records' spectra, their mean, the target and its band on one axes (plot_suite);
    say: the figure's words (rockcli.plots.phrases)."""
    T = doc["periods"]
    for i, rec in enumerate(doc["records"]):
        color = RECORD_COLORS[i % len(RECORD_COLORS)]
        ax.plot(T, rec["Sa"], lw=0.7, alpha=0.7, color=color, label=rec["name"])
    height = doc.get("at_height")
    mean_label = say("mean_floor") if height else say("mean_records")
    target_label = say("floor_target", Z=height["Z"]) if height else say("target")
    ax.plot(T, doc["mean"], color="k", lw=2.4, label=mean_label)
    ax.plot(T, doc["target"], color="tab:red", lw=1.6, label=target_label)
    lo, hi = doc["tolerance"]
    lower = [(1.0 + lo) * t for t in doc["target"]]
    upper = [(1.0 + hi) * t for t in doc["target"]] if hi is not None else None
    ax.plot(T, lower, color="tab:red", lw=1.0, ls="--", label=say("band_lower", lo=lo))
    if upper is not None:
        ax.plot(T, upper, color="tab:red", lw=1.0, ls="--", label=say("band_upper", hi=hi))
        ax.fill_between(T, lower, upper, color="tab:red", alpha=0.08)
    _period_axis(ax, T[0], T[-1])
    ax.set_xlabel("period T [s]")
    ax.set_ylabel("spectral acceleration (5 % damping) [g]")
    verdict = "compatible" if doc["passed"] else "NOT compatible"
    where = f", floor motions at Z = {height['Z']:g} m" if height else ""
    ax.set_title(f"{doc['suite']}{where}: {verdict}", fontsize="medium")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize="x-small", ncols=2)


def _period_axis(ax: Any, lo: float, hi: float) -> None:
    """A log period axis with plain numbers (0.15, 0.2, … s) instead of powers of ten."""
    from matplotlib.ticker import FixedLocator, NullFormatter, ScalarFormatter

    ax.set_xscale("log")
    ax.xaxis.set_major_locator(FixedLocator([t for t in PERIOD_TICKS if lo <= t <= hi]))
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.xaxis.set_minor_formatter(NullFormatter())
