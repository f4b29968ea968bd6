"""The report's risk class: the class of DM 58/2017 Allegato A (conventional method) of the
wall's local mechanisms from the verification's code check (rockcli.risk.local), with the
statement that it is an upper bound of the building's. Only the 2019 edition's checks give
the T_Rc it needs, and only a demand with a hazard curve (a site, or [ntc.demand] whose ag
grows with the return period)."""

from __future__ import annotations

from typing import Any

from rockcli.document.content import Block, Grid, Paragraph
from rockcli.document.words import Words
from rockcli.risk.classification import CR, TR_SLID
from rockcli.risk.local import BuildingRisk, building_risk

#: The states of the curve in the order of the table.
STATES = ("SLID", "SLO", "SLD", "SLV", "SLC")


def risk_class_blocks(verification: Any, w: Words) -> list[Block]:
    """The class of the verification's mechanisms: a table of T_Rc, λ and the cost of each
    state, PAM, IS-V and the class in a sentence, the upper bound, and the notes (nothing when
    the check gives no T_Rc: the 2009 edition, or no hazard curve)."""
    if verification is None or verification.result.edition != "2019":
        return []
    risk = building_risk(verification.result.catalogue)
    if risk is None:
        return []
    blocks: list[Block] = [Paragraph(w("risk.heading"), "subheading")]
    if risk.risk is None:
        missing = "; ".join(w.note(m) for m in risk.missing)
        return [*blocks, Paragraph(w("risk.not_evaluated", missing=missing), "warning"),
                Paragraph(w("risk.upper_bound"), "warning")]  # fmt: skip
    r, n = risk.risk, w.number
    rows = tuple(
        (w(f"risk.state_{ls}"),
         n(TR_SLID if ls == "SLID" else r.T_Rc[ls], "{:.4g}"),
         n(r.rates[ls], "{:.4g}"), n(100.0 * CR[ls], "{:g}"),
         w.note(risk.governing["SLD" if ls == "SLO" else ls]) if ls != "SLID" else "—")
        for ls in STATES
    )  # fmt: skip
    headers = (w("concl.state"), w("risk.period"), w("risk.rate"), w("risk.cost"),
               w("risk.mechanism"))  # fmt: skip
    caption = w("risk.caption", points=points_text(risk, w))
    blocks += [
        Grid(caption, headers, rows, (False, True, True, True, False)),
        Paragraph(w("risk.result", pam=n(100.0 * r.PAM, "{:.2f}"), pam_class=r.pam_class,
                    isv=n(100.0 * r.IS_V, "{:.1f}"), isv_class=r.isv_class,
                    risk_class=r.risk_class, name=w.note(risk.governing["IS_V"])), "verdict"),
        Paragraph(w("risk.upper_bound"), "warning"),
    ]  # fmt: skip
    return blocks + risk_notes(risk, w)


def points_text(risk: BuildingRisk, w: Words) -> str:
    """Where the curve's points come from, in words."""
    years = ", ".join(w.number(TR, "{:.4g}") for TR in risk.hazard.periods)
    return w(f"risk.points_{risk.hazard.source}", years=years)


def risk_notes(risk: BuildingRisk, w: Words) -> list[Block]:
    """The extrapolated T_Rc, step 3's cap, a T_Rc below the SLID's."""
    assert risk.risk is not None
    periods = risk.hazard.periods
    out = [f"{ls} {w.number(years, '{:.4g}')}" for ls, years in risk.T_Rc.items()
           if not periods[0] <= years <= periods[-1]]  # fmt: skip
    blocks: list[Block] = []
    if out:
        blocks.append(Paragraph(w("risk.extrapolated", values=", ".join(out),
                                  first=w.number(periods[0], "{:.4g}"),
                                  last=w.number(periods[-1], "{:.4g}"))))  # fmt: skip
    if risk.risk.capped:
        blocks.append(Paragraph(w("risk.capped", states=", ".join(risk.risk.capped))))
    if any(years < TR_SLID for years in risk.T_Rc.values()):
        blocks.append(Paragraph(w("risk.below_slid")))
    return blocks
