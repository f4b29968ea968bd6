"""A retrofit: the code's ζ and the time history's max θ/α against the rod's diameter."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rockcli.plots.files import new_figure, save

if TYPE_CHECKING:
    from matplotlib.axes import Axes

#: The limit both quantities are read against: the code's ULS passes at ζ ≥ 1; θ/α = 1 is
#: θ = α, past which a free block's weight no longer restores it (paper §2).
PASS_LIMIT = 1.0
#: Where an overturned candidate is marked (it has no max θ/α): above every other point, at
#: this multiple of the highest of them and the limit.
OVERTURN_MARK = 1.1
#: The top of a panel at least this multiple of the limit (the limit line never on the frame).
HEADROOM = 1.25
FIGURE_SIZE = (6.4, 5.6)


def plot_retrofit(doc: Mapping[str, Any], path: str | Path) -> None:
    """Two panels against d [mm]: ζ (code ULS, capacity/demand: passes ≥ 1) and max θ/α
    (time history: an overturned candidate marked ×), each with the limit 1 drawn and the
    chosen diameter marked."""
    rows = doc["candidates"]
    fig = new_figure(path, FIGURE_SIZE)
    code, rocking = fig.subplots(2, 1, sharex=True)
    _draw_code(code, rows)
    _draw_rocking(rocking, rows)
    for ax in (code, rocking):
        ax.axhline(PASS_LIMIT, color="k", lw=1.0, ls="--", label="limit 1")
        if doc["chosen"] is not None:
            c = doc["chosen"]["diameter_mm"]
            ax.axvline(c, color="tab:green", lw=1.2, ls=":", label=f"chosen Ø{c:g} mm")
        ax.set_ylim(0.0, max(ax.get_ylim()[1], HEADROOM * PASS_LIMIT))
        ax.grid(True, lw=0.3)
        ax.legend(fontsize="small")
    rocking.set_xticks([r["diameter_mm"] for r in rows])
    rocking.tick_params(axis="x", labelsize="small")
    rocking.set_xlabel("rod diameter d [mm]")
    record = doc["record"]
    under = (
        "on the model's code spectra (no record)" if record is None else f"under {record['name']}"
    )
    code.set_title(f"{doc['model']['name']} {under}", fontsize="medium")
    save(fig, path)


def _draw_code(ax: Axes, rows: Sequence[Mapping[str, Any]]) -> None:
    """ζ of the candidates whose code ULS is evaluated (a note when none is)."""
    points = [(r["diameter_mm"], r["code_zeta"]) for r in rows if r["code_zeta"] is not None]
    if points:
        ax.plot(*zip(*points, strict=True), "s-", color="tab:blue", label="ζ (passes ≥ 1)")
    else:
        ax.text(0.5, 0.5, "code ULS not evaluated", transform=ax.transAxes, ha="center")
    ax.set_ylabel("code ULS ζ [-]")


def _draw_rocking(ax: Axes, rows: Sequence[Mapping[str, Any]]) -> None:
    """max θ/α of the candidates that stand; × where the block overturns (a note when none
    was rocked: no record, or the rod on no mechanism)."""
    standing = [(r["diameter_mm"], r["max_ratio"]) for r in rows
                if not r["overturned"] and r["max_ratio"] is not None]  # fmt: skip
    if not standing and not any(r["overturned"] for r in rows):
        ax.text(0.5, 0.5, "no time history", transform=ax.transAxes, ha="center")
    if standing:
        ax.plot(*zip(*standing, strict=True), "o-", color="tab:orange", label="max θ/α")
    fallen = [r["diameter_mm"] for r in rows if r["overturned"]]
    if fallen:
        top = max([PASS_LIMIT, *(ratio for _, ratio in standing)])
        marks = [OVERTURN_MARK * top] * len(fallen)
        ax.plot(fallen, marks, "x", color="tab:red", ms=9, mew=2, label="overturns")
    ax.set_ylabel("max θ/α [-]")
