"""Benchmark: the cost of the tolerance check (rockcli.dynamics.tolerance) in `rock assess`.

Prints, per case, the median CPU time (time.thread_time: on a shared, loaded machine the wall
time of runs of a few ms includes the scheduler's preemptions) of the rocking analysis of
`rock assess` (both polarities, the engine loaded; rockcli.analyses.assess.assess_model_output)
without and with the check, interleaved over REPEATS runs, their difference, and the median
wall times.

    python benchmarks/tolerance_check.py   # the real records need ../shared/records

Cases: the façade example on the shipped Ricker pulse (the README's first command), the
issue's wall (18 kN on top 0.10 m from O) on NORTHR_ARL360 × 0.8, the example wall on
ELC180, the façade on NORTHR_ARL360.
"""

from __future__ import annotations

import statistics
import time
from pathlib import Path

from rockcli.analyses.assess import assess_model_output
from rockcli.model.load import load_model, validate_model
from rockcli.model.schema import Model
from rockcli.records import files, transform
from rockcli.records.record import Record

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "records"
REPEATS = 101
ISSUE_WALL = {
    "name": "issue wall",
    "kind": "wall",
    "geometry": {"thickness": 0.5, "height": 4.0, "width": 1.0},
    "mass": {"unit_weight": 18.0},
    "loads": [{"name": "floor", "weight": 18.0, "position": "top", "from_pivot": 0.1}],
}


def record(path: Path, scale: float = 1.0) -> Record:
    rec = files.read_record(str(path))
    return transform.scale(rec, scale) if scale != 1.0 else rec


def cases() -> list[tuple[str, Model, Record]]:
    facade = load_model(str(ROOT / "examples" / "facade.toml"))
    found = [("facade, Ricker", facade, record(ROOT / "records" / "ricker_Tp0.5s_0.5g.txt"))]
    if SHARED.is_dir():
        found += [
            ("issue wall, NORTHR × 0.8", validate_model(ISSUE_WALL),
             record(SHARED / "NORTHR_ARL360_CRCRLF.AT2", 0.8)),
            ("wall, ELC180", load_model(str(ROOT / "examples" / "wall.toml")),
             record(SHARED / "ELC180.AT2")),
            ("facade, NORTHR", facade, record(SHARED / "NORTHR_ARL360.AT2")),
        ]  # fmt: skip
    return found


def main() -> None:
    for name, model, rec in cases():
        cpu: dict[bool, list[float]] = {False: [], True: []}
        wall: dict[bool, list[float]] = {False: [], True: []}
        assess_model_output(model, rec, "fast")  # load the engine, fill the caches
        for _ in range(REPEATS):
            for check in (False, True):
                start, start_cpu = time.perf_counter(), time.thread_time()
                assess_model_output(model, rec, "fast", tolerance_check=check)
                cpu[check].append(time.thread_time() - start_cpu)
                wall[check].append(time.perf_counter() - start)
        without, with_ = (1e3 * statistics.median(cpu[k]) for k in (False, True))
        walls = [1e3 * statistics.median(wall[k]) for k in (False, True)]
        print(f"{name}: CPU without {without:.2f} ms, with {with_:.2f} ms, extra "
              f"{with_ - without:.2f} ms (medians of {REPEATS}); wall {walls[0]:.2f} and "
              f"{walls[1]:.2f} ms")  # fmt: skip


if __name__ == "__main__":
    main()
