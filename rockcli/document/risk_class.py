"""The report's risk class: the class of DM 58/2017 Allegato A (conventional method) of the
wall's local mechanisms from the verification's code check (rockcli.risk.local), with the
statement that it is an upper bound of the building's. Only the 2019 edition's checks give
the T_Rc it needs, and only a demand with a hazard curve (a site, or [ntc.demand] whose ag
grows with the return period)."""

from __future__ import annotations

from typing import Any

from rockcli.document.content import Block, Grid, Paragraph
from rockcli.document.words import Words
from rockcli.risk.classification import CR
from rockcli.risk.local import building_risk

#: The states of the curve in the order of the table.
STATES = ("SLID", "SLO", "SLD", "SLV", "SLC")


def risk_class_blocks(verification: Any, w: Words) -> list[Block]:
    """The class of the verification's mechanisms: a table of T_Rc, λ and the cost of each
    state, PAM, IS-V and the class in a sentence, the reading of SLO and the upper bound
    (nothing when the check gives no T_Rc: the 2009 edition, or no hazard curve)."""
    if verification is None or verification.result.edition != "2019":
        return []
    risk = building_risk(verification.result.catalogue)
    if risk is None:
        return []
    r, n = risk.risk, w.number
    rows = tuple(
        (w(f"risk.state_{ls}"),
         n(10.0 if ls == "SLID" else r.T_Rc[ls], "{:.4g}"),
         n(r.rates[ls], "{:.4g}"), n(100.0 * CR[ls], "{:g}"),
         w.note(risk.governing.get(ls, risk.governing["SLD"] if ls == "SLO" else "—")))
        for ls in STATES
    )  # fmt: skip
    headers = (w("concl.state"), w("risk.period"), w("risk.rate"), w("risk.cost"),
               w("risk.mechanism"))  # fmt: skip
    blocks: list[Block] = [
        Paragraph(w("risk.heading"), "subheading"),
        Grid(w("risk.caption"), headers, rows, (False, True, True, True, False)),
        Paragraph(w("risk.result", pam=n(100.0 * r.PAM, "{:.2f}"), pam_class=r.pam_class,
                    isv=n(100.0 * r.IS_V, "{:.1f}"), isv_class=r.isv_class,
                    risk_class=r.risk_class, name=w.note(risk.governing["IS_V"])), "verdict"),
        Paragraph(w("risk.upper_bound"), "warning"),
    ]  # fmt: skip
    if r.capped:
        blocks.append(Paragraph(w("risk.capped", states=", ".join(r.capped))))
    if any(r.T_Rc[ls] < 10.0 for ls in ("SLD", "SLV", "SLC")):
        blocks.append(Paragraph(w("risk.below_slid")))
    return blocks
