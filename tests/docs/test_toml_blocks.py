"""Every model-file block the README and the user guide show loads unchanged.

A user copies these blocks first; a block that does not load (a key missing, a table renamed)
teaches the wrong file. A block is a model file when it has a ``kind`` key; a study file's
block (``base = …``) is checked by the study tests against the example studies.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from rockcli.model.load import load_model

ROOT = Path(__file__).resolve().parents[2]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
_TOML_BLOCK = re.compile(r"^```toml\n(.*?)^```", re.S | re.M)


def model_blocks() -> list[tuple[str, str]]:
    """(page:index, text) of every ```toml block that is a model file."""
    found = []
    for page in PAGES:
        for i, text in enumerate(_TOML_BLOCK.findall(page.read_text(encoding="utf-8"))):
            if "kind" in tomllib.loads(text):
                found.append((f"{page.relative_to(ROOT)}#{i}", text))
    return found


def test_the_readme_shows_a_model_block() -> None:
    assert any(name.startswith("README.md") for name, _ in model_blocks())


@pytest.mark.parametrize(("name", "text"), model_blocks(), ids=lambda v: v[:40])
def test_model_block_loads(name: str, text: str, tmp_path: Path) -> None:
    path = tmp_path / "block.toml"
    path.write_text(text, encoding="utf-8")
    load_model(path)  # raises InputError naming the key if the block does not load
