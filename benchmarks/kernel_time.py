"""Benchmark: where the compiled kernel's time goes in a study (issue 24, item 6).

On 3 000 random cases of the `--scale` study of benchmarks/sweep.py (the §4.4 wall with its
top spring, R × α × K, on ELC180, a 40 s record, 4 000 samples), run as a batched study runs
them (rockcli.dynamics.batch.run_blocks, one call), the best of three:

- the time per case;
- the same blocks on the record scaled by 1e-3, so that they never uplift: the rest scan
  over the record, the packing, the call (the free tail is skipped at rest);
- the steps per case (accepted, rejected) and the time per step;
- the same runs with no free tail after the record: the tail's share.

    python benchmarks/kernel_time.py      # needs ../shared/records
"""

from __future__ import annotations

import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

CASES = 3000
REPEATS = 3


def main() -> None:
    import numpy as np

    import rockcli.kernels  # noqa: F401 - registers the warm-up
    from benchmarks.sweep import SHARED, scale_study
    from rockcli.analyses.assess import settings_from
    from rockcli.dynamics import batch as arrays
    from rockcli.dynamics import layout as L
    from rockcli.model.derive import solver_options
    from rockcli.studies.parallel.setup import warm
    from rockcli.studies.sweep import batch, worker
    from rockcli.studies.sweep.cases import expand
    from rockcli.studies.sweep.study import load_study

    if not SHARED.is_dir():
        sys.exit(f"{SHARED} is not there: the scale study needs ELC180.AT2 from ../shared")
    warm()
    with tempfile.TemporaryDirectory() as tmp:
        plan = load_study(str(scale_study(Path(tmp))))
        cases = expand(plan)
        ids = np.sort(np.random.default_rng(3).choice(len(cases), CASES, replace=False))
        form = batch.batch_form(plan)
        assert form is not None
        record = worker.read_source(plan.records[0])
        blocks, _ = batch.derive(form, np.array([cases[int(k)].indices for k in ids]))
        settings = settings_from(solver_options(form.model))

        def per_case(accel: np.ndarray, how: object = settings) -> tuple[float, object]:
            best, runs = float("inf"), None
            for _ in range(REPEATS):
                start = time.perf_counter()
                runs = arrays.run_blocks(record.time, accel, record.dt, blocks, how)  # type: ignore[arg-type]
                best = min(best, time.perf_counter() - start)
            return best / CASES, runs

        full, runs = per_case(record.accel)
        rest, _ = per_case(record.accel * 1e-3)
        short, _ = per_case(record.accel, replace(settings, tail=record.dt))
    out_i = runs.out_i[:, 0]  # type: ignore[attr-defined]
    steps, rejected = out_i[:, L.I_STEPS], out_i[:, L.I_REJECTED]
    print(
        f"{CASES} cases of the scale study on ELC180 ({record.npts} samples), one call, "
        f"best of {REPEATS}; every block is mirror-symmetric: one polarity integrated"
    )
    print(f"  per case                                   {1e3 * full:7.3f} ms")
    print(
        f"  never uplifting (record × 1e-3): rest scan, packing, call "
        f"{1e3 * rest:7.3f} ms  ({100 * rest / full:.0f} %)"
    )
    print(
        f"  the free tail after the record             {1e3 * (full - short):7.3f} ms  "
        f"({100 * (full - short) / full:.0f} %)"
    )
    per_step = 1e9 * (full - rest) / np.mean(steps + rejected)
    print(f"  steps per case: median {np.median(steps):.0f} accepted, "
          f"{np.median(rejected):.0f} rejected; {per_step:.0f} ns per step")  # fmt: skip


if __name__ == "__main__":
    main()
