"""Benchmark: the fast engine of this checkout against another checkout, on the single-block
cases of benchmarks/engine.py (its records, three of its noise seeds) and the loaded block of
examples/facade.toml on ELC180, in one run.

Each round times every case (median of REPEATS runs, compile excluded) in a fresh process of
each checkout, the two alternating, so that a drift of the machine's speed falls on both;
the figure of a case is the median over the rounds. Prints each case's medians, their ratio
(this / other) and the median ratio over the cases.

    python benchmarks/regression.py --against /path/to/other/checkout [--rounds 5]

Make the other checkout with ``git worktree add /tmp/old COMMIT``. Needs ../shared/records
beside this clone (the cases' records).
"""

from __future__ import annotations

import json
import statistics
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPEATS = 51
ROUNDS = 5

#: Run in the child: import rockcli from the checkout given (an editable install's finder
#: removed, so that the path decides), time every case of benchmarks/engine.py.
CHILD = r"""
import json, statistics, sys, time
sys.meta_path = [f for f in sys.meta_path if "editable" not in repr(f).lower()]
sys.path.insert(0, sys.argv[1])
sys.path.insert(0, sys.argv[2])
from rockcli.dynamics.simulate import simulate
from rockcli.model.derive import to_block
from rockcli.model.load import load_model
import engine
repeats = int(sys.argv[3])
cases = [(label, engine.read_record(engine.SHARED / name), blk)
         for label, name, blk in engine.CASES]
cases += [(f"noise seed {k} R3 a0.20", engine.noise_record(k), engine.block(3.0, 0.2))
          for k in range(3)]
facade = to_block(load_model(sys.argv[4]))  # loads, thrust, tie: the loaded path
cases.append(("facade.toml (loaded) ELC180", engine.read_record(engine.SHARED / "ELC180.AT2"),
              facade))
out = {}
for label, rec, block in cases:
    t, a, dt = rec if isinstance(rec, tuple) else (rec.time, rec.accel, rec.dt)
    simulate(block, t, a, dt)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        simulate(block, t, a, dt)
        times.append(time.perf_counter() - start)
    out[label] = statistics.median(times)
print(json.dumps(out))
"""


def timings(checkout: Path, repeats: int) -> dict[str, float]:
    """{case: median seconds} of one fresh process importing rockcli from ``checkout``."""
    done = subprocess.run(
        [sys.executable, "-c", CHILD, str(checkout), str(HERE), str(repeats),
         str(HERE.parent / "examples" / "facade.toml")],
        capture_output=True, text=True, check=True,
    )  # fmt: skip
    return json.loads(done.stdout.strip().splitlines()[-1])


def main() -> None:
    args = sys.argv[1:]
    other = Path(args[args.index("--against") + 1]).resolve()
    rounds = int(args[args.index("--rounds") + 1]) if "--rounds" in args else ROUNDS
    this = HERE.parent
    timings(this, 1), timings(other, 1)  # compile both into their caches first
    runs: dict[str, list[dict[str, float]]] = {"this": [], "other": []}
    for _ in range(rounds):
        runs["this"].append(timings(this, REPEATS))
        runs["other"].append(timings(other, REPEATS))
    print(f"fast engine, median of {REPEATS} runs per round, median over {rounds} rounds")
    print(f"{'case':36s} {'this ms':>8s} {'other ms':>9s} {'this/other':>11s}")
    ratios = []
    for case in runs["this"][0]:
        mine = statistics.median(r[case] for r in runs["this"])
        theirs = statistics.median(r[case] for r in runs["other"])
        ratios.append(mine / theirs)
        print(f"{case:36s} {mine * 1e3:8.3f} {theirs * 1e3:9.3f} {mine / theirs:11.3f}")
    print(f"median ratio this/other over the cases: {statistics.median(ratios):.3f}")


if __name__ == "__main__":
    main()
