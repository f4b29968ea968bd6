"""What users read names only what they have: no design files of the developers (`spec/…`),
no "workspace" or "user's clone" (issue 7, item 19).

Users read the README, the guide (docs/), the examples, the records' headers, the messages
and help texts of the package (its string constants, docstrings aside) and the reasons of
skipped tests.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
#: Words that point a user at something they do not have.
FOREIGN = re.compile(r"\bspec/|\bworkspace\b|user's clone")


def _pages() -> list[Path]:
    return [
        ROOT / "README.md",
        ROOT / "CHANGELOG.md",
        *ROOT.joinpath("docs").rglob("*.md"),
        *(p for p in ROOT.joinpath("examples").rglob("*") if p.is_file()),
        *ROOT.joinpath("records").glob("*"),
    ]


def _strings(path: Path) -> list[tuple[int, str]]:
    """The string constants of a module that are not docstrings, with their line."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    docstrings = {
        id(node.body[0].value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef)
        and node.body
        and isinstance(node.body[0], ast.Expr)
        and isinstance(node.body[0].value, ast.Constant)
    }
    return [
        (node.lineno, node.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant)
        and isinstance(node.value, str)
        and id(node) not in docstrings
    ]


def test_pages_users_read_name_nothing_they_lack() -> None:
    found = [
        f"{page.relative_to(ROOT)}:{n}: {line.strip()}"
        for page in _pages()
        for n, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1)
        if FOREIGN.search(line)
    ]
    assert found == []


def test_messages_and_skip_reasons_name_nothing_users_lack() -> None:
    modules = [*ROOT.joinpath("rockcli").rglob("*.py"), *ROOT.joinpath("tests").rglob("*.py")]
    found = [
        f"{path.relative_to(ROOT)}:{line}: {text[:60]!r}"
        for path in modules
        if path != Path(__file__)
        for line, text in _strings(path)
        if FOREIGN.search(text) and not text.endswith(r"spec/[^()]*\)")  # schema_doc's filter
    ]
    assert found == []
