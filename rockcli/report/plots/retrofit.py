"""A retrofit: the code's ζ and the time history's max θ/α against the rod's diameter."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from rockcli.report.plots.files import new_figure, save

#: The line both quantities are read against: the code's ULS passes at ζ ≥ 1; θ/α = 1 is
#: θ = α, past which a free block's weight no longer restores it (paper §2).
PASS_LIMIT = 1.0
FIGURE_SIZE = (6.4, 4.0)


def plot_retrofit(doc: Mapping[str, Any], path: str | Path) -> None:
    """ζ (code ULS, capacity/demand: passes ≥ 1) and max θ/α (time history) against d [mm],
    with the limit 1 drawn, the overturned candidates marked and the chosen one circled."""
    rows = doc["candidates"]
    d = [r["diameter_mm"] for r in rows]
    fig = new_figure(path, FIGURE_SIZE)
    ax = fig.add_subplot()
    zeta = [(x, r["code_zeta"]) for x, r in zip(d, rows, strict=True) if r["code_zeta"] is not None]
    if zeta:
        ax.plot(*zip(*zeta, strict=True), "s-", color="tab:blue", label="code ULS ζ (pass ≥ 1)")
    standing = [(x, r["max_ratio"]) for x, r in zip(d, rows, strict=True) if not r["overturned"]]
    if standing:
        ax.plot(*zip(*standing, strict=True), "o-", color="tab:orange", label="max θ/α")
    fallen = [x for x, r in zip(d, rows, strict=True) if r["overturned"]]
    if fallen:
        ax.plot(fallen, [PASS_LIMIT] * len(fallen), "x", color="tab:red", ms=9, mew=2,
                label="overturns")  # fmt: skip
    ax.axhline(PASS_LIMIT, color="k", lw=1.0, ls="--", label="limit 1")
    if doc["chosen"] is not None:
        c = doc["chosen"]["diameter_mm"]
        ax.axvline(c, color="tab:green", lw=1.2, ls=":", label=f"chosen Ø{c:g} mm")
    ax.set_xlabel("rod diameter d [mm]")
    ax.set_ylabel("ζ, max θ/α [-]")
    ax.set_title(f"{doc['model']['name']} under {doc['record']['name']}", fontsize="medium")
    ax.legend(fontsize="small")
    ax.grid(True, lw=0.3)
    save(fig, path)
