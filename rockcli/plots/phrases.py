"""The words inside the figures (legends, marks), by key, in English.

The terminal commands draw with :func:`english`; the calculation report passes the phrases of
its language (rockcli/document/messages, table ``[plot]``, the same keys and fields: a test
keeps them so). Numbers keep the point as decimal mark inside a figure, like its tick labels.
"""

from __future__ import annotations

from typing import Any, Protocol

ENGLISH = {
    "not_evaluated": "not evaluated",
    "satisfied": "satisfied",
    "not_satisfied": "NOT satisfied",
    "state_DLS": "DLS",
    "state_ULS": "ULS",
    "state_SLO": "SLO",
    "state_SLD": "SLD",
    "state_SLV": "SLV",
    "state_SLC": "SLC",
    "method_linear": "linear",
    "method_nonlinear": "non-linear",
    "where_ground": "ground",
    "where_height": "height",
    "curve": "capacity curve a*(d*)",
    "a0": "a0* = {a0:.4g} m/s²",
    "d0": "d0* = {d0:.4g} m",
    "du": "du* = {du:.4g} m (ULS capacity)",
    "secant_2009": "(ds*, as*) = ({ds:.3g} m, {a:.3g} m/s²), Ts = {T:.3g} s",
    "secant_2019": "{state}: d = {d:.4g} m, a = {a:.3g} m/s²",
    "secant_period": "{state}: d = {d:.4g} m, a = {a:.3g} m/s², T_{state} = {T:.3g} s",
    "check_name": "{state} {method}, {where}",
    "check_not_evaluated": "{name}: not evaluated (see the notes)",
    "check_demand": "{name}: demand {demand:.3g} {unit} ({word})",
    "check_capacity": "{name}: capacity {capacity:.3g} vs demand {demand:.3g} {unit} ({word})",
    "check_ag": "{name}: ag capacity {capacity:.3g} vs demand {demand:.3g} {unit} ({word})",
    "demand_mark": "{state} {where}",
    "off_frame": "the curve leaves the frame: a* = {a:.3g} m/s² at d* = {d:.3g} m",
    "verdict_item": "{state} {word}",
    "run": "polarity {sign}1: max θ/α = {ratio:.3f}",
    "run_overturns": "polarity {sign}1: overturns at {t:.2f} s",
    "alpha_level": "θ = ±α",
    "overturn_level": "overturning, |θ| = {angle:.3g} rad",
    "histories_title": "Rocking time history, both polarities: {verdict}",
    "histories_one_sided": (
        "Rocking time history, both polarities: {verdict} (one-sided: θ {sign} 0 stopped)"
    ),
    "verdict_survives": "survives",
    "verdict_overturns": "overturns",
    "verdict_undecided": "undecided",
    "record": "{record} (polarity +1)",
    "pga": "PGA {pga:.3g} g",
    "floor_acc": "floor acc. [g]",
    "ground_acc": "ground acc. [g]",
    "mean_records": "mean of the records",
    "mean_floor": "mean of the floor motions",
    "target": "target Se",
    "floor_target": "floor spectrum S_eZ at Z = {Z:g} m",
    "band_lower": "band {lo:+.0%} (lower)",
    "band_upper": "band {hi:+.0%} (upper)",
}  # fmt: skip


class Say(Protocol):
    """A figure's phrase by key, its fields filled."""

    def __call__(self, key: str, **values: Any) -> str: ...


def english(key: str, **values: Any) -> str:
    """The English phrase ``key`` with its fields filled."""
    return ENGLISH[key].format(**values)
