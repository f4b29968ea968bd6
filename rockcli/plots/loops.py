"""Force–elongation loops of the restrainers whose law acted (they yielded or were lost).

The elongation at each sample is the one the run computed (History.elongations: the engine's
geometry, u = r·[sin φ − sin(φ − |θ|)] of the member of the pivot the block rotates about, or a
member's path on a chain's upper block), else r·[sin φ − sin(φ − |θ|)] from the model's r and
φ (rockcli.mechanics.spring_elongation); the force is
the engine's own, recorded at the sample (its law and state). One curve per polarity, the
yield force and the design strength as lines; a member that was lost ends at a cross.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from rockcli.mechanics import spring_elongation
from rockcli.plots.colors import POLARITY_COLORS

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from rockcli.dynamics.result import RockingRun


def acted(runs: Sequence[RockingRun]) -> list[int]:
    """Rows of the restrainers that yielded or were lost in some run."""
    if not runs:
        return []
    return [
        j
        for j in range(len(runs[0].restrainers))
        if any(r.restrainers[j].yielded or r.restrainers[j].ruptured for r in runs)
    ]


def elongation(theta: np.ndarray, spring: Mapping[str, Any], linearized: bool) -> np.ndarray:
    """u at each rotation θ [m]: the member of pivot O for θ > 0, of O′ for θ < 0, 0 at rest."""
    out = np.zeros(theta.size)
    for k, th in enumerate(theta):
        if th != 0.0:
            side = "pos" if th > 0 else "neg"
            r, phi = spring[f"r_{side}"], spring[f"phi_{side}"]
            out[k] = spring_elongation(r, phi, abs(float(th)), linearized)
    return out


def draw_loops(ax: Axes, model: Mapping[str, Any], runs: Sequence[RockingRun], row: int) -> None:
    """Force [kN] against elongation [mm] of restrainer ``row`` in both polarities."""
    spring = model["restrainers"][row]
    for run in runs:
        hist = run.history
        if hist is None:
            continue
        if hist.elongations is not None:
            u = hist.elongations[row]
        else:
            u = elongation(hist.theta, spring, model.get("linearized", False))
        force = hist.forces[row]
        t_lost = run.restrainers[row].t_fail
        if t_lost is not None:  # the member is gone: its loop ends where it was lost
            keep = hist.time <= t_lost
            u, force = u[keep], force[keep]
        color = POLARITY_COLORS.get(run.polarity, "k")
        ax.plot(1e3 * u, force / 1e3, color=color, lw=0.9, label=f"{run.polarity:+d}")
        if t_lost is not None and u.size:
            ax.plot(1e3 * u[-1], force[-1] / 1e3, "x", color=color, ms=8, mew=2)
    yields = {spring.get("yield_pos"), spring.get("yield_neg")} - {None}
    for k, f_y in enumerate(sorted(yields)):
        ax.axhline(f_y / 1e3, color="k", ls="--", lw=0.8, label="yield F_y" if k == 0 else None)
    if spring.get("strength") is not None:
        ax.axhline(
            spring["strength"] / 1e3, color="tab:red", ls=":", lw=1.2, label="design strength"
        )
    ax.set_xlabel("elongation u [mm]")
    ax.set_ylabel("force [kN]")
    ax.set_title(f"{spring['name']} ({spring.get('law', 'elastic')})", fontsize="medium")
    ax.legend(loc="lower right", fontsize="small", title="polarity")
    ax.grid(alpha=0.3)
