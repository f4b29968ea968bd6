"""Ctrl-C around compiled code: a flag while numba runs, a KeyboardInterrupt between its calls.

Python's own SIGINT handler raises KeyboardInterrupt wherever the interpreter next checks for
signals. Inside a numba-compiled function that point can be in the middle of the compiled
code (the runtime checks for signals where it calls back into the C API), which the compiled
code does not expect: `rock record spectrum` interrupted during its loop over periods ended in
SIGSEGV (6 tries in 8) or in ``SystemError: CPUDispatcher(peak_response) returned a result
with an exception set``, never in the one line and exit 130 of an interrupt.

Within :func:`deferred`, SIGINT only sets a flag. The long compiled loops run in chunks (the
response spectra: a few periods per call) or in one call per run (the rocking engine: one
polarity), and :func:`check` between the calls, or the end of the block, raises
KeyboardInterrupt in Python, where the CLI turns it into "interrupted" and exit 130. Used by
every compiled loop the CLI runs in its main process: :mod:`rockcli.codecheck.response`
(record spectra, suites' and floors' spectra, the code check's demand) and
:mod:`rockcli.dynamics.simulate` (each rocking run, the tolerance check's included).

Only the standard library; silent. A process whose SIGINT is not Python's default (a worker
that ignores it, a host application with its own handler) is left as it is, and so is any
thread but the main one (only it may set handlers).
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, TypeVar

T = TypeVar("T")

#: A SIGINT arrived inside :func:`deferred` and has not been raised yet.
_pending = False
#: Nesting depth of :func:`deferred` (only the outermost installs and restores the handler).
_depth = 0


def _note(signum: int, frame: object) -> None:
    """The SIGINT handler inside :func:`deferred`: remember it, raise nothing."""
    global _pending
    _pending = True


def _ours_to_defer() -> bool:
    """True when this thread may install a handler and SIGINT has Python's default one."""
    return (
        threading.current_thread() is threading.main_thread()
        and signal.getsignal(signal.SIGINT) is signal.default_int_handler
    )


@contextmanager
def deferred() -> Iterator[None]:
    """Within: SIGINT sets a flag; at the end, or at :func:`check`, KeyboardInterrupt."""
    global _depth, _pending
    if _depth == 0 and not _ours_to_defer():
        yield
        return
    _depth += 1
    previous = signal.signal(signal.SIGINT, _note) if _depth == 1 else None
    try:
        yield
    finally:
        _depth -= 1
        if _depth == 0:
            signal.signal(signal.SIGINT, previous)
            if _pending:
                _pending = False
                raise KeyboardInterrupt


def check() -> None:
    """Raise KeyboardInterrupt now if a SIGINT arrived inside :func:`deferred` (call it between
    compiled calls)."""
    global _pending
    if _pending:
        _pending = False
        raise KeyboardInterrupt


def call(function: Callable[..., T], *args: Any) -> T:
    """``function(*args)`` (a compiled function) with SIGINT deferred to its return."""
    with deferred():
        return function(*args)
