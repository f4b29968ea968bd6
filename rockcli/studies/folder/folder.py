"""The output folder of a study: checked, locked, written without following links, resumed.

Every command that writes a study folder (`rock sweep`, `rock fragility`) uses this one class,
so that they all behave alike:

- ``--out`` is checked before any work: a file in its place, an unwritable parent, a symbolic
  link leading out of the current folder (a link planted at the default folder name would send
  the results elsewhere) are refused in one line;
- one run at a time writes into it (:mod:`rockcli.studies.folder.lock`);
- the state file names the study by a fingerprint of the *contents* of its inputs (the
  study's own digest, records by their bytes), never their paths: a folder copied or moved
  resumes, a record edited since does not;
- every file is written through a new temporary file beside it and renamed onto its name
  (rockcli.outfile: a link planted at ``cases.csv.tmp`` or at the name itself is never
  followed); the rows file is appended to with O_NOFOLLOW;
- on ``--resume`` the rows file is read back line by line and every line checked by the
  study's own rule (:attr:`StudyFolder.row_problem`): a damaged line is one error naming it,
  never a silent gap or a wrong row kept;
- a write that fails (a full disk) is bad input (exit 2) saying how much is on disk and to
  rerun with ``--resume``, and leaves a folder that resumes.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import os
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import Any, NoReturn

from rockcli.errors import InputError
from rockcli.outfile import write_text
from rockcli.studies.folder.lock import (
    LOCK_FILE,
    FolderBusy,
    NotALockFile,
    lock_folder,
    unlock_folder,
)

#: Bytes read at a time when hashing a file.
HASH_BLOCK = 1 << 20
#: The name of the rows file.
CASES_FILE = "cases.csv"

#: What is wrong with a row of the rows file (its cells, its line number), or None.
RowProblem = Callable[[Sequence[str]], str | None]


def file_digest(path: str) -> str:
    """The sha256 of a file's bytes (a record edited at the same size changes it); a regular
    file only (rockcli.textfile.open_regular: a FIFO named by a study would block)."""
    from rockcli.textfile import open_regular

    digest = hashlib.sha256()
    with os.fdopen(open_regular(path, "input file"), "rb") as fh:
        for block in iter(lambda: fh.read(HASH_BLOCK), b""):
            digest.update(block)
    return digest.hexdigest()


def source_digest(path: str, *, suite: bool) -> str:
    """The sha256 of a record file; of a suite file, over its bytes and its records' (a
    record of the suite edited changes the study's results)."""
    if not suite:
        return file_digest(path)
    from rockcli.suites.load import load_suite

    parts = [file_digest(path)]
    entries = load_suite(path, allow_outside=True).entries  # checked by the study's reader
    parts += [file_digest(str(e.path)) for e in entries]
    return hashlib.sha256(" ".join(parts).encode()).hexdigest()


def record_identities(records: Iterable[Any]) -> list[dict[str, Any]]:
    """Each record source of a study (a dataclass with ``path`` and ``suite``) as its fields
    with its file's name for its path and the sha256 of its bytes: what a fingerprint holds
    of it (a folder moved resumes; a record edited does not)."""
    from dataclasses import asdict

    return [
        {**asdict(r), "path": Path(r.path).name, "sha256": source_digest(r.path, suite=r.suite)}
        for r in records
    ]


def digest_of(facts: Any) -> str:
    """The sha256 of facts made of JSON values (anything else by its str)."""
    text = json.dumps(facts, sort_keys=True, default=str)
    return hashlib.sha256(text.encode("utf-8", "surrogateescape")).hexdigest()


class PartialWrite(OSError):
    """A write that failed part-way; ids: the rows whose whole line is in the file."""

    def __init__(self, exc: OSError, ids: list[int]) -> None:
        super().__init__(exc.errno, exc.strerror)
        self.ids = ids


def write_all(fd: int, data: bytes, saved: Callable[[int], list[int]]) -> None:
    """Write every byte of data (os.write may write part of it); on an error, PartialWrite
    with ``saved(bytes written)``."""
    view = memoryview(data)
    written = 0
    while written < len(data):
        try:
            written += os.write(fd, view[written:])
        except OSError as exc:
            raise PartialWrite(exc, saved(written)) from exc


def whole_lines(lines: Sequence[bytes], written: int) -> int:
    """How many of the lines the first ``written`` bytes of their concatenation hold whole."""
    count = end = 0
    for line in lines:
        end += len(line)
        if end > written:
            break
        count += 1
    return count


def csv_text(rows: Iterable[Sequence[str]]) -> str:
    """CSV text of rows of cells (\\n line ends)."""
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(rows)
    return buffer.getvalue()


class StudyFolder:
    """The output folder of one study run.

    Args:
        folder: the folder (``--out``).
        command: the command that writes it (``rock sweep``), for the messages.
        state_file: the state file's name. header: the rows file's columns.
        fingerprint: the digest of everything that decides the study's rows.
        row_problem: what is wrong with a row read back on resume (None: nothing).
    """

    def __init__(
        self,
        folder: str | Path,
        *,
        command: str,
        state_file: str,
        header: Sequence[str],
        fingerprint: str,
        row_problem: RowProblem | None = None,
    ) -> None:
        self.folder = Path(folder)
        self.command = command
        self.state_path = self.folder / state_file
        self.header = list(header)
        self.fingerprint = fingerprint
        self.row_problem = row_problem

    @property
    def cases_path(self) -> Path:
        return self.folder / CASES_FILE

    # -- before any work ---------------------------------------------------------------------

    @contextmanager
    def lock(self) -> Iterator[None]:
        """The folder checked, made and locked for the block: no other run writes into it
        meanwhile (InputError naming the pid of the one that holds it). A folder this run
        made is removed again when the run is refused before it wrote anything."""
        self.check_writable()
        created = not self.folder.exists()
        self.make_folder()
        fd = self._take_lock()
        try:
            yield
        except BaseException:
            unlock_folder(self.folder, fd)
            if created:
                with suppress(OSError):
                    self.folder.rmdir()
            raise
        unlock_folder(self.folder, fd)

    def _take_lock(self) -> int | None:
        try:
            return lock_folder(self.folder)
        except FolderBusy as exc:
            pid = f" (pid {exc.pid})" if exc.pid is not None else ""
            self.refuse(
                f"is in use by another {self.command}{pid}",
                "another --out, or wait until that run ends",
            )
        except (NotALockFile, OSError) as exc:
            reason = (
                exc.strerror if isinstance(exc, OSError) and exc.strerror else "not a regular file"
            )
            self.refuse(f"cannot be locked ({LOCK_FILE}: {reason})", f"remove {LOCK_FILE}")

    def check_writable(self) -> None:
        """Refuse a folder path that cannot be used: a name the system refuses, a file, a
        link out of the current folder, an unwritable place."""
        folder = self.folder
        try:
            os.stat(folder)  # a name too long, a loop of links: refused here, not later
        except FileNotFoundError:
            pass
        except OSError as exc:
            self.refuse(f"cannot be used: {exc.strerror or exc}", "a shorter, plain folder path")
        if folder.exists() and not folder.is_dir():
            self.refuse("is a file", "a folder path")
        self._check_link()
        target = folder if folder.is_dir() else _existing_parent(folder)
        if not os.access(target, os.W_OK | os.X_OK):
            self.refuse(f"cannot be written ({target} is not writable)", "a writable folder")

    def _check_link(self) -> None:
        """Refuse an output folder that is a symbolic link leading out of the current folder
        (a link planted at the default folder name would send the results elsewhere)."""
        if not self.folder.is_symlink():
            return
        if not self.folder.resolve().is_relative_to(Path.cwd().resolve()):
            self.refuse(
                f"is a symbolic link to {self.folder.resolve()}, outside the current folder",
                "the folder itself as --out, or a link to a folder inside the current one",
            )

    def make_folder(self) -> None:
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            self.refuse(f"cannot be made: {exc.strerror or exc}", "a writable folder path")

    def keeps(self, *, resume: bool, overwrite: bool) -> bool:
        """Before any work: the folder may be used. True when the rows on disk are this
        study's and are to be kept (``resume``); the folder is refused when it holds rows rock
        did not write, another study's, or an unfinished run of this one (without
        ``resume`` or ``overwrite``)."""
        self.check_writable()
        state = self.read_state() if self.cases_path.exists() else None
        same = state is not None and state.get("fingerprint") == self.fingerprint
        if overwrite:
            return False
        if state is None:
            if self.cases_path.exists():
                self.refuse(
                    f"holds a {CASES_FILE} of another run (no {self.state_path.name}: not "
                    f"{self.command}'s)",
                    "another --out, or --force to start over in it",
                )
            return False
        if not same:
            self.refuse(
                "holds the results of another study (or its model, records, options or rock "
                "changed since)",
                "--force to start over, or another --out",
            )
        if not resume and not state.get("complete"):
            self.refuse(
                "holds an unfinished run of this study",
                "--resume to continue it, or --force to start over",
            )
        return resume

    def refuse(self, problem: str, allowed: str) -> NoReturn:
        raise InputError(
            f"the output folder {problem}", file=str(self.folder), where="--out", allowed=allowed
        )

    # -- the state file ----------------------------------------------------------------------

    def read_state(self) -> dict[str, Any] | None:
        """The state file's content (None when absent or not a JSON object)."""
        try:
            state = json.loads(self.state_path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        return state if isinstance(state, dict) else None

    def write_state(self, *, complete: bool, **facts: Any) -> None:
        """The state file: the fingerprint, the columns, whether the study is complete."""
        state = {**facts, "fingerprint": self.fingerprint, "columns": self.header}
        self.write_file(self.state_path.name, json.dumps({**state, "complete": complete}, indent=2))

    def write_file(self, name: str, text: str, *, saved: str = "") -> None:
        """A file of the folder written whole (temporary file beside it, then renamed; a link
        at either name never followed); InputError when the disk refuses (saying ``saved``:
        what is on disk)."""
        self.make_folder()
        try:
            write_text(self.folder / name, text)
        except InputError as exc:
            raise self.unwritable(str(exc.value), saved) from None

    def unwritable(self, reason: str, saved: str) -> InputError:
        """The error of a write that failed (a full disk, a folder turned read-only): bad
        input, with how much is on disk (``saved``) and how to go on."""
        return InputError(
            f"cannot write the output folder: {reason}{'; ' + saved if saved else ''}",
            file=str(self.folder),
            where="--out",
            allowed="a writable folder with free space, then rerun with --resume",
        )

    # -- the rows file -----------------------------------------------------------------------

    def read_lines(self) -> list[list[str]]:
        """The rows of the rows file after its header (a half-written last line is dropped).

        Every other line must be a row this study wrote: the header, then rows that pass
        :attr:`row_problem`. A damaged file is an InputError naming its line (start over with
        --force), never a silent gap.
        """
        try:
            text = self.cases_path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            self.damaged(None, f"cannot be read ({exc.__class__.__name__})")
        lines = text.splitlines(keepends=True)
        if lines and not lines[-1].endswith("\n"):
            lines.pop()  # interrupted in the middle of a line
        try:
            rows = list(csv.reader(lines, strict=True))
        except csv.Error as exc:
            self.damaged(None, f"is not valid CSV ({exc})")
        if not rows or rows[0] != self.header:
            self.damaged(1, "the header is not this study's columns")
        for number, row in enumerate(rows[1:], start=2):
            problem = self._problem(row)
            if problem:
                self.damaged(number, problem)
        return rows[1:]

    def _problem(self, row: Sequence[str]) -> str | None:
        if len(row) != len(self.header):
            return f"{len(row)} cells, not {len(self.header)}"
        return self.row_problem(row) if self.row_problem is not None else None

    def damaged(self, line: int | None, problem: str) -> NoReturn:
        raise InputError(
            f"cannot resume: {CASES_FILE} {problem}",
            file=str(self.cases_path),
            where=f"line {line}" if line else None,
            allowed=f"a {CASES_FILE} written by {self.command}, or --force to start over",
        )

    def rewrite(self, rows: Iterable[Sequence[str]], *, saved: str = "") -> None:
        """The rows file with the header and the given rows (atomically: a full disk leaves
        the old file whole; ``saved``: what it holds, for the error)."""
        self.write_file(CASES_FILE, csv_text([self.header, *rows]), saved=saved)

    def append_bytes(self, ids: list[int], lines: Sequence[bytes]) -> int:
        """Append the lines of completed cases (ids: each line's case); returns the offset
        in the file they start at.

        A write that fails part-way (a full disk) raises :class:`PartialWrite` with the ids of
        the rows whose whole line reached the file (--resume keeps those).
        """
        data = b"".join(lines)
        flags = os.O_WRONLY | os.O_APPEND | getattr(os, "O_NOFOLLOW", 0)  # never via a link
        fd = os.open(self.cases_path, flags)
        try:
            offset = os.fstat(fd).st_size
            write_all(fd, data, lambda written: ids[: whole_lines(lines, written)])
        finally:
            os.close(fd)
        return offset


def _existing_parent(path: Path) -> Path:
    """The nearest folder above path that exists (where the output folder will be made)."""
    for parent in path.absolute().parents:
        if parent.is_dir():
            return parent
    return Path(".")
