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
    python benchmarks/sweep.py --scale    # 5. below, alone (needs ../shared/records)
    python benchmarks/sweep.py --million  # 6. below, alone (needs ../shared/records)

4. stopping (issue 7, item 13): a study with the reference engine (the pulses, 32 cases)
   with --jobs 2, sent SIGINT to its process group (a terminal's Ctrl-C) or SIGTERM, or
   SIGKILL, after STOP_AFTER s: the exit code, the time it takes to stop, the cases saved,
   and the processes (with their memory) still alive STOP_SETTLE s later.

5. scale (issue 11, item 5): a rocking-only study of SCALE_CASES cases (R × α × K of the
   paper's §4.4 wall with its top spring) on ELC180 (a 40 s record), and one of a tenth of the
   cases, each with --jobs 1 and --jobs 2: wall time and cases/s (start-up included), the
   peak memory of the processes (RSS, the largest of rock and its workers), the size of
   cases.csv and of cases.parquet (pyarrow installed), and the 10⁶-case time extrapolated from
   the larger study's throughput. Peak memory that does not grow with the cases is the
   streaming at work. Then (issue 24) the tenth run in this process with --jobs 1 both
   ways, batched and case by case (the old path), in the same run.

6. million (issue 24): one study of 10⁶ cases (ten times the R values), --jobs 2: wall
   time, peak RSS, the sizes of cases.csv and cases.parquet. Target: under 4.5 min.

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
    load = "from rockcli.studies.parallel.setup import init_worker; init_worker()"
    best, median = wall([sys.executable, "-c", load])
    print(f"  fresh interpreter + kernels        {best:.3f}  {median:.3f}")
    code = (
        "import time; import rockcli.studies.sweep.run; t = time.perf_counter();"
        "from rockcli.studies.parallel.setup import warm; warm();"
        "print(time.perf_counter() - t)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    print(f"  kernels, rock already imported     {float(out.stdout):.3f}")


def per_case() -> None:
    import numpy as np

    from rockcli.analyses.assess import assess_model
    from rockcli.analyses.kinematic import kinematic_model
    from rockcli.codecheck.response import RecordSpectrum, response_spectrum
    from rockcli.studies.parallel.setup import warm
    from rockcli.studies.sweep.cases import Case, build_model
    from rockcli.studies.sweep.study import load_study
    from rockcli.studies.sweep.worker import read_source

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


#: Cases of the scale study (issue 11: 10⁵), and its grid: R × α × K.
SCALE_CASES = 100_000
SCALE_GRID = {"R": (1.0, 10.0, 50), "alpha": (0.05, 0.30, 50), "K": (1e2, 1e6, 40)}


def scale_study(folder: Path, shrink: int = 1, grow: int = 1) -> Path:
    """The scale study in ``folder`` (its base model and ELC180 copied beside it); with
    shrink = 10, a tenth of the R values (a tenth of the cases); with grow = 10, ten times as
    many R values between the same ends (10⁶ cases)."""
    import numpy as np

    (folder / "wall.toml").write_bytes((STUDIES / "paper-4.4-wall.toml").read_bytes())
    (folder / "ELC180.AT2").write_bytes((SHARED / "ELC180.AT2").read_bytes())
    lo, hi, n = SCALE_GRID["R"]
    R = np.linspace(lo, hi, n * grow // shrink)
    alpha = np.linspace(*SCALE_GRID["alpha"][:2], SCALE_GRID["alpha"][2])
    K = np.geomspace(*SCALE_GRID["K"][:2], SCALE_GRID["K"][2])
    text = 'name = "scale"\nbase = "wall.toml"\nanalyses = ["rocking"]\n'
    for name, path, values in (
        ("R", '"geometry.R"', R),
        ("alpha", '"geometry.alpha"', alpha),
        ("K", '["restrainers[0].k_pos", "restrainers[0].k_neg"]', K),
    ):
        cells = ", ".join(f"{v:.6g}" for v in values)
        text += f'[[axes]]\npath = {path}\nname = "{name}"\nvalues = [{cells}]\n'
    text += '[[records]]\npath = "ELC180.AT2"\n'
    study = folder / f"scale-{shrink}-{grow}.toml"
    study.write_text(text)
    return study


def peak_rss_mb(args: list[str]) -> tuple[float, float]:
    """(wall time [s], peak RSS [MB]) of a command and its workers (ru_maxrss of the
    waited-for children: the largest of the process tree)."""
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    start = time.perf_counter()
    subprocess.run(args, check=True, capture_output=True, cwd=ROOT)
    took = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return took, max(after, before) / 1024


def run_study(study: Path, jobs: str, out: Path) -> tuple[float, float, float, float]:
    """`rock sweep` of a study with --jobs (and --output parquet with pyarrow installed):
    (wall time [s], peak RSS [MB], cases.csv [MB], cases.parquet [MB], nan without it)."""
    import importlib.util

    parquet = importlib.util.find_spec("pyarrow") is not None
    args = [ROCK, "sweep", str(study), "--jobs", jobs, "--out", str(out), "--force",
            "--no-progress", "--format", "json"]  # fmt: skip
    if parquet:
        args += ["--output", "parquet"]
    took, rss = peak_rss_mb(args)
    csv_mb = (out / "cases.csv").stat().st_size / 1e6
    pq = (out / "cases.parquet").stat().st_size / 1e6 if parquet else float("nan")
    return took, rss, csv_mb, pq


def scale() -> None:
    import importlib.util

    parquet = importlib.util.find_spec("pyarrow") is not None
    missing = "" if parquet else " (no pyarrow: no parquet)"
    print(f"\nscale: rocking-only studies on ELC180 (40 s), one run each{missing}")
    print("  cases    jobs   wall [s]   cases/s   peak RSS [MB]   cases.csv [MB]   parquet [MB]")
    best = None
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for shrink in (10, 1):
            study = scale_study(folder, shrink)
            cases = SCALE_CASES // shrink
            for jobs in ("1", "2"):
                took, rss, csv_mb, pq = run_study(study, jobs, folder / f"out-{shrink}-{jobs}")
                print(f"  {cases:7d}  {jobs:>4}   {took:8.1f}   {cases / took:7.0f}   "
                      f"{rss:13.0f}   {csv_mb:14.1f}   {pq:12.1f}")  # fmt: skip
                if shrink == 1 and (best is None or took < best):
                    best = took
    if best is not None:
        extrapolated = best * 1e6 / SCALE_CASES
        print(f"  10^6 cases extrapolated from the fastest 10^5 run: {extrapolated:.0f} s "
              f"({extrapolated / 60:.1f} min; target 4.5 min)")  # fmt: skip
    old_path()


def old_path() -> None:
    """The tenth of the scale study (10⁴ cases) run in this process with --jobs 1 both ways:
    batched, and case by case (the path before issue 24, still that of studies that are not
    batched: rockcli.studies.sweep.batch's form turned off), start-up excluded."""
    from rockcli.studies.parallel.executor import local_executor
    from rockcli.studies.sweep import batch
    from rockcli.studies.sweep.run import run_sweep
    from rockcli.studies.sweep.study import load_study

    print("\nscale, a tenth, in this process, --jobs 1 (the worker thread), start-up excluded")
    with tempfile.TemporaryDirectory() as tmp:
        plan = load_study(str(scale_study(Path(tmp), 10)))
        form, cached = batch.batch_form, batch.cached_form
        for name in ("batched", "case by case"):
            if name != "batched":
                batch.batch_form = batch.cached_form = lambda plan: None  # type: ignore[assignment]
            start = time.perf_counter()
            with local_executor(1) as lanes:
                run_sweep(plan, str(Path(tmp) / name), lanes)
            took = time.perf_counter() - start
            cases = len(plan.axes[0].values) * 2000
            print(f"  {name:13s} {took:7.1f} s   {cases / took:6.0f} cases/s")
        batch.batch_form, batch.cached_form = form, cached


def million() -> None:
    """One study of 10⁶ cases (the scale study with ten times the R values), --jobs 2."""
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        study = scale_study(folder, grow=10)
        out = folder / "out"
        took, rss, csv_mb, pq = run_study(study, "2", out)
        rows = sum(1 for _ in open(out / "cases.csv", encoding="utf-8")) - 1
        print(f"10^6 scale study, --jobs 2: {rows} cases in {took:.0f} s ({took / 60:.2f} min; "
              f"target 4.5 min), peak RSS {rss:.0f} MB, cases.csv {csv_mb:.0f} MB, "
              f"cases.parquet {pq:.0f} MB")  # fmt: skip


if __name__ == "__main__" and "--stop" in sys.argv:
    stop_times()
elif __name__ == "__main__" and "--scale" in sys.argv:
    scale()
elif __name__ == "__main__" and "--million" in sys.argv:
    million()
elif __name__ == "__main__":
    start_up()
    if SHARED.is_dir():
        per_case()
    else:
        print(f"\n{SHARED} is absent: per-case costs and the §4.4 study skipped")
    studies()
