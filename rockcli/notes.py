"""A note or warning an analysis writes, in English and in any report language.

A :class:`Note` is the English text the terminal and the JSON show (it *is* a ``str``), and
the key and values from which a calculation report writes it in its own language: the
report's message catalogue holds, under ``[note]``, a template per key with the same fields
(``rockcli/document/messages/it.toml``). A value may itself be a note (written in the same
language) or :class:`Items` (a list, joined with commas); numbers are formatted by the
template's own format spec and take the language's decimal mark.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from typing import Any


class Items(tuple[Any, ...]):
    """Values written one after another, joined with ``sep`` (a list inside a note)."""

    sep: str

    def __new__(cls, values: Iterable[Any] = (), sep: str = ", ") -> Items:
        self = super().__new__(cls, values)
        self.sep = sep
        return self

    def __format__(self, spec: str) -> str:
        return self.sep.join(format(item, spec) for item in self)

    def __reduce__(self) -> tuple[Any, ...]:
        return Items, (tuple(self), self.sep)


class Note(str):
    """English ``template.format(**values)``, with ``key``, ``template`` and ``values`` kept
    for a report to write the same note in another language."""

    key: str
    template: str
    values: Mapping[str, Any]

    def __new__(cls, key: str, template: str, /, **values: Any) -> Note:
        self = super().__new__(cls, template.format(**values))
        self.key, self.template, self.values = key, template, values
        return self

    def __reduce__(self) -> tuple[Callable[..., Note], tuple[Any, ...]]:
        return _restore, (self.key, self.template, dict(self.values))


def _restore(key: str, template: str, values: dict[str, Any]) -> Note:
    return Note(key, template, **values)
