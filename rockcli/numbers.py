"""Numbers typed by a user, read as ASCII only.

Python's ``float()`` and ``int()`` read any Unicode decimal digit: ``float("０.３")``
(fullwidth) is 0.3 and ``int("٣")`` (Arabic-Indic) is 3. A number rock reads from an option
(``--target``, ``--periods``, ``--site``…) or a hand-parsed file must be written the way a
TOML file or a record file writes it, in ASCII: text that only looks like a number (pasted
from a word processor, typed with an East Asian input method) is refused, never read as
another value than the one the user sees.
"""

from __future__ import annotations


def ascii_float(text: str) -> float:
    """``float(text)`` for ASCII text; ValueError otherwise (as ``float`` raises it)."""
    if not text.isascii():
        raise ValueError(f"not an ASCII number: {text!r}")
    return float(text)


def ascii_int(text: str) -> int:
    """``int(text)`` for ASCII text; ValueError otherwise (as ``int`` raises it)."""
    if not text.isascii():
        raise ValueError(f"not an ASCII number: {text!r}")
    return int(text)
