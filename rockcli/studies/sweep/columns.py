"""The code check's columns of a study's case: the verdicts, the governing ULS ratio and the
mechanism's numbers, as `rock sweep` writes them (and `rock retrofit` reads its ULS ratio)."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from rockcli.codecheck.result import Check, KinematicResult


def kinematic_columns(result: KinematicResult) -> dict[str, Any]:
    """The code's verdicts (pass/fail), the governing ULS ratio and the mechanism's numbers."""
    verdict = result.verdict()
    quantities = result.quantities
    return {
        "code_dls": _pass_fail(verdict["DLS"]),
        "code_uls": _pass_fail(verdict["ULS"]),
        "uls_ratio": uls_ratio(result.checks),
        "a0_star": plain_number(result.a0_star),
        "Ts": plain_number(quantities.get("Ts", quantities.get("T_SLV"))),
    }


def uls_ratio(checks: Sequence[Check]) -> float | None:
    """The governing ζ = capacity/demand of the ULS: the smallest over the checks that decide
    the verdict (the non-linear ones when the analysis has them, else the linear ones; the
    rule of :func:`rockcli.codecheck.result.deciding`); None when one is not evaluated."""
    from rockcli.codecheck.result import deciding

    ratios = [c.ratio for c in deciding(tuple(checks), ("ULS", "SLV", "SLC"))]
    known = [r for r in ratios if r is not None]
    return min(known) if known and len(known) == len(ratios) else None


def plain_number(value: float | None) -> float | None:
    """A plain float (numpy scalars print as np.float64(…) in a CSV cell)."""
    return None if value is None else float(value)


def _pass_fail(value: bool | None) -> str | None:
    return None if value is None else ("pass" if value else "fail")


def sliding_columns(plan: Any, mechanisms: Any, name: str | None) -> dict[str, Any]:
    """``slides`` of a study with a ``[base]``: whether the case's mechanism (the one named,
    else the catalogue's first) slides on its base before it lifts — against the engines'
    uplift when the study rocks it, else the code check's α0 (None: not at the base)."""
    from rockcli.analyses.sliding import alpha0_of, at_the_base, slides_first, uplift_of
    from rockcli.model.catalogue import named
    from rockcli.studies.sweep.output import has_sliding_column

    if not has_sliding_column(plan):
        return {}
    mech = mechanisms[0] if name is None else named(mechanisms, name)
    base = mech.model.base
    if base is None or not at_the_base(mech):
        return {"slides": None}
    lifts = uplift_of(mech) if "rocking" in plan.analyses else alpha0_of(mech)
    return {"slides": slides_first(mech, base.mu, lifts) is not None}
