"""Fitting a table to a width without cutting a number (issue 19, item 7).

A table must fit the terminal (80 columns by default) and a piped or redirected report must
stay within :data:`rockcli.terminal.table.FILE_WIDTH` columns. The reporter tries, in order,
until the columns fit:

1. the boxed table (rich's default frame), each column its natural width;
2. the boxed table with text cells wrapped at spaces, then with the short header of the
   columns that have one (:attr:`ColumnText.headers`), the one that saves most first;
3. the same with a lighter frame: a rule under the header and two blanks between columns,
   then one blank;
4. with the lighter frames again, the longest text words broken (after ``.``, ``-``, ``/``
   or ``_`` where they can be), never below the longest number of the column;
5. wider than the width, the columns at their narrowest: the terminal wraps the lines,
   and still no number is cut.

A number — a numeric column's cell, or a word of a text cell that reads as a number — is
never cut, wrapped or folded at any step.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from rich import box
from rich.box import Box
from rich.cells import cell_len

#: A word that reads as a number (with a sign, exponent, thousands mark, a percent, and the
#: brackets or punctuation around it): 0.055058, −1.5e-05, (r_f = 1, …, 82.28 kN), 30 %.
NUMBER_WORD = re.compile(r"[(\[‘'\"“]*[-+−±]?(\d[\d,.]*|\.\d+)([eE][-+−]?\d+)?%?[)\],;:°'’\"”]*")
#: Where a long text word may be broken: after ``/``, ``_`` or ``-``, and after a ``.`` that
#: no digit follows (``ricker_Tp0.5s`` keeps its ``0.5``).
BREAK_AFTER = re.compile(r"(?<=[/_\-])|(?<=\.)(?!\d)")
#: Two characters a hard cut must not fall between (inside a number of a text word).
_INSIDE_NUMBER = re.compile(r"[\d.]")
#: Fewest characters of a text column when its words must be broken (step 4).
MIN_FOLDED = 6


@dataclass(frozen=True)
class Frame:
    """How a table is drawn, and the characters that takes besides the columns' content."""

    name: str
    box: Box
    show_edge: bool
    #: Blanks left and right of a cell (rich's padding), and whether the outer cells have
    #: them (rich's pad_edge).
    left: int
    right: int
    pad_edge: bool

    def overhead(self, count: int) -> int:
        """Characters of ``count`` columns' frame: edges, separators and padding."""
        separators = count - 1 + (2 if self.show_edge else 0)
        padding = count * (self.left + self.right)
        if not self.pad_edge:
            padding -= self.left + self.right
        return separators + padding


#: The frames of step 1–2 and 3, in the order they are tried.
FRAMES = (
    Frame("boxed", box.HEAVY_HEAD, show_edge=True, left=1, right=1, pad_edge=True),
    Frame("plain", box.SIMPLE_HEAD, show_edge=False, left=0, right=1, pad_edge=False),
    Frame("tight", box.SIMPLE_HEAD, show_edge=False, left=0, right=0, pad_edge=False),
)


@dataclass(frozen=True)
class ColumnText:
    """One column as it will be shown.

    Attributes:
        headers: the full header, then the short one when the column has it.
        cells: the cells, formatted.
        numeric: the cells are numbers (never wrapped).
    """

    headers: tuple[str, ...]
    cells: tuple[str, ...]
    numeric: bool


@dataclass(frozen=True)
class Layout:
    """How to draw a table: its frame, each column's header and width, and whether text
    words are broken.

    ``widths`` is None when every cell fits on one line (rich's natural layout).
    """

    frame: Frame
    headers: tuple[str, ...]
    widths: tuple[int, ...] | None
    fold: bool = False

    def total(self) -> int:
        """The table's width in characters (0 for a natural layout: it fits)."""
        if self.widths is None:
            return 0
        return self.frame.overhead(len(self.widths)) + sum(self.widths)


def fit(columns: Sequence[ColumnText], width: int) -> Layout:
    """The first layout of the module's steps that fits ``width`` (the last one otherwise)."""
    for frame in FRAMES:
        available = width - frame.overhead(len(columns))
        for headers in header_choices(columns):
            layout = _wrapped(columns, headers, available, frame, fold=False)
            if layout is not None:
                return layout
    headers = tuple(c.headers[-1] for c in columns)
    for frame in FRAMES[1:]:
        available = width - frame.overhead(len(columns))
        folded = _wrapped(columns, headers, available, frame, fold=True)
        if folded is not None:
            return folded
    frame = FRAMES[-1]
    narrowest = tuple(_least(c, h, cap=MIN_FOLDED) for c, h in zip(columns, headers, strict=True))
    return Layout(frame, headers, narrowest, fold=True)


def _wrapped(
    columns: Sequence[ColumnText],
    headers: tuple[str, ...],
    available: int,
    frame: Frame,
    *,
    fold: bool,
) -> Layout | None:
    """The layout with these headers in ``available`` characters, or None if it cannot fit.

    With ``fold``, the text words longer than a common cap are broken (a case id is broken, a
    short word such as "skipped" is not): of the caps that fit, the one whose table takes
    fewest lines.
    """
    full = [_longest(c, h) for c, h in zip(columns, headers, strict=True)]
    if not fold and sum(full) <= available:
        return Layout(frame, headers, None)
    caps = _caps(columns) if fold else (None,)
    best: Layout | None = None
    for cap in caps:
        least = [_least(c, h, cap=cap) for c, h in zip(columns, headers, strict=True)]
        if sum(least) > available:
            continue
        layout = Layout(frame, headers, tuple(share(least, full, available)), fold=fold)
        if best is None or height(columns, layout) < height(columns, best):
            best = layout
    return best


def _caps(columns: Sequence[ColumnText]) -> list[int]:
    """The caps worth trying, widest first: each width of a text word down to MIN_FOLDED."""
    words = {
        word_width(word)
        for column in columns
        if not column.numeric
        for cell in column.cells
        for word in cell.split()
    }
    return sorted({w for w in words if w > MIN_FOLDED} | {MIN_FOLDED}, reverse=True)


def height(columns: Sequence[ColumnText], layout: Layout) -> int:
    """Lines of a layout's header and rows (their cells wrapped to the widths)."""
    pairs = zip(columns, layout.headers, strict=True)
    widths = layout.widths or tuple(_longest(c, h) for c, h in pairs)
    rows = [layout.headers, *zip(*(c.cells for c in columns), strict=True)]
    return sum(
        max(wrap_text(cell, w).count("\n") + 1 for cell, w in zip(row, widths, strict=True))
        for row in rows
    )


def header_choices(columns: Sequence[ColumnText]) -> Iterator[tuple[str, ...]]:
    """The full headers, then one more column with its short header at a time: the column
    whose short header narrows it most first."""
    headers = [c.headers[0] for c in columns]
    yield tuple(headers)
    gains = []
    for i, column in enumerate(columns):
        if len(column.headers) > 1:
            gain = _least(column, headers[i]) - _least(column, column.headers[1])
            gains.append((gain, i))
    for gain, i in sorted(gains, key=lambda pair: (-pair[0], pair[1])):
        if gain <= 0:
            break
        headers[i] = columns[i].headers[1]
        yield tuple(headers)


def share(least: Sequence[int], full: Sequence[int], available: int) -> list[int]:
    """Each column at least its ``least`` width, and the rest of ``available`` shared out up
    to each column's ``full`` width: the columns that need least first, whole, then an equal
    share each (max–min fairness: a short text is not left wrapped for a long one's sake)."""
    widths = list(least)
    spare = available - sum(least)
    order = sorted(range(len(widths)), key=lambda i: full[i] - least[i])
    for k, i in enumerate(order):
        grant = min(max(full[i] - least[i], 0), max(spare, 0) // (len(order) - k))
        widths[i] += grant
        spare -= grant
    return widths


def _longest(column: ColumnText, header: str) -> int:
    """The column's width with no cell wrapped."""
    return max(line_width(text) for text in (header, *column.cells))


def _least(column: ColumnText, header: str, *, cap: int | None = None) -> int:
    """The narrowest width that cuts no number, and no text word unless it is longer than
    ``cap`` (None: no word)."""
    words = [word_width(header)]
    for cell in column.cells:
        if column.numeric:
            words.append(line_width(cell))
        elif cap is not None:
            words.append(max(number_width(cell), min(word_width(cell), cap)))
        else:
            words.append(word_width(cell))
    return max(words)


def line_width(text: str) -> int:
    """The widest line of ``text`` [characters]."""
    return max((cell_len(line) for line in text.splitlines()), default=0)


def word_width(text: str) -> int:
    """The widest word of ``text`` [characters]."""
    return max((cell_len(word) for word in text.split()), default=0)


def number_width(text: str) -> int:
    """The widest word of ``text`` that reads as a number (0 when there is none)."""
    return max((cell_len(w) for w in text.split() if NUMBER_WORD.fullmatch(w)), default=0)


def wrap_text(text: str, width: int, *, indent: int = 0) -> str:
    """``text`` wrapped at spaces to ``width``, each paragraph's later lines indented by
    ``indent`` blanks; a longer word broken after ``.-/_`` where it can be, else at the
    width. A word that reads as a number is never broken (a table's caller gives a width of
    at least its length; a line of text is wider than any number)."""
    room = max(width - indent, 1)  # of a later line, after its indent
    lines: list[str] = []
    for paragraph in text.splitlines() or [""]:
        done: list[str] = []
        line = ""
        for word in paragraph.split():
            whole = NUMBER_WORD.fullmatch(word) or cell_len(word) <= room
            for piece in [word] if whole else break_word(word, room):
                joined = f"{line} {piece}" if line else piece
                if line and cell_len(joined) > (room if done else width):
                    done.append(line)
                    joined = piece
                line = joined
        done.append(line)
        lines += [done[0], *(" " * indent + later for later in done[1:])]
    return "\n".join(lines)


def break_word(word: str, width: int) -> list[str]:
    """``word`` in pieces of at most ``width`` characters, broken after ``.-/_`` when a piece
    allows it."""
    pieces: list[str] = []
    rest = word
    while cell_len(rest) > width:
        parts = BREAK_AFTER.split(rest)
        head = ""
        for part in parts:
            if cell_len(head + part) > width:
                break
            head += part
        if not head:
            head = _cut(rest, width)
        pieces.append(head)
        rest = rest[len(head) :]
    return [*pieces, rest] if rest else pieces


def _cut(text: str, width: int) -> str:
    """The longest start of ``text`` that takes at most ``width`` cells and does not end
    inside a run of digits (one character at least)."""
    end = 1
    while end < len(text) and cell_len(text[: end + 1]) <= width:
        end += 1
    cut = end
    while cut > 1 and _splits_number(text, cut):
        cut -= 1
    return text[:end] if _splits_number(text, cut) else text[:cut]


def _splits_number(text: str, at: int) -> bool:
    """Whether cutting ``text`` before index ``at`` splits a run of digits and points."""
    return bool(_INSIDE_NUMBER.match(text[at - 1]) and _INSIDE_NUMBER.match(text[at]))
