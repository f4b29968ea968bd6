"""The report's words: one message catalogue per language (messages/<lang>.toml).

Italian is the filing language (the code's own terms: SLV, SLD, moltiplicatore di
attivazione…); English the other. Both catalogues hold the same keys (a test keeps them so).
Numbers are written with the language's decimal mark (0,1645 in Italian).
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any

#: The report's languages, the filing language first (the default).
LANGUAGES = ("it", "en")


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

    def number(self, value: float | None, fmt: str = "{:.4g}") -> str:
        """A number as this language writes it; an em dash for none (or NaN)."""
        if value is None or value != value:
            return "—"
        text = fmt.format(value)
        return text.replace(".", ",") if self.lang == "it" else text

    def yes_no(self, value: bool | None) -> str:
        return "—" if value is None else self("word.yes" if value else "word.no")

    def passed(self, value: bool | None) -> str:
        return (
            self("word.not_evaluated")
            if value is None
            else (self("word.passed") if value else self("word.failed"))
        )
