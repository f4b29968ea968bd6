"""The tolerance check in the outputs: its JSON, its rows and warning in words.

The check itself is :mod:`rockcli.dynamics.tolerance`; here, its data as the assess document
carries it (``runs[].tolerance_check`` = {"rtol", "max_ratio", "impacts", "overturned",
"sensitive"}, top-level ``sensitive``, ``engine.tolerance_check``) and what the reader is
told when a run is tolerance-sensitive.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from typing import Any

from rockcli.dynamics.result import RockingRun
from rockcli.dynamics.tolerance import SENSITIVE_CHANGE, TIGHT_FACTOR, relative_change


def check_document(run: RockingRun) -> dict[str, Any] | None:
    """A run's ``tolerance_check`` (None when it was not checked)."""
    check = run.tolerance
    if check is None:
        return None
    return {
        "rtol": check.rtol,
        "max_ratio": check.max_ratio,
        "impacts": check.impacts,
        "overturned": check.overturned,
        "sensitive": check.sensitive,
    }


def engine_document(runs: Sequence[RockingRun]) -> dict[str, Any] | None:
    """How the runs were checked (``engine.tolerance_check``): the tight rtol and atol, the
    factor and the threshold; None when no run was (the reference engine, or tolerances
    already at the engine's floor)."""
    check = next((r.tolerance for r in runs if r.tolerance is not None), None)
    if check is None:
        return None
    return {
        "rtol": check.rtol,
        "atol": check.atol,
        "factor": TIGHT_FACTOR,
        "max_ratio_change": SENSITIVE_CHANGE,
    }


def tol(x: float) -> str:
    """A tolerance as written in the text: 1e-8, 2.5e-9 (no zero-padded exponent)."""
    return re.sub(r"e([+-])0*(\d)", r"e\1\2", f"{x:g}").replace("e+", "e")


def ratio_text(run: Mapping[str, Any], impacts: str) -> str:
    """``0.2727 (116 impacts)``, or ``overturns`` for an overturned run."""
    if run["overturned"]:
        return "overturns"
    return f"{run['max_ratio']:.4f} ({run['impacts']}{impacts})"


def sensitive_warning(run: Mapping[str, Any], rtol: float) -> str | None:
    """The warning of one run, in words: what moved between the two tolerances and how to
    read it (None when the run is not sensitive)."""
    check = run.get("tolerance_check")
    if not check or check["sensitive"] is False:
        return None
    head = f"polarity {run['polarity']:+d}: "
    if check["sensitive"] is None:
        return (
            f"{head}the run again at rtol {tol(check['rtol'])} stopped before the end (an "
            "engine guard): whether the result depends on the integration tolerance is not "
            "known"
        )
    both = (
        f"{ratio_text(run, ' impacts')} at rtol {tol(rtol)}, "
        f"{ratio_text(check, '')} at {tol(check['rtol'])}"
    )
    if run["overturned"] != check["overturned"]:
        return (
            f"{head}the overturning verdict depends on the integration tolerance: {both} — "
            "read it as undecided on this record: the block is at the edge of overturning "
            "and its rocking is chaotic (each impact amplifies small differences); judge it on "
            "several records (a suite)"
        )
    spread = 100 * relative_change(run["max_ratio"], check["max_ratio"])
    return (
        f"{head}max θ/α depends on the integration tolerance: {both} — read it as known to "
        f"about {spread:.0f} % only: this rocking is chaotic (each impact amplifies small "
        "differences), so neither value is exact; judge the block on several records (a "
        "suite), not on this one value"
    )


def tolerance_warnings(runs: Sequence[Mapping[str, Any]], rtol: float) -> list[str]:
    """The warning of every tolerance-sensitive run (and of every check not known)."""
    return [w for w in (sensitive_warning(r, rtol) for r in runs) if w is not None]


def table_rows(runs: Sequence[Mapping[str, Any]]) -> list[tuple[str, dict[str, str]]]:
    """Rows of the runs table for a sensitive document: max θ/α and impacts at the tight
    rtol, and the flag, each polarity's cell keyed ``p<polarity>`` (none when no run is
    sensitive)."""
    checks = {r["polarity"]: r.get("tolerance_check") for r in runs}
    if not any(c and c["sensitive"] for c in checks.values()):
        return []
    rtol = tol(next(c["rtol"] for c in checks.values() if c))

    def cells(show: Any) -> dict[str, str]:
        return {f"p{p}": "—" if c is None else show(c) for p, c in checks.items()}

    return [
        (f"max θ/α at rtol {rtol}",
         cells(lambda c: "overturned" if c["overturned"] else f"{c['max_ratio']:.4f}")),
        (f"impacts at rtol {rtol}", cells(lambda c: str(c["impacts"]))),
        ("tolerance-sensitive",
         cells(lambda c: {True: "yes", False: "no", None: "not known"}[c["sensitive"]])),
    ]  # fmt: skip


def compare_rows(rocking: Mapping[str, Any]) -> list[dict[str, str]]:
    """The comparison table's row of each tolerance-sensitive run (the rocking side: both
    values and impact counts); none when no run is sensitive."""
    rows = []
    for run in rocking["runs"]:
        check = run.get("tolerance_check")
        if not check or not check["sensitive"]:
            continue
        rows.append({
            "label": f"tolerance ({run['polarity']:+d})",
            "code": "—",
            "rocking": f"sensitive: {ratio_text(run, ' impacts')} at rtol "
            f"{tol(rocking['engine']['rtol'])}, {ratio_text(check, '')} at {tol(check['rtol'])}",
        })  # fmt: skip
    return rows


def tolerance_note(doc: Mapping[str, Any]) -> str:
    """The note of how the runs were checked, and what it found."""
    check = doc["engine"].get("tolerance_check")
    if check is None:
        if doc["engine"]["name"] == "reference":
            return "tolerance check: none with the reference engine (the accuracy reference)"
        return "tolerance check: none (rtol and atol are already the engine's tightest)"
    flags = {r["polarity"]: (r.get("tolerance_check") or {}).get("sensitive") for r in doc["runs"]}
    sensitive = [f"{p:+d}" for p, f in flags.items() if f]
    unknown = [f"{p:+d}" for p, f in flags.items() if f is None]
    found = "no polarity is sensitive"
    if sensitive:
        found = f"polarity {' and '.join(sensitive)} sensitive (see the warning)"
    elif unknown:
        found = f"polarity {' and '.join(unknown)} not known (see the warning)"
    return (
        f"tolerance check: each polarity again at rtol {tol(check['rtol'])}, atol "
        f"{tol(check['atol'])}, sensitive when max θ/α moves by more than "
        f"{100 * check['max_ratio_change']:g} % or the overturning verdict changes: {found}"
    )


def verdict_caveat(doc: Mapping[str, Any]) -> str:
    """What the verdict line adds when the envelope itself depends on the tolerance: the
    verdict (overturns or not) changes at the tight rtol, or the envelope's max θ/α of a
    surviving block moves by more than the threshold; empty otherwise."""
    checks = [r.get("tolerance_check") for r in doc["runs"]]
    if not doc.get("sensitive") or not all(checks):
        return ""
    overturns = any(c["overturned"] for c in checks)
    if overturns != any(r["overturned"] for r in doc["runs"]):
        return " — the verdict depends on the integration tolerance (see the warning)"
    tight = max(c["max_ratio"] for c in checks)
    if not overturns and relative_change(doc["max_ratio"], tight) > SENSITIVE_CHANGE:
        return " — max θ/α depends on the integration tolerance (see the warning)"
    return ""
