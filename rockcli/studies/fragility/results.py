"""The fragility of each grid point and damage state, fitted from the tasks' runs.

- IDA: each record's first exceedance of the state (the intensity, found again from the
  runs by the same search: rockcli.studies.fragility.run.exceedances) and the lognormal of those
  intensities (rockcli.studies.fragility.fit.ida_fit); a record that does not reach the state by the
  scan's last intensity is right-censored there (``not_reached``), and the fit is then the
  censored maximum likelihood (rockcli.studies.fragility.fit.ida_censored_fit: β with divisor n,
  whatever ddof asks: docs/fragility.md).
- MSA: at each level, the records run and those whose max θ/α reaches the state's level, and
  the binomial maximum likelihood over the levels (rockcli.studies.fragility.fit.msa_fit).

Each fit has its 95 % band at intensities inside the analysed range (MSA: at the levels, at
most as many as rockcli.studies.fragility.fit.band_points gives), and ``band_method``
says what the band is (rockcli.studies.fragility.fit.band_method: the profile likelihood
for MSA; for IDA the exact noncentral-t band, or with censored records a parametric bootstrap). The
document is the `rock fragility --format json` contract.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from rockcli.studies.fragility.fit import Fit, band_method, band_points, ida_curve, msa_curve
from rockcli.studies.fragility.run import Task, TaskResult, exceedances, stripe_counts
from rockcli.studies.fragility.search import scan_points
from rockcli.studies.fragility.study import FragilityPlan, State
from rockcli.version import __version__

SCHEMA = 1
#: Intensities at which an IDA curve's band is given, across the scan.
BAND_POINTS = 50


def level_value(level: float) -> float | str:
    """A state's level as JSON holds it (overturning by name: JSON has no infinity)."""
    return "overturning" if math.isinf(level) else level


def document(
    plan: FragilityPlan,
    todo: Sequence[Task],
    results: Mapping[int, TaskResult],
    run: Mapping[str, Any],
) -> dict[str, Any]:
    """The `rock fragility --format json` document."""
    from rockcli.studies.sweep.cases import axis_points

    study = plan.study
    points = axis_points(study)
    states, records = [], []
    for p, indices in enumerate(points):
        labels = {a.name: a.label(i) for a, i in zip(study.axes, indices, strict=True)}
        mine = [t for t in todo if t.point == p]
        found = [results[t.id] for t in mine]
        firsts = _first_exceedances(plan, found)
        for k, state in enumerate(plan.states):
            entry = _state_entry(plan, state, found, [f[k] for f in firsts])
            states.append({**({"point": labels} if labels else {}), **entry})
        for t, r, f in zip(mine, found, firsts, strict=True):
            records.append(_record_entry(plan, t, r, f, labels))
    doc: dict[str, Any] = {
        "schema": SCHEMA,
        "rock_version": __version__,
        "study": plan.name,
        "file": plan.file,
        "method": plan.method,
        "im": plan.measure,
        "im_label": plan.measure_label,
        "damage_states": states,
        "records": records,
    }
    if plan.scan is not None:
        doc.update(
            scan_first=plan.scan[0],
            scan_step=plan.scan[1],
            scan_last=plan.scan[2],
            tolerance=plan.scan[3],
        )
    else:
        doc["levels"] = list(plan.levels)
    doc["run"] = dict(run)
    return doc


def _first_exceedances(
    plan: FragilityPlan, found: Sequence[TaskResult]
) -> list[list[float | None]]:
    """Each task's first exceedance intensity of each state (IDA; None: not reached or the
    task failed; MSA: none)."""
    out: list[list[float | None]] = []
    for r in found:
        if plan.method != "ida" or r.error is not None:
            out.append([None] * len(plan.states))
            continue
        out.append([e.scale for e in exceedances(plan, r.runs)])
    return out


def _state_entry(
    plan: FragilityPlan, state: State, found: Sequence[TaskResult], firsts: Sequence[float | None]
) -> dict[str, Any]:
    """One damage state's fit, band and counts."""
    entry: dict[str, Any] = {"name": state.name, "level": level_value(state.level)}
    n_runs = sum(len(r.runs) for r in found if r.error is None)
    fit: Fit | None = None
    censored = np.array([])
    try:
        if plan.method == "ida":
            assert plan.scan is not None
            reached = np.array([x for x in firsts if x is not None], dtype=float)
            entry["n_records"] = sum(r.error is None for r in found)
            censored = np.full(entry["n_records"] - reached.size, scan_points(*plan.scan[:3])[-1])
            entry["not_reached"] = int(censored.size)
            entry["collapse_im"] = sorted(reached.tolist())
            at = np.linspace(plan.scan[0], plan.scan[2], BAND_POINTS)
            fit, band = ida_curve(reached, censored, at, plan.ddof)
        else:
            runs, hits = stripe_counts(plan, found, state.level)
            entry["n_records"] = sum(r.error is None for r in found)
            entry["stripes"] = [
                {"im": x, "runs": n, "exceedances": k}
                for x, n, k in zip(plan.levels, runs, hits, strict=True)
            ]
            levels = np.array(plan.levels, dtype=float)
            at = band_points(levels, msa=True)  # every level, unless hundreds of them
            fit, band = msa_curve(levels, np.array(runs), np.array(hits), at)
    except ValueError as exc:
        entry.update(
            median=None,
            beta=None,
            beta_ddof=None,
            n_runs=n_runs,
            ci_im=[],
            ci=[],
            probability=[],
            band_method=None,
            note=str(exc),
        )
        return entry
    entry.update(
        median=fit.median,
        beta=fit.beta,
        beta_ddof=fit.beta_ddof,
        n_runs=n_runs,
        ci_im=at.tolist(),
        ci=[[_finite(lo), _finite(hi)] for lo, hi in band.tolist()],
        probability=fit.probability(at).tolist(),
        band_method=band_method(plan.method, censored.size > 0),
    )
    return entry


def _record_entry(
    plan: FragilityPlan,
    task: Task,
    result: TaskResult,
    firsts: Sequence[float | None],
    labels: Mapping[str, Any],
) -> dict[str, Any]:
    source = plan.study.records[task.record]
    entry: dict[str, Any] = {
        **({"point": dict(labels)} if labels else {}),
        "name": source.name,
        "mechanism": result.mechanism,
        "im_at_scale_1": result.unit_im,
        "runs": len(result.runs),
        "error": result.error,
    }
    if plan.method == "ida":
        entry["first_exceedance"] = {s.name: x for s, x in zip(plan.states, firsts, strict=True)}
    return entry


def _finite(x: float) -> float | None:
    return x if np.isfinite(x) else None
