"""Benchmark: a two-block vertical flexure against a single block, on ELC180, one run each.

Prints the median wall time (over REPEATS runs, compile excluded) of the fast engine on

- a block (R = 3 m, α = 0.3 rad, Housner e) under ELC180 scaled to 1.3 g: it rocks through
  about a hundred impacts and survives;
- the vertical flexure of storey 2 of examples/two-storey-facade.toml (two blocks, its
  chain's table) under ELC180 scaled to 1.6 g on the ground (its α0 is 0.80 g): it rocks
  through about eighty impacts and survives;

their ratios to the single block (issue 22: the two-block run under 10× a single-block run),
and the time to build the chain's table once (rockcli.mechanisms.table.tabulate).

    python benchmarks/chain.py            # needs ../shared/records beside the clone

With ``--single`` it times the single block only, so that the same script run against an
older checkout (PYTHONPATH=that checkout) gives the single-block path's speed before and after
a change on the same machine in the same session.
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

import numpy as np

from rockcli.dynamics.simulate import simulate
from rockcli.mechanics import Block, housner_restitution
from rockcli.records.files import read_record

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "records"
REPEATS = 21
#: ELC180 scaled to these PGAs [g]: each body rocks long and survives (module docstring).
PGA_BLOCK = 1.3
PGA_FLEXURE = 1.6


def median_time(run, repeats: int = REPEATS) -> tuple[float, object]:
    """(median seconds, last result) of ``run()`` after one untimed call (compile, caches)."""
    result = run()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def record(pga: float) -> tuple[np.ndarray, np.ndarray, float]:
    """ELC180 at ``pga`` [s, g, s]."""
    rec = read_record(str(SHARED / "ELC180.AT2"))
    accel = np.asarray(rec.accel) * (pga / float(np.max(np.abs(rec.accel))))
    return np.asarray(rec.time), accel, float(rec.dt)


def single_block() -> Block:
    """A block of R = 3 m, α = 0.3 rad with a mass."""
    return Block(R=3.0, alpha=0.3, e=housner_restitution(0.3), mass=30e3)


def mechanism(name: str) -> Block:
    """A mechanism of the example façade as the engine rocks it."""
    from rockcli.analyses.rocked import mechanism_block, named_spec
    from rockcli.model.derive_wall import to_wall
    from rockcli.model.load import load_model

    model = load_model(str(ROOT / "examples" / "two-storey-facade.toml"))
    wall = to_wall(model)
    return mechanism_block(model, wall, named_spec(wall, name))


def table_time() -> float:
    """Seconds to tabulate the flexure's chain once (cache cleared)."""
    from rockcli.mechanisms.table import tabulate

    tabulate.cache_clear()
    start = time.perf_counter()
    mechanism("vertical flexure, storey 2")
    return time.perf_counter() - start


def main() -> None:
    cases = [("single block R3 a0.30, 1.3 g", single_block(), PGA_BLOCK)]
    if "--single" not in sys.argv:
        flexure = mechanism("vertical flexure, storey 2")
        cases.append(("flexure storey 2 (two blocks), 1.6 g", flexure, PGA_FLEXURE))
    base = None
    print(f"ELC180, fast engine, median of {REPEATS} runs")
    for label, body, pga in cases:
        t, a, dt = record(pga)
        seconds, run = median_time(lambda b=body, t=t, a=a, dt=dt: simulate(b, t, a, dt))
        base = base or seconds
        print(f"  {label:38s} {seconds * 1e3:8.2f} ms  ×{seconds / base:5.2f}  "
              f"max θ/α {run.max_ratio:.4f}, {run.impacts} impacts, {run.status}")  # fmt: skip
    if "--single" not in sys.argv:
        print(f"  building the flexure's table once: {table_time():.2f} s")


if __name__ == "__main__":
    main()
