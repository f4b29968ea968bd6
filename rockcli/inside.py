"""Where a file named by another file may be: inside that file's folder.

A study or a suite names other files (a base model, records). Received from someone else (a
pull request, an e-mail), it could name any file of the machine — ``/etc/passwd``,
``../../.ssh/id_rsa``, a symlink planted beside it — and rock would read it and quote it back
in an error. So the paths such a file names must stay inside its folder, after resolving
``..`` and every symlink, unless the user lifts the rule (``--allow-outside``): the studies
(rockcli.studies.sweep.study) and the suites (rockcli.suites.load) share this check.
"""

from __future__ import annotations

from pathlib import Path

from rockcli.errors import InputError

#: What a path the system refuses is allowed to be instead.
PATH_ALLOWED = "a path the file system accepts (no NUL character, each name at most 255 bytes)"


def check_inside(
    path: Path, folder: Path, *, file: str, where: str, value: str, problem: str, allowed: str
) -> None:
    """InputError (``problem``, ``allowed``) when ``path`` resolves outside ``folder``.

    Args:
        path: the path as the file names it, joined to the folder it is relative to.
        folder: the folder it must stay in.
        file: the file that names it (for the message); where: its key; value: as written.
    """
    try:
        inside = path.resolve().is_relative_to(folder.resolve())
    except (OSError, ValueError) as exc:  # a NUL character, a name too long, a loop
        raise path_error(exc, file, where) from None
    if not inside:
        raise InputError(problem, file=file, where=where, value=value, allowed=allowed)


def path_error(exc: OSError | ValueError, file: str | None, where: str | None) -> InputError:
    """A path the system refuses, as one error naming the key of the file that names it."""
    reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else str(exc)
    return InputError(
        f"cannot use this path: {reason}", file=file, where=where, allowed=PATH_ALLOWED
    )
