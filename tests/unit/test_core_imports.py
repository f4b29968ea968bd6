"""The numeric core is silent and pure (spec/style.md, principle 1): the dynamics, the code
check and the block mechanics import neither click, rich, pydantic nor tomllib. Read from the
source with ast, so a lazy import inside a function counts too."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2] / "rockcli"
CORE = [
    *sorted((ROOT / "dynamics").glob("*.py")),
    *sorted((ROOT / "codecheck").glob("*.py")),
    ROOT / "mechanics.py",
]
FORBIDDEN = {"click", "rich", "pydantic", "tomllib", "tomli_w"}


def imported_roots(path: Path) -> set[str]:
    roots = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            roots |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            roots.add(node.module.split(".")[0])
    return roots


@pytest.mark.parametrize("path", CORE, ids=lambda p: str(p.relative_to(ROOT)))
def test_core_module_imports_no_edge_library(path: Path) -> None:
    assert not imported_roots(path) & FORBIDDEN
