"""The report's words: one message catalogue per language (messages/<lang>.toml).

Italian is the filing language (the code's own terms: SLV, SLD, moltiplicatore di
attivazione…); English the other. Both catalogues hold the same keys (a test keeps them so).
Numbers are written with the language's decimal mark (0,1645 in Italian).
"""

from __future__ import annotations

import datetime
import tomllib
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

from rockcli.notes import Items, Note

#: The report's languages, the filing language first (the default).
LANGUAGES = ("it", "en")
#: The months as each language writes them in a date ("7 dicembre 2026").
MONTHS = {
    "it": ("gennaio", "febbraio", "marzo", "aprile", "maggio", "giugno", "luglio", "agosto",
           "settembre", "ottobre", "novembre", "dicembre"),
    "en": ("January", "February", "March", "April", "May", "June", "July", "August",
           "September", "October", "November", "December"),
}  # fmt: skip


@cache
def catalogue(lang: str) -> dict[str, str]:
    """Every message of a language, keyed ``section.name`` (the TOML's tables flattened)."""
    text = (
        resources.files("rockcli.document")
        .joinpath("messages", f"{lang}.toml")
        .read_text(encoding="utf-8")
    )
    return dict(_flatten(tomllib.loads(text)))


def _flatten(table: dict[str, Any], prefix: str = "") -> list[tuple[str, str]]:
    items: list[tuple[str, str]] = []
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            items.extend(_flatten(value, name + "."))
        else:
            items.append((name, str(value)))
    return items


@dataclass(frozen=True)
class Words:
    """A language's messages and number format."""

    lang: str

    def __call__(self, key: str, **values: Any) -> str:
        """The message ``key``, its ``{name}`` fields filled (numbers already formatted)."""
        text = catalogue(self.lang)[key]
        return text.format(**values) if values else text

    def date(self, day: datetime.date) -> str:
        """A calendar day as this language writes it in a document: "7 dicembre 2026",
        "7 December 2026" (never ISO 8601 in the text a reviewer reads)."""
        return f"{day.day} {MONTHS[self.lang][day.month - 1]} {day.year}"

    def moment(self, stamp: str) -> str:
        """The report's time stamp ("2026-12-07 09:30 UTC", document.run.report_date) as this
        language writes it: "7 dicembre 2026, 09:30 UTC"."""
        day = datetime.date.fromisoformat(stamp[:10])
        rest = stamp[10:].strip()
        return f"{self.date(day)}, {rest}" if rest else self.date(day)

    def number(self, value: float | None, fmt: str = "{:.4g}") -> str:
        """A number as this language writes it; an em dash for none (or NaN)."""
        if value is None or value != value:
            return "—"
        text = fmt.format(value)
        return text.replace(".", ",") if self.lang == "it" else text

    def ratio(self, value: float | None, overturned: bool, fmt: str = "{:.4g}") -> str:
        """max θ/α as a table shows it: the number, or "ribalta" ("overturns") for a run that
        overturned, whose number (the overturn angle over θc) measures nothing."""
        return self("word.overturns") if overturned else self.number(value, fmt)

    def note(self, text: str) -> str:
        """A note or warning of the analyses in this language: a :class:`Note` from the
        catalogue's ``[note]`` template of its key (its values written in this language too),
        any other text as it is (the model's own words, a name)."""
        if isinstance(text, Items):
            return format(self._localised(text), "")
        if not isinstance(text, Note) or self.lang == "en":
            return str(text)
        template = catalogue(self.lang).get(f"note.{text.key}")
        if template is None:
            return str(text)
        return template.format(**{k: self._localised(v) for k, v in text.values.items()})

    def localised(self, value: Any) -> Any:
        """A value to format into this language's text: a float with its decimal mark, a
        note in this language, any other value as it is."""
        return self._localised(value)

    def _localised(self, value: Any) -> Any:
        if isinstance(value, Note):
            return self.note(value)
        if isinstance(value, Items):
            return Items((self._localised(v) for v in value), value.sep)
        if isinstance(value, float):
            return _Decimal(value, "," if self.lang == "it" else ".")
        return value

    def yes_no(self, value: bool | None) -> str:
        return "—" if value is None else self("word.yes" if value else "word.no")

    def passed(self, value: bool | None) -> str:
        return (
            self("word.not_evaluated")
            if value is None
            else (self("word.passed") if value else self("word.failed"))
        )


@dataclass(frozen=True)
class _Decimal:
    """A float formatted by its spec, then written with the language's decimal mark."""

    value: float
    mark: str

    def __format__(self, spec: str) -> str:
        return format(self.value, spec).replace(".", self.mark)
