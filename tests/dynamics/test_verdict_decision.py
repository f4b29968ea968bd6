"""A comparison's rocking verdict is decided only when a second integration agrees
(rockcli.analyses.compare.decided_collapse; docs/interpretations.md, "A verdict two
integrations disagree on").

The rule: the rocking verdict (overturning in either polarity) is not decided, and the
classification `undetermined` with a note saying why, when

- the tolerance check's runs (each polarity again at rtol/1000) give the other verdict; or
- an overturning polarity overturned at both tolerances after different numbers of impacts
  (its histories parted before the overturn) and the reference engine's run of it survives.

The reference engine runs only in that second case, and not when another polarity overturns
after the same impacts at both tolerances (that overturn decides the envelope alone).
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import pytest

from rockcli.analyses import compare
from rockcli.analyses.compare import (
    Classification,
    classify,
    compare_model_output,
    decided_collapse,
)
from rockcli.dynamics.result import Assessment, RockingRun, RunStatus, ToleranceCheck
from rockcli.model.load import load_model
from rockcli.records.pulses import ricker
from rockcli.terminal.compare import comparison_output_document, comparison_warnings

ROOT = Path(__file__).resolve().parents[2]
#: A one-sided wall of two mechanisms (the casebook's): whole wall, and storey 2.
WALL = ROOT / "examples" / "validation" / "models" / "mech-two-storey.toml"

SURVIVED = RockingRun(
    polarity=1, status=RunStatus.COMPLETED, message="survived", max_ratio=0.5,
    theta_max=0.05, theta_min=0.0, max_velocity=0.1, t_overturn=None, t_uplift=1.0,
    impacts=40, uplifts=1, steps=1000, rejected=0, t_end=20.0, engine="fast", rtol=1e-8,
    atol=1e-8, rest_velocity=1e-4,
)  # fmt: skip
OVERTURNED = replace(SURVIVED, status=RunStatus.OVERTURNED, max_ratio=math.pi / 2 / 0.1,
                     t_overturn=12.0, message="overturned")  # fmt: skip


def checked(run: RockingRun, tight: RockingRun) -> RockingRun:
    """``run`` with ``tight`` as its tolerance check."""
    check = ToleranceCheck(rtol=1e-11, atol=1e-11, max_ratio=tight.max_ratio,
                           impacts=tight.impacts, overturned=tight.overturned,
                           status=tight.status, sensitive=None)  # fmt: skip
    return replace(run, tolerance=check)


def both(plus: RockingRun, minus: RockingRun) -> Assessment:
    return Assessment(runs=(replace(plus, polarity=1), replace(minus, polarity=-1)))


def never(polarity: int) -> RockingRun:
    raise AssertionError(f"the reference engine ran polarity {polarity:+d}")


class Reference:
    """A reference engine that gives ``run`` and counts what it was asked for."""

    def __init__(self, run: RockingRun) -> None:
        self.run, self.asked = run, []

    def __call__(self, polarity: int) -> RockingRun:
        self.asked.append(polarity)
        return replace(self.run, polarity=polarity, engine="reference")


def test_the_tolerance_checks_other_verdict_is_not_decided() -> None:
    # Fast overturns polarity +1 at rtol 1e-8, survives it at 1e-11: the envelope's verdict
    # changes (−1 survives at both).
    result = both(checked(OVERTURNED, SURVIVED), checked(SURVIVED, SURVIVED))
    collapse, why = decided_collapse(result, never)
    assert collapse is None
    assert why is not None and why.startswith("not decided")
    assert "overturns at rtol 1e-8 and survives at rtol 1e-11" in why
    assert classify(True, collapse) is Classification.UNDETERMINED
    # ... and the other way round: survives at 1e-8, overturns at 1e-11.
    result = both(checked(SURVIVED, SURVIVED), checked(SURVIVED, OVERTURNED))
    collapse, why = decided_collapse(result, never)
    assert collapse is None and "survives at rtol 1e-8 and overturns at rtol 1e-11" in why


def test_an_envelope_both_tolerances_agree_on_is_decided_without_the_reference() -> None:
    # One polarity flips but the other overturns at both after the same impacts: the
    # envelope overturns either way.
    result = both(checked(OVERTURNED, SURVIVED), checked(OVERTURNED, OVERTURNED))
    assert decided_collapse(result, never) == (True, None)
    # Chaotic survivals (max θ/α moved) keep their verdict: the tolerance warning tells.
    result = both(checked(SURVIVED, replace(SURVIVED, max_ratio=0.7, impacts=55)),
                  checked(SURVIVED, SURVIVED))  # fmt: skip
    assert decided_collapse(result, never) == (False, None)
    # A tight run stopped at a guard decides nothing: the verdict stands.
    guard = replace(SURVIVED, status=RunStatus.STEP_LIMIT)
    result = both(checked(OVERTURNED, guard), checked(SURVIVED, guard))
    assert decided_collapse(result, never) == (True, None)
    # Without a tolerance check, the runs' own verdict (the reference engine's comparison).
    assert decided_collapse(both(OVERTURNED, SURVIVED)) == (True, None)
    assert decided_collapse(both(SURVIVED, SURVIVED)) == (False, None)


def test_an_overturn_after_parted_histories_is_decided_by_the_reference_engine() -> None:
    diverged = checked(OVERTURNED, replace(OVERTURNED, impacts=47))
    result = both(diverged, checked(SURVIVED, SURVIVED))
    # The reference engine survives it: the two engines disagree.
    survives = Reference(SURVIVED)
    collapse, why = decided_collapse(result, survives)
    assert survives.asked == [1]  # that polarity only
    assert collapse is None and "the fast engine overturns polarity +1" in why
    assert "the reference engine survives it" in why
    # The reference engine overturns it too: decided.
    overturns = Reference(OVERTURNED)
    assert decided_collapse(result, overturns) == (True, None)
    assert overturns.asked == [1]
    # The reference run stops at a guard: not known, the verdict stands.
    assert decided_collapse(result, Reference(replace(SURVIVED, status=RunStatus.EVENT_LIMIT))) \
        == (True, None)  # fmt: skip
    # Another polarity overturning after the same impacts at both tolerances decides it.
    robust = checked(replace(OVERTURNED, impacts=12), replace(OVERTURNED, impacts=12))
    assert decided_collapse(both(diverged, robust), never) == (True, None)


def test_a_mirrored_polarity_is_run_once() -> None:
    # A mirror-symmetric block: −1 is +1 mirrored (not integrated); the reference engine runs
    # +1 only, and its verdict stands for both.
    diverged = checked(OVERTURNED, replace(OVERTURNED, impacts=47))
    result = Assessment(runs=(diverged, replace(diverged, polarity=-1, mirror_of=1)))
    survives = Reference(SURVIVED)
    collapse, why = decided_collapse(result, survives)
    assert survives.asked == [1]
    assert collapse is None and why is not None


@pytest.fixture(scope="module")
def model():
    return load_model(str(WALL))


def faked(monkeypatch: pytest.MonkeyPatch, name: str, result: Assessment) -> None:
    """compare's assess_model_output, with ``result`` as the runs of mechanism ``name``."""
    real = compare.assess_model_output

    def assess(*args, **kwargs):
        out = real(*args, **kwargs)
        if kwargs.get("mechanism") == name:
            return replace(out, result=result)
        return out

    monkeypatch.setattr(compare, "assess_model_output", assess)


def test_rock_compare_marks_the_shown_mechanism_undetermined(monkeypatch, model) -> None:
    name = "overturning, storey 2"
    faked(monkeypatch, name, both(checked(OVERTURNED, SURVIVED), checked(SURVIVED, SURVIVED)))
    record = ricker(0.4, 0.5, dt=0.01, total=4.0)
    out = compare_model_output(model, record, mechanism=name)
    assert out.classification is Classification.UNDETERMINED
    assert out.classification_note is not None and "tolerance check" in out.classification_note
    shown = {m.name: m for m in out.mechanisms}
    assert shown[name].classification is Classification.UNDETERMINED
    assert shown[name].classification_note == out.classification_note
    # The other mechanism now carries its tolerance check (it had none before), and is
    # decided (its runs are the engine's own).
    other = shown["overturning, whole wall"]
    assert all(r.tolerance is not None for r in other.rocking.runs)
    assert other.classification is not Classification.UNDETERMINED
    # The JSON and the warnings say why.
    doc = comparison_output_document(out, record)
    assert doc["classification"] == "undetermined"
    assert doc["classification_note"] == out.classification_note
    assert out.classification_note in comparison_warnings(doc)


def test_rock_compare_marks_a_mechanism_the_engines_disagree_on(monkeypatch, model) -> None:
    name = "overturning, whole wall"
    diverged = checked(OVERTURNED, replace(OVERTURNED, impacts=47))
    faked(monkeypatch, name, both(diverged, checked(SURVIVED, SURVIVED)))
    survives = Reference(SURVIVED)
    asked = []

    def rerun(model, record, ground, file, mechanism, mechanisms=None):
        asked.append(mechanism)
        return survives

    monkeypatch.setattr(compare, "reference_rerun", rerun)
    record = ricker(0.4, 0.5, dt=0.01, total=4.0)
    out = compare_model_output(model, record, mechanism="overturning, storey 2")
    entry = {m.name: m for m in out.mechanisms}[name]
    assert entry.classification is Classification.UNDETERMINED
    assert "the two engines disagree" in entry.classification_note
    assert survives.asked == [1]  # one reference run, of that polarity of that mechanism
    doc = comparison_output_document(out, record)
    assert f"'{name}': {entry.classification_note}" in comparison_warnings(doc)
    # The reference engine's own comparison has no second engine to ask.
    assert compare.rerun(model, record, "reference", False, None, name) is None
