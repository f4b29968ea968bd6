"""How a rock process ends: quickly, without collecting numba's object graph; and, for the
worker processes of a study, with the process that started them, never on Ctrl-C.

Kept light (no numpy, numba or pydantic): the fork server of a study imports it first, before
its heavy imports, to check that `rock sweep` is still there.
"""

from __future__ import annotations

import atexit
import gc
import os
import signal
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager

#: The pid of the `rock sweep` process that starts a study's worker processes, set in its
#: environment before it starts the fork server (or spawns a worker), so that they know their
#: creator without asking their parent after a second of imports, when it may be gone.
CREATOR_ENV = "ROCK_SWEEP_CREATOR"
#: The fork server's pid, in its environment, for the workers it forks (their parent).
SERVER_ENV = "ROCK_SWEEP_SERVER"
#: Seconds between two looks of a worker at its parent (how soon an orphan exits).
PARENT_POLL = 0.5
#: Linux prctl option: the signal a process gets when its parent thread ends (<linux/prctl.h>).
PR_SET_PDEATHSIG = 1


def quick_exit() -> None:
    """At exit, freeze the objects instead of collecting them.

    The interpreter's last garbage collections walk numba's large object graph: 0.2–0.4 s at
    the exit of every process that loaded the kernels, measured on this machine (`rock assess`:
    0.88 s to the end of the command, 1.08 s to the end of the process), which the user and a
    pool's shutdown wait for. Frozen objects are left to the OS; objects freed by reference
    counting (open files, flushed as usual) are not affected.
    """
    atexit.register(gc.freeze)


def interrupted(exc: BaseException | None) -> bool:
    """True for Ctrl-C: a KeyboardInterrupt, or an error it caused on its way out.

    A KeyboardInterrupt raised while numba's dispatcher runs a compiled function comes out as
    ``SystemError: CPUDispatcher(…) returned a result with an exception set``, with the
    KeyboardInterrupt as its ``__context__``; an error raised while handling the interrupt
    carries it the same way. Both end the command as an interrupt (exit 130), not as an
    internal error.
    """
    seen: set[int] = set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, KeyboardInterrupt):
            return True
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return False


def ignore_interrupts() -> None:
    """Ignore Ctrl-C in this process (a study's worker or fork server): the terminal sends
    SIGINT to the whole process group, and `rock sweep` alone handles it (it stops the
    workers, saves what is done and prints one line)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


@contextmanager
def interrupts_blocked() -> Iterator[None]:
    """Hold Ctrl-C back in this thread for the block: a process started in it starts with
    SIGINT blocked (the mask is inherited across fork and exec), so it cannot be interrupted
    before it ignores SIGINT; here the signal is delivered when the block ends (as the
    standard library's resource tracker is started)."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def creator_pid() -> int | None:
    """The pid :data:`CREATOR_ENV` holds (None when absent or not a pid)."""
    text = os.environ.get(CREATOR_ENV, "")
    return int(text) if text.isascii() and text.isdigit() else None


def die_with_creator() -> bool:
    """For the fork server: SIGKILL when `rock sweep` (its parent) ends, whatever ends it.

    Linux sends it when the parent thread ends (prctl PR_SET_PDEATHSIG); the server stays
    single-threaded (it forks the workers), so no watcher thread. The parent is then checked
    against :data:`CREATOR_ENV`: a parent already gone (the server adopted by init) ends the
    server at once. False where prctl is not available (not Linux).
    """
    armed = set_death_signal()
    creator = creator_pid()
    if creator is not None and os.getppid() != creator:
        os._exit(1)
    return armed


def set_death_signal() -> bool:
    """Ask Linux to SIGKILL this process when its parent thread ends; False where prctl is
    not available."""
    import ctypes

    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        return bool(libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0) == 0)
    except (OSError, AttributeError):
        return False


def expected_parent() -> int | None:
    """The parent a study's worker must have: the fork server that forked it
    (:data:`SERVER_ENV`), or `rock sweep` that spawned it (:data:`CREATOR_ENV`)."""
    text = os.environ.get(SERVER_ENV, "")
    return int(text) if text.isascii() and text.isdigit() else creator_pid()


def exit_with_parent(parent: int | None = None) -> None:
    """End this process when its parent ends, whatever killed the parent (even SIGKILL).

    parent: the pid the parent must have (default: the present one). A process whose parent
    is not that one already exits at once; then a daemon thread looks at os.getppid() every
    PARENT_POLL s: an orphan is re-parented (to init or a subreaper), so a changed parent id
    means the parent is gone.
    """
    expected = os.getppid() if parent is None else parent
    if os.getppid() != expected:
        os._exit(1)

    def watch() -> None:
        while os.getppid() == expected:
            time.sleep(PARENT_POLL)
        os._exit(1)

    threading.Thread(target=watch, name="rock-parent-watch", daemon=True).start()


def exit_at_once(code: int) -> None:
    """End the process now with ``code``, the output flushed, without the interpreter's exit.

    For an interrupted command, whose work is stopped and whose files are closed: nothing is
    waited for (a case still running in a thread, a worker pool's joins, a worker starting).
    multiprocessing's resource tracker removes the pools' semaphores once every process that
    uses them has ended (silently: :func:`start_resource_tracker`).
    """
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError, AttributeError):
            pass
    os._exit(code)


def start_resource_tracker() -> None:
    """Start multiprocessing's resource tracker with its standard error on the null device.

    It warns there ("There appear to be N leaked semaphore objects to clean up") when it
    removes the semaphores of a pool whose process ended without its finalizers — a `rock
    sweep` interrupted (:func:`exit_at_once`) or killed: lines about multiprocessing's
    internals, not for the user. Nothing else writes to standard error meanwhile (the main
    thread starts it, before the study's threads).
    """
    from multiprocessing import resource_tracker

    try:
        sys.stderr.flush()
        saved = os.dup(2)
    except (OSError, ValueError, AttributeError):  # no standard error to save
        resource_tracker.ensure_running()
        return
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 2)
        resource_tracker.ensure_running()
    finally:
        os.dup2(saved, 2)
        os.close(saved)
        os.close(devnull)
