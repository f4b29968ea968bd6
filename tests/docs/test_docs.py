"""The user guide in docs/ cannot drift from the code.

- docs/model-reference.md is exactly what :func:`rockcli.terminal.schema_doc.model_reference`
  generates from the pydantic schema, and every key of every table of the model file is in
  its table's section;
- every relative link of docs/*.md points to a file that exists (and to an anchor that exists
  when it names one);
- every ``$ rock …`` line of docs/examples.md runs with exit code 0 (CliRunner); the lines
  that read ``../shared`` skip when the shared folder is absent (rock does not ship it).
"""

from __future__ import annotations

import re
import shlex
import subprocess
import sys
from collections.abc import Iterator
from inspect import isclass
from pathlib import Path
from typing import Any, get_args

import pytest
from click.testing import CliRunner
from pydantic import BaseModel

from rockcli.cli.main import cli
from rockcli.model.schema import Model
from rockcli.terminal.schema_doc import REGENERATE, model_reference

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
REFERENCE = DOCS / "model-reference.md"
EXAMPLES = DOCS / "examples.md"
SHARED = ROOT.parent / "shared"

#: The commands the guide must show at work.
EXAMPLE_COMMANDS = (
    "init",
    "record info",
    "record pulse",
    "record spectrum",
    "assess",
    "kinematic",
    "compare",
    "sweep",
)

_FENCE = re.compile(r"^```.*?^```", re.S | re.M)
_INLINE_CODE = re.compile(r"`[^`\n]*`")
_LINK = re.compile(r"(?<!!)\[[^\]]*\]\(([^)\s]+)\)")
_ANCHOR_ID = re.compile(r'<a id="([^"]+)"')
_HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$", re.M)
_COMMAND = re.compile(r"^\$ (rock .*)$", re.M)


# --- the generated model-file reference ----------------------------------------------------


def test_reference_is_generated_from_the_schema() -> None:
    committed = REFERENCE.read_text(encoding="utf-8")
    assert committed == model_reference(), (
        f"docs/model-reference.md is out of date with the schema; regenerate it with\n"
        f"    {REGENERATE}"
    )


def test_reference_entry_point_prints_the_reference() -> None:
    done = subprocess.run(
        [sys.executable, "-m", "rockcli.terminal.schema_doc"],
        cwd=ROOT,
        capture_output=True,
        check=True,
    )
    assert done.stdout.decode("utf-8") == model_reference()


def test_reference_generator_does_not_import_numpy() -> None:
    code = "import sys, rockcli.terminal.schema_doc; sys.exit('numpy' in sys.modules)"
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert done.returncode == 0, "rockcli.terminal.schema_doc imports numpy: " + done.stderr


def _table_of(annotation: Any) -> type[BaseModel] | None:
    """The pydantic table inside an annotation (X, X | None, tuple[X, ...]), if any."""
    if isclass(annotation) and issubclass(annotation, BaseModel):
        return annotation
    for arg in get_args(annotation):
        found = _table_of(arg)
        if found is not None:
            return found
    return None


def _tables(
    table: type[BaseModel] = Model, path: str = ""
) -> Iterator[tuple[str, type[BaseModel]]]:
    """(dotted TOML path, table class) of every table of the model file, walked afresh."""
    yield path, table
    for key, info in table.model_fields.items():
        sub = _table_of(info.annotation)
        if sub is not None:
            yield from _tables(sub, f"{path}.{key}" if path else key)


def _section(doc: str, path: str) -> str:
    """The text of the reference's section whose heading names the table at ``path``."""
    for chunk in doc.split("<a id=")[1:]:
        heading = next(line for line in chunk.splitlines() if line.startswith("## "))
        top = not path and heading.startswith("## Top level")
        if top or (path and re.search(rf"`\[\[?{re.escape(path)}\]?\]`", heading)):
            return chunk
    raise AssertionError(f"no section for [{path}] in docs/model-reference.md")


TABLES = list(_tables())


@pytest.mark.parametrize("path, table", TABLES, ids=[path or "top" for path, _ in TABLES])
def test_every_key_of_every_table_is_in_the_reference(path: str, table: type[BaseModel]) -> None:
    doc = REFERENCE.read_text(encoding="utf-8")
    keys = list(table.model_fields)
    if all(_table_of(f.annotation) is not None for f in table.model_fields.values()) and path:
        # A table of tables only ([ntc.demand]): each sub-table has its own heading.
        missing = [k for k in keys if f"`[{path}.{k}]`" not in doc]
    else:
        section = _section(doc, path)
        missing = [k for k in keys if f"| `{k}` |" not in section]
    assert not missing, f"[{path}] keys missing from docs/model-reference.md: {missing}"


# --- links -----------------------------------------------------------------------------------


def _prose(text: str) -> str:
    """The Markdown without fenced blocks and inline code (links there are not links)."""
    return _INLINE_CODE.sub("", _FENCE.sub("", text))


def _slug(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = re.sub(r"[`*_]", "", heading).strip().lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def _anchors(path: Path) -> set[str]:
    text = path.read_text(encoding="utf-8")
    headings = _HEADING.findall(_FENCE.sub("", text))
    return set(_ANCHOR_ID.findall(text)) | {_slug(h) for h in headings}


def _links() -> list[tuple[str, str]]:
    return [
        (page.name, target)
        for page in sorted(DOCS.glob("*.md"))
        for target in _LINK.findall(_prose(page.read_text(encoding="utf-8")))
        if not re.match(r"^[a-z][a-z0-9+.-]*:", target)  # http:, https:, mailto: …
    ]


def test_the_guide_has_its_pages() -> None:
    pages = {p.name for p in DOCS.glob("*.md")}
    expected = {
        "index.md",
        "model-reference.md",
        "conventions.md",
        "interpretations.md",
        "reading-a-comparison.md",
        "examples.md",
    }
    assert expected <= pages


@pytest.mark.parametrize("page, target", _links(), ids=lambda x: x)
def test_internal_link_points_to_an_existing_file(page: str, target: str) -> None:
    file_part, _, fragment = target.partition("#")
    path = (DOCS / file_part).resolve() if file_part else DOCS / page
    assert path.is_file(), f"docs/{page}: link to {target}: no such file {path}"
    if fragment and path.suffix == ".md":
        assert fragment in _anchors(path), f"docs/{page}: link to {target}: no such anchor"


# --- the examples run ----------------------------------------------------------------------


def _example_lines() -> list[str]:
    text = EXAMPLES.read_text(encoding="utf-8")
    return [m for block in _FENCE.findall(text) for m in _COMMAND.findall(block)]


def _registered(command: str) -> bool:
    """Whether the first word of a command is a command of this build of rock."""
    return command.split()[0] in cli.commands


def test_examples_show_every_command() -> None:
    lines = _example_lines()
    for command in filter(_registered, EXAMPLE_COMMANDS):
        assert any(line.startswith(f"rock {command} ") for line in lines), command


@pytest.fixture
def clone(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A working directory laid out like the repository root, beside ``shared`` if present.

    examples/ and records/ link to the repository's; files the commands write stay in the
    temporary directory.
    """
    work = tmp_path / "clone"
    work.mkdir()
    for name in ("examples", "records"):
        (work / name).symlink_to(ROOT / name, target_is_directory=True)
    if SHARED.is_dir():
        (tmp_path / "shared").symlink_to(SHARED, target_is_directory=True)
    monkeypatch.chdir(work)
    return work


@pytest.mark.parametrize("line", _example_lines())
def test_example_runs(line: str, clone: Path) -> None:
    args = shlex.split(line)[1:]
    if not _registered(args[0]):
        pytest.skip(f"rock {args[0]} is not a command of this build")
    if "../shared/" in line and not SHARED.is_dir():
        pytest.skip(f"needs {SHARED} (real records, hazard grid), absent in this clone")
    result = CliRunner().invoke(cli, args, catch_exceptions=True)
    assert result.exit_code == 0, (
        f"`{line}` exited with {result.exit_code}:\n{result.output}\n{result.exception!r}"
    )
