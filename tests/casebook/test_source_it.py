"""Each bundled case's source in Italian (``source_it``), which an Italian report prints.

Every case has one; it names no repository path (a reviewer has the report, not the
repository: rock's guides are named, not their files); it keeps every number and every "§…"
clause of the English ``source`` (a mistranslated citation shows as a number or a clause
missing or added); and `rock validate --format json` carries it, null for a case without one.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.casebook.load import LoadedCase, load_casebook
from rockcli.cli.main import cli
from tests.casebook.conftest import CASEBOOK, SPECTRUM_CASE, write_casebook

#: A number as the sources write it: digits, with a decimal point (so "1,05" for "1.05" and an
#: exponent rewritten show as a different set).
NUMBER = re.compile(r"\d+(?:\.\d+)*")
#: A clause: "§3.2.3.2.1", "§C8A.4.2.3", "§C8.7.1.1" (a trailing full stop is not part of it).
CLAUSE = re.compile(r"§\s*[0-9A-Z]+(?:\.[0-9A-Z]+)*")
#: What a repository path starts with.
REPOSITORY_PATH = re.compile(r"\b(?:docs|spec|rockcli)/")

CASES = load_casebook(CASEBOOK)


def case_id(loaded: LoadedCase) -> str:
    return loaded.case.id


def italian(loaded: LoadedCase) -> str:
    text = loaded.case.source_it
    assert text, f"{loaded.case.id} ({loaded.file}) has no source_it"
    return text


def numbers(text: str) -> set[str]:
    return set(NUMBER.findall(text))


def clauses(text: str) -> set[str]:
    return {re.sub(r"\s+", "", clause) for clause in CLAUSE.findall(text)}


@pytest.mark.parametrize("loaded", CASES, ids=case_id)
def test_every_case_has_an_italian_source(loaded: LoadedCase) -> None:
    text = italian(loaded)
    assert text != loaded.case.source, "source_it is the English source"
    assert text.strip() == text


@pytest.mark.parametrize("loaded", CASES, ids=case_id)
def test_italian_source_names_no_repository_path(loaded: LoadedCase) -> None:
    text = italian(loaded)
    assert REPOSITORY_PATH.search(text) is None, text
    assert ".md" not in text and ".toml" not in text, text


@pytest.mark.parametrize("loaded", CASES, ids=case_id)
def test_italian_source_keeps_every_number_and_clause(loaded: LoadedCase) -> None:
    english, text = loaded.case.source, italian(loaded)
    for extract, what in ((numbers, "numbers"), (clauses, "clauses")):
        want, got = extract(english), extract(text)
        assert got == want, (
            f"{what}: missing {sorted(want - got)}, added {sorted(got - want)} in {text!r}"
        )


def test_extraction_catches_a_mistranslated_citation() -> None:
    cited = "Housner 1963, BSSA 53(2):403–417, Circolare 617/2009 §C8A.4.2.3"
    english, good = f"closed form: {cited}", f"soluzione in forma chiusa: {cited}"
    assert numbers(good) == numbers(english) and clauses(good) == clauses(english)
    assert numbers(good.replace("403", "430")) != numbers(english)
    assert clauses(good.replace("§C8A.4.2.3", "§C8A.4.2")) != clauses(english)
    assert numbers("e* = 1, FC = 1,05") != numbers("e* = 1, FC = 1.05")


def test_validate_json_carries_the_italian_source(no_grid: None) -> None:
    result = CliRunner().invoke(cli, ["validate", "--format", "json"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    by_id = {case["id"]: case for case in doc["cases"]}
    assert set(by_id) == {loaded.case.id for loaded in CASES}
    for loaded in CASES:
        assert by_id[loaded.case.id]["source_it"] == loaded.case.source_it
        assert by_id[loaded.case.id]["source"] == loaded.case.source


def test_validate_json_source_it_is_null_without_one(tmp_path: Path) -> None:
    folder = write_casebook(tmp_path / "book", SPECTRUM_CASE)
    result = CliRunner().invoke(cli, ["validate", "--casebook", str(folder), "--format", "json"])
    assert result.exit_code == 0, result.stderr
    (case,) = json.loads(result.stdout)["cases"]
    assert "source_it" in case and case["source_it"] is None


def test_an_empty_italian_source_is_refused(tmp_path: Path) -> None:
    text = SPECTRUM_CASE.replace("[cases.input]", 'source_it = ""\n[cases.input]')
    folder = write_casebook(tmp_path / "book", text)
    result = CliRunner().invoke(cli, ["validate", "--casebook", str(folder)])
    assert result.exit_code == 2
    assert "cases[0].source_it" in result.stderr
