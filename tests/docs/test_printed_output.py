"""Every ``$ rock …`` block of docs/ runs, and prints what the doc says it prints (issue 36).

Each command runs as a user runs it (a process, not a terminal: the tables at their file width)
in a scratch folder laid out as the repository's root, with the reader's own files the docs
name made there (tests/docs/printed.py). Only timings and that folder's path are normalised. A
block that shows no output must exit 0. Commands that read ``../shared`` skip when it is absent.
After a change of output, ``python -m tests.docs.printed`` writes the docs' blocks anew.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.docs.printed import (
    SHARED,
    DocCommand,
    every_command,
    matches,
    normalised,
    run,
    scratch_copy,
)

COMMANDS = every_command()


def test_the_docs_have_their_commands() -> None:
    # The guide shows every command it documents with its output: at least the pages below.
    pages = {c.page for c in COMMANDS if c.expected is not None}
    assert {"examples.md", "fragility.md", "retrofit.md", "spectra.md", "suites.md"} <= pages


@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: f"{c.page}:{c.line}")
def test_a_documented_command_prints_what_the_doc_says(command: DocCommand, tmp_path: Path) -> None:
    if "../shared" in command.command and not SHARED.is_dir():
        pytest.skip(f"needs {SHARED} (real records, the hazard grid), absent beside this clone")
    if "my-records" in command.command and not SHARED.is_dir():
        pytest.skip("my-records/ is made of ../shared's records, absent beside this clone")
    cwd = scratch_copy(tmp_path)
    code, out = run(command.command, cwd)
    if command.expected is None:
        assert code == 0, f"{command.page}:{command.line}: `{command.command}` exited {code}\n{out}"
        return
    printed, expected = normalised(out, cwd), normalised(command.expected)
    assert matches(printed, expected), (
        f"{command.page}:{command.line}: `{command.command}` prints otherwise than the doc "
        f"(python -m tests.docs.printed writes it anew):\n{printed}"
    )
