"""rockcli.studies.fragility (the fits, the searches, the fragility and overturning-spectrum
runs) is a study built on the others: it uses the sweep's lanes, records and models, and the
other studies and the analyses know nothing of it; like every study module, it imports no
document, terminal or command layer. Read from the source with ast (tests/sweep/test_layers.py),
so a lazy import inside a function counts."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.sweep.test_layers import ROOT, forbidden, imported_modules

FRAGILITY = sorted((ROOT / "studies" / "fragility").rglob("*.py"))


@pytest.mark.parametrize("path", FRAGILITY, ids=lambda p: str(p.relative_to(ROOT)))
def test_a_fragility_module_imports_no_report_cli_click_or_rich(path: Path) -> None:
    assert not forbidden(imported_modules(path))


def test_the_other_studies_and_the_analyses_import_nothing_of_fragility() -> None:
    others = [p for p in (ROOT / "studies").rglob("*.py") if "fragility" not in p.parts]
    assert others  # the sweep, the suites, the retrofit, the executors, the folder
    for path in sorted(others + list((ROOT / "analyses").rglob("*.py"))):
        wrong = {n for n in imported_modules(path) if n.startswith("rockcli.studies.fragility")}
        assert not wrong, f"{path.relative_to(ROOT)} imports {sorted(wrong)}"
