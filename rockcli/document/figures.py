"""The report's figures as SVG markup: the block to scale, the spectra, the capacity curve,
θ/α(t) over the record, the restrainer forces against their strength.

The plots of the terminal commands (rockcli.plots) draw the capacity curve and the
time histories; this module puts them on the report's pages with the report's axis labels.
matplotlib writes SVG with its text as paths (``svg.fonttype = "path"``, its default), so the
figures look the same in every browser and in the PDF.
"""

from __future__ import annotations

import functools
import io
import math
import re
import weakref
from collections.abc import Callable, Mapping, Sequence
from contextvars import ContextVar
from typing import TYPE_CHECKING, Any

from rockcli.document.words import Words
from rockcli.plots.phrases import Say

if TYPE_CHECKING:
    import numpy as np
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure as MplFigure

    from rockcli.codecheck.position import Position
    from rockcli.codecheck.spectra import ElasticSpectrum
    from rockcli.dynamics.result import RockingRun
    from rockcli.records.record import Record

#: Width of a full-width figure on an A4 page with 2 cm margins [in].
PAGE_WIDTH = 6.7
#: Periods of the spectra figure [s].
SPECTRUM_PERIODS = (0.0, 4.0, 401)
#: Room above the highest curve of the spectra at height, a share of the axis (the names of
#: the periods marked stand there).
HEADROOM = 0.12
#: Periods closer than this have their names one under the other [s].
MARK_GAP = 0.2
LS_COLORS = {"SLO": "tab:gray", "SLD": "tab:green", "SLV": "tab:red", "SLC": "tab:purple"}


#: The decimal mark of each figure's language (a figure made for an Italian report writes its
#: tick labels 0,5 as the report's tables do); weak keys: a figure is freed once rendered.
DECIMAL_MARKS: weakref.WeakKeyDictionary[MplFigure, str] = weakref.WeakKeyDictionary()


def new_figure(width: float, height: float, words: Words) -> MplFigure:
    """A figure of the report (constrained layout), its tick labels in ``words``' language."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    DECIMAL_MARKS[fig] = "," if words.lang == "it" else "."
    return fig


def decimal_ticks(fig: MplFigure) -> None:
    """The tick labels of every axis with the figure's decimal mark (DECIMAL_MARKS)."""
    mark = DECIMAL_MARKS.get(fig, ".")
    if mark == ".":
        return
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            formatter = axis.get_major_formatter()
            if not isinstance(formatter, decimal_mark_type()):
                axis.set_major_formatter(decimal_mark_type()(formatter, mark))


#: Resolution of a figure's PNG (the Word copy) [dots per inch].
PNG_DPI = 200
#: Whether the report being built needs each figure as PNG (its Word copy): a report without
#: --docx does not draw them (a second rendering of every figure). Set by
#: rockcli.document.run for the report it builds.
PNG_WANTED: ContextVar[bool] = ContextVar("png_wanted", default=True)


def rendered(fig: MplFigure) -> tuple[str, bytes]:
    """The figure as inline SVG (:func:`svg_markup`) and as PNG (PNG_DPI; empty when the
    report has no Word copy, PNG_WANTED), the figure then cleared."""
    from rockcli.plots.files import clean_texts

    clean_texts(fig)
    decimal_ticks(fig)
    buffer = io.BytesIO()
    if PNG_WANTED.get():
        fig.savefig(buffer, format="png", dpi=PNG_DPI, metadata={"Software": None})
    return svg_markup(fig), buffer.getvalue()


def svg_markup(fig: MplFigure) -> str:
    """The figure as an <svg> element to inline in HTML (no XML prolog, no fixed size: it
    scales to the width of the page); its texts cleaned first
    (:func:`rockcli.plots.files.clean_texts`)."""
    from rockcli.plots.files import clean_texts

    buffer = io.StringIO()
    try:
        clean_texts(fig)
        fig.savefig(buffer, format="svg", metadata={"Date": None})
    finally:
        fig.clear()
    text = buffer.getvalue()
    text = text[text.index("<svg") :]
    return re.sub(r'<svg([^>]*?) width="[^"]*" height="[^"]*"', r"<svg\1", text, count=1)


def block_sketch(model: Mapping[str, Any], words: Words) -> MplFigure:
    """The block to scale: its outline 2b × 2h, pivots O and O′, centroid G, loads (weights
    at their points), thrusts (arrows) and restrainers (springs to an anchor), every point
    where the model puts it (docs/conventions.md: x from O, z above the base)."""
    b, h = model["b"], model["h"]
    width = 2.0 * b
    fig = new_figure(
        PAGE_WIDTH * 0.62, min(6.5, max(3.0, 4.2 * (2 * h) / max(2 * h, 3 * width))), words
    )
    ax = fig.add_subplot()
    ax.fill([0, width, width, 0], [0, 0, 2 * h, 2 * h], color="#d9cbb5", ec="k", lw=1.2)
    ax.plot([-0.6 * width, 1.6 * width], [0, 0], color="k", lw=0.8)
    ax.plot([0], [0], "o", color="k", ms=5)
    ax.annotate("O", (0, 0), xytext=(-10, -12), textcoords="offset points")
    ax.plot([width], [0], "o", color="k", ms=5)
    ax.annotate("O′", (width, 0), xytext=(4, -12), textcoords="offset points")
    ax.plot([b], [h], "+", color="k", ms=10, mew=1.5)
    ax.annotate("G", (b, h), xytext=(5, 5), textcoords="offset points")
    span = max(width, 2 * h)
    for load in model.get("loads", []):
        ax.annotate("", (load["x_pos"], load["z"]), xytext=(load["x_pos"], load["z"] + 0.12 * span),
                    arrowprops={"arrowstyle": "-|>", "color": "tab:blue", "lw": 1.5})  # fmt: skip
        ax.annotate(load["name"], (load["x_pos"], load["z"] + 0.12 * span), fontsize="x-small",
                    color="tab:blue", ha="center", va="bottom")  # fmt: skip
    for thrust in model.get("thrusts", []):
        sign = 1.0 if thrust["direction"] in (1, "positive") else -1.0  # towards θ > 0: −x
        start = thrust["x_pos"] + sign * 0.15 * span
        ax.annotate("", (thrust["x_pos"], thrust["z"]), xytext=(start, thrust["z"]),
                    arrowprops={"arrowstyle": "-|>", "color": "tab:red", "lw": 1.5})  # fmt: skip
        ax.annotate(thrust["name"], (start, thrust["z"]), xytext=(0, -10),
                    textcoords="offset points", fontsize="x-small", color="tab:red", ha="center",
                    va="top")  # fmt: skip
    for spring in model.get("restrainers", []):
        _draw_spring(ax, spring, width, span)
    ax.set_aspect("equal")
    ax.set_xlim(-0.6 * width - 0.05 * span, 1.6 * width + 0.25 * span)
    ax.set_ylim(-0.08 * span, 2 * h + 0.2 * span)
    ax.set_xlabel(words("figure.x_m"))
    ax.set_ylabel(words("figure.z_m"))
    return fig


def _draw_spring(ax: Axes, spring: Mapping[str, Any], width: float, span: float) -> None:
    """A restrainer of the positive side: its point (r, φ from O) joined by a zig-zag to an
    anchor beyond the face O′, the side towards which it holds the block back."""
    import numpy as np

    r, phi = spring["r_pos"], spring["phi_pos"]
    if not spring["k_pos"]:
        r, phi = spring["r_neg"], spring["phi_neg"]
    x, z = r * math.sin(phi), r * math.cos(phi)
    end = width + 0.35 * span
    xs = np.linspace(x, end, 41)
    zig = np.where((np.arange(41) > 8) & (np.arange(41) < 32), 0.02 * span, 0.0)
    zs = z + zig * np.sign(np.sin(np.arange(41) * np.pi / 2 + 0.1))
    ax.plot(xs, zs, color="tab:green", lw=1.2)
    ax.plot([x], [z], "o", color="tab:green", ms=4)
    ax.plot([end, end], [z - 0.05 * span, z + 0.05 * span], color="k", lw=2.5)
    ax.annotate(spring["name"], (end, z), xytext=(4, 4), textcoords="offset points",
                fontsize="x-small", color="tab:green")  # fmt: skip


def spectra(
    code: Sequence[tuple[str, Any]], record: Any | None, record_name: str,
    marks: Mapping[str, float], words: Words,
) -> MplFigure:  # fmt: skip
    """Se(T) [g]: the code's elastic spectra (limit state, ElasticSpectrum), the record's
    5 %-damped response spectrum (RecordSpectrum) when there is one, and the periods marked
    (T1, Ts…)."""
    import numpy as np

    periods = np.linspace(*SPECTRUM_PERIODS)
    fig = new_figure(PAGE_WIDTH, 3.2, words)
    ax = fig.add_subplot()
    for state, spectrum in code:
        values = [spectrum.Se(float(T)) for T in periods]
        ax.plot(periods, values, color=LS_COLORS.get(state, "k"), lw=1.4,
                label=words("figure.code_spectrum", state=state))  # fmt: skip
    if record is not None:
        Se, _ = record.curve(periods[1:])
        ax.plot(periods[1:], Se, color="k", lw=1.0, label=words("figure.record_spectrum",
                                                                   record=record_name))  # fmt: skip
    _mark_periods(ax, marks)
    ax.set_xlim(0.0, SPECTRUM_PERIODS[1])
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel(words("figure.period"))
    ax.set_ylabel(words("figure.se"))
    ax.grid(alpha=0.3)
    ax.legend(fontsize="small")
    return fig


def floor_spectra(
    code: Sequence[tuple[str, Any]], pos: Position, edition: str, motion: Any | None,
    record_name: str, marks: Mapping[str, float], words: Words,
) -> MplFigure:  # fmt: skip
    """The spectra at the mechanism's height Z [g]: per limit state the code's demand at height
    (:func:`floor_curve`, the check's own rule), the 5 %-damped response spectrum of the floor
    motion the rocking analysis used (RecordSpectrum; None: it used the record itself), the
    building's T1 and the periods of ``marks`` marked."""
    import numpy as np

    periods = np.linspace(*SPECTRUM_PERIODS)
    Z = words.number(pos.Z, "{:g}")
    fig = new_figure(PAGE_WIDTH, 4.0, words)
    ax = fig.add_subplot()
    for state, spectrum in code:
        T, values = floor_curve(spectrum, state, pos, edition, periods)
        if len(T):
            ax.plot(T, values, color=LS_COLORS.get(state, "k"), lw=1.4,
                    label=words(f"figure.floor_spectrum_{edition}", Z=Z, state=state))  # fmt: skip
    if motion is not None:
        Se, _ = motion.curve(periods[1:])
        ax.plot(periods[1:], Se, color="k", lw=1.0,
                label=words("figure.floor_record_spectrum", record=record_name, Z=Z))  # fmt: skip
    assert pos.T1 is not None
    _mark_periods(ax, {"T1": pos.T1, **marks})
    ax.margins(y=HEADROOM)  # the marks' names above the peaks, which lie near T1
    ax.set_xlim(0.0, SPECTRUM_PERIODS[1])
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel(words("figure.period"))
    ax.set_ylabel(words("figure.se"))
    ax.grid(alpha=0.3)
    # Under the axes: the curves peak anywhere from T1 to the record's periods.
    fig.legend(loc="outside lower center", fontsize="small")
    return fig


def _mark_periods(ax: Axes, marks: Mapping[str, float]) -> None:
    """A dashed vertical line at each period, its name at the top of the axes (a name below
    the one before when their periods are closer than MARK_GAP)."""
    previous: list[float] = []
    for name, T in marks.items():
        below = sum(abs(T - t) < MARK_GAP for t in previous)
        previous.append(T)
        ax.axvline(T, color="0.4", lw=0.8, ls="--")
        ax.annotate(name, (T, 1.0), xycoords=("data", "axes fraction"),
                    xytext=(3, -12 - 11 * below), textcoords="offset points",
                    fontsize="small")  # fmt: skip


def floor_curve(
    spectrum: ElasticSpectrum, state: str, pos: Position, edition: str, periods: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """(T [s], S [g]): the demand at the mechanism's height ``pos`` of one limit state's
    ground spectrum, by the edition's rule (:func:`floor_curve_2019`, :func:`floor_curve_2009`);
    empty for a limit state the edition does not check (analyses.kinematic.LIMIT_STATES)."""
    import numpy as np

    from rockcli.analyses.kinematic import LIMIT_STATES

    if state not in LIMIT_STATES[edition]:
        return np.array([]), np.array([])
    if edition == "2009":
        return floor_curve_2009(spectrum, pos, periods)
    return floor_curve_2019(spectrum, state, pos, periods)


def floor_curve_2019(
    spectrum: ElasticSpectrum, state: str, pos: Position, periods: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """(T, S_eZ(T)) [s, g]: the floor spectrum of Circolare 7/2019 §C7.2.3 as the check reads
    it (§C8.7.1.2.1): rules2019.bounded_floor_spectrum, the first mode's floor spectrum at the
    position (the building's T1 and damping ξ_k) not below the ground spectrum for T > T1
    (Eq. C7.2.5), at the mechanism's damping of the limit state's check (rules2019.DAMPING)."""
    import numpy as np

    from rockcli.codecheck import rules2019

    xi = rules2019.DAMPING[state]
    values = [rules2019.bounded_floor_spectrum(spectrum, float(T), pos, xi) for T in periods]
    return np.asarray(periods, dtype=float), np.array(values)


def floor_curve_2009(
    spectrum: ElasticSpectrum, pos: Position, periods: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """(T, S) [s, g], T > 0: the displacement demand at height of Circolare 617/2009
    §C8A.4.2.3 (rules2009.height_displacement, read there at T = Ts) as a pseudo-acceleration
    S = d·(2π/T)²/g (NTC 2008 §3.2.3.2.3, Eq. 3.2.12). It tends to Se(T1)·ψ·γ as T → 0, the
    demand of the linear checks at height (§C8A.4.2.1–C8A.4.2.2)."""
    import numpy as np

    from rockcli.codecheck import rules2009

    T = np.asarray(periods, dtype=float)
    T = T[T > 0.0]
    d = np.array([rules2009.height_displacement(spectrum, pos, float(t)) for t in T])
    return T, d * (2.0 * math.pi / T) ** 2 / spectrum.g


def phrases(words: Words) -> Say:
    """The figures' words in the report's language (the catalogue's ``[plot]`` table)."""

    def say(key: str, **values: Any) -> str:
        # Numbers with the language's decimal mark, as in the tables (0,6479 m/s²).
        return words(f"plot.{key}", **{k: words.localised(v) for k, v in values.items()})

    return say


def on_page(
    draw: Callable[..., None], data: Mapping[str, Any], height: float, labels: tuple[str, str],
    words: Words,
) -> MplFigure:  # fmt: skip
    """A terminal command's plot (``draw(ax, data, say)``) at the page's width, its title
    left to the caption, its words and axis labels in the report's language."""
    fig = new_figure(PAGE_WIDTH, height, words)
    ax = fig.add_subplot()
    draw(ax, data, phrases(words))
    ax.set_title("")
    ax.set_xlabel(labels[0])
    ax.set_ylabel(labels[1])
    return fig


def capacity(kin: Mapping[str, Any], words: Words) -> MplFigure:
    """The capacity curve with a0*, d0*, the edition's quantities and the demands."""
    from rockcli.plots.capacity import draw_capacity

    labels = (words("figure.d_star"), words("figure.a_star"))
    fig = on_page(draw_capacity, kin, 5.4, labels, words)
    # One column under the axes: the checks' labels are long, two columns leave the page.
    fig.axes[0].legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), fontsize="x-small")
    return fig


def compatibility(check: Mapping[str, Any], words: Words) -> MplFigure:
    """A suite's spectra, their mean, the target and its band (`rock suite check`'s plot)."""
    from rockcli.plots.suite import draw_suite

    return on_page(draw_suite, check, 4.2, (words("figure.period"), words("figure.sa")), words)


def histories(
    rocking: Mapping[str, Any], runs: Sequence[RockingRun], record: Record, overturn_angle: float,
    words: Words,
) -> MplFigure:  # fmt: skip
    """θ/α of both polarities against time, the record's acceleration beneath."""
    from rockcli.plots.histories import draw_time_panels

    fig = new_figure(PAGE_WIDTH, 4.4, words)
    spec = fig.add_gridspec(2, 1, height_ratios=(3, 1))
    draw_time_panels(fig, [spec[0], spec[1]], rocking, runs, record, overturn_angle,
                     phrases(words))  # fmt: skip
    top, bottom = fig.axes[0], fig.axes[1]
    top.set_title("")
    top.set_ylabel(words("figure.ratio"))
    bottom.set_xlabel(words("figure.time"))
    return fig


def restrainer_forces(
    model: Mapping[str, Any], runs: Sequence[RockingRun], words: Words
) -> MplFigure | None:
    """Each restrainer's force against time in both polarities, its strength as a line;
    None when the model has no restrainer."""
    springs = model.get("restrainers", [])
    if not springs:
        return None
    fig = new_figure(PAGE_WIDTH, 1.2 + 1.6 * len(springs), words)
    axes = fig.subplots(len(springs), 1, sharex=True, squeeze=False)[:, 0]
    for j, (ax, spring) in enumerate(zip(axes, springs, strict=True)):
        for run in runs:
            hist = run.history
            if hist is None or hist.forces.shape[0] <= j:
                continue
            color = "tab:blue" if run.polarity > 0 else "tab:orange"
            sign = "+" if run.polarity > 0 else "−"
            ax.plot(hist.time, hist.forces[j] / 1e3, color=color, lw=1.0,
                    label=words("figure.polarity", sign=sign))  # fmt: skip
        strength = spring.get("strength")
        if strength:
            ax.axhline(strength / 1e3, color="tab:red", lw=1.0, ls="--",
                       label=words("figure.strength"))  # fmt: skip
        ax.set_ylabel(words("figure.force_kn"))
        ax.set_title(spring["name"], fontsize="small", loc="left")
        ax.grid(alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper right")
    axes[-1].set_xlabel(words("figure.time"))
    return fig


@functools.cache
def decimal_mark_type() -> type:
    """A formatter type writing another's labels with a given decimal mark, built on
    matplotlib's Formatter when first asked for (matplotlib is the report extra's, imported
    only when a figure is made)."""
    from matplotlib.ticker import Formatter

    class _DecimalMark(Formatter):
        """Another formatter's labels with the decimal point written as ``mark``."""

        def __init__(self, inner: Any, mark: str) -> None:
            self.inner, self.mark = inner, mark

        def set_axis(self, axis: Any) -> None:
            super().set_axis(axis)
            self.inner.set_axis(axis)

        def set_locs(self, locs: Any) -> None:
            self.inner.set_locs(locs)

        def format_ticks(self, values: Any) -> list[str]:
            return [t.replace(".", self.mark) for t in self.inner.format_ticks(values)]

        def __call__(self, x: float, pos: int | None = None) -> str:
            return str(self.inner(x, pos)).replace(".", self.mark)

        def get_offset(self) -> str:
            return str(self.inner.get_offset()).replace(".", self.mark)

    return _DecimalMark
