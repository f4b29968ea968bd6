"""Benchmark: the time per diameter of `rock retrofit --diameters` (issue 34, F15).

Since the 2019 demand of a record is the maximum of its spectrum over [T0, T_SLV] (Circolare
7/2019 §C8.7.1.2.1.8), each code check reads a few hundred ordinates of the record's
response spectrum. Each candidate made its own spectrum and computed them all again (2 000
diameters: over 300 s); the candidates of a process now share one spectrum
(rockcli.studies.retrofit.run.shared_spectrum), whose cached ordinates are read as they are.

Prints, in one run:

1. per diameter, in this process (CPU time of this thread, medians of REPEATS passes over
   DIAMETERS sizes): a candidate as `rock retrofit` runs it, the same candidate with its own
   spectrum (the path before the fix: the reference), and its two parts, the time history
   alone (both polarities) and the code check alone on the shared spectrum;
2. the whole command as a user runs it (`rock retrofit MODEL --record R --diameters …`, a
   fresh process, start-up included) with 2 and with COMMAND_DIAMETERS sizes: the medians of
   REPEATS runs (wall and CPU of the process) and the time per further diameter.

    python benchmarks/retrofit.py [--model M] [--record R] [--repeats N]

Defaults: examples/facade.toml (a block with its tie-rod) on ELC180 (40 s at 0.01 s) of
../shared/records, else on the shipped Ricker pulse. Measured on this 2-core machine (shared):
about 6 ms per diameter before the 2019 range maximum, about 90 ms after it, about 7 ms with
the shared spectrum.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "records"
REPEATS = 5
#: Sizes per pass in this process [mm] (10, 10.2, … 13.8), and sizes of the long command.
DIAMETERS = tuple(10.0 + 0.2 * i for i in range(20))
COMMAND_DIAMETERS = 200


def default_record() -> Path:
    elc = SHARED / "ELC180.AT2"
    return elc if elc.is_file() else ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"


def cpu_per_item(fn: Any, items: tuple[float, ...]) -> float:
    """CPU seconds of this thread per item of one pass of fn over items."""
    start = time.thread_time()
    for item in items:
        fn(item)
    return (time.thread_time() - start) / len(items)


def in_process(model_path: str, record_path: str, repeats: int) -> None:
    from rockcli.analyses.assess import assess_model_output
    from rockcli.analyses.choices import Analyses
    from rockcli.analyses.kinematic import kinematic_model
    from rockcli.model.load import read_toml, validate_model
    from rockcli.records import files
    from rockcli.studies.retrofit import run as retrofit_run
    from rockcli.studies.retrofit.candidates import build_candidate, make_plan
    from rockcli.studies.retrofit.run import run_candidate, shared_spectrum

    table = read_toml(model_path)
    plan = make_plan(table, validate_model(table), diameters_mm=DIAMETERS)
    record = files.read_record(record_path)
    models = {d: build_candidate(plan, d) for d in DIAMETERS}
    g = models[DIAMETERS[0]].analysis.g

    def shared(d: float) -> object:
        return run_candidate(plan, d, record, Analyses())

    def own(d: float) -> object:  # each candidate its own spectrum: the path before the fix
        retrofit_run._spectra.clear()
        return run_candidate(plan, d, record, Analyses())

    def rocking(d: float) -> object:
        return assess_model_output(models[d], record, "fast", tolerance_check=False)

    def check(d: float) -> object:
        spectrum = shared_spectrum(record, g)
        return kinematic_model(models[d], record=record, spectrum=spectrum)

    paths = {"as run (one shared spectrum)": shared, "its own spectrum (before)": own,
             "time history alone": rocking, "code check alone (shared)": check}  # fmt: skip
    for fn in paths.values():  # load the engine, fill the spectrum's cache
        fn(DIAMETERS[0])
    times: dict[str, list[float]] = {name: [] for name in paths}
    for _ in range(repeats):
        for name, fn in paths.items():
            times[name].append(cpu_per_item(fn, DIAMETERS))
    print(f"per diameter, in this process (CPU, median of {repeats} passes over "
          f"{len(DIAMETERS)} sizes) [ms]")  # fmt: skip
    median = {name: 1e3 * statistics.median(t) for name, t in times.items()}
    for name, ms in median.items():
        print(f"  {name:30s} {ms:8.2f}")
    ratio = median["its own spectrum (before)"] / median["as run (one shared spectrum)"]
    print(f"  the shared spectrum is {ratio:.1f}× faster per diameter")


def command(model_path: str, record_path: str, count: int) -> list[str]:
    sizes = ",".join(f"{10 + 0.05 * i:g}" for i in range(count))
    return [sys.executable, "-m", "rockcli", "retrofit", model_path, "--record", record_path,
            "--diameters", sizes, "--format", "json", "--no-progress"]  # fmt: skip


def run_once(args: list[str]) -> tuple[float, float]:
    """(wall, CPU of the child) seconds of one command."""
    before = os.times()
    start = time.perf_counter()
    subprocess.run(args, check=True, capture_output=True, cwd=ROOT)
    wall = time.perf_counter() - start
    after = os.times()
    cpu = (after.children_user - before.children_user) + (
        after.children_system - before.children_system
    )
    return wall, cpu


def whole_command(model_path: str, record_path: str, repeats: int) -> None:
    short = command(model_path, record_path, 2)
    long = command(model_path, record_path, COMMAND_DIAMETERS)
    run_once(short)  # compiled caches loaded once
    runs: dict[int, list[tuple[float, float]]] = {2: [], COMMAND_DIAMETERS: []}
    for _ in range(repeats):
        runs[2].append(run_once(short))
        runs[COMMAND_DIAMETERS].append(run_once(long))
    print(f"\n`rock retrofit … --diameters` (fresh process; median of {repeats}) [s]")
    med = {}
    for n, rows in runs.items():
        wall = statistics.median(r[0] for r in rows)
        cpu = statistics.median(r[1] for r in rows)
        med[n] = (wall, cpu)
        print(f"  {n:4d} diameters: wall {wall:7.2f}  CPU {cpu:7.2f}")
    extra = COMMAND_DIAMETERS - 2
    wall = 1e3 * (med[COMMAND_DIAMETERS][0] - med[2][0]) / extra
    cpu = 1e3 * (med[COMMAND_DIAMETERS][1] - med[2][1]) / extra
    print(f"  per further diameter: wall {wall:.1f} ms, CPU {cpu:.1f} ms (so the cap, "
          f"1000 diameters, is about {cpu:.0f} s of CPU)")  # fmt: skip


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default=str(ROOT / "examples" / "facade.toml"))
    parser.add_argument("--record", default=str(default_record()))
    parser.add_argument("--repeats", type=int, default=REPEATS)
    opts = parser.parse_args()
    print(f"{Path(opts.model).name} on {Path(opts.record).name}\n")
    in_process(opts.model, opts.record, opts.repeats)
    whole_command(opts.model, opts.record, opts.repeats)


if __name__ == "__main__":
    main()
