"""The one error family of rock: bad input, named where it is and what is allowed.

A physics outcome (overturning, a run stopped by the event guard) is a *result*, never an
exception. Everything the user can get wrong raises :class:`InputError`, which the CLI turns
into one line on stderr and a non-zero exit code in a single place (``cli/main.py``).
"""

from __future__ import annotations

import unicodedata

#: Unicode's bidirectional controls: they reorder what the terminal shows ("Trojan Source").
BIDI_CONTROLS = frozenset(
    "\u061c\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069"
)


def printable(text: str) -> str:
    """``text`` safe for a terminal: control characters (an escape sequence in a model's name,
    a line break in a file name) and bidirectional controls shown as ``\\xNN``/``\\uNNNN``.
    """
    if text.isprintable():
        return text
    return "".join(_escaped(c) for c in text)


#: The line breaks and tab a document keeps (a model's notes run over several lines; HTML,
#: SVG and Typst take them as white space).
DOCUMENT_WHITESPACE = frozenset("\t\n\r")


def display_text(text: str) -> str:
    """``text`` safe for a document or a figure (the HTML and PDF report, a plot file).

    As :func:`printable`, but tab and line breaks are kept: control characters (a bell or an
    escape sequence in a record's name), bidirectional controls, and the code points XML
    forbids (surrogates, U+FFFE, U+FFFF, which make an SVG figure unreadable to Typst) are
    shown as ``\\xNN``/``\\uNNNN``, so the reader sees that the name holds them.
    """
    if text.isprintable():
        return text
    return "".join(c if c in DOCUMENT_WHITESPACE else _escaped(c) for c in text)


def _escaped(char: str) -> str:
    category = unicodedata.category(char)
    if category not in ("Cc", "Cs") and char not in BIDI_CONTROLS and char not in "\ufffe\uffff":
        return char
    code = ord(char)
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def install_hint(extra: str) -> str:
    """The command that installs an optional extra (``plot``, ``report``, ``dask``,
    ``parquet``): rock installs from a clone of its repository, its distribution ``rockcli``
    is not published on a package index: a hint that names it sends pip looking for nothing."""
    return f"pip install '.[{extra}]' from the repository's folder"


class RockError(Exception):
    """Base of every error rock raises on purpose."""


class InputError(RockError):
    """Bad input: a file, a field or line, the value found and what is allowed.

    Args:
        problem: what is wrong, e.g. "must be greater than 0".
        file: the file the input came from (path as the user gave it), if any.
        where: the field path (``geometry.thickness``) or the line (``line 12``), if known.
        value: the offending value as found, if any.
        allowed: what would be accepted, e.g. "a number > 0 [m]".
    """

    def __init__(
        self,
        problem: str,
        *,
        file: str | None = None,
        where: str | None = None,
        value: object = None,
        allowed: str | None = None,
    ) -> None:
        self.problem = problem
        self.file = file
        self.where = where
        self.value = value
        self.allowed = allowed
        super().__init__(self.render())

    def render(self) -> str:
        """One line: ``file: where: problem (got value; allowed: ...)``."""
        head = ": ".join(str(x) for x in (self.file, self.where) if x)
        text = f"{head}: {self.problem}" if head else self.problem
        extras = []
        if self.value is not None:
            extras.append(f"got {self.value!r}")
        if self.allowed:
            extras.append(f"allowed: {self.allowed}")
        return f"{text} ({'; '.join(extras)})" if extras else text

    def note(self) -> str:
        """:meth:`render`'s line, as a Note a report writes in its language when the problem
        and what is allowed are Notes (rockcli.notes) and no file is named; else the line."""
        from rockcli.notes import Note

        text = self.render()
        notes = isinstance(self.problem, Note) and isinstance(self.allowed, Note)
        if self.file or self.where is None or self.value is None or not notes:
            return text
        note = Note("input_error", "{where}: {problem} (got {value!r}; allowed: {allowed})",
                    where=self.where, problem=self.problem, value=self.value,
                    allowed=self.allowed)  # fmt: skip
        return note if note == text else text

    def with_file(self, file: str) -> InputError:
        """The same error, naming the file (when a lower layer did not know it)."""
        if self.file:
            return self
        return InputError(
            self.problem, file=file, where=self.where, value=self.value, allowed=self.allowed
        )
