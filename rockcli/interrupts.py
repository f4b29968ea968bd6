"""Ctrl-C around compiled code: a flag while numba runs, a KeyboardInterrupt between its calls.

Python's own SIGINT handler raises KeyboardInterrupt wherever the interpreter next checks for
signals. Inside a numba-compiled function that point can be in the middle of the compiled
code (the runtime checks for signals where it calls back into the C API), which the compiled
code does not expect: `rock record spectrum` interrupted during its loop over periods ended in
SIGSEGV (6 tries in 8) or in ``SystemError: CPUDispatcher(peak_response) returned a result
with an exception set``, never in the one line and exit 130 of an interrupt.

While compiled code runs (within :func:`deferred` or :func:`call`), SIGINT only sets a flag.
The long compiled loops run in chunks (the response spectra: a few periods per call) or in
one call per run (the rocking engine: one polarity), and :func:`check` between the calls, or
the end of the block, raises KeyboardInterrupt in Python, where the CLI turns it into
"interrupted" and exit 130. Used by every compiled loop the CLI runs in its main process:
:mod:`rockcli.codecheck.response` (record spectra, suites' and floors' spectra, the code
check's demand) and :mod:`rockcli.dynamics.simulate` (each rocking run, the tolerance check's
included).

The handler is installed at the first use, in place of Python's default one, and stays:
outside compiled code it raises KeyboardInterrupt as the default handler does (installing
and restoring a handler around each run cost 5 µs, 3 % of a short run). A process whose
SIGINT is not Python's default (a worker that ignores it, a host application with its own
handler) is left as it is, and so is any thread but the main one (only it may set handlers).
Only the standard library; silent.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, TypeVar

T = TypeVar("T")

#: A SIGINT arrived while compiled code ran and has not been raised yet.
_pending = False
#: Nesting depth of the blocks that run compiled code (0: Python code, SIGINT raises at once).
_inside = 0


def _on_sigint(signum: int, frame: object) -> None:
    """SIGINT: noted while compiled code runs, else KeyboardInterrupt (Python's default)."""
    global _pending
    if _inside:
        _pending = True
    else:
        raise KeyboardInterrupt


def _take_over() -> bool:
    """True when SIGINT is ours to defer: our handler is in place, or Python's default one is
    (then replaced by ours), in the main thread."""
    current = signal.getsignal(signal.SIGINT)
    if current is _on_sigint:
        return True
    if current is not signal.default_int_handler:
        return False
    if threading.current_thread() is not threading.main_thread():
        return False
    signal.signal(signal.SIGINT, _on_sigint)
    return True


@contextmanager
def deferred() -> Iterator[None]:
    """Within: SIGINT sets a flag; at the end, or at :func:`check`, KeyboardInterrupt."""
    global _inside
    if not _inside and not _take_over():
        yield
        return
    _inside += 1
    try:
        yield
    finally:
        _inside -= 1
    if not _inside:
        check()


def check() -> None:
    """Raise KeyboardInterrupt now if a SIGINT arrived while compiled code ran (call it between
    compiled calls)."""
    global _pending
    if _pending:
        _pending = False
        raise KeyboardInterrupt


def call(function: Callable[..., T], *args: Any) -> T:
    """``function(*args)`` (a compiled function) with SIGINT deferred to its return.

    :func:`deferred` written out: one call per rocking run, the context manager's own cost
    (2 µs) saved.
    """
    global _inside
    if not _inside and not _take_over():
        return function(*args)
    _inside += 1
    try:
        result = function(*args)
    finally:
        _inside -= 1
    if not _inside:
        check()
    return result
