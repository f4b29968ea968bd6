"""Fragility at the sweep's speed: an IDA of 7 records × 3 damage states on one wall, against
`rock sweep` running time histories of the same wall on the same records, in one run.

    python benchmarks/fragility.py [--records DIR] [--repeats N] [--jobs J]

Both commands run as a user runs them (`rock ... --jobs J`, a fresh process each time), on
examples/two-storey-facade.toml (a wall: its governing mechanism rocks, on its floor motion)
and the seven PEER records of ../shared/records. The sweep runs each record at six scale
factors (42 runs). Printed: each repeat's wall time, the runs computed and runs per second
(of the whole command, and within the wall time each command reports for its study: the
process start and imports left out), and their medians. The issue's target: the IDA under
10 s on 2 cores.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MODEL = ROOT / "examples" / "two-storey-facade.toml"
RECORDS = (
    "ELC180.AT2", "CPM000.AT2", "NORTHR_ARL360.AT2", "KOBE95_NIS090_NGAW1.AT2",
    "RSN753_LOMAP_CLS000.AT2", "RSN808_LOMAP_TRI000.AT2", "FRIULI76_TMZ000_NGAW2_RSN125.AT2",
)  # fmt: skip
SCALES = (0.5, 1.0, 1.5, 2.0, 2.5, 3.0)


def ida_study(records: Path) -> str:
    entries = "".join(f'\n[[records]]\npath = "{records / r}"\n' for r in RECORDS)
    return f"""name = "IDA benchmark"
model = "{MODEL}"
method = "ida"

[intensity]
measure = "pga"

[[damage_states]]
level = 0.1

[[damage_states]]
level = 0.5

[[damage_states]]
level = "overturning"

[ida]
first = 0.02
step = 0.02
last = 1.5
tolerance = 0.001
{entries}"""


def sweep_study(records: Path) -> str:
    entries = "".join(
        f'\n[[records]]\nname = "{r} x{s:g}"\npath = "{records / r}"\nscale = {s}\n'
        for r in RECORDS
        for s in SCALES
    )
    return f"""name = "sweep benchmark"
base = "{MODEL}"
analyses = ["rocking"]
{entries}"""


def run(args: list[str]) -> tuple[float, dict]:
    start = time.perf_counter()
    done = subprocess.run(args, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"failed: {' '.join(args)}\n{done.stderr}")
    return wall, json.loads(done.stdout)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--records", default=str(ROOT.parent / "shared" / "records"))
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--jobs", type=int, default=2)
    opts = parser.parse_args()
    records = Path(opts.records).resolve()
    if not all((records / r).is_file() for r in RECORDS):
        sys.exit(f"the seven PEER records are not all in {records}")
    rock = [sys.executable, "-m", "rockcli"]
    common = ["--jobs", str(opts.jobs), "--no-progress", "--format", "json", "--allow-outside"]
    with tempfile.TemporaryDirectory() as tmp:
        here = Path(tmp)
        (here / "ida.toml").write_text(ida_study(records), encoding="utf-8")
        (here / "sweep.toml").write_text(sweep_study(records), encoding="utf-8")
        ida, sweep = [], []
        for k in range(opts.repeats):
            wall, doc = run([*rock, "fragility", str(here / "ida.toml"), "--out",
                             str(here / f"ida{k}"), *common])  # fmt: skip
            runs, inner = doc["run"]["computed_runs"], doc["run"]["wall_time_s"]
            ida.append((wall, runs, runs / wall, runs / inner))
            print(f"IDA   repeat {k + 1}: {wall:6.2f} s, {runs} runs, {runs / wall:6.1f} runs/s "
                  f"(study alone: {inner:.2f} s, {runs / inner:.0f} runs/s)")  # fmt: skip
            wall, doc = run([*rock, "sweep", str(here / "sweep.toml"), "--out",
                             str(here / f"sweep{k}"), *common])  # fmt: skip
            runs, inner = doc["computed_cases"], doc["wall_time_s"]
            sweep.append((wall, runs, runs / wall, runs / inner))
            print(f"sweep repeat {k + 1}: {wall:6.2f} s, {runs} runs, {runs / wall:6.1f} runs/s "
                  f"(study alone: {inner:.2f} s, {runs / inner:.0f} runs/s)")  # fmt: skip
    for name, rows in (("IDA (7 records × 3 states)", ida), ("rock sweep (42 runs)", sweep)):
        wall = statistics.median(r[0] for r in rows)
        rate = statistics.median(r[2] for r in rows)
        inner = statistics.median(r[3] for r in rows)
        print(f"median {name}: {wall:.2f} s, {rate:.1f} runs/s (whole command, --jobs "
              f"{opts.jobs}); {inner:.0f} runs/s within the study's own wall time")  # fmt: skip


if __name__ == "__main__":
    main()
