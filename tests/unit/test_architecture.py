"""The layers of docs/architecture.md, enforced: a package of rockcli imports only packages of
the layers below it (or earlier in its own row), in any form (lazy and TYPE_CHECKING imports
included: tests/unit/test_import_cycles.py reads them); every package is placed."""

from __future__ import annotations

from pathlib import Path

from tests.unit.test_import_cycles import ROOT, module_graph, package_of

#: Bottom to top, as docs/architecture.md's table: each row a layer, in the order its
#: packages may import one another.
LAYERS = (
    ("version", "interrupts", "process", "numbers", "notes", "errors", "jitcache", "inside",
     "outfile", "textfile", "units", "searches"),
    ("mechanics", "mechanisms"),
    ("dynamics", "codecheck", "records", "kernels"),
    ("model",),
    ("suites",),
    ("analyses",),
    ("studies", "risk", "casebook"),
    ("terminal", "plots", "document"),
    ("api", "rockcli", "cli", "__main__"),
)  # fmt: skip
ORDER = {f"rockcli.{p}" if p != "rockcli" else p: k for k, p in enumerate(sum(LAYERS, ()))}


def upward_imports(graph: dict[str, set[str]]) -> list[str]:
    """Every import of a package by one that comes earlier in the order."""
    found = []
    for name, targets in graph.items():
        own = package_of(name)
        for target in targets:
            other = package_of(target)
            if other != own and ORDER[other] > ORDER[own]:
                found.append(f"{name} imports {target}")
    return sorted(found)


def test_every_package_has_its_layer() -> None:
    packages = {package_of(name) for name in module_graph()}
    assert packages - set(ORDER) == set()


def test_no_package_imports_a_layer_above() -> None:
    assert upward_imports(module_graph()) == []


def test_the_docs_table_lists_the_layers() -> None:
    """docs/architecture.md names every package of LAYERS in its table, in the same rows."""
    text = (ROOT.parent / "docs" / "architecture.md").read_text(encoding="utf-8")
    rows = [line for line in text.splitlines() if line.startswith("| ") and ". " in line[:8]]
    assert len(rows) == len(LAYERS)
    for row, layer in zip(rows, LAYERS, strict=True):
        cell = row.split("|")[2]
        assert all(f"`{p}`" in cell for p in layer), (row, layer)


def test_the_check_sees_an_upward_import(tmp_path: Path) -> None:
    """The checker itself: the engine importing the command line is caught."""
    graph = {"rockcli.dynamics.kernel": {"rockcli.cli.main"}, "rockcli.cli.main": set()}
    assert upward_imports(graph) == ["rockcli.dynamics.kernel imports rockcli.cli.main"]
