"""A project file's sections stay inside its folder (issue 34, F2).

On main, ``[[project.sections]]`` read a file from anywhere — an absolute path, ``..``, a
symlink out of the folder, ``/proc/self/environ`` — and put it in the HTML, PDF and DOCX with
exit 0: the process's environment, tokens included, in a document meant to be filed. Now a
section's file must resolve inside the project file's folder unless ``--allow-outside``, and a
pipe, a device or a file of ``/proc`` is refused even then: one line, exit 2, no output file.

The refusals run ``rock`` in a child process (its own environment holds the secret, which
``/proc/self/environ`` would show) under a memory limit and a timeout, in its own process
group killed in a ``finally``: a FIFO that blocked the read fails the test instead of hanging
it.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from rockcli.cli.main import cli
from rockcli.document.project import load_project
from tests.limited import run_rock

ROOT = Path(__file__).resolve().parents[2]
ALTAR = ROOT / "examples" / "altar.toml"
RICKER = ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"
#: What a section outside the folder holds; it must reach no output and no message.
SECRET = "F2-SECRET-TOKEN-d41d8cd98f00b204"
#: The message's end when a section leaves the folder.
INSIDE = "allowed: a file inside the project file's folder, or --allow-outside)"
#: Address space of the child [bytes], and the seconds a refusal may take.
MEMORY_LIMIT = 2 << 30
TIMEOUT = 60.0
HEAD = '[project]\nclient = "C"\nsubject = "S"\ncomune = "M"\ndesigner = "D"\n'

pytestmark = pytest.mark.skipif(
    not sys.platform.startswith("linux"), reason="needs /proc and FIFOs"
)


def rock(*args: str, cwd: Path) -> tuple[int, str, str]:
    """``rock ARGS`` in a child whose environment holds :data:`SECRET` (tests/limited.py):
    (code, stdout, stderr)."""
    done = run_rock(*args, memory=MEMORY_LIMIT, timeout=TIMEOUT, cwd=cwd,
                    env={"F2_TOKEN": SECRET}, columns=400)  # fmt: skip
    return done.code, done.out, done.err


def project(folder: Path, section: str) -> Path:
    """``folder/p.toml``, one section whose file is ``section``."""
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "p.toml"
    path.write_text(HEAD + f'[[project.sections]]\ntitle = "T"\nfile = "{section}"\n',
                    encoding="utf-8")  # fmt: skip
    return path


def report_args(extra: tuple[str, ...] = ()) -> list[str]:
    """A report with every output (HTML, PDF, DOCX) of the project ``p.toml``."""
    return ["report", str(ALTAR), "--record", str(RICKER), "--project", "p.toml",
            "--casebook", "none", "-o", "r.html", "--pdf", "r.pdf", "--docx", "r.docx",
            *extra]  # fmt: skip


def refused(folder: Path, *extra: str) -> str:
    """Run the report in ``folder``: exit 2, one line naming the file and the key, no output
    file, the secret nowhere; the line."""
    code, out, err = rock(*report_args(extra), cwd=folder)
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("error: p.toml: project.sections[0].file: "), err
    assert SECRET not in out + err
    assert not any((folder / f"r.{kind}").exists() for kind in ("html", "pdf", "docx"))
    return lines[0]


@pytest.fixture
def outside(tmp_path: Path) -> Path:
    """A Markdown file holding the secret, in a folder beside the project's."""
    path = tmp_path / "elsewhere" / "secret.md"
    path.parent.mkdir()
    path.write_text(f"# Secret\n\n{SECRET}\n", encoding="utf-8")
    return path


def test_an_absolute_path_outside_is_refused(tmp_path: Path, outside: Path) -> None:
    folder = tmp_path / "project"
    project(folder, str(outside))
    line = refused(folder)
    assert f"leaves the project file's folder (got '{outside}'; {INSIDE}" in line


def test_dot_dot_is_refused(tmp_path: Path, outside: Path) -> None:
    folder = tmp_path / "project"
    project(folder, "../elsewhere/secret.md")
    line = refused(folder)
    assert f"(got '../elsewhere/secret.md'; {INSIDE}" in line


def test_a_symlink_out_of_the_folder_is_refused(tmp_path: Path, outside: Path) -> None:
    folder = tmp_path / "project"
    project(folder, "notes.md")
    (folder / "notes.md").symlink_to(outside)
    line = refused(folder)
    assert f"(got 'notes.md'; {INSIDE}" in line


def test_proc_self_environ_is_refused_even_with_allow_outside(tmp_path: Path) -> None:
    folder = tmp_path / "project"
    project(folder, "/proc/self/environ")
    assert f"(got '/proc/self/environ'; {INSIDE}" in refused(folder)
    line = refused(folder, "--allow-outside")
    assert "a file of the kernel (/proc, /sys)" in line
    # Through a link inside the folder, the same.
    project(folder, "env.md")
    (folder / "env.md").symlink_to("/proc/self/environ")
    assert "a file of the kernel" in refused(folder, "--allow-outside")


def test_a_fifo_is_refused_without_blocking(tmp_path: Path) -> None:
    folder = tmp_path / "project"
    project(folder, "pipe.md")
    os.mkfifo(folder / "pipe.md")
    for extra in ((), ("--allow-outside",)):
        line = refused(folder, *extra)
        assert "not a regular file (a named pipe)" in line, extra


def test_a_section_inside_the_folder_is_read(tmp_path: Path) -> None:
    # A subfolder, and a link that stays inside the folder.
    folder = tmp_path / "project"
    (folder / "text").mkdir(parents=True)
    (folder / "text" / "premessa.md").write_text("Testo della premessa.\n", encoding="utf-8")
    (folder / "link.md").symlink_to(Path("text") / "premessa.md")
    for section in ("text/premessa.md", "./text/../link.md"):
        got = load_project(project(folder, section))
        assert got.sections == (("T", "Testo della premessa.\n"),), section
    html = folder / "r.html"
    result = CliRunner().invoke(cli, ["report", str(ALTAR), "--record", str(RICKER),
                                      "--project", str(folder / "p.toml"), "--casebook", "none",
                                      "-o", str(html)])  # fmt: skip
    assert result.exit_code == 0, result.stderr
    assert "Testo della premessa." in html.read_text(encoding="utf-8")


def test_allow_outside_lets_a_regular_file_outside_through(tmp_path: Path, outside: Path) -> None:
    pytest.importorskip("jinja2")
    folder = tmp_path / "project"
    path = project(folder, str(outside))
    html = folder / "r.html"
    args = ["report", str(ALTAR), "--record", str(RICKER), "--project", str(path),
            "--casebook", "none", "-o", str(html)]  # fmt: skip
    result = CliRunner().invoke(cli, [*args, "--allow-outside"])
    assert result.exit_code == 0, result.stderr
    assert SECRET in html.read_text(encoding="utf-8")  # the user chose to let it in


def test_allow_outside_needs_a_suite_or_a_project(tmp_path: Path) -> None:
    args = ["report", str(ALTAR), "--record", str(RICKER), "-o", str(tmp_path / "r.html")]
    result = CliRunner().invoke(cli, [*args, "--allow-outside"])
    assert result.exit_code == 2
    assert "--allow-outside: applies only to a suite or a project file" in result.stderr


def test_a_file_that_says_0_bytes_but_holds_some_is_refused(monkeypatch) -> None:
    # A pseudo file system the device test would not know (a /proc mounted elsewhere): its
    # files report st_size 0 whatever they hold.
    from rockcli.document import project as module
    from rockcli.document.project import read_markdown
    from rockcli.errors import InputError

    monkeypatch.setattr(module, "kernel_file", lambda device: False)
    with pytest.raises(InputError, match="its size says 0 bytes but it holds some"):
        read_markdown(Path("/proc/self/status"))
