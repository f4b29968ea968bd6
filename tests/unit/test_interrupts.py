"""rockcli.interrupts: SIGINT deferred around compiled calls, raised between them (issue 20, 7).

A timer thread sends SIGINT to this process while the main thread is inside a compiled call
(the response-spectrum kernel on a long load, about 0.3 s): the call completes, and
KeyboardInterrupt is raised when the deferred block ends, or at the first check() between
chunks; outside compiled code SIGINT raises at once, as Python's default handler does. A
process that ignores SIGINT (a sweep's worker) keeps ignoring it.
"""

from __future__ import annotations

import os
import signal
import threading
import time
from collections.abc import Iterator

import numpy as np
import pytest

from rockcli import interrupts
from rockcli.codecheck.response import CHUNK_SAMPLES, peak_displacement_uniform, step_coefficients
from rockcli.codecheck.response_kernel import peak_response

pytestmark = pytest.mark.skipif(not hasattr(signal, "pthread_kill"), reason="POSIX signals")


@pytest.fixture(autouse=True)
def _default_handler() -> Iterator[None]:
    """Each test starts and ends with Python's default SIGINT handler."""
    signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, signal.default_int_handler)


def assert_sigint_raises_at_once() -> None:
    """Outside compiled code SIGINT is KeyboardInterrupt right away (Python's default)."""
    with pytest.raises(KeyboardInterrupt):
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(1.0)
    interrupts.check()  # nothing left pending


#: A load long enough that one compiled call over 40 periods lasts about 0.3 s.
SAMPLES = 1_500_000
PERIODS = 40


def load() -> np.ndarray:
    t = np.arange(SAMPLES) * 0.01
    return np.ascontiguousarray(np.sin(2 * np.pi * t) * 3.0)


def sigint_after(seconds: float) -> threading.Timer:
    """SIGINT to this process after `seconds`, from another thread (as a terminal sends it)."""
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_sigint_inside_a_compiled_call_waits_for_its_end() -> None:
    omega = 2 * np.pi / np.linspace(0.1, 4.0, PERIODS)
    coefficients = np.ascontiguousarray(np.array(step_coefficients(0.01, omega, 0.05)))
    p = load()
    start = time.monotonic()
    expected = peak_response(p, coefficients)[0]
    duration = time.monotonic() - start
    assert duration > 0.1  # the signal below comes inside the call
    peak = None
    timer = sigint_after(0.02)
    with pytest.raises(KeyboardInterrupt):
        with interrupts.deferred():
            peak = peak_response(p, coefficients)[0]
            returned = time.monotonic()
        pytest.fail("the SIGINT was lost")
    timer.join()
    assert peak is not None  # the call ran whole, then the interrupt came
    np.testing.assert_array_equal(peak, expected)
    assert time.monotonic() - returned < 0.05  # raised at the end of the block, not later
    assert_sigint_raises_at_once()


def test_call_defers_sigint_to_the_return_of_the_function() -> None:
    timer = sigint_after(0.02)
    with pytest.raises(KeyboardInterrupt):
        interrupts.call(time.sleep, 0.2)  # the handler runs in the sleep: it only notes it
    timer.join()
    assert_sigint_raises_at_once()


def test_the_spectrum_loop_stops_between_chunks() -> None:
    # Chunks of CHUNK_SAMPLES // SAMPLES = 3 periods: 2000 periods would take minutes, the
    # interrupt ends the loop at the next chunk.
    assert CHUNK_SAMPLES // SAMPLES >= 1
    omega = 2 * np.pi / np.linspace(0.01, 4.0, 2000)
    timer = sigint_after(0.2)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        peak_displacement_uniform(load(), 0.01, omega, 0.05)
    timer.join()
    assert time.monotonic() - start < 5.0
    assert_sigint_raises_at_once()


def test_a_process_that_ignores_sigint_keeps_ignoring_it() -> None:
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        with interrupts.deferred():
            os.kill(os.getpid(), signal.SIGINT)
            assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
        interrupts.check()  # nothing pending: no KeyboardInterrupt
    finally:
        signal.signal(signal.SIGINT, previous)


def test_nested_blocks_raise_once_at_the_outermost_end() -> None:
    with pytest.raises(KeyboardInterrupt):
        with interrupts.deferred():
            with interrupts.deferred():
                os.kill(os.getpid(), signal.SIGINT)
                time.sleep(0.05)  # the handler runs here: it only sets the flag
    interrupts.check()  # raised once: nothing left pending
    assert_sigint_raises_at_once()
