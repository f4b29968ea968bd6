"""The distribution is `rockcli` (PyPI's `rock` is another project): every install hint says so."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
#: Files users read hints in: sources (messages, help), docs, README, CHANGELOG.
HINT_FILES = [
    *ROOT.joinpath("rockcli").rglob("*.py"),
    *ROOT.joinpath("docs").rglob("*.md"),
    ROOT / "README.md",
    ROOT / "CHANGELOG.md",
    *ROOT.joinpath("examples").rglob("*.md"),
]


def test_distribution_name_is_rockcli():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    assert project["name"] == "rockcli"
    assert project["scripts"]["rock"].startswith("rockcli.")


def test_no_hint_installs_the_unrelated_rock_package():
    bad = re.compile(r"pip install\s+['\"]?rock(\[|['\"\s]|$)")
    found = [
        f"{path.relative_to(ROOT)}:{n}"
        for path in HINT_FILES
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if bad.search(line) or "'rock[" in line
    ]
    assert found == []


def test_every_extra_hint_works_from_a_clone():
    # Issue 19: `pip install 'rockcli[report]'` fails, no distribution of that name is
    # published; a hint names the command that works in a clone, `pip install '.[report]'`.
    # (CHANGELOG.md keeps the history as it was written.)
    published = re.compile(r"rockcli\[")
    found = [
        f"{path.relative_to(ROOT)}:{n}"
        for path in HINT_FILES
        if path.name != "CHANGELOG.md"
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if published.search(line)
    ]
    assert found == []


def test_the_install_hint_names_the_clone():
    from rockcli.cli.report import EXTRA
    from rockcli.errors import install_hint
    from rockcli.plots.files import MISSING

    assert install_hint("report") == "pip install '.[report]' from the repository's folder"
    assert EXTRA == install_hint("report") and MISSING.endswith(install_hint("plot"))
