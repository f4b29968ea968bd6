"""Benchmark: where the time of a `rock sweep` goes, and the wall time of whole studies.

Prints:

1. start-up: `rock --help`; a fresh interpreter loading the compiled kernels (what a spawned
   worker pays); loading them in a process that has rock imported already (the main
   process with --jobs 1, or the fork server once);
2. per case, on each record of the paper's §4.4 study (R = 3.5 m, α = 0.05 rad, K = 1e3
   N/m): building and validating the model, the rocking run (both polarities), the kinematic
   check, one period of the record's response spectrum (compiled, and the numpy loop);
3. whole studies, run as a user runs them (`rock sweep …`, start-up and exit included), the
   best and the median of REPEATS runs: the §4.4 study with --jobs 2 and --jobs 1, and the
   pulse study.

    python benchmarks/sweep.py            # the §4.4 parts need ../shared/records
    python benchmarks/sweep.py --stop     # 4. below, alone

4. stopping (issue 7, item 13): a study with the reference engine (the pulses, 32 cases)
   with --jobs 2, sent SIGINT to its process group (a terminal's Ctrl-C) or SIGTERM, or
   SIGKILL, after STOP_AFTER s: the exit code, the time it takes to stop, the cases saved,
   and the processes (with their memory) still alive STOP_SETTLE s later.

Target (issue: rock sweep): the §4.4 study on the three available real records (336 cases,
both polarities, with the kinematic checks) under 5 s with --jobs 2, start-up included, on
this 2-core machine (goal 2 s).
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "records"
STUDIES = ROOT / "examples" / "studies"
ROCK = str(Path(sys.executable).with_name("rock"))
REPEATS = 5
PER_CASE_REPEATS = 20


def best_of(fn: Callable[[], object], repeats: int) -> float:
    """The smallest wall time of `repeats` calls [s]."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def wall(args: list[str], repeats: int = REPEATS) -> tuple[float, float]:
    """(best, median) wall time of a command [s]."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        subprocess.run(args, check=True, capture_output=True, cwd=ROOT)
        times.append(time.perf_counter() - start)
    return min(times), statistics.median(times)


def start_up() -> None:
    print("start-up (best, median of 5) [s]")
    best, median = wall([ROCK, "--help"])
    print(f"  rock --help                        {best:.3f}  {median:.3f}")
    load = "from rockcli.studies.sweep.worker import init_worker; init_worker()"
    best, median = wall([sys.executable, "-c", load])
    print(f"  fresh interpreter + kernels        {best:.3f}  {median:.3f}")
    code = (
        "import time; import rockcli.studies.sweep.run; t = time.perf_counter();"
        "from rockcli.studies.sweep.worker import warm; warm();"
        "print(time.perf_counter() - t)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    print(f"  kernels, rock already imported     {float(out.stdout):.3f}")


def per_case() -> None:
    import numpy as np

    from rockcli.codecheck.response import RecordSpectrum, response_spectrum
    from rockcli.studies.assess import assess_model
    from rockcli.studies.kinematic import kinematic_model
    from rockcli.studies.sweep.cases import Case, build_model
    from rockcli.studies.sweep.study import load_study
    from rockcli.studies.sweep.worker import read_source, warm

    warm()
    plan = load_study(str(STUDIES / "paper-4.4.toml"), records_dir=str(SHARED))
    case = Case(0, 0, (4, 0, 1))  # R = 3.5, α = 0.05, K = 1e3
    model = build_model(plan, case)
    print(f"\nper case (best of {PER_CASE_REPEATS}) [ms]")
    T = np.array([1.234])  # s, a secant period
    print("  record          npts   model  rocking  kinematic  Sd(T) compiled  Sd(T) numpy")
    for source in plan.records:
        record = read_source(source)
        spectrum = RecordSpectrum.from_record(record)
        kinematic_model(model, record=record, spectrum=spectrum)  # its period, cached
        build = best_of(lambda: build_model(plan, case), PER_CASE_REPEATS)
        rock = best_of(lambda r=record: assess_model(model, r, "fast"), PER_CASE_REPEATS)
        kin = best_of(
            lambda r=record, s=spectrum: kinematic_model(model, record=r, spectrum=s),
            PER_CASE_REPEATS,
        )
        fast = best_of(lambda r=record: response_spectrum(r.time, r.accel, T, compiled=True), 5)
        slow = best_of(lambda r=record: response_spectrum(r.time, r.accel, T), 1)
        print(
            f"  {source.name:12s} {record.npts:7d}  {1e3 * build:6.2f}  {1e3 * rock:7.2f}"
            f"  {1e3 * kin:9.2f}  {1e3 * fast:14.2f}  {1e3 * slow:11.1f}"
        )


def studies() -> None:
    print(f"\nwhole studies, `rock sweep …` (best, median of {REPEATS}) [s]")
    with tempfile.TemporaryDirectory() as out:
        outside = ["--allow-outside"]
        runs = [(f"pulses, --jobs {jobs}", "pulses.toml", jobs, outside) for jobs in ("2", "1")]
        if SHARED.is_dir():
            shared = ["--records-dir", str(SHARED)]
            runs += [(f"§4.4, --jobs {jobs}", "paper-4.4.toml", jobs, shared) for jobs in "21"]
        for label, study, jobs, extra in runs:
            args = [ROCK, "sweep", str(STUDIES / study), "--jobs", jobs, *extra]
            args += ["--out", str(Path(out) / "run"), "--force", "--format", "json"]
            best, median = wall(args)
            print(f"  {label:22s} {best:.2f}  {median:.2f}")


#: Seconds a study runs before it is stopped, and seconds left to orphans to exit.
STOP_AFTER = 15.0
STOP_SETTLE = 3.0
#: A study slow enough to be stopped half-way: the reference engine on the shipped pulses.
REFERENCE_STUDY = """\
name = "reference engine"
base = "paper-4.4-wall.toml"
engine = "reference"
[[axes]]
path = "geometry.R"
name = "R"
values = [1.5, 3.5, 7.0, 10.0]
[[axes]]
path = "geometry.alpha"
name = "alpha"
values = [0.05, 0.1, 0.15, 0.25]
[[records]]
path = "one-cosine_Tp2s_0.31g.txt"
[[records]]
path = "ricker_Tp0.5s_0.5g.txt"
"""


def stop_one(how: str, folder: Path) -> str:
    """Start the reference study, stop it one way, describe what happened."""
    import os
    import shutil
    import signal

    import psutil

    shutil.copy(STUDIES / "paper-4.4-wall.toml", folder)
    for name in ("one-cosine_Tp2s_0.31g.txt", "ricker_Tp0.5s_0.5g.txt"):
        shutil.copy(ROOT / "records" / name, folder)
    study = folder / "ref.toml"
    study.write_text(REFERENCE_STUDY)
    out = folder / f"out-{how}"
    args = [sys.executable, "-m", "rockcli", "sweep", str(study), "-j", "2", "--out", str(out)]
    proc = subprocess.Popen(
        [*args, "--no-progress", "--format", "json"],
        cwd=ROOT,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    time.sleep(STOP_AFTER)
    children = psutil.Process(proc.pid).children(recursive=True)
    start = time.perf_counter()
    if how == "ctrl-c":
        os.killpg(proc.pid, signal.SIGINT)
    else:
        proc.send_signal(signal.SIGTERM if how == "sigterm" else signal.SIGKILL)
    _, err = proc.communicate()
    took = time.perf_counter() - start
    time.sleep(STOP_SETTLE)
    alive = [c for c in children if c.is_running() and c.status() != psutil.STATUS_ZOMBIE]
    left = ", ".join(f"{c.memory_info().rss >> 20} MB" for c in alive) or "none"
    for c in alive:
        c.kill()
    cases = out / "cases.csv"
    saved = sum(1 for _ in cases.open()) - 1 if cases.exists() else 0
    last = err.strip().splitlines()[-1][:90] if err.strip() else ""
    return (
        f"  {how:8s} exit {proc.returncode:4d}  stop {took:5.1f} s  saved {saved:2d}"
        f"  left: {left}  {last}"
    )


def stop_times() -> None:
    print(f"\nstopping a reference-engine study (--jobs 2) after {STOP_AFTER:g} s")
    for how in ("ctrl-c", "sigterm", "sigkill"):
        with tempfile.TemporaryDirectory() as folder:
            print(stop_one(how, Path(folder)))


if __name__ == "__main__" and "--stop" in sys.argv:
    stop_times()
elif __name__ == "__main__":
    start_up()
    if SHARED.is_dir():
        per_case()
    else:
        print(f"\n{SHARED} is absent: per-case costs and the §4.4 study skipped")
    studies()
