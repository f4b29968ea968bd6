"""The report's words on the tolerance check (rockcli.dynamics.tolerance): one sentence for
a result that does not depend on the tolerance, one per polarity that does."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from rockcli.document.content import Paragraph
from rockcli.document.words import Words
from rockcli.dynamics.tolerance import relative_change
from rockcli.terminal.tolerance import tolerance_warnings


def tolerance_paragraphs(rocking: Mapping[str, Any], w: Words) -> list[Paragraph]:
    """What the report says of the check: that the result does not depend on the tolerance,
    or, for each polarity that does, both values and impact counts and how to read them
    (warnings), or why there was no check."""
    engine = rocking["engine"]
    check = engine.get("tolerance_check")
    if check is None:
        key = "reference" if engine["name"] == "reference" else "floor"
        return [Paragraph(w(f"rock.tolerance_{key}"), "note")]
    tight = w.number(check["rtol"], "{:.0e}")
    said = [run_sentence(r, engine["rtol"], tight, w) for r in rocking["runs"]]
    warnings = [Paragraph(text, "warning") for text in said if text]
    if warnings:
        return warnings
    threshold = w.number(100 * check["max_ratio_change"], "{:g}")
    return [Paragraph(w("rock.tolerance_robust", rtol=tight, threshold=threshold), "note")]


def suite_paragraphs(records: Sequence[tuple[str, Mapping[str, Any]]], w: Words) -> list[Paragraph]:
    """The check over a suite: each polarity of each record whose result depends on the
    tolerance, named by its record; else the one sentence of a result that does not (or why
    there was no check, from the first record)."""
    said = []
    for name, rocking in records:
        check = rocking["engine"].get("tolerance_check")
        if check is None:
            continue
        tight = w.number(check["rtol"], "{:.0e}")
        for run in rocking["runs"]:
            text = run_sentence(run, rocking["engine"]["rtol"], tight, w)
            if text:
                said.append(Paragraph(f"{name}: {text}", "warning"))
    if said or not records:
        return said
    return tolerance_paragraphs(records[0][1], w)


def run_sentence(run: Mapping[str, Any], rtol: float, tight: str, w: Words) -> str | None:
    """The sentence of one polarity whose result depends on the tolerance (None otherwise)."""
    check = run.get("tolerance_check")
    if not check or check["sensitive"] is False:
        return None
    n = w.number
    sign = "+1" if run["polarity"] > 0 else "−1"
    if check["sensitive"] is None:
        return w("rock.tolerance_unknown", sign=sign, tight_rtol=tight)
    values = {"sign": sign, "rtol": n(rtol, "{:.0e}"), "tight_rtol": tight}
    if run["overturned"] != check["overturned"]:
        return w("rock.tolerance_verdict", verdict=outcome(run, w), tight_verdict=outcome(check, w),
                 **values)  # fmt: skip
    spread = 100 * relative_change(run["max_ratio"], check["max_ratio"])
    return w("rock.tolerance_sensitive", ratio=n(run["max_ratio"]), impacts=run["impacts"],
             tight_ratio=n(check["max_ratio"]), tight_impacts=check["impacts"],
             spread=n(spread, "{:.0f}"), **values)  # fmt: skip


def outcome(run: Mapping[str, Any], w: Words) -> str:
    """``overturns``, or ``survives with max θ/α … (… impacts)``, in the report's language."""
    if run["overturned"]:
        return w("rock.overturns")
    return w("rock.survives", ratio=w.number(run["max_ratio"]), impacts=run["impacts"])


def other_warnings(texts: Sequence[str], rocking: Mapping[str, Any]) -> list[str]:
    """The warnings without the tolerance check's (the report says those in its own words)."""
    said = set(tolerance_warnings(rocking["runs"], rocking["engine"]["rtol"]))
    return [t for t in texts if t not in said]


def other_suite_warnings(
    texts: Sequence[str], records: Sequence[tuple[str, Mapping[str, Any]]]
) -> list[str]:
    """A suite's warnings without the tolerance check's of its records (as
    rockcli.terminal.suite.suite_tolerance_warnings words them: the report says those in its
    own words)."""
    said = {
        f"record {name}, {text}"
        for name, rocking in records
        for text in tolerance_warnings(rocking["runs"], rocking["engine"]["rtol"])
    }
    return [t for t in texts if t not in said]
