"""The code's capacity curve a*–d* with the demands of the checks (paper Fig. 6)."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rockcli.plots.files import new_figure, save
from rockcli.plots.phrases import Say, english

if TYPE_CHECKING:
    from matplotlib.axes import Axes

PASSED_COLORS = {True: "tab:green", False: "tab:red", None: "0.5"}
LIMIT_STATE_STYLES = {"DLS": "--", "SLD": "--", "ULS": "-.", "SLV": "-.", "SLC": ":"}


def _word(passed: bool | None, say: Say) -> str:
    if passed is None:
        return say("not_evaluated")
    return say("satisfied" if passed else "not_satisfied")


def _curve(kin: Mapping[str, Any]) -> tuple[list[float], list[float]]:
    rows = kin["curve"]
    return [r["d_star"] for r in rows], [r["a_star"] for r in rows]


def _a_on_curve(kin: Mapping[str, Any], d: float) -> float:
    """a* at d* by linear interpolation of the curve rows (past the last row: 0 beyond d0*,
    else the last value)."""
    import numpy as np

    ds, as_ = _curve(kin)
    if d > ds[-1]:
        return 0.0 if kin["d0_star"] is not None else as_[-1]
    return float(np.interp(d, ds, as_))


def _draw_secant(ax: Axes, d: float, a: float, label: str, color: str) -> None:
    """The secant from the origin to (d, a) on the curve, and the point."""
    ax.plot([0.0, d], [0.0, a], color=color, lw=0.9, ls="-")
    ax.plot([d], [a], "o", color=color, ms=6, label=label)


def _draw_quantities(ax: Axes, kin: Mapping[str, Any], say: Say) -> None:
    """2009: du* and the secant to (ds*, as*) with Ts; 2019: the SLV/SLC points with T."""
    if kin.get("du_star") is not None:
        du = kin["du_star"]
        ax.axvline(du, color="k", ls="--", lw=1.0, label=say("du", du=du))
        ax.annotate(
            "du*", (du, 1.0), xycoords=("data", "axes fraction"), xytext=(3, -3),
            textcoords="offset points", ha="left", va="top", fontsize="small",
        )  # fmt: skip
    if kin.get("ds_star") is not None and kin.get("Ts") is not None:
        label = say("secant_2009", ds=kin["ds_star"], a=kin["as_star"], T=kin["Ts"])
        _draw_secant(ax, kin["ds_star"], kin["as_star"], label, "tab:blue")
    for ls, color in (("SLV", "tab:blue"), ("SLC", "tab:purple")):
        d, a, T = kin.get(f"d_{ls}"), kin.get(f"a_{ls}"), kin.get(f"T_{ls}")
        if d is not None and a is not None:
            state = say(f"state_{ls}")
            label = (
                say("secant_period", state=state, d=d, a=a, T=T)
                if T is not None
                else say("secant_2019", state=state, d=d, a=a)
            )
            _draw_secant(ax, d, a, label, color)


def _check_name(c: Mapping[str, Any], say: Say) -> str:
    state, method = say(f"state_{c['limit_state']}"), say(f"method_{c['method']}")
    return say("check_name", state=state, method=method, where=say(f"where_{c['location']}"))


def _check_label(c: Mapping[str, Any], say: Say) -> str:
    name = _check_name(c, say)
    if c["demand"] is None or c["capacity"] is None:
        return say("check_not_evaluated", name=name)
    numbers = {"name": name, "demand": c["demand"], "capacity": c["capacity"],
               "unit": c["unit"], "word": _word(c["passed"], say)}  # fmt: skip
    if c["unit"] in ("m/s²", "m"):
        return say("check_demand", **numbers)
    # 2019 compares peak ground accelerations: the ag the element withstands and the site's.
    return say("check_ag" if c["unit"] == "g" else "check_capacity", **numbers)


def on_the_plane(c: Mapping[str, Any], kin: Mapping[str, Any]) -> tuple[str, float] | None:
    """Where a check of ag (Circ. 7/2019 §C8.7.1.2.1.5–6: the ag the mechanism withstands
    against the limit state's) has its demand on the a*–d* plane: a linear check's demand is
    the spectral acceleration a0*·ag_D/ag_C (its demand scales with ag and meets a0* at the
    capacity), ("a", a*) [m/s²]; a non-linear check's is the spectral displacement it read at
    the limit state's ag (``demand_spectral``), ("d", d*) [m]; None when it has neither."""
    if c["unit"] != "g" or not c["demand"] or not c["capacity"]:
        return None
    if c["method"] == "linear" and kin.get("a0_star"):
        return "a", kin["a0_star"] * c["demand"] / c["capacity"]
    if c["method"] == "nonlinear" and c.get("demand_spectral"):
        return "d", c["demand_spectral"]
    return None


def _draw_checks(ax: Axes, kin: Mapping[str, Any], say: Say) -> None:
    """The demands of the checks: accelerations [m/s²] as horizontal lines (against a0*),
    displacements [m] as points on the curve (against du*); a check of ag (2019) where its
    demand lies on the plane (:func:`on_the_plane`); those not evaluated as legend entries
    with a square of their colour."""
    from matplotlib.lines import Line2D

    for c in kin["checks"]:
        color = PASSED_COLORS[c["passed"]]
        style = LIMIT_STATE_STYLES.get(c["limit_state"], "-")
        if c["passed"] is not None and c["unit"] == "m/s²":
            ax.axhline(c["demand"], color=color, ls=style, lw=1.2, label=_check_label(c, say))
            mark = say("demand_mark", state=say(f"state_{c['limit_state']}"),
                       where=say(f"where_{c['location']}"))  # fmt: skip
            ax.annotate(
                mark, (1.0, c["demand"]),
                xycoords=("axes fraction", "data"), xytext=(-3, 2), textcoords="offset points",
                ha="right", va="bottom", fontsize="x-small", color=color,
            )  # fmt: skip
        elif c["passed"] is not None and c["unit"] == "m":
            a = _a_on_curve(kin, c["demand"])
            ax.plot([c["demand"]] * 2, [0.0, a], color=color, ls=style, lw=1.2)
            ax.plot([c["demand"]], [a], "D", color=color, ms=6, label=_check_label(c, say))
        elif c["passed"] is not None and (plane := on_the_plane(c, kin)) is not None:
            # A check of ag (2019) drawn where its demand lies on the a*–d* plane.
            kind, value = plane
            label = _check_label(c, say)
            if kind == "a":
                ax.axhline(value, color=color, ls=style, lw=1.2, label=label)
            else:
                a = _a_on_curve(kin, value)
                ax.plot([value] * 2, [0.0, a], color=color, ls=style, lw=1.2)
                ax.plot([value], [a], "D", color=color, ms=6, label=label)
        else:
            label = _check_label(c, say)
            ax.add_line(Line2D([], [], ls="none", marker="s", color=color, label=label))


#: The frame shows a* up to this multiple of the largest acceleration the checks use (a0*, the
#: demands, the points of the edition): a curve that stiffens far past them (positive global
#: stiffness, sampled to θ = π/4) leaves the frame instead of flattening everything else.
FRAME_FACTOR = 2.5


def _crossing(ds: list[float], as_: list[float], level: float) -> float:
    """d* where the curve first rises through a* = level (linear between rows)."""
    for k in range(1, len(ds)):
        if as_[k] > level:
            share = (level - as_[k - 1]) / (as_[k] - as_[k - 1])
            return ds[k - 1] + max(0.0, share) * (ds[k] - ds[k - 1])
    return ds[-1]


def _frame(ax: Axes, kin: Mapping[str, Any], say: Say) -> None:
    """Axes from 0; when the curve rises past FRAME_FACTOR × the checks' accelerations, the
    frame stops there and the legend says where the curve goes."""
    from matplotlib.lines import Line2D

    ds, as_ = _curve(kin)
    marks = [kin["a0_star"], *(kin.get(k) for k in ("as_star", "a_SLV", "a_SLC"))]
    marks += [c["demand"] for c in kin["checks"] if c["unit"] == "m/s²"]
    planes = [p for p in (on_the_plane(c, kin) for c in kin["checks"]) if p is not None]
    marks += [value for kind, value in planes if kind == "a"]
    top = FRAME_FACTOR * max(m for m in marks if m is not None)
    if max(as_) <= top:
        ax.set_xlim(left=0.0)
        ax.set_ylim(bottom=0.0)
        return
    xs = [_crossing(ds, as_, top), *(kin.get(k) for k in ("du_star", "d_SLV", "d_SLC"))]
    xs += [c["demand"] for c in kin["checks"] if c["unit"] == "m"]
    xs += [value for kind, value in planes if kind == "d"]
    ax.set_xlim(0.0, 1.05 * max(x for x in xs if x is not None))
    ax.set_ylim(0.0, top)
    note = say("off_frame", a=as_[-1], d=ds[-1])
    ax.add_line(Line2D([], [], ls="none", label=note))


def _verdict_text(kin: Mapping[str, Any], say: Say) -> str:
    """2009: DLS and ULS; 2019: its three limit states."""
    states = ("SLD", "SLV", "SLC") if kin["edition"] == "2019" else ("DLS", "ULS")
    return ", ".join(
        say("verdict_item", state=say(f"state_{ls}"), word=_word(kin["verdict"].get(ls), say))
        for ls in states
    )


def draw_capacity(ax: Axes, kin: Mapping[str, Any], say: Say = english) -> None:
    """The capacity curve a*–d* with a0*, d0*, the edition's quantities and the demands
    (paper Fig. 6); say: the figure's words (rockcli.plots.phrases)."""
    from rockcli.terminal.kinematic import CIRCOLARE

    ds, as_ = _curve(kin)
    ax.plot(ds, as_, color="k", lw=2.0, label=say("curve"))
    a0 = kin["a0_star"]
    ax.plot([0.0], [a0], "o", color="k", ms=6, clip_on=False, label=say("a0", a0=a0))
    if kin["d0_star"] is not None:
        d0 = kin["d0_star"]
        ax.plot([d0], [0.0], "o", color="k", mfc="w", clip_on=False, label=say("d0", d0=d0))
    _draw_quantities(ax, kin, say)
    _draw_checks(ax, kin, say)
    _frame(ax, kin, say)
    ax.set_xlabel("spectral displacement d* [m]")
    ax.set_ylabel("spectral acceleration a* [m/s²]")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), fontsize="x-small", ncols=2)
    ax.grid(alpha=0.3)
    ax.set_title(
        f"Kinematic analysis, {CIRCOLARE[kin['edition']]}\n{_verdict_text(kin, say)}",
        fontsize="medium",
    )


def plot_kinematic(doc: Mapping[str, Any], path: str | Path) -> None:
    """The capacity curve a*–d* with the checks' demands (paper Fig. 6).

    2009: a0* against the linear checks' accelerations (horizontal lines), du* = 0.4·d0* and
    the secant to (ds*, as*) that gives Ts, the non-linear checks' displacement demands
    (SDe(Ts) at the ground, the amplified one at height) as points on the curve. 2019: the
    SLV and SLC points (d, a) with their secant periods; the checks, in ag [g], as text.

    Args:
        doc: the `rock kinematic` JSON document.
        path: the file to write, .png or .svg.
    """
    fig = new_figure(path, (9.0, 7.0))
    draw_capacity(fig.add_subplot(), doc)
    fig.suptitle(f"rock kinematic — {doc['model']['name']}")
    save(fig, path)
