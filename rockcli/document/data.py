"""The numbers a report shows, as data: the HTML's ``<script type="application/json"
id="rock-data">`` (docs/report.md, "The report's data"), so that a reviewer's tools and the
tests read what the page prints without scraping it.

One wall: ``{"model", "verification", "mechanisms", "scenario"}``; several: ``{"walls":
[…]}`` of those. ``verification`` is the code check on the site's (or the model's) spectra,
the same with or without a record (null when the model sets no code spectrum); ``scenario``
the record's comparison (null without a record).
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from typing import Any

from rockcli.document.walls import Part


def report_data(parts: Sequence[Part]) -> str:
    """The report's data as JSON text, safe inside an HTML script element."""
    walls = [wall_data(part) for part in parts]
    data: dict[str, Any] = walls[0] if len(walls) == 1 else {"walls": walls}
    return json.dumps(data, allow_nan=False).replace("</", "<\\/")


def wall_data(part: Part) -> dict[str, Any]:
    """One wall's data (module docstring)."""
    from rockcli.document.verification import verification_data

    ver = part.verification
    kin = ver.doc if ver is not None else (part.doc or {}).get("kinematic", {})
    return {
        "model": part.name,
        "verification": None if ver is None else verification_data(ver),
        "mechanisms": [mechanism_data(m) for m in kin.get("mechanisms", ())],
        "scenario": None if part.doc is None else scenario_data(part.doc),
    }


def mechanism_data(m: Mapping[str, Any]) -> dict[str, Any]:
    """A mechanism of the catalogue as the verification checked it: α0, ζ_E, and α0's
    virtual work item by item on the side of α0 (weights in kN, points and virtual
    displacements in m, m/rad): α0 = Σ resisting_kNm / Σ overturning_kNm."""
    return {"name": str(m["name"]), "type": m["type"], "alpha0": m["alpha0"], "side": m["side"],
            "zeta_E": {"DLS": m["zeta"]["DLS"], "ULS": m["zeta"]["ULS"]},
            "virtual_work": m["virtual_work"]}  # fmt: skip


def scenario_data(doc: Mapping[str, Any]) -> dict[str, Any]:
    """The record's scenario: the record, the code check's demand and ζ_E on it, the time
    history's verdict and the classification."""
    from rockcli.document.verification import zeta_by_state

    rocking = doc["rocking"]
    return {
        "record": rocking["record"]["name"],
        "code_demand": doc["code_demand"],
        "mechanism": doc["kinematic"].get("mechanism"),
        "zeta_E": zeta_by_state(doc["kinematic"]),
        "rocking": {"verdict": rocking["verdict"], "max_ratio": rocking["max_ratio"]},
        "classification": doc["classification"],
    }


def governing_body(part: Part) -> tuple[dict[str, Any], dict[str, str] | None]:
    """The body of the verification's governing mechanism as the model section describes it
    (the document `rock assess` gives of what it rocks), and its (name, type) for a wall."""
    from rockcli.analyses.assess import restitution_rule
    from rockcli.analyses.catalogue import main_mechanism
    from rockcli.analyses.rocked import refuse_unrocked
    from rockcli.model.catalogue import named
    from rockcli.model.derive import describe
    from rockcli.terminal.assess import model_document

    ver = part.verification
    assert ver is not None
    model = part.inputs.model
    main = main_mechanism(ver.result)  # a horizontal flexure has no body the engines rock
    mech = named(ver.mechanisms, main.name if main is not None else ver.result.governing or "")
    refuse_unrocked(mech)
    rocked = None if mech.wall is None else (mech.name, mech.type.value)
    rule = restitution_rule(describe(model).e_rule, mech.rocker, rocked)
    body = model_document(model.name, str(model.kind), mech.rocker, rule)
    return body, None if rocked is None else {"name": rocked[0], "type": rocked[1]}
