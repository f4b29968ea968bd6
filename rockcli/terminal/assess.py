"""The `rock assess` result as data: the JSON document and the Report for the terminal."""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from rockcli.dynamics.result import RockingRun
from rockcli.dynamics.tolerance import sensitive
from rockcli.mechanics import (
    Chain,
    Rocker,
    collapse_rotations,
    uplift_accelerations,
)
from rockcli.notes import Note
from rockcli.records.record import Record
from rockcli.terminal.records import record_document, record_report
from rockcli.terminal.table import Column, Report, Table, format_value, key_value
from rockcli.terminal.tolerance import (
    check_document,
    engine_document,
    table_rows,
    tolerance_note,
    tolerance_warnings,
    verdict_caveat,
)
from rockcli.version import __version__

if TYPE_CHECKING:
    from rockcli.analyses.assess import AssessmentOutput

SCHEMA = 1


def check_table_row(c: dict[str, Any]) -> dict[str, Any]:
    """A restrainer check in the terminal's units (kN, mm): force, ductility, anchorage."""
    duct, anchor = c["ductility"], c["anchor"] or {}
    return {
        **c,
        "demand": c["demand"] / 1e3,
        "strength": _scaled(c["strength"], 1e-3),
        "elongation": _scaled(duct["demand"], 1e3),
        "elongation_capacity": _scaled(duct["capacity"], 1e3),
        "overstrength": _scaled(anchor.get("demand"), 1e-3),
        "anchor": _scaled(anchor.get("capacity"), 1e-3),
    }


def _scaled(value: float | None, factor: float) -> float | None:
    return None if value is None else value * factor


def check_notes(checks: list[dict[str, Any]]) -> list[Note]:
    """Where each restrainer check's capacities come from, and an anchorage to be designed."""
    out = [
        about(c, Note("strength_from", "strength from {rule}", rule=c["rule"])
              if c["strength"] is not None
              else Note("verified_displacement", "verified on displacement: {rule}",
                        rule=c["rule"]))
        for c in checks
    ]  # fmt: skip
    out += [
        about(c, Note("elongation_from", "elongation it can take: {rule}",
                      rule=c["ductility"]["rule"]))
        for c in checks
        if c["ductility"]["capacity"] is not None and c["ductility"]["rule"] != c["rule"]
    ]  # fmt: skip
    out += [
        about(c, Note(
            "anchor_to_design", "anchorage not verified (no anchor_capacity): design it for at "
            "least γov·A·fy = {force:.4g} kN (capacity design, NTC 2018 §7.5.1)",
            force=c["anchor"]["demand"] / 1e3))
        for c in checks
        if c["anchor"] is not None and c["anchor"]["passed"] is None
    ]  # fmt: skip
    return out


def about(c: Mapping[str, Any], note: Note) -> Note:
    """``restrainer 'name': note``."""
    return Note("restrainer", "restrainer {name!r}: {note}", name=c["name"], note=note)


def strength_warnings(checks: list[dict[str, Any]]) -> list[Note]:
    """A warning per restrainer that fails its strength check: an elastic one beyond its
    strength (the run is not valid after that), an elastic-plastic one that yielded or broke."""
    return [about(c, strength_warning(c)) for c in checks if not c["passed"]]


def strength_warning(c: dict[str, Any]) -> Note:
    """The warning of one failed check (analyses.strength.restrainer_checks row): its force,
    its ductility or its anchorage."""
    duct, anchor = c["ductility"], c["anchor"] or {}
    if c["utilisation"] is None and c["ruptured"]:
        return Note("lost_elongation", "its elongation reached {capacity:.4g} mm, what it can "
                    "take ({rule}): it was lost at t = {t:.3f} s", capacity=duct["capacity"] * 1e3,
                    rule=duct["rule"], t=c["t_rupture"])  # fmt: skip
    if duct["passed"] is False:
        values = {"demand": duct["demand"] * 1e3, "capacity": duct["capacity"] * 1e3,
                  "rule": duct["rule"]}  # fmt: skip
        longer = ("its largest elongation {demand:.4g} mm exceeds what it can take, "
                  "{capacity:.4g} mm ({rule})")  # fmt: skip
        if c["ruptured"]:
            return Note("too_long_broke", longer + "; it broke at t = {t:.3f} s",
                        t=c["t_rupture"], **values)  # fmt: skip
        return Note("too_long", longer, **values)
    if anchor.get("passed") is False:
        return Note(
            "anchor_governs", "the anchor governs: its capacity {capacity:.4g} kN is below the "
            "bar's over-strength γov·A·fy = {demand:.4g} kN (capacity design, NTC 2018 §7.5.1): "
            "the anchor would give way before the bar yields",
            capacity=anchor["capacity"] / 1e3, demand=anchor["demand"] / 1e3,
        )  # fmt: skip
    force = Note(
        "force_against", "the time history's force {demand:.4g} kN against its design strength "
        "{strength:.4g} kN (utilisation {utilisation:.3g})", demand=c["demand"] / 1e3,
        strength=c["strength"] / 1e3, utilisation=c["utilisation"],
    )  # fmt: skip
    if not c["time_history_valid"]:
        return Note(
            "elastic_beyond", '{force}: it is elastic in this model (law = "elastic"), so the '
            "member would have yielded or its anchorage given way, and the result after that is "
            'not valid; give it its steel or law = "elastic-plastic" with a yield force',
            force=force,
        )  # fmt: skip
    if c["ruptured"]:
        return Note("force_lost", "{force}: it was lost at t = {t:.3f} s", force=force,
                    t=c["t_rupture"])  # fmt: skip
    return Note("force_beyond", "{force}: it is beyond its strength", force=force)


def yield_notes(checks: list[dict[str, Any]]) -> list[Note]:
    """A note per member that yielded and held: when, and its plastic elongation."""
    out = []
    for c in checks:
        if not c["yielded"] or c["ruptured"]:
            continue
        values = {"strength": c["strength"] / 1e3, "t": c["t_yield"],
                  "plastic": c["plastic_elongation"] * 1e3}  # fmt: skip
        held = ("restrainer {name!r} yielded at its design strength {strength:.4g} kN (first at "
                "t = {t:.3f} s): plastic elongation {plastic:.3g} mm at the end")  # fmt: skip
        duct = c["ductility"]
        if duct["capacity"] is None:
            out.append(Note("yielded", held, name=c["name"], **values))
            continue
        out.append(Note(
            "yielded_within", held + "; largest elongation {demand:.4g} mm of the {capacity:.4g} "
            "mm it can take", name=c["name"], demand=duct["demand"] * 1e3,
            capacity=duct["capacity"] * 1e3, **values))  # fmt: skip
    return out


def run_document(run: RockingRun) -> dict[str, Any]:
    """One polarity's results with full precision (JSON)."""
    return {
        "polarity": run.polarity,
        "status": str(run.status),
        "message": run.message,
        "max_ratio": run.max_ratio,
        "overturned": run.overturned,
        "t_overturn": run.t_overturn,
        "t_uplift": run.t_uplift,
        "impacts": run.impacts,
        "uplifts": run.uplifts,
        "theta_max": run.theta_max,
        "theta_min": run.theta_min,
        "max_velocity": run.max_velocity,
        "steps": run.steps,
        "t_end": run.t_end,
        "restrainers": [
            {
                "name": p.name,
                "max_displacement": p.max_displacement,
                "max_force": p.max_force,
                "t_fail": p.t_fail,
                "yielded": p.yielded,
                "t_yield": p.t_yield,
                "plastic_elongation": p.plastic_elongation,
                "ruptured": p.ruptured,
                "t_rupture": p.t_fail,
                "energy_dissipated": p.energy_dissipated,
            }
            for p in run.restrainers
        ],
        "impact_energy_loss": run.impact_loss,
        "mirror_of": run.mirror_of,
        "tolerance_check": check_document(run),
    }


def model_document(name: str, kind: str, block: Rocker, e_rule: str) -> dict[str, Any]:
    """The block as analysed (JSON)."""
    return {
        "name": name,
        "kind": kind,
        "R": block.R,
        "alpha": block.alpha,
        "b": block.centroid[0],
        "h": block.centroid[1],
        "p": block.p,
        "e": block.e,
        "e_rule": e_rule,
        "mass": block.mass,
        "g": block.g,
        "sides": "one" if block.one_sided else "two",
        "free_side": block.free_side if block.one_sided else None,
        "rebound": block.rebound if block.one_sided else None,
        "impact_rule": impact_rule(block),
        "linearized": block.linearized,
        "uplift_acceleration_g": block.uplift_acceleration,
        "uplift_acceleration_by_side_g": dict(
            zip(("1", "-1"), uplift_accelerations(block), strict=True)
        ),
        "e_by_side": {"1": block.restitution(1), "-1": block.restitution(-1)},
        "collapse_rotation_by_side": dict(zip(("1", "-1"), collapse_rotations(block), strict=True)),
        "chain": chain_document(block),
        "loads": [
            {
                "name": ld.name,
                "weight": ld.weight,
                "x_pos": ld.x_pos,
                "x_neg": ld.x_neg,
                "z": ld.z,
                "bears": ld.bears,
                "moves": ld.moves,
            }
            for ld in block.loads
        ],
        "thrusts": [
            {
                "name": t.name,
                "force": t.force,
                "direction": t.direction,
                "x_pos": t.x_pos,
                "x_neg": t.x_neg,
                "z": t.z,
            }
            for t in block.thrusts
        ],
        "restrainers": [
            {
                "name": r.name,
                "k_pos": r.k_pos,
                "k_neg": r.k_neg,
                "r_pos": r.r_pos,
                "phi_pos": r.phi_pos,
                "r_neg": r.r_neg,
                "phi_neg": r.phi_neg,
                "fails_at": r.fails_at if math.isfinite(r.fails_at) else None,
                "strength": finite_or_none(r.strength),
                "strength_rule": r.strength_rule or None,
                "law": r.law,
                "yield_pos": finite_or_none(r.yield_pos),
                "yield_neg": finite_or_none(r.yield_neg),
                "pretension": r.pretension,
                "anchor_capacity": finite_or_none(r.anchor_capacity),
                "rupture_force": finite_or_none(r.rupture_force),
                "code_action": r.code_action,
                "code_force": r.code_force,
            }
            for r in block.restrainers
        ],
    }


def chain_document(block: Rocker) -> dict[str, Any] | None:
    """A chain's constants (JSON; None for a single body): M(0), the impact ratio by
    projection before the model's factor, d(V′ − T)/dθ at rest, per side, and the rotation
    at which the run counts it collapsed."""
    if not isinstance(block, Chain):
        return None
    chain = block.table
    return {
        "inertia_by_side": {"1": chain.inertia[0], "-1": chain.inertia[1]},
        "impact_ratio_by_side": {"1": chain.restitution[0], "-1": chain.restitution[1]},
        "stiffness_by_side": {"1": chain.stiffness[0], "-1": chain.stiffness[1]},
        "collapse_rotation": chain.end,
    }


def finite_or_none(x: float) -> float | None:
    """x, or None (JSON null) when it is infinite: "not given", "never"."""
    return x if math.isfinite(x) else None


def impact_rule(block: Rocker) -> str:
    """Which impact rule the run used (spec/rocking.md: say it in the output)."""
    e = f"e = {block.e:.4g}"
    if block.restitution(-1) != block.e:
        e = f"e = {block.e:.4g} from θ > 0, {block.restitution(-1):.4g} from θ < 0"
    if block.one_sided:
        return f"one-sided rebound: θ̇⁺ = −r_f·e·θ̇⁻ (r_f = {block.rebound:g}, {e})"
    return f"two-sided: θ̇⁺ = e·θ̇⁻, pivot switches ({e})"


def assessment_document(
    model: dict[str, Any],
    record: Record,
    out: AssessmentOutput,
) -> dict[str, Any]:
    """The whole `rock assess --format json` document (schema 1) of an assess workflow's
    results; its warnings: the inputs' (model and record magnitudes that look like unit
    slips), before the runs' own."""
    result, warnings = out.result, out.warnings
    first = result.runs[0]
    checks = list(out.restrainer_checks)
    runs = [run_document(r) for r in result.runs]
    return {
        "schema": SCHEMA,
        "rock_version": __version__,
        "model": model,
        "record": record_document(record),
        "engine": {
            "name": first.engine,
            "rtol": first.rtol,
            "atol": first.atol,
            "rest_velocity": first.rest_velocity,
            "tolerance_check": engine_document(result.runs),
        },
        "runs": runs,
        "restrainer_checks": checks,
        "effectiveness": list(out.effectiveness),
        "verdict": str(result.verdict),
        "max_ratio": result.max_ratio,
        # max_ratio: max |θ|/θc with θc the collapse rotation of the side of θ
        # (model.collapse_rotation_by_side); of an overturned run, the overturn angle over it
        "max_ratio_overturned": any(r.overturned for r in result.runs),
        "sensitive": sensitive(result.runs),
        "warnings": [
            *warnings,
            *(w for r in result.runs for w in r.warnings),
            *strength_warnings(checks),
            *tolerance_warnings(runs, first.rtol),
        ],
    }


def assessment_output_document(out: AssessmentOutput, record: Record) -> dict[str, Any]:
    """The `rock assess --format json` document of an assess workflow's results."""
    info = model_document(out.name, out.kind, out.block, out.e_rule)
    doc = assessment_document(info, record, out)
    doc["record"] = {**doc["record"], **input_document(out)}
    if out.mechanism is not None:
        doc["mechanism"] = {"name": out.mechanism[0], "type": out.mechanism[1]}
    return doc


#: The rocking's input when the block stands on the ground (or --ground).
GROUND_INPUT = Note("input_ground", "the record itself, at the block's base")


def input_document(out: AssessmentOutput) -> dict[str, Any]:
    """``record.input`` ("ground" or "floor") and, for a floor input, ``record.floor`` (its
    first mode: T1, psi, gamma, xi, Z) and the notes on how it was made."""
    if out.floor is None:
        note = (
            Note("input_ground_flag", "the record itself, at the block's base (--ground: the "
                 "block stands at height; the code check still applies the code's at-height "
                 "rules)")
            if out.ground
            else GROUND_INPUT
        )  # fmt: skip
        return {"input": "ground", "input_note": note}
    pga = out.shaking.pga if out.shaking is not None else math.nan
    return {
        "input": "floor",
        "floor": {**out.floor.document(), "pga_g": pga},
        "input_note": Note(
            "input_floor", "{floor}; its PGA {pga:.3g} g", floor=out.floor.label, pga=pga
        ),  # fmt: skip
        "floor_notes": list(out.floor.notes),
    }


RUN_ROWS = (
    ("max_ratio", "max θ/α", "", "{:.4f}"),
    ("theta_max", "θ max", "rad", "{:.5f}"),
    ("theta_min", "θ min", "rad", "{:.5f}"),
    ("max_velocity", "max |θ̇|", "rad/s", "{:.4f}"),
    ("t_uplift", "first uplift", "s", "{:.3f}"),
    ("impacts", "impacts", "", "{:d}"),
    ("overturned", "overturned", "", ""),
    ("t_overturn", "overturned at", "s", "{:.3f}"),
    ("status", "status", "", ""),
)


#: What an overturned run shows instead of its θ/α (the overturn angle over α, not a peak).
OVERTURNED = "overturned"


def _run_cell(run: dict[str, Any], key: str, fmt: str) -> str:
    if key == "max_ratio" and run["overturned"]:
        return OVERTURNED
    return format_value(run[key], fmt)


#: Why a polarity was not integrated.
MIRROR_NOTE = (
    "polarity {p:+d} is the mirror image of polarity {of:+d} (θ → −θ), not integrated: the block "
    "is mirror-symmetric (two-sided, each restrainer and load the same from either pivot, no "
    "thrust)"
)


def mirror_note(runs: list[dict[str, Any]]) -> str | None:
    """The note that a run is a mirror image (None when both were integrated)."""
    for r in runs:
        if r.get("mirror_of") is not None:
            return MIRROR_NOTE.format(p=r["polarity"], of=r["mirror_of"])
    return None


def polarity_label(run: dict[str, Any]) -> str:
    """``polarity +1``, or ``polarity -1 (mirror of +1)`` for a run not integrated."""
    label = f"polarity {run['polarity']:+d}"
    if run.get("mirror_of") is not None:
        label += f" (mirror of {run['mirror_of']:+d})"
    return label


def runs_table(runs: list[dict[str, Any]]) -> Table:
    """Quantities down, polarities across (an overturned run's θ/α reads "overturned")."""
    cols = (
        Column("label", ""),
        *(Column(f"p{r['polarity']}", polarity_label(r)) for r in runs),
        Column("unit", "unit"),
    )
    rows = tuple(
        {
            "label": label,
            "unit": unit,
            **{f"p{r['polarity']}": _run_cell(r, key, fmt) for r in runs},
        }
        for key, label, unit, fmt in RUN_ROWS
    ) + tuple({"label": label, "unit": "", **cells} for label, cells in table_rows(runs))
    return Table("Rocking time history, both polarities", cols, rows)


SPRING_COLUMNS = (
    Column("polarity", "polarity", "", "{:+d}"),
    Column("name", "restrainer", ""),
    Column("max_displacement", "max displacement", "mm", "{:.2f}"),
    Column("max_force", "max force", "kN", "{:.2f}"),
    Column("t_yield", "yielded at", "s", "{:.3f}"),
    Column("plastic_elongation", "plastic elong.", "mm", "{:.2f}"),
    Column("t_fail", "lost at", "s", "{:.3f}"),
)
CHECK_COLUMNS = (
    Column("name", "restrainer", ""),
    Column("demand", "max force", "kN", "{:.2f}"),
    Column("strength", "strength", "kN", "{:.2f}"),
    Column("utilisation", "utilisation", "", "{:.3f}"),
    Column("elongation", "elongation", "mm", "{:.1f}"),
    Column("elongation_capacity", "can take", "mm", "{:.1f}"),
    Column("overstrength", "γov·A·fy", "kN", "{:.2f}"),
    Column("anchor", "anchor", "kN", "{:.2f}"),
    Column("passed", "passed", ""),
)
EFFECT_COLUMNS = (
    Column("name", "restrainer", ""),
    Column("side", "side", ""),
    Column("K", "K", "N/m", "{:.3g}"),
    Column("c_K", "c_K = K r²/I0", "1/s²", "{:.4g}"),
    Column("c_E", "c_E = p²", "1/s²", "{:.4g}"),
    Column("ratio", "c_K/c_E", "", "{:.3g}"),
    Column("global_stiffness", "global stiffness", ""),
)


def assessment_report(doc: dict[str, Any]) -> Report:
    """The terminal report of an assessment document."""
    m, rec, eng = doc["model"], doc["record"], doc["engine"]
    mechanism = doc.get("mechanism")
    title = f"Block: {m['name']} ({m['kind']})"
    shape = ("thickness 2b × height 2h", f"{2 * m['b']:.3f} × {2 * m['h']:.3f}", "m", "")
    geometry = [
        ("semi-diagonal R", m["R"], "m", "{:.4g}"),
        ("slenderness α", m["alpha"], "rad", "{:.4g}"),
    ]
    if mechanism is not None:  # a wall's mechanism: a body of its own shape about its hinge
        title = f"Mechanism: {m['name']}, {mechanism['name']} ({mechanism['type']})"
        shape = ("centroid from pivot O: x, z", f"{m['b']:.3f}, {m['h']:.3f}", "m", "")
    if m.get("chain") is not None:  # two blocks: no rectangle, α is where V′ vanishes
        geometry = [
            ("instability rotation α", m["alpha"], "rad", "{:.4g}"),
            ("generalised mass M(0)", m["chain"]["inertia_by_side"]["1"], "kg·m²", "{:.4g}"),
        ]
        shape = ("centroid of both bodies from O: x, z", f"{m['b']:.3f}, {m['h']:.3f}", "m", "")
    block = key_value(
        title,
        [
            *geometry,
            shape,
            ("frequency parameter p", m["p"], "rad/s", "{:.4g}"),
            ("restitution e", f"{m['e']:.4f} ({m['e_rule']})", "", ""),
            ("impact rule", m["impact_rule"], "", ""),
            _uplift_row(m),
        ],
    )
    record = record_report(rec).tables[0]
    runs = runs_table(doc["runs"])
    tables = [block, *_loads_tables(m), record, runs]
    springs = tuple(
        {
            **p,
            "polarity": r["polarity"],
            "max_displacement": p["max_displacement"] * 1e3,
            "max_force": p["max_force"] / 1e3,
            "plastic_elongation": p["plastic_elongation"] * 1e3,
        }
        for r in doc["runs"]
        for p in r["restrainers"]
    )
    if springs:
        tables.append(Table("Restrainer demands", SPRING_COLUMNS, springs))
    if doc.get("restrainer_checks"):
        rows = tuple(check_table_row(c) for c in doc["restrainer_checks"])
        tables.append(Table("Restrainer checks", CHECK_COLUMNS, rows))
    if doc["effectiveness"]:
        tables.append(
            Table(
                "Restrainer effectiveness (paper §4.3)", EFFECT_COLUMNS, tuple(doc["effectiveness"])
            )
        )
    notes = [
        f"input: {rec['input_note']}" if "input_note" in rec else None,
        *rec.get("floor_notes", ()),
        f"engine {eng['name']}, rtol {eng['rtol']:g}, atol {eng['atol']:g}, "
        f"rest threshold {eng['rest_velocity']:g} rad/s",
        tolerance_note(doc),
        *rec["notes"],
        *yield_notes(doc.get("restrainer_checks", [])),
        *check_notes(doc.get("restrainer_checks", [])),
        mirror_note(doc["runs"]),
    ]
    notes = [n for n in notes if n]
    verdict = _verdict_line(doc)
    return Report(
        title=f"rock assess — {m['name']}",
        tables=tuple(tables),
        notes=tuple(notes),
        verdict=verdict,
        warnings=tuple(doc["warnings"]),
    )


def _uplift_row(m: dict[str, Any]) -> tuple[str, Any, str, str]:
    """The uplift acceleration: one value, or one per side when loads or thrusts differ."""
    by_side = m.get("uplift_acceleration_by_side_g", {})
    if len(set(by_side.values())) > 1:
        text = f"{by_side['1']:.4f} (θ > 0), {by_side['-1']:.4f} (θ < 0)"
        return ("uplift acceleration", text, "g", "")
    return ("uplift acceleration", m["uplift_acceleration_g"], "g", "{:.4f}")


LOAD_COLUMNS = (
    Column("name", "load", ""),
    Column("weight", "weight", "kN", "{:.4g}"),
    Column("z", "height", "m", "{:.3f}"),
    Column("x_pos", "from pivot O", "m", "{:.3f}"),
    Column("bears", "bears", ""),
    Column("moves", "moves", ""),
)
THRUST_COLUMNS = (
    Column("name", "thrust", ""),
    Column("force", "force", "kN", "{:.4g}"),
    Column("z", "height", "m", "{:.3f}"),
    Column("towards", "towards", ""),
)


def _loads_tables(m: dict[str, Any]) -> list[Table]:
    """The loads and thrusts on the block, when there are any (kN for reading)."""
    tables = []
    if m.get("loads"):
        rows = tuple({**ld, "weight": ld["weight"] / 1e3} for ld in m["loads"])
        tables.append(Table("Loads on the block", LOAD_COLUMNS, rows))
    if m.get("thrusts"):
        rows = tuple(
            {**t, "force": t["force"] / 1e3, "towards": "θ > 0" if t["direction"] > 0 else "θ < 0"}
            for t in m["thrusts"]
        )
        tables.append(Table("Thrusts on the block", THRUST_COLUMNS, rows))
    return tables


def _verdict_line(doc: dict[str, Any]) -> str:
    caveat = strength_caveat(doc.get("restrainer_checks", ())) + verdict_caveat(doc)
    if doc["verdict"] == "overturns":
        return "overturns" + caveat
    return f"{doc['verdict']} (max θ/α = {doc['max_ratio']:.4f} over both polarities){caveat}"


def strength_caveat(checks: Any) -> str:
    """What the verdict line adds for restrainers that fail their strength check: "not valid"
    for an elastic one beyond its strength, the failed check for an elastic-plastic one."""
    invalid = [repr(c["name"]) for c in checks if not c["time_history_valid"]]
    failed = [repr(c["name"]) for c in checks if c["time_history_valid"] and not c["passed"]]
    parts = []
    if invalid:
        parts.append(f"not valid: {', '.join(invalid)} beyond its strength as an elastic member")
    if failed:
        parts.append(f"restrainer check failed: {', '.join(failed)} (see the warnings)")
    return "".join(f" — {p}" for p in parts)


#: Header of the --history CSV before the restrainer columns.
HISTORY_HEADER = ("t_s", "ground_acc_g", "theta_rad", "omega_rad_s", "polarity", "status")


def history_csv(
    run: RockingRun, record: Record, model: dict[str, Any], floor: Record | None = None
) -> str:
    """The --history CSV of one run: a plain header row, then one row per sample time.

    Columns: t [s], the ground acceleration the run saw [g] (the record times the polarity,
    zero in the tail after it), for a block at height the floor acceleration that shook it [g]
    (floor_acc_g, likewise), θ [rad], θ̇ [rad/s], the polarity and the run's status, and
    each restrainer's force [N] as the engine's law gave it at that sample (K·u for an elastic
    spring; yield plateau, slack and pretension for an elastic-plastic member; zero once it
    was lost).

    Args:
        run: the run, with its history.
        record: the ground record.
        floor: the floor motion the run integrated (None: the record itself).
        model: the model section of the assessment document (restrainers, linearized).
    """
    hist = run.history
    if hist is None:
        raise ValueError("the run was made without its history (history=True)")
    inputs = [record] if floor is None else [record, floor]
    accel = [
        run.polarity * np.interp(hist.time, rec.time, rec.accel, left=0.0, right=0.0)
        for rec in inputs
    ]
    header = list(HISTORY_HEADER)
    if floor is not None:
        header.insert(2, "floor_acc_g")
    names = [r["name"] for r in model["restrainers"]]
    forces = hist.forces
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow([*header, *(f"force_N_{name}" for name in names)])
    for i, t in enumerate(hist.time):
        writer.writerow(
            [
                f"{t:.6f}",
                *(f"{a[i]:.10e}" for a in accel),
                f"{hist.theta[i]:.10e}",
                f"{hist.omega[i]:.10e}",
                f"{run.polarity:+d}",
                str(run.status),
                *(f"{f[i]:.10e}" for f in forces),
            ]
        )
    return buffer.getvalue()
