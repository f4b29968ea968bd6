"""`rockcli.studies` composes the cores (dynamics, codecheck, mechanics), the records and the
model into results; the command layer (rockcli.cli) turns them into documents and reports.
Read from the source with ast, so a lazy import inside a function counts too."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2] / "rockcli"
STUDIES = sorted([*(ROOT / "studies").rglob("*.py"), *(ROOT / "analyses").rglob("*.py")])
#: What a study module may not import: the document and terminal layers, the command line.
FORBIDDEN = ("rockcli.terminal", "rockcli.plots", "rockcli.cli", "click", "rich")


def imported_modules(path: Path, root: Path = ROOT) -> set[str]:
    """Every module a file imports, absolute (``from rockcli import terminal`` included)."""
    package = ".".join(path.relative_to(root.parent).with_suffix("").parts[:-1])
    names = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parent = package.rsplit(".", node.level - 1)[0] if node.level > 1 else package
                base = f"{parent}.{base}" if base else parent
            names.add(base)
            names |= {f"{base}.{alias.name}" for alias in node.names}
    return names


def forbidden(names: set[str]) -> set[str]:
    return {n for n in names for f in FORBIDDEN if n == f or n.startswith(f + ".")}


def test_the_check_sees_every_form_of_import(tmp_path: Path) -> None:
    """The checker itself: each way of importing the report layer is caught."""
    folder = tmp_path / "rockcli" / "studies"
    folder.mkdir(parents=True)
    sample = folder / "x.py"
    sample.write_text(
        "import rich.console\nfrom rockcli import terminal\nfrom ..cli import main\n"
        "def f():\n    from rockcli.terminal.assess import assessment_document\n"
    )
    found = forbidden(imported_modules(sample, tmp_path / "rockcli"))
    assert {"rich.console", "rockcli.terminal", "rockcli.cli", "rockcli.terminal.assess"} <= found


def test_studies_has_its_sweep_package() -> None:
    assert (ROOT / "studies" / "sweep" / "__init__.py").is_file()
    assert not list((ROOT / "studies").glob("sweep_*.py"))


@pytest.mark.parametrize("path", STUDIES, ids=lambda p: str(p.relative_to(ROOT)))
def test_a_study_module_imports_no_report_cli_click_or_rich(path: Path) -> None:
    assert not forbidden(imported_modules(path))


#: Imports run one way between the studies' packages (spec/style.md): each package below may
#: not import the ones listed for it. parallel is where every study runs, and knows none of
#: them; a suite in the time history is used by sweep, not the other way round.
ONE_WAY = {
    "parallel": ("rockcli.studies.sweep", "rockcli.studies.suite_run", "rockcli.studies.retrofit"),
    "suite": ("rockcli.studies.sweep", "rockcli.studies.retrofit"),
}


@pytest.mark.parametrize("package", sorted(ONE_WAY))
def test_imports_run_one_way_between_the_studies_packages(package: str) -> None:
    for path in sorted((ROOT / "studies" / package).glob("*.py")):
        names = imported_modules(path)
        wrong = {n for n in names for f in ONE_WAY[package] if n == f or n.startswith(f + ".")}
        assert not wrong, f"{path.relative_to(ROOT)} imports {sorted(wrong)}"


def test_the_study_file_and_its_key_paths_import_one_way() -> None:
    # study.py (the file's schema, load_study) uses paths.py (key paths and axes); not back.
    names = imported_modules(ROOT / "studies" / "sweep" / "paths.py")
    assert not any(n.startswith("rockcli.studies.sweep.study") for n in names)


@pytest.mark.parametrize(
    ("package", "other"), [("dynamics", "codecheck"), ("codecheck", "dynamics")]
)
def test_the_numeric_packages_import_neither_each_other_nor_the_warmup(
    package: str, other: str
) -> None:
    # rockcli.kernels compiles every kernel (dynamics and codecheck) and registers itself with
    # rockcli.jitcache; the numeric packages ask jitcache, never kernels, and not each other
    # (the warm-up in dynamics once made dynamics and codecheck import each other).
    for path in sorted((ROOT / package).rglob("*.py")):
        names = imported_modules(path)
        wrong = {
            n for n in names if n.split(".")[:2] in (["rockcli", "kernels"], ["rockcli", other])
        }
        assert not wrong, f"{path.relative_to(ROOT)} imports {sorted(wrong)}"
