"""Benchmark: a study's time per case against the compiled kernel's own time (issue 24).

The issue's target is a study whose time per case is within 1.25× of the kernel's own time
for the same cases. This measures, in one run, in this process (one core, no worker
start-up), the cases of the `--scale` study of benchmarks/sweep.py (the §4.4 wall with its
top spring, R × α × K, on ELC180, a 40 s record) run through the study's own chunk runner
(:func:`rockcli.studies.sweep.worker.run_chunk`) two ways, alternately:

- batched (rockcli/studies/sweep/batch.py): the blocks derived as arrays, one compiled call
  for the chunk, the rows from the output arrays;
- case by case (the path before issue 24, still the path of studies that are not batched):
  each case's model built and validated, its block derived, both polarities run through
  rockcli.dynamics.simulate, its row.

The kernel's share is the time spent inside the compiled ``integrate`` calls of the
case-by-case runs, timed where the engine calls them (``rockcli.interrupts.call``): the same
runs, bit for bit, as the batched call makes.

    python benchmarks/overhead.py [CASES]     # default 2000; needs ../shared/records
    python benchmarks/overhead.py --suite     # a suite study (seven records per case) both
                                              # ways; needs ../shared records and ntc grid

Prints the median over REPEATS runs of: the time per case of each path and of the kernel,
the ratios, and the 10⁶-case time on two cores each would give.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

REPEATS = 5
#: The issue's target: a study's time per case at most this many times the kernel's.
TARGET_RATIO = 1.25


def both_paths(plan: Any, ids: range) -> tuple[float, float, float]:
    """(batched, case by case, kernel) seconds per case of the plan's first record's cases
    ids, medians of REPEATS alternate runs; the kernel's from the case-by-case runs."""
    from rockcli import interrupts
    from rockcli.studies.sweep import batch
    from rockcli.studies.sweep.worker import Chunk, run_chunk

    spent = [0.0]
    call = interrupts.call

    def timed(fn, *args):  # type: ignore[no-untyped-def]
        start = time.perf_counter()
        try:
            return call(fn, *args)
        finally:
            spent[0] += time.perf_counter() - start

    batched_form = batch.cached_form
    interrupts.call = timed  # type: ignore[assignment]
    chunk = Chunk(plan, 0, ids)
    run_chunk(Chunk(plan, 0, ids[:2]))  # the records read, the caches warm
    study, kernel, old = [], [], []
    try:
        for _ in range(REPEATS):
            batch.cached_form = lambda plan: None  # type: ignore[assignment]  # case by case
            spent[0] = 0.0
            start = time.perf_counter()
            rows = run_chunk(chunk)
            old.append((time.perf_counter() - start) / len(rows))
            kernel.append(spent[0] / len(rows))
            batch.cached_form = batched_form  # type: ignore[assignment]
            start = time.perf_counter()
            rows = run_chunk(chunk)
            study.append((time.perf_counter() - start) / len(rows))
            assert not any(r.get("error") for r in rows), rows[0]
    finally:
        interrupts.call = call  # type: ignore[assignment]
        batch.cached_form = batched_form  # type: ignore[assignment]
    return statistics.median(study), statistics.median(old), statistics.median(kernel)


def report(what: str, s: float, o: float, k: float) -> None:
    print(f"{what}, in process, median of {REPEATS} runs")
    print(f"  study, batched, per case      {1e3 * s:7.3f} ms")
    print(f"  study, case by case           {1e3 * o:7.3f} ms   (the path before issue 24)")
    print(f"  kernel alone, per case        {1e3 * k:7.3f} ms   (its integrate calls)")
    print(f"  batched study / kernel        {s / k:7.2f}   (target ≤ {TARGET_RATIO:g})")
    print(f"  case by case / kernel         {o / k:7.2f}")


def main(cases: int) -> None:
    from benchmarks.sweep import SHARED, scale_study
    from rockcli.studies.parallel.setup import warm
    from rockcli.studies.sweep.cases import expand
    from rockcli.studies.sweep.study import load_study

    if not SHARED.is_dir():
        sys.exit(f"{SHARED} is not there: the scale study needs ELC180.AT2 from ../shared")
    warm()
    with tempfile.TemporaryDirectory() as folder:
        plan = load_study(str(scale_study(Path(folder), shrink=10)))
        n = min(cases, len(expand(plan)))
        s, o, k = both_paths(plan, range(n))
    report(f"{n} cases of the scale study", s, o, k)
    print(f"  10^6 cases on 2 cores         {1e6 * s / 2 / 60:7.1f} min   "
          f"(case by case {1e6 * o / 2 / 60:.1f} min; the kernel alone: "
          f"{1e6 * k / 2 / 60:.1f} min)")  # fmt: skip


#: The suite study: the §4.4 wall, R × α, rocking alone, under the seven records of
#: examples/suites/laquila-slv.toml (copied beside it with its records from ../shared).
SUITE_STUDY = """\
name = "suite overhead"
base = "wall.toml"
analyses = ["rocking"]
records_dir = "records"
[[axes]]
path = "geometry.R"
values = [1.5, 2.0, 2.5, 3.0, 3.5, 5.0, 7.0, 10.0]
[[axes]]
path = "geometry.alpha"
values = [0.05, 0.10, 0.15, 0.25]
[[records]]
suite = "suite.toml"
"""


def suite() -> None:
    """The 32 cases of SUITE_STUDY both ways (each case: seven records, both polarities)."""
    from benchmarks.sweep import ROOT, SHARED, STUDIES
    from rockcli.studies.parallel.setup import warm
    from rockcli.studies.sweep.study import load_study

    grid = SHARED.parent / "ntc" / "AllegatoB.txt"
    if not SHARED.is_dir() or not grid.is_file():
        sys.exit(f"{SHARED} or {grid} is not there: the suite study needs them")
    warm()
    text = (ROOT / "examples" / "suites" / "laquila-slv.toml").read_text(encoding="utf-8")
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        (folder / "records").mkdir()
        (folder / "wall.toml").write_bytes((STUDIES / "paper-4.4-wall.toml").read_bytes())
        for record in SHARED.iterdir():
            (folder / "records" / record.name).write_bytes(record.read_bytes())
        suite_text = text.replace("../../../shared/records/", "")
        (folder / "records" / "suite.toml").write_text(suite_text, encoding="utf-8")
        (folder / "study.toml").write_text(SUITE_STUDY, encoding="utf-8")
        plan = load_study(str(folder / "study.toml"), grid_file=str(grid))
        s, o, k = both_paths(plan, range(32))
    report("32 cases of a suite study (seven records each)", s, o, k)


if __name__ == "__main__" and "--suite" in sys.argv:
    suite()
elif __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 2000)
