"""The `$ rock …` blocks of docs/*.md: what each runs and what the doc says it prints.

A fenced block whose lines start with ``$ rock`` holds commands; the lines after a command, up
to the next command or the fence, are what the doc says it prints (stdout and stderr as a
terminal shows them). tests/docs/test_printed_output.py runs every command in a scratch copy
of the repository's layout and compares; ``python -m tests.docs.printed`` writes the docs'
blocks anew from what this build prints (docs/CONTRIBUTING-docs: after a change of output).

Normalised on both sides, and only these: the run's timings ("in 0.43 s", "engine compiled in
60 s"), the scratch folder's path, trailing spaces.
"""

from __future__ import annotations

import re
import shlex
import shutil
import sys
import tempfile
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
SHARED = ROOT.parent / "shared"
#: A fenced block: its opening fence's info string and its body.
FENCE = re.compile(r"^```([^\n`]*)\n(.*?)^```[ \t]*$", re.S | re.M)
#: Timings a run prints, which no doc can hold still.
TIMINGS = (
    (re.compile(r"\bin \d+(\.\d+)? ?(ms|s)\b"), "in <time>"),
    (re.compile(r"compiling the rocking engine for this machine, once: ~\d+ s\n"), ""),
    (re.compile(r"engine compiled in \d+ s; later runs start at once\n"), ""),
)


@dataclass(frozen=True)
class DocCommand:
    """One ``$ rock …`` of a doc: where it is, the command line, what the doc says it prints
    (None: the block lists commands only, no output under them)."""

    page: str
    line: int
    command: str
    expected: str | None


def doc_commands(path: Path) -> Iterator[DocCommand]:
    """Every ``$ rock`` command of a page, with its printed output when the block shows it."""
    text = path.read_text(encoding="utf-8")
    for match in FENCE.finditer(text):
        body = match.group(2)
        start = text.count("\n", 0, match.start(2)) + 1
        lines = body.split("\n")
        k = 0
        while k < len(lines):
            if not lines[k].startswith("$ rock"):
                k += 1
                continue
            first, command = k, lines[k][2:]
            while command.endswith("\\") and k + 1 < len(lines):
                k += 1
                command = command[:-1].rstrip() + " " + lines[k].strip()
            k += 1
            out = []
            while k < len(lines) and not lines[k].startswith("$ "):
                out.append(lines[k])
                k += 1
            printed = "\n".join(out).strip("\n")
            yield DocCommand(path.name, start + first, command, printed or None)


def every_command() -> list[DocCommand]:
    """The commands of every page of docs/, in order."""
    return [c for path in sorted(DOCS.glob("*.md")) for c in doc_commands(path)]


def normalised(text: str, scratch: Path | None = None, timings: bool = True) -> str:
    """Output as the comparison reads it (module docstring); ``timings`` False: as a doc
    shows it (the engine's one-off compile lines and the scratch path still left out)."""
    if scratch is not None:
        text = text.replace(str(scratch) + "/", "").replace(str(scratch), ".")
    for pattern, repl in TIMINGS if timings else TIMINGS[1:]:
        text = pattern.sub(repl, text)
    return "\n".join(line.rstrip() for line in text.strip("\n").split("\n"))


#: The files the docs name as a reader's own (a wall of theirs, a folder of their records, a
#: project file, their cases), made in the scratch folder from the repository's.
PLACEHOLDER_RECORDS = ("ELC180.AT2", "CPM000.AT2", "KOBE95_NIS090_NGAW1.AT2")


def scratch_copy(base: Path) -> Path:
    """A working folder laid out as the repository's root (examples/, records/, docs/ linked;
    ../shared beside it when present), with the reader's own files the docs name
    (:func:`placeholders`), in which the docs' commands run and write."""
    work = base / "repo"
    work.mkdir()
    for name in ("examples", "records", "docs"):
        (work / name).symlink_to(ROOT / name, target_is_directory=True)
    if SHARED.is_dir():
        (base / "shared").symlink_to(SHARED, target_is_directory=True)
    placeholders(work)
    return work


def placeholders(work: Path) -> None:
    """wall.toml (examples/wall.toml), r.txt (a pulse), p.toml (a project file whose section
    lies outside its folder: docs/report.md shows the refusal), my-cases/ (the casebook's
    folder), my-records/ (three of ../shared's records, when present)."""
    shutil.copy(ROOT / "examples" / "wall.toml", work / "wall.toml")
    shutil.copy(ROOT / "records" / "ricker_Tp0.5s_0.5g.txt", work / "r.txt")
    (work / "p.toml").write_text(
        '[project]\nclient = "C"\nsubject = "S"\ncomune = "L\'Aquila (AQ)"\n'
        'designer = "Ing. M. Rossi"\n\n[[project.sections]]\ntitle = "Premessa"\n'
        'file = "../x.md"\n', encoding="utf-8")  # fmt: skip
    (work / "my-cases").symlink_to(ROOT / "examples" / "validation", target_is_directory=True)
    if SHARED.is_dir():
        (work / "my-records").mkdir()
        for name in PLACEHOLDER_RECORDS:
            shutil.copy(SHARED / "records" / name, work / "my-records" / name)


def matches(printed: str, expected: str) -> bool:
    """Whether the output is the doc's: equal, or for an excerpt (a line "⋮" where lines are
    left out) each shown part in order, the last at the end."""
    if "⋮" not in expected.split("\n"):
        return printed == expected
    parts = [
        p.strip("\n")
        for p in "\n".join("\x00" if line == "⋮" else line for line in expected.split("\n")).split(
            "\x00"
        )
    ]
    at = 0
    for part in parts:
        if not part:
            continue
        found = printed.find(part, at)
        if found < 0:
            return False
        at = found + len(part)
    return parts[-1] == "" or printed.endswith(parts[-1])


def excerpt_of(printed: str, expected: str) -> str:
    """The new output shown as the doc's excerpt was: its last lines, as many as the doc
    shows after its last "⋮" (an excerpt without one: the whole output)."""
    lines = expected.split("\n")
    if "⋮" not in lines:
        return printed
    tail = len(lines) - 1 - max(k for k, line in enumerate(lines) if line == "⋮")
    return "\n".join(["⋮", *printed.split("\n")[-tail:]]) if tail else printed


def run(command: str, cwd: Path) -> tuple[int, str]:
    """The command as a user runs it (a process, its stdout and stderr as one stream, not a
    terminal), in ``cwd``: its exit code and what it printed."""
    import subprocess

    args = shlex.split(command)
    done = subprocess.run(
        [sys.executable, "-m", "rockcli", *args[1:]], cwd=cwd, capture_output=False,
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=600,
    )  # fmt: skip
    return done.returncode, done.stdout


def regenerate() -> None:
    """Write every doc's printed blocks anew from this build's output."""
    with tempfile.TemporaryDirectory(prefix="rock-docs-") as tmp:
        cwd = scratch_copy(Path(tmp))
        for path in sorted(DOCS.glob("*.md")):
            text = path.read_text(encoding="utf-8")
            new = text
            for c in reversed(list(doc_commands(path))):  # bottom up: the lines above stay
                if c.expected is None:
                    continue
                began = time.perf_counter()
                code, out = run(c.command, cwd)
                print(f"{path.name}:{c.line}: exit {code}, {time.perf_counter() - began:.1f} s")
                if not matches(normalised(out, cwd), normalised(c.expected)):
                    shown = normalised(out, cwd, timings=False)
                    new = replace_output(new, c, excerpt_of(shown, c.expected))
            if new != text:
                path.write_text(new, encoding="utf-8")
        shutil.rmtree(cwd, ignore_errors=True)


def replace_output(text: str, c: DocCommand, printed: str) -> str:
    """The page's text with the output under command ``c`` (up to the next command or the
    block's fence) replaced by ``printed``."""
    lines = text.split("\n")
    k = c.line - 1
    while lines[k].endswith("\\"):
        k += 1
    end = k + 1
    while end < len(lines) and not lines[end].startswith(("$ ", "```")):
        end += 1
    return "\n".join([*lines[: k + 1], printed, *lines[end:]])


if __name__ == "__main__":
    regenerate()
