"""Commented model-file templates for `rock init wall|altar|facade`.

Each template is a plain dict dumped by tomli-w (:func:`rockcli.model.load.dumps`); comments
are added afterwards, line by line: a note above each table, and above each key the field's
own description from the schema (one source for the units and the allowed values). The text
loads unchanged through :func:`rockcli.model.load.load_model` (tested).

Values: the altar and the façade are the source paper's cases (§3.2 and §4.2), the same
elements as examples/altar.toml and examples/facade.toml (tested); the wall is a generic
free-standing wall with the paper's systemic-study settings (§3.3: 0.9 × Housner's e; §4.4:
width 3 m, unit weight 18 kN/m³).
"""

from __future__ import annotations

import re
import textwrap
from collections.abc import Iterator
from typing import Any

from rockcli.model.load import dumps, field_at
from rockcli.model.schema import (
    LOOSEST_TOLERANCE,
    OVERTURN_ANGLE,
    REST_VELOCITY,
    TOLERANCE,
    Kind,
)
from rockcli.units import DEFAULT_GRAVITY

_HEADER = re.compile(r"^\[\[?(?P<table>[^\]]+)\]\]?$")
_KEY = re.compile(r"^(?P<key>[A-Za-z0-9_-]+) = ")

#: Width of the comment lines [characters].
COMMENT_WIDTH = 92

#: The [analysis] table with every default written out (tail left to the engine).
_ANALYSIS = {
    "overturn_angle": OVERTURN_ANGLE,
    "rtol": TOLERANCE,
    "atol": TOLERANCE,
    "rest_velocity": REST_VELOCITY,
    "linearized": False,
    "g": DEFAULT_GRAVITY,
}

#: The [ntc] table: the code check's settings, demand given per limit state (a site needs the
#: user's copy of the hazard grid, which rock does not ship).
_NTC = {
    "edition": "2019",
    "FC": 1.35,
    "q": 2.0,
    "soil": "B",
    "topography": "T1",
    "VN": 50.0,
    "CU": 1.0,
    "mass_distribution": "lumped",
    "demand": {
        "SLD": {"ag": 0.06, "F0": 2.5, "Tc_star": 0.27},
        "SLV": {"ag": 0.15, "F0": 2.5, "Tc_star": 0.29},
        "SLC": {"ag": 0.19, "F0": 2.5, "Tc_star": 0.30},
    },
}

#: The [building] table: an element on the ground (Z = 0 needs no other key).
_BUILDING = {"Z": 0.0}
#: The bell cell of the frame template, and the frame table's example keys.
_FRAME = {"piers": 4, "pier_width": 0.6, "pier_depth": 0.6, "pier_height": 3.0,
          "roof_mass": 15000.0, "roof_height": 0.5}  # fmt: skip

#: The altar's code check, as the paper's (§3.2, Fig. 6; examples/altar.toml): Circolare
#: 617/2009, FC = 1.05, soil C, and the demand of Allegato B (DM 14/01/2008) at Reggiolo
#: (10.807 E, 44.918 N) for TR = 50, 475 and 975 years.
_ALTAR_NTC = {
    "edition": "2009",
    "FC": 1.05,
    "q": 2.0,
    "soil": "C",
    "topography": "T1",
    "VN": 50.0,
    "CU": 1.0,
    "mass_distribution": "lumped",
    "demand": {
        "SLD": {"ag": 0.0443, "F0": 2.568, "Tc_star": 0.262},
        "SLV": {"ag": 0.1181, "F0": 2.574, "Tc_star": 0.278},
        "SLC": {"ag": 0.1586, "F0": 2.556, "Tc_star": 0.284},
    },
}

TEMPLATES: dict[Kind, dict[str, Any]] = {
    Kind.FRAME: {
        "name": "Bell cell",
        "kind": "frame",
        "notes": "Four piers capped by the belfry's roof and bells, on the tower (Makris & "
        "Vassiliou 2013): they rock together, uplift at g·tan α of a pier whatever the roof.",
        "frame": _FRAME,
        "mass": {"unit_weight": 18.6},
        "restitution": {"model": "housner"},
        "motion": {"sides": "two"},
        "analysis": _ANALYSIS,
        "building": {"Z": 20.0, "H": 23.0, "N": 1},
        "ntc": _NTC,
    },
    Kind.WALL: {
        "name": "Wall with a tie-rod",
        "kind": "wall",
        "notes": "Generic wall, restitution 0.9 x Housner as in the paper's systemic study "
        "(section 3.3). Delete the [[restrainers]] table for a free-standing wall.",
        "geometry": {"thickness": 0.5, "height": 4.0, "width": 3.0, "pivot_height": 0.0},
        "mass": {"unit_weight": 18.0},
        "restitution": {"model": "housner", "factor": 0.9},
        "motion": {"sides": "two"},
        "analysis": _ANALYSIS,
        "building": _BUILDING,
        "ntc": _NTC,
        "loads": [{"name": "floor at the top", "weight": 30.0, "position": "top"}],
        "restrainers": [
            {
                "name": "tie-rod near the top",
                "kind": "tie-rod",
                "diameter": 0.02,
                "length": 3.0,
                "E": 210e9,
                "grade": "S275",
                "height": 3.8,
                "from_pivot": 0.25,
            }
        ],
    },
    Kind.ALTAR: {
        "name": "Altar, B.V. Annunziata",
        "kind": "altar",
        "notes": "Equivalent prism of the altar (paper section 3.2): base length 2.40 m, "
        "height 2.96 m from the top to the crack, thickness 0.487 m; its base 3.04 m up the "
        "6.00 m altar, T1 = Ts = 1.09 s, as in the paper's code check (examples/altar.toml).",
        "geometry": {"R": 1.499, "alpha": 0.163, "width": 2.40},
        "mass": {"unit_weight": 18.0},
        "restitution": {"model": "housner"},
        "motion": {"sides": "two"},
        "analysis": _ANALYSIS,
        "building": {"Z": 3.04, "H": 6.00, "gamma": 1.0, "psi": 0.51, "T1": 1.09},
        "ntc": _ALTAR_NTC,
    },
    Kind.FACADE: {
        "name": "Façade, B.V. Annunziata",
        "kind": "facade",
        "notes": "Facade of B.V. Annunziata (paper section 4.2): transverse walls stop the "
        "inward (negative) rotation, the facade rocks outward only; the groin vault gives way "
        "at 1 mm of support displacement, the S275 tie-rod yields at its design strength "
        "(examples/facade.toml).",
        "geometry": {"R": 5.04, "alpha": 0.05},
        "mass": {"weight": 1755.0},
        "restitution": {"model": "housner"},
        "motion": {"sides": "one", "stopped": "negative", "rebound": 1.0},
        "analysis": _ANALYSIS,
        "building": _BUILDING,
        "ntc": _NTC,
        "restrainers": [
            {"name": "groin vault", "k": 4e6, "radius": 7.0, "angle": 0.072, "fails_at": 0.001},
            {
                "name": "tie-rod",
                "kind": "tie-rod",
                "diameter": 0.02,
                "length": 3.0,
                "grade": "S275",
                "radius": 7.0,
                "angle": 0.072,
            },
        ],
    },
}

#: Notes written above each table header (and above the top-level keys, table "").
TABLE_NOTES: dict[str, tuple[str, ...]] = {
    "": (
        "rock model file: one masonry macro-element rocking on its base.",
        "SI units throughout (m, kN, N/m, s, rad). Check every value against your element.",
        "Sign convention (the source paper's, docs/conventions.md): a positive ground "
        "acceleration drives a positive rotation.",
    ),
    "geometry": ("The rocking block: either R + alpha, or thickness + height (full 2b and 2h).",),
    "mass": (
        "Either weight [kN] or unit_weight [kN/m³] (needs geometry.width).",
        "Optional without restrainers; required when a restrainer has a stiffness.",
    ),
    "restitution": (
        'model = "housner" (e = 1 − 1.5 sin²α, times factor), or e = value (model = "explicit").',
    ),
    "motion": (
        'sides = "two", or "one" with stopped = "negative"|"positive" (the side the '
        "transverse walls block) and rebound = r_f.",
    ),
    "analysis": (
        "Settings of the time-history run; all optional, shown here at their defaults.",
        f"tail = 10.0 (s of free vibration after the record) overrides the engine's default; "
        f"rtol and atol at most {LOOSEST_TOLERANCE:g}.",
    ),
    "restrainers": (
        "Horizontal springs, any number, one [[restrainers]] table each.",
        'Stiffness: k (both sides), or k_pos + k_neg, or kind = "tie-rod" with diameter, '
        "length, E (K = E·π·d²/4 / L).",
        "Point: radius + angle (same for both pivots), or height + from_pivot, or position = "
        '"top" (r = 2R, φ = α).',
        "Optional: fails_at = elongation [m] at which the spring is lost for good.",
        'Law: "elastic", or "elastic-plastic" (yields, goes slack, cannot push) with yield_pos, '
        "yield_neg [N]; a tie-rod with a grade or fy, fu is elastic-plastic, yields at A·fy and",
        "breaks at elongation_at_break·length (default: its grade's, in the time history). "
        "pretension [N] acts until it goes slack. "
        'code_action = "force" (its strength in α0) or "spring".',
    ),
    "building": (
        "Where the element stands in the building (a property of the element, not of a code).",
        "Z = 0: on the ground. An element at height: Z > 0 with H, N (or gamma), T1 (default "
        "0.05·H^0.75), psi (default Z/H).",
    ),
    "ntc": (
        "Settings of the NTC kinematic check (rock kinematic). The demand below is an example:",
        "replace it with your site's parameters, or use [ntc.site] lon, lat with a hazard grid "
        "(--hazard-grid or ROCK_HAZARD_GRID), or --record FILE.",
    ),
    "loads": (
        "Weights on the block (floors, roof), one [[loads]] table each; need [mass].",
        'Point: height (+ from_pivot, default the mid-plane) or position = "top". bears = false: '
        "its weight rests elsewhere; moves = false: its mass does not push the block.",
    ),
}


#: An example value of every key a user may set, by table: the keys a template does not set
#: are shown commented under their table (or, for a table the template lacks, as a commented
#: table at the end), so that each template names every key of the file (tested against the
#: schema). Keys of one table may exclude each other: the notes and descriptions say which.
OTHER_KEYS: dict[str, dict[str, Any]] = {
    "": {"name": "My wall", "kind": "wall", "notes": "Where the element is, what was surveyed."},
    "geometry": {
        "R": 1.5,
        "alpha": 0.17,
        "thickness": 0.5,
        "height": 3.0,
        "width": 3.0,
        "pivot_height": 0.0,
        "gable_height": 2.0,
    },
    "geometry.storeys": {"height": 4.0, "thickness": 0.6},
    "frame": _FRAME,
    "return_walls": {
        "thickness": 0.45,
        "toothed": True,
        "mu": 0.577,
        "course_height": 0.25,
        "overlap": 0.25,
        "sides": 2,
    },
    "base": {"mu": 0.6},
    "masonry": {"f_m": 2.0e6, "E": 6.0e8, "type": "rough-cut-stone"},
    "mechanisms": {
        "type": "overturning",
        "hinge_height": "each-floor",
        "name": "overturning of each storey",
        "storey": 1,
        "angle": 30.0,
        "sides": 2,
        "free": False,
        "friction": True,
        "level": 5.0,
        "strip_height": 1.0,
        "span": 6.0,
        "thrust_limit": 50.0,
        "tie": "tie at the eaves",
        "thickness_return": 0.45,
        "hip_thrust": 5.0,
    },
    "mass": {"weight": 100.0, "unit_weight": 18.0},
    "restitution": {"model": "explicit", "factor": 0.9, "e": 0.8},
    "motion": {"sides": "one", "stopped": "negative", "rebound": 1.0},
    "analysis": {"tail": 10.0, **_ANALYSIS, "limit_ratio": {"SLV": 1.0}},
    "restrainers": {
        "name": "spring at the top",
        "kind": "spring",
        "k": 1e6,
        "k_pos": 1e6,
        "k_neg": 0.0,
        "diameter": 0.02,
        "length": 3.0,
        "E": 210e9,
        "acts": "both",
        "grade": "S275",
        "fy": 240e6,
        "fu": 380e6,
        "count": 1,
        "anchor_capacity": 80e3,
        "radius": 3.0,
        "angle": 0.08,
        "height": 2.8,
        "from_pivot": 0.25,
        "position": "top",
        "fails_at": 0.05,
        "law": "elastic-plastic",
        "yield_pos": 60e3,
        "yield_neg": 60e3,
        "pretension": 5e3,
        "elongation_at_break": 0.2,
        "code_action": "force",
    },
    "building": {
        "Z": 0.0,
        "H": 9.0,
        "N": 3,
        "T1": 0.26,
        "gamma": 1.29,
        "psi": 0.67,
        "damping": 0.05,
    },
    "ntc": {
        **{k: v for k, v in _NTC.items() if k != "demand"},
        "knowledge_level": "LC1",
        "use_class": "II",
        "ultimate_displacement": 0.1,
    },
    "ntc.site": {"lon": 13.4, "lat": 42.35},
    "ntc.demand.SLO": {"ag": 0.05, "F0": 2.5, "Tc_star": 0.26},
    "ntc.demand.SLD": {"ag": 0.06, "F0": 2.5, "Tc_star": 0.27},
    "ntc.demand.SLV": {"ag": 0.15, "F0": 2.5, "Tc_star": 0.29},
    "ntc.demand.SLC": {"ag": 0.19, "F0": 2.5, "Tc_star": 0.30},
    "loads": {
        "name": "floor",
        "weight": 50.0,
        "position": "top",
        "height": 2.5,
        "from_pivot": 0.25,
        "bears": True,
        "moves": True,
    },
    "thrusts": {
        "name": "roof thrust",
        "force": 10.0,
        "position": "top",
        "direction": "positive",
        "height": 2.5,
        "from_pivot": 0.0,
    },
}

#: Tables written as arrays of tables (``[[name]]``).
ARRAYS = frozenset({"restrainers", "loads", "thrusts", "mechanisms", "geometry.storeys"})

#: For a table a template lacks: the keys that, uncommented together, make a valid table
#: (the other keys of :data:`OTHER_KEYS` follow as alternatives).
TABLE_CORE: dict[str, tuple[str, ...]] = {
    "restrainers": ("name", "k", "position", "fails_at"),
    "loads": ("name", "weight", "position"),
    "thrusts": ("name", "force", "position", "direction"),
    "mechanisms": ("type", "hinge_height"),
    "geometry.storeys": ("height", "thickness"),
}

#: Notes of the tables a template may show commented only.
OPTIONAL_TABLE_NOTES: dict[str, tuple[str, ...]] = {
    "geometry.storeys": (
        "A wall of several storeys instead of thickness + height (or R + alpha): one "
        "[[geometry.storeys]] table per storey, bottom up; needs geometry.width and [mass]. "
        "See docs/mechanisms.md.",
    ),
    "return_walls": (
        "The return walls, where a wedge (compound overturning) can form; toothed into the "
        "wall, their friction holds an overturning back (docs/mechanisms/friction.md).",
    ),
    "base": ("The base joint's friction: whether the element slides before it rocks.",),
    "frame": (
        'A rocking frame (kind = "frame", no [geometry]): equal piers capped by a rigid roof, '
        "a bell cell (docs/mechanisms/frame.md).",
    ),
    "masonry": (
        "The masonry's strength (each hinge moves inward by half the stress block) and its "
        "stiffness (E, or a type of Circolare 7/2019 Tab. C8.5.I) for elements free to "
        "vibrate.",
    ),
    "mechanisms": (
        "The local mechanisms to check, one [[mechanisms]] table each (none: overturning about "
        'the base). type = "overturning" | "wedge" | "vertical-flexure" | "gable" | '
        '"horizontal-flexure" | "corner"; each type takes only its own keys '
        "(docs/mechanisms.md).",
    ),
    "ntc.site": ("Instead of [ntc.demand.*]: the site, for the demand from a hazard grid.",),
    "ntc.demand.SLO": ("Spectrum parameters of the operational limit state, if needed.",),
    "thrusts": (
        "Horizontal forces independent of the earthquake (roof, arch), one [[thrusts]] table "
        'each; need [mass]. direction = "positive" | "negative": the rotation it pushes towards.',
    ),
}


def render_template(kind: Kind) -> str:
    """The commented TOML template of a macro-element kind."""
    return annotate(dumps(TEMPLATES[kind]))


def annotate(text: str) -> str:
    """Add the table notes, above each key the field's description from the schema, and the
    keys and tables the text does not set, commented (:data:`OTHER_KEYS`)."""
    blocks = _blocks(text.splitlines())
    return "\n".join(_annotated_lines(blocks)) + "\n"


Block = tuple[str, list[str]]


def _blocks(lines: list[str]) -> list[Block]:
    """The text cut at each table header: (table path, its lines, header first)."""
    blocks: list[Block] = [("", [])]
    for line in lines:
        header = _HEADER.match(line)
        if header:
            blocks.append((header["table"], []))
        blocks[-1][1].append(line)
    return blocks


def _annotated_lines(blocks: list[Block]) -> Iterator[str]:
    noted: set[str] = set()
    last = {table: i for i, (table, _) in enumerate(blocks)}
    for i, (table, lines) in enumerate(blocks):
        yield from _notes(table, noted)
        body = list(_explained(table, lines))
        while body and not body[-1]:
            body.pop()
        yield from body
        if last[table] == i:
            given = {m["key"] for t, ls in blocks if t == table for m in map(_KEY.match, ls) if m}
            yield from _other_keys(table, given)
        if i < len(blocks) - 1:
            yield ""
    yield from _absent_tables(set(last))


def _explained(table: str, lines: list[str]) -> Iterator[str]:
    for line in lines:
        key = _KEY.match(line)
        if key:
            yield from _key_comment(table, key["key"])
        yield line


def _other_keys(table: str, given: set[str]) -> Iterator[str]:
    """The keys of ``table`` not given, commented, each under its description."""
    others = {k: v for k, v in OTHER_KEYS.get(table, {}).items() if k not in given}
    if not others:
        return
    yield "#"
    yield from _comment('Other keys of this table: remove the "# " before a key to use it.')
    for key, value in others.items():
        yield from _key_comment(table, key)
        yield f"# {_key_line(key, value)}"


def _absent_tables(present: set[str]) -> Iterator[str]:
    """The tables the text lacks, commented at the end (a header anywhere is valid TOML)."""
    for table, keys in OTHER_KEYS.items():
        if table in present or not table:
            continue
        yield ""
        yield from _comment(
            f'Optional: remove the "# " before the header and the keys to use [{table}].'
        )
        for note in TABLE_NOTES.get(table, OPTIONAL_TABLE_NOTES.get(table, ())):
            yield from _comment(note)
        yield f"# [[{table}]]" if table in ARRAYS else f"# [{table}]"
        core = TABLE_CORE.get(table, tuple(keys))
        for key in core:
            yield from _key_comment(table, key)
            yield f"# {_key_line(key, keys[key])}"
        yield from _other_keys(table, set(core))


def _key_line(key: str, value: Any) -> str:
    """``key = value`` as tomli-w writes it; a table value as an inline table, on one line."""
    if isinstance(value, dict):
        inner = ", ".join(_key_line(str(k), v) for k, v in value.items())
        return f"{key} = {{{inner}}}"
    return dumps({key: value}).strip()


def _notes(table: str, noted: set[str]) -> Iterator[str]:
    if table in noted:
        return
    noted.add(table)
    for note in TABLE_NOTES.get(table, ()):
        yield from _comment(note)


def _key_comment(table: str, key: str) -> Iterator[str]:
    info = field_at((*table.split("."), key) if table else (key,))
    if info is not None and info.description:
        yield from _comment(info.description)


def _comment(text: str) -> Iterator[str]:
    """``# `` lines of at most :data:`COMMENT_WIDTH` characters."""
    yield from (f"# {line}" for line in textwrap.wrap(text, COMMENT_WIDTH - 2))
