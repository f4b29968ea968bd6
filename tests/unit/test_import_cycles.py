"""No import cycle in rockcli (issue "One mechanism, one description", item 4): read from the
source with ast, every import counts — at module level, inside a function (a lazy import),
under ``if TYPE_CHECKING:`` — so a cycle cannot hide behind a lazy import. Between modules,
and between the packages of rockcli (its first-level folders and modules)."""

from __future__ import annotations

import ast
from collections.abc import Mapping
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2] / "rockcli"


def module_names(root: Path) -> dict[str, Path]:
    """Every module below root by its dotted name (a package by its folder's name)."""
    out = {}
    for path in root.rglob("*.py"):
        parts = path.relative_to(root.parent).with_suffix("").parts
        out[".".join(parts[:-1] if parts[-1] == "__init__" else parts)] = path
    return out


def imports_of(name: str, path: Path, modules: Mapping[str, Path]) -> set[str]:
    """The modules of ``modules`` that the file imports, in any form and place."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parent = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
                base = f"{parent}.{base}" if base else parent
            # ``from rockcli import jitcache`` imports the module rockcli.jitcache, not the
            # package's __init__ (which Python runs, but which the importer does not use).
            names = [
                f"{base}.{alias.name}" if f"{base}.{alias.name}" in modules else base
                for alias in node.names
            ]
        else:
            continue
        for candidate in names:
            while candidate and candidate not in modules:
                candidate = candidate.rpartition(".")[0]
            if candidate and candidate != name:
                found.add(candidate)
    return found


def cycles(graph: Mapping[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one node (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for start in graph:
        if start in index:
            continue
        work = [(start, iter(sorted(graph.get(start, ()))))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                if len(component) > 1:
                    found.append(sorted(component))
    return found


def module_graph(root: Path = ROOT) -> dict[str, set[str]]:
    modules = module_names(root)
    return {name: imports_of(name, path, modules) for name, path in modules.items()}


def package_of(name: str) -> str:
    """``rockcli.studies.sweep.run`` → ``rockcli.studies``; a first-level module is its own."""
    return ".".join(name.split(".")[:2])


def test_no_module_imports_itself_back() -> None:
    assert cycles(module_graph()) == []


def test_no_package_imports_itself_back() -> None:
    packages: dict[str, set[str]] = {}
    for name, targets in module_graph().items():
        own = package_of(name)
        packages.setdefault(own, set()).update(
            package_of(t) for t in targets if package_of(t) != own
        )
    assert cycles(packages) == []


def test_the_check_sees_a_lazy_and_a_type_checking_cycle(tmp_path: Path) -> None:
    """The checker itself: a cycle closed by a lazy import, and one closed under
    TYPE_CHECKING, are both found."""
    root = tmp_path / "rockcli"
    (root / "sub").mkdir(parents=True)
    (root / "__init__.py").write_text("")
    (root / "sub" / "__init__.py").write_text("")
    (root / "a.py").write_text("from rockcli import b\n")
    (root / "b.py").write_text("def f():\n    from rockcli.a import x\n")
    (root / "sub" / "c.py").write_text("from .d import y\n")
    (root / "sub" / "d.py").write_text(
        "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from rockcli.sub import c\n"
    )
    assert sorted(cycles(module_graph(root))) == [
        ["rockcli.a", "rockcli.b"],
        ["rockcli.sub.c", "rockcli.sub.d"],
    ]
