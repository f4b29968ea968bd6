"""No function of the rocking engine is longer than 120 lines (issue 35, item 3): the driver,
the step and the events each read on one screen or two."""

from __future__ import annotations

import ast
from pathlib import Path

ENGINE = Path(__file__).resolve().parents[2] / "rockcli" / "dynamics"
MAX_LINES = 120


def long_functions(folder: Path, limit: int) -> list[str]:
    """'file:function (lines)' of every function or method longer than ``limit`` lines."""
    found = []
    for path in sorted(folder.glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                lines = node.end_lineno - node.lineno + 1
                if lines > limit:
                    found.append(f"{path.name}:{node.name} ({lines})")
    return found


def test_no_engine_function_is_longer_than_the_limit() -> None:
    assert long_functions(ENGINE, MAX_LINES) == []


def test_the_check_sees_a_long_function(tmp_path: Path) -> None:
    body = "\n".join(f"    x{k} = {k}" for k in range(MAX_LINES))
    (tmp_path / "long.py").write_text(f"def f():\n{body}\n", encoding="utf-8")
    assert long_functions(tmp_path, MAX_LINES) == [f"long.py:f ({MAX_LINES + 1})"]
