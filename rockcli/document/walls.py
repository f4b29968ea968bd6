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

from rockcli.document.code_check import risk_indices
from rockcli.document.content import Figure, Grid, Paragraph, Section
from rockcli.document.words import Words


@dataclass(frozen=True)
class Part:
    """One wall of a report: its inputs, comparison, JSON document, the other mechanisms
    shown in full ((comparison, document) each) and what rock retrofit found for its tie-rod
    (None: not asked; rockcli.document.conclusions.conclusions_section)."""

    inputs: Any
    #: The record's comparison and its document (the scenario); None without a record.
    out: Any
    doc: Mapping[str, Any] | None
    others: tuple[tuple[Any, Mapping[str, Any]], ...] = ()
    sizing: Any = None
    #: The code check on the site's (or model's) spectra (rockcli.document.verification);
    #: None when the model sets no code spectrum.
    verification: Any = None

    @property
    def name(self) -> str:
        """The wall's (the model's) name."""
        return str(self.inputs.model.name)


def merged_files(inputs: Sequence[Any]) -> tuple[tuple[str, str], ...]:
    """The input files of several models' inputs, each once: the models first, in order, then
    the others (the record or the suite, its records, the grid) as the first model lists them."""
    files = dict.fromkeys(f for i in inputs for f in i.files)
    return tuple([f for f in files if f[0] == "model"] + [f for f in files if f[0] != "model"])


def summary_section(parts: Sequence[Part], w: Words) -> Section:
    """Every wall's every mechanism in one table, each wall's governing mechanism first: the
    verification's α0 and ζ_E on the site's spectra, and with a record its scenario's time
    history and classification."""
    many = len(parts) > 1
    scenario = any(part.doc is not None for part in parts)
    rows = tuple(row[0 if many else 1 :] for part in parts for row in summary_rows(part, w))
    headers: tuple[str, ...] = (w("summary.element"), w("cmp.mechanism"), "α0",
                                w("summary.zeta_dls"), w("summary.zeta_uls"))  # fmt: skip
    numeric: tuple[bool, ...] = (False, False, True, True, True)
    if scenario:
        headers += ("max θ/α", w("cmp.rocking_verdict"), w("cmp.classification"))
        numeric += (True, False, False)
    else:
        rows = tuple(row[:-3] for row in rows)
    verified = any(part.verification is not None for part in parts)
    # What the table holds: the verification alone, with a record's scenario, or (no code
    # spectrum) the record's comparison alone.
    kind = ("verify" if not scenario else "both") if verified else "record"
    grid = Grid(w(f"summary.caption_{kind}"), headers[0 if many else 1 :], rows,
                numeric[0 if many else 1 :])  # fmt: skip
    intro = w(f"summary.intro_{kind}_many" if many else f"summary.intro_{kind}")
    return Section("summary", w("section.summary"), (Paragraph(intro), grid))


def zeta_pair(kin: Mapping[str, Any]) -> tuple[float | None, float | None]:
    """(ζ_E of the damage limit state, ζ_E of the ultimate ones): the risk indices of the
    check (rockcli.document.conclusions.risk_indices), the ultimate one the smaller of SLV and
    SLC, as the catalogue ranks its mechanisms (None: not evaluated)."""
    zeta = {state: ratio for state, ratio, _ in risk_indices(kin)}
    uls = [r for r in (zeta.get(s) for s in ("SLV", "SLC", "ULS")) if r is not None]
    return zeta.get("SLD", zeta.get("DLS")), (min(uls) if uls else None)


def kinematic_of(part: Any) -> Mapping[str, Any]:
    """The code check a wall's summary reads: the verification's, else (the model sets no
    code spectrum) the record's comparison's."""
    if part.verification is not None:
        return part.verification.doc
    assert part.doc is not None  # a part has a verification or a record
    return part.doc["kinematic"]


def summary_rows(part: Part, w: Words) -> Iterator[tuple[str, ...]]:
    """A wall's rows, one per mechanism of its catalogue: α0 and ζ_E of the verification (of
    the record's spectrum when the model sets no code spectrum), and the scenario's rocking
    (three dashes without a record, which the table then drops)."""
    n = w.number
    kin = kinematic_of(part)
    scenario = {m["name"]: m for m in (part.doc or {}).get("mechanisms", ())}
    for k in kin.get("mechanisms") or [{"name": None, "alpha0": kin["alpha0"]}]:
        dls, uls = (k["zeta"]["DLS"], k["zeta"]["ULS"]) if "zeta" in k else zeta_pair(kin)
        name = w("summary.whole_block") if k["name"] is None else w.note(k["name"])
        yield (part.name, name, n(k["alpha0"]), n(dls, "{:.3f}"), n(uls, "{:.3f}"),
               *scenario_cells(part.doc, scenario.get(k["name"]), w))  # fmt: skip


def scenario_cells(
    doc: Mapping[str, Any] | None, m: Mapping[str, Any] | None, w: Words
) -> tuple[str, str, str]:
    """max θ/α, the rocking's verdict and the classification of a mechanism under the record
    (a block's: the comparison's own); dashes without a record or for a mechanism not rocked."""
    if doc is None:
        return ("—", "—", "—")
    if not doc.get("mechanisms"):
        rocking, kind = doc["rocking"], doc["classification"]
    elif m is None or m["rocking"] is None:
        return ("—", w("cmp.not_rocked"), "—")
    else:
        rocking, kind = m["rocking"], m["classification"]
    overturned = rocking["verdict"] == "overturns"
    return (w.ratio(rocking["max_ratio"], overturned, "{:.3f}"),
            w(f"cmp.rocked_{rocking['verdict']}"),
            "—" if kind is None else w(f"kind.{kind}"))  # fmt: skip


def rekeyed(section: Section, prefix: str, title: str = "") -> Section:
    """The section with its anchor and its figures' keys prefixed (unique in the report), its
    title prefixed by ``title`` (a wall's name in a report over several)."""
    heading = f"{title} — {section.title}" if title else section.title
    if not prefix:  # the title alone
        return Section(section.key, heading, section.blocks)
    blocks = tuple(replace(b, key=f"{prefix}-{b.key}") if isinstance(b, Figure) else b
                   for b in section.blocks)  # fmt: skip
    return Section(f"{prefix}-{section.key}", heading, blocks)
