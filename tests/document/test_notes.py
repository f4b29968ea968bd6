"""The analyses' notes and warnings in the report's language: every Note the code makes has
an Italian template with the same fields, notes nest and take the language's decimal mark,
and no English sentence reaches the Italian report of any example (record or suite).

The English-word check reads the report's own text: the model's words (its name, notes,
the names of its loads and restrainers), file names, digests, the command line and the
bibliography's titles are the user's or the literature's and are left out first.
"""

from __future__ import annotations

import ast
import html as htmlmod
import json
import pickle
import re
import string
import tomllib
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.document.words import Words, catalogue
from rockcli.notes import Items, Note

ROOT = Path(__file__).resolve().parents[2]
SHARED = ROOT.parent / "shared"
GRID = SHARED / "ntc" / "AllegatoB.txt"
PULSE = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
EXAMPLES = sorted((ROOT / "examples").glob("*.toml"))
SUITES = sorted((ROOT / "examples" / "suites").glob("*.toml"))

#: Words of English that Italian does not use (short function words: a sentence left in
#: English has several of them; Italian text has none; and the mechanisms' English names).
#: "no" and "a", "e" are Italian too.
ENGLISH = frozenset(
    "the of and is are with from which when given not its than this that by been was were "
    "into only each every their there these those until while would should could has have "
    "does an or on it overturning storey wedge flexure gable".split()
)


def fields(template: str) -> set[str]:
    return {name for _, name, _, _ in string.Formatter().parse(template) if name}


def source_notes() -> dict[str, set[frozenset[str]]]:
    """Every Note(key, template, ...) in the package: key → the templates' field sets. A
    template held in a name is read from the module's string assignments to it."""
    found: dict[str, set[frozenset[str]]] = {}
    for path in sorted((ROOT / "rockcli").rglob("*.py")):
        if path.name == "notes.py":  # the class itself
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        strings = {
            t.id: node.value
            for node in ast.walk(tree)
            if isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant)
            for t in node.targets
            if isinstance(t, ast.Name) and isinstance(node.value.value, str)
        }
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "Note":
                key, template = node.args[0], node.args[1]
                if not isinstance(key, ast.Constant):  # an existing note made again
                    continue
                text = eval(  # noqa: S307 — literals and the module's own string constants
                    compile(ast.Expression(template), str(path), "eval"),
                    {n: ast.literal_eval(v) for n, v in strings.items()},
                )
                found.setdefault(key.value, set()).add(frozenset(fields(text)))
    return found


def test_every_note_has_an_italian_template_with_its_fields() -> None:
    notes = source_notes()
    italian = {k.removeprefix("note."): v for k, v in catalogue("it").items()
               if k.startswith("note.")}  # fmt: skip
    assert set(notes) == set(italian), set(notes) ^ set(italian)
    for key, variants in notes.items():
        assert variants == {frozenset(fields(italian[key]))}, key


def test_a_note_nests_and_takes_the_decimal_mark() -> None:
    # The restitution rule as derive.restitution makes it, 0.9 × Housner with loads.
    rule = Note("factored", "{factor:g} × {rule}", factor=0.9,
                rule=Note("housner_loads", "Housner of the block with its loads"))  # fmt: skip
    assert rule == "0.9 × Housner of the block with its loads"
    assert Words("it").note(rule) == "0,9 × Housner del blocco con i suoi carichi"
    assert Words("en").note(rule) == rule
    listed = Note("defaults", "defaults (not in the model's [ntc]): {settings}",
                  settings=Items([Note("setting_number", "{key} = {value:g}", key="q",
                                       value=2.5), "x"]))  # fmt: skip
    assert Words("it").note(listed).endswith("[ntc] del modello): q = 2,5, x")


def test_a_note_is_its_english_text_in_json_and_pickles() -> None:
    note = Note("T1_default", "T1 = 0.05·H^0.75 = {T1:.3f} s (NTC §7.3.3.2), not given",
                T1=0.2153)  # fmt: skip
    assert json.loads(json.dumps([note])) == [
        "T1 = 0.05·H^0.75 = 0.215 s (NTC §7.3.3.2), not given"
    ]
    back = pickle.loads(pickle.dumps(note))
    assert back == note and back.key == note.key
    assert Words("it").note(back).startswith("T1 = 0,05")


def text_of(page: str, model: dict[str, Any]) -> list[str]:
    """The report's lines of text, without what is the user's or the literature's."""
    page = re.sub(r"<(style|script|svg)\b.*?</\1>", " ", page, flags=re.S)
    page = re.sub(r'<section id="identification".*?</section>', " ", page, flags=re.S)
    text = htmlmod.unescape(re.sub(r"<[^>]+>", "\n", page))
    for own in sorted(user_strings(model), key=len, reverse=True):
        text = text.replace(own, " ")
    skip = ("Bibliografia", "rock report")
    reference = re.compile(r"^\s*\[\d+\] ")  # an entry of the bibliography: its title
    return [line for line in text.splitlines()
            if line.strip() and not any(s in line for s in skip)
            and not reference.match(line)]  # fmt: skip


def user_strings(value: Any) -> set[str]:
    """Every string of the model file (names, notes, descriptions): the user's words."""
    if isinstance(value, str):
        return {value} if len(value) > 2 else set()
    if isinstance(value, dict):
        return set().union(*(user_strings(v) for v in value.values()))
    if isinstance(value, list):
        return set().union(*(user_strings(v) for v in value))
    return set()


def english_lines(lines: list[str]) -> list[str]:
    out = []
    for line in lines:
        words = {w.lower() for w in re.findall(r"(?<![\w./-])[A-Za-z]+(?![\w./-])", line)}
        if len(words & ENGLISH) >= 1:
            out.append(line.strip())
    return out


def report(tmp_path: Path, model: Path, *args: str, casebook: str = "none") -> str:
    out = tmp_path / f"{model.stem}.html"
    result = CliRunner().invoke(cli, ["report", str(model), *args, "-o", str(out),
                                      "--casebook", casebook, "--lang", "it"])  # fmt: skip
    assert result.exit_code == 0, result.stderr
    return out.read_text(encoding="utf-8")


def grid_args() -> list[str]:
    return ["--hazard-grid", str(GRID)] if GRID.exists() else []


@pytest.mark.parametrize("model", EXAMPLES, ids=lambda p: p.stem)
def test_no_english_in_an_examples_italian_report(tmp_path: Path, model: Path) -> None:
    page = report(tmp_path, model, "--record", str(PULSE), *grid_args())
    parsed = tomllib.loads(model.read_text(encoding="utf-8"))
    assert english_lines(text_of(page, parsed)) == []


@pytest.mark.parametrize(
    ("suite", "model"),
    list(
        zip(
            SUITES,
            [ROOT / "examples" / m for m in ("altar.toml", "two-storey-facade.toml")],
            strict=True,
        )
    ),  # fmt: skip
    ids=lambda p: p.stem,
)
def test_no_english_in_a_suites_italian_report(tmp_path: Path, suite: Path, model: Path) -> None:
    # The altar at height (a block) and the two-storey façade (the catalogue of a wall).
    if not (SHARED / "records").is_dir() or not GRID.exists():
        pytest.skip("../shared (the suites' records and the hazard grid) is not beside the clone")
    page = report(tmp_path, model, "--suite", str(suite), "--allow-outside", *grid_args())
    parsed = tomllib.loads(model.read_text(encoding="utf-8"))
    assert english_lines(text_of(page, parsed)) == []


def test_no_repository_path_in_a_report(tmp_path: Path) -> None:
    # A reviewer has no clone: the method is cited by name and source, not by a file of ours.
    page = report(tmp_path, ROOT / "examples" / "facade.toml", "--record", str(PULSE),
                  casebook="annex")  # fmt: skip
    assert not re.search(r"\b(docs|spec|rockcli|tests)/\w", page)
