"""The report's message catalogues: the same keys in every language, fields that match, and
numbers written as each language writes them."""

from __future__ import annotations

import re
import string

import pytest

from rockcli.document.words import LANGUAGES, Words, catalogue


def fields(text: str) -> set[str]:
    return {name for _, name, _, _ in string.Formatter().parse(text) if name}


def test_every_key_is_in_every_language() -> None:
    # The analyses' notes ([note]) are English where they are made (rockcli.notes): the other
    # languages hold them (tests/document/test_notes.py).
    keys = {lang: {k for k in catalogue(lang) if not k.startswith("note.")} for lang in LANGUAGES}
    first = keys[LANGUAGES[0]]
    for lang, found in keys.items():
        assert found == first, f"{lang}: missing {first - found}, extra {found - first}"


@pytest.mark.parametrize("key", sorted(k for k in catalogue("en") if not k.startswith("note.")))
def test_a_message_has_the_same_fields_in_every_language(key: str) -> None:
    # A field named in one language and not the other would raise or vanish at render time.
    assert len({frozenset(fields(catalogue(lang)[key])) for lang in LANGUAGES}) == 1


def words_of(text: str) -> list[str]:
    """The words of a message: letters only, fields and symbols (m/s², d*, Ts) left out."""
    return re.findall(r"[^\W\d_]{4,}", re.sub(r"\{[^}]*\}", "", text))


def test_no_message_is_left_untranslated() -> None:
    # Italian is the filing language: a sentence copied over from English is a slip. Symbols,
    # units, formulas and proper names are the same in both, so only messages of three or
    # more words count.
    same = [
        k for k, text in catalogue("it").items()
        if text == catalogue("en").get(k) and len(words_of(text)) >= 3
    ]  # fmt: skip
    assert not same


def test_numbers_take_the_languages_decimal_mark() -> None:
    assert Words("it").number(0.16445909, "{:.4f}") == "0,1645"
    assert Words("en").number(0.16445909, "{:.4f}") == "0.1645"
    assert Words("it").number(None) == "—" and Words("en").number(float("nan")) == "—"


def test_a_day_is_written_as_the_language_writes_it() -> None:
    import datetime

    assert Words("it").date(datetime.date(2026, 12, 7)) == "7 dicembre 2026"
    assert Words("en").date(datetime.date(2026, 1, 31)) == "31 January 2026"
    assert Words("it").date(datetime.date(2027, 8, 1)) == "1 agosto 2027"


def test_the_code_terms_in_italian() -> None:
    it = Words("it")
    assert it("ls.ULS") == "SLV" and it("ls.DLS") == "SLD"
    assert "moltiplicatore di attivazione" in it("kin.intro_2019").lower()


def test_the_figures_english_words_are_the_terminal_plots() -> None:
    # The report's English figures say what the terminal commands' plots say
    # (rockcli.plots.phrases), and every phrase is in every language.
    from rockcli.plots.phrases import ENGLISH

    plot = {k.removeprefix("plot."): v for k, v in catalogue("en").items() if k.startswith("plot.")}
    assert plot == ENGLISH
