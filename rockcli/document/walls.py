"""The whole catalogue in a report: a summary of every wall's every mechanism, the other
mechanisms' full sections, and one report over several walls (a building's).

A wall's local mechanisms are checked one by one and the governing one decides (Circolare
7/2019 §C8.7.1): the summary lists each with its α0, its risk indices ζ_E (capacity PGA /
demand PGA, §C8.3) and what the time history does with it, the governing one first.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from rockcli.document.conclusions import risk_indices
from rockcli.document.content import Figure, Grid, Paragraph, Section
from rockcli.document.words import Words


@dataclass(frozen=True)
class Part:
    """One wall of a report: its inputs, comparison, JSON document, the other mechanisms
    shown in full ((comparison, document) each) and what rock retrofit found for its tie-rod
    (None: not asked; rockcli.document.conclusions.conclusions_section)."""

    inputs: Any
    out: Any
    doc: Mapping[str, Any]
    others: tuple[tuple[Any, Mapping[str, Any]], ...] = ()
    sizing: Any = None


def merged_files(inputs: Sequence[Any]) -> tuple[tuple[str, str], ...]:
    """The input files of several models' inputs, each once: the models first, in order, then
    the others (the record or the suite, its records, the grid) as the first model lists them."""
    files = dict.fromkeys(f for i in inputs for f in i.files)
    return tuple([f for f in files if f[0] == "model"] + [f for f in files if f[0] != "model"])


def summary_section(parts: Sequence[Part], w: Words) -> Section:
    """Every wall's every mechanism in one table, each wall's governing mechanism first."""
    many = len(parts) > 1
    rows = tuple(
        row[0 if many else 1 :]
        for part in parts
        for row in summary_rows(part.doc["rocking"]["model"]["name"], part.doc, w)
    )
    headers = (w("summary.element"), w("cmp.mechanism"), "α0", w("summary.zeta_dls"),
               w("summary.zeta_uls"), "max θ/α", w("cmp.rocking_verdict"),
               w("cmp.classification"))  # fmt: skip
    numeric = (False, False, True, True, True, True, False, False)
    grid = Grid(w("summary.caption"), headers[0 if many else 1 :], rows,
                numeric[0 if many else 1 :])  # fmt: skip
    intro = w("summary.intro_many" if many else "summary.intro")
    return Section("summary", w("section.summary"), (Paragraph(intro), grid))


def zeta_pair(kin: Mapping[str, Any]) -> tuple[float | None, float | None]:
    """(ζ_E of the damage limit state, ζ_E of the ultimate ones): the risk indices of the
    check (rockcli.document.conclusions.risk_indices), the ultimate one the smaller of SLV and
    SLC, as the catalogue ranks its mechanisms (None: not evaluated)."""
    zeta = {state: ratio for state, ratio, _ in risk_indices(kin)}
    uls = [r for r in (zeta.get(s) for s in ("SLV", "SLC", "ULS")) if r is not None]
    return zeta.get("SLD", zeta.get("DLS")), (min(uls) if uls else None)


def summary_rows(name: str, doc: Mapping[str, Any], w: Words) -> Iterator[tuple[str, ...]]:
    """A wall's rows: each mechanism of its catalogue, or its one block."""
    n = w.number
    kin = doc["kinematic"]
    if not doc.get("mechanisms"):
        dls, uls = zeta_pair(kin)
        rocking = doc["rocking"]
        yield (name, w("summary.whole_block"), n(kin["alpha0"]), n(dls, "{:.3f}"),
               n(uls, "{:.3f}"), n(rocking["max_ratio"], "{:.3f}"),
               w(f"cmp.rocked_{rocking['verdict']}"),
               w(f"kind.{doc['classification']}"))  # fmt: skip
        return
    checked = {m["name"]: m for m in kin.get("mechanisms", ())}
    for m in doc["mechanisms"]:
        k, rocking, kind = checked.get(m["name"], {}), m["rocking"], m["classification"]
        zeta = k.get("zeta", {})
        yield (name, w.note(m["name"]), n(k.get("alpha0")), n(zeta.get("DLS"), "{:.3f}"),
               n(zeta.get("ULS"), "{:.3f}"),
               "—" if rocking is None else n(rocking["max_ratio"], "{:.3f}"),
               w("cmp.not_rocked") if rocking is None else w(f"cmp.rocked_{rocking['verdict']}"),
               "—" if kind is None else w(f"kind.{kind}"))  # fmt: skip


def rekeyed(section: Section, prefix: str, title: str = "") -> Section:
    """The section with its anchor and its figures' keys prefixed (unique in the report), its
    title prefixed by ``title`` (a wall's name in a report over several)."""
    blocks = tuple(replace(b, key=f"{prefix}-{b.key}") if isinstance(b, Figure) else b
                   for b in section.blocks)  # fmt: skip
    heading = f"{title} — {section.title}" if title else section.title
    return Section(f"{prefix}-{section.key}", heading, blocks)
