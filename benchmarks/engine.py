"""Benchmark: the fast engine against a straight solve_ivp port, on the same cases, one run.

Prints, per case and polarity +1: the median wall time of the fast engine (over FAST_REPEATS
runs, compile excluded) and of the solve_ivp port (PORT_REPEATS runs), their ratio, and the
agreement of max θ/α with the reference engine (scipy DOP853, rtol 1e-10). Then the median of
the ratios.

    python benchmarks/engine.py            # needs ../shared/records beside the clone

Target (issue #2): ratio ≥ 250×, max θ/α within 1e-3 of the reference.
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from solve_ivp_port import run_port  # noqa: E402

from rockcli.dynamics.settings import Engine, SolverSettings  # noqa: E402
from rockcli.dynamics.simulate import simulate  # noqa: E402
from rockcli.mechanics import Block, Restrainer, housner_restitution  # noqa: E402
from rockcli.records.files import read_record  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "records"
FAST_REPEATS = 21
PORT_REPEATS = 3


def block(R: float, alpha: float, factor: float = 1.0, k: float = 0.0) -> Block:
    """A block with Housner e × factor and, if k > 0, the paper's top spring on both sides."""
    springs = (Restrainer("top", k, k, 2 * R, alpha, 2 * R, alpha),) if k else ()
    mass = 18e3 * (2 * R) ** 2 * np.sin(alpha) * np.cos(alpha) * 3.0 / 9.81
    return Block(R=R, alpha=alpha, e=factor * housner_restitution(alpha), mass=mass,
                 restrainers=springs)


CASES = [
    ("ELC180 R3 a0.20 (paper §3.1)", "ELC180.AT2", block(3.0, 0.2)),
    ("ELC180 R1.5 a0.10 0.9e", "ELC180.AT2", block(1.5, 0.10, 0.9)),
    ("CPM000 R3.5 a0.15 0.9e", "CPM000.AT2", block(3.5, 0.15, 0.9)),
    ("CPM000 R10 a0.25 0.9e", "CPM000.AT2", block(10.0, 0.25, 0.9)),
    ("KOBE NIS090 R2 a0.15", "KOBE95_NIS090_NGAW1.AT2", block(2.0, 0.15)),
    ("ELC180 R7 a0.05 K=1e3 top", "ELC180.AT2", block(7.0, 0.05, 0.9, 1e3)),
    ("CPM000 R2 a0.10 K=1e6 top", "CPM000.AT2", block(2.0, 0.10, 0.9, 1e6)),
]


def median_time(fn, repeats: int) -> tuple[float, object]:  # type: ignore[no-untyped-def]
    times, out = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), out


def main() -> None:
    if not SHARED.is_dir():
        sys.exit(f"benchmark needs the real records in {SHARED}")
    settings = SolverSettings()
    print(f"{'case':32s} {'fast ms':>8s} {'port ms':>8s} {'ratio':>7s} "
          f"{'θ/α fast':>10s} {'θ/α ref':>10s} {'rel diff':>9s} {'θ/α port':>9s}")
    ratios = []
    for label, rec_name, blk in CASES:
        rec = read_record(SHARED / rec_name)
        args = (blk, rec.time, rec.accel, rec.dt)
        simulate(*args, settings=settings)  # compile / load the cache
        t_fast, fast = median_time(lambda: simulate(*args, settings=settings), FAST_REPEATS)
        ref = simulate(*args, settings=settings, engine=Engine.REFERENCE)
        t_end = rec.time[-1] + settings.tail_for(blk.p)
        times = np.concatenate([rec.time, [rec.time[-1] + rec.dt, t_end]])
        accel = np.concatenate([rec.accel, [0.0, 0.0]])
        t_port, port = median_time(lambda: run_port(blk, times, accel, t_end), PORT_REPEATS)
        rel = abs(fast.max_ratio - ref.max_ratio) / ref.max_ratio
        ratios.append(t_port / t_fast)
        print(f"{label:32s} {t_fast * 1e3:8.3f} {t_port * 1e3:8.1f} {t_port / t_fast:6.0f}× "
              f"{fast.max_ratio:10.6f} {ref.max_ratio:10.6f} {rel:9.1e} {port['max_ratio']:9.4f}")
    print(f"median ratio port/fast: {statistics.median(ratios):.0f}× "
          f"(min {min(ratios):.0f}×, max {max(ratios):.0f}×)")


if __name__ == "__main__":
    main()
