"""Benchmark: a study of a wall against a study of a block, per case, in one run (issue 37).

Measures in this process (one core, no worker start-up), each the median of REPEATS runs:

- the block: the paper's §4.4 wall with its top spring (R × α × K) on ELC180 (a 40 s
  record), rocking alone, batched (rockcli/studies/sweep/batch.py): what a block's study
  costs a case;
- the wall: the shipped two-storey façade (examples/two-storey-facade.toml) with the two
  storeys' thicknesses as axes, rocking and kinematic on the same record, through the
  study's own chunk runner (rockcli.studies.sweep.worker.run_chunk), and the same cases'
  parts on their own: the model built and validated, its catalogue derived (the optimal
  flexure hinges searched), the catalogue's code check (rockcli.analyses.kinematic
  .kinematic_model on the record's own spectrum, as the study's default --code-demand: every
  mechanism's α0, capacity curve, M*, e* and checks), the governing mechanism rocked (both
  polarities).

Prints the time a case of each, the wall's ratio to the block (the issue's target: ≤ 5), the
integration steps a case of each and the time a step (like with like: a case of the wall rocks
through the whole record and its tail, most of the block study's cases overturn early or stay
at rest), and the catalogue check's time a case (the target: ≤ 1 ms with --jobs 2, so ≤ 2 ms
on one core).

    python benchmarks/wall_study.py [CASES]    # default 12; needs ../shared/records
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared" / "records"
REPEATS = 5
#: The issue's targets: a wall's case at most this many times a block's (batched, same
#: record); the catalogue's code check at most this long a case with --jobs 2 [s].
TARGET_RATIO = 5.0
TARGET_CHECK = 1e-3

#: The wall's study: the storeys' thicknesses (3 × 4 values: 12 distinct geometries).
WALL_STUDY = """\
name = "two-storey façade, thicknesses"
base = "wall.toml"
analyses = ["rocking", "kinematic"]
records_dir = "records"
[[records]]
path = "ELC180.AT2"
[[axes]]
path = "geometry.storeys[0].thickness"
name = "t1"
values = [0.50, 0.55, 0.60, 0.65]
[[axes]]
path = "geometry.storeys[1].thickness"
name = "t2"
values = [0.40, 0.45, 0.50]
"""


def median_per_case(fn: Callable[[], int]) -> float:
    """The median over REPEATS runs of fn's time divided by the cases it ran [s]."""
    times = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        n = fn()
        times.append((time.perf_counter() - start) / n)
    return statistics.median(times)


def block_per_case(folder: Path) -> tuple[float, float]:
    """A batched block study's (time a case, integration steps a case, both polarities): the
    §4.4 scale study's first 2000 cases."""
    from benchmarks.sweep import scale_study
    from rockcli.dynamics import batch
    from rockcli.dynamics import layout as L
    from rockcli.studies.sweep.study import load_study
    from rockcli.studies.sweep.worker import Chunk, run_chunk

    plan = load_study(str(scale_study(folder, shrink=10)))
    chunk = Chunk(plan, 0, range(2000))
    run_chunk(Chunk(plan, 0, range(2)))  # the record read, the kernels loaded
    per_case = median_per_case(lambda: len(run_chunk(chunk)))
    run_blocks, steps = batch.run_blocks, [0]

    def counted(*args: Any) -> Any:
        runs = run_blocks(*args)
        integrated = ~runs.mirrored
        steps[0] += int(runs.out_i[:, 0, L.I_STEPS].sum())
        steps[0] += int(runs.out_i[integrated, 1, L.I_STEPS].sum())
        return runs

    batch.run_blocks = counted
    try:
        n = len(run_chunk(chunk))
    finally:
        batch.run_blocks = run_blocks
    return per_case, steps[0] / n


def wall_plan(folder: Path) -> Any:
    """The wall's study plan, written into ``folder`` with its model and record."""
    from rockcli.studies.sweep.study import load_study

    (folder / "records").mkdir()
    (folder / "records" / "ELC180.AT2").write_bytes((SHARED / "ELC180.AT2").read_bytes())
    model = (ROOT / "examples" / "two-storey-facade.toml").read_bytes()
    (folder / "wall.toml").write_bytes(model)
    (folder / "study.toml").write_text(WALL_STUDY, encoding="utf-8")
    return load_study(str(folder / "study.toml"))


def integration_per_case(rock: Callable[[], int]) -> float:
    """The time a case spends in the compiled integration itself (rockcli.dynamics.kernel
    .integrate, both polarities) when ``rock`` runs its cases [s]: the physics' own cost,
    which no batching removes (a wall's mechanism that rocks through the whole record costs
    as much as a block that does)."""
    from rockcli.dynamics import kernel

    compiled = kernel.integrate
    spent = [0.0]

    def timed(*args: Any) -> None:
        start = time.perf_counter()
        compiled(*args)
        spent[0] += time.perf_counter() - start

    kernel.integrate = timed
    try:
        n = rock()
    finally:
        kernel.integrate = compiled
    return spent[0] / n


def wall_parts(plan: Any, ids: range) -> dict[str, float]:
    """The wall's study a case, whole and by part [s]."""
    from rockcli.analyses.assess import assess_model_output
    from rockcli.analyses.kinematic import kinematic_model
    from rockcli.model.catalogue import catalogue
    from rockcli.studies.sweep.cases import Cases, build_model
    from rockcli.studies.sweep.worker import (
        Chunk,
        case_mechanism,
        read_source,
        run_chunk,
        spectrum_of,
    )

    every = Cases(plan)
    cases = [every[k] for k in ids]
    record = read_source(plan.records[0])
    chunk = Chunk(plan, 0, ids)
    rows = run_chunk(chunk)  # warm: the kernels, the record's spectrum
    assert not any(r.get("error") for r in rows), rows[0]
    models = [build_model(plan, c) for c in cases]
    catalogues = [catalogue(m) for m in models]
    spectrum = spectrum_of(plan.records[0], models[0].analysis.g)

    def code_check(model: Any, mechanisms: Any) -> Any:
        """As a study's case checks it: on the record's own spectrum (--code-demand record)."""
        return kinematic_model(model, record=record, spectrum=spectrum, mechanisms=mechanisms)

    checks = [code_check(m, c) for m, c in zip(models, catalogues, strict=True)]
    names = [case_mechanism(k)[0] for k in checks]

    def build() -> int:
        for c in cases:
            build_model(plan, c)
        return len(cases)

    def derive() -> int:
        for m in models:
            catalogue(m)
        return len(models)

    def check() -> int:
        for m, c in zip(models, catalogues, strict=True):
            code_check(m, c)
        return len(models)

    def rock() -> int:
        for m, c, name in zip(models, catalogues, names, strict=True):
            assess_model_output(
                m, record, "fast", mechanism=name, mechanisms=c, tolerance_check=False
            )  # as a study's case (no --check-tolerance)
        return len(models)

    def steps() -> float:
        """Integration steps a case, both polarities (a mirrored run is not integrated)."""
        total = 0
        for m, c, name in zip(models, catalogues, names, strict=True):
            out = assess_model_output(
                m, record, "fast", mechanism=name, mechanisms=c, tolerance_check=False
            )
            total += sum(r.steps for r in out.result.runs if r.mirror_of is None)
        return total / len(models)

    return {
        "integration": integration_per_case(rock),
        "steps": steps(),
        "study": median_per_case(lambda: len(run_chunk(chunk))),
        "build": median_per_case(build),
        "catalogue": median_per_case(derive),
        "check": median_per_case(check),
        "rocking": median_per_case(rock),
    }


def main(cases: int) -> None:
    from rockcli.studies.parallel.setup import warm

    if not SHARED.is_dir():
        sys.exit(f"{SHARED} is not there: both studies need ELC180.AT2 from ../shared")
    warm()
    with tempfile.TemporaryDirectory() as a, tempfile.TemporaryDirectory() as b:
        block, block_steps = block_per_case(Path(a))
        plan = wall_plan(Path(b))
        parts = wall_parts(plan, range(min(cases, 12)))
    ms = 1e3
    print(f"per case, in process (one core), median of {REPEATS} runs, ELC180")
    print(f"  block study, batched (§4.4, R × α × K)     {ms * block:9.3f} ms")
    print(f"  wall study (two-storey façade, t1 × t2)    {ms * parts['study']:9.3f} ms")
    print(f"    model built and validated                {ms * parts['build']:9.3f} ms")
    print(f"    catalogue derived (optimal hinges)       {ms * parts['catalogue']:9.3f} ms")
    print(f"    catalogue's code check                   {ms * parts['check']:9.3f} ms")
    print(f"    governing mechanism rocked               {ms * parts['rocking']:9.3f} ms")
    print(f"      of which the compiled integration      {ms * parts['integration']:9.3f} ms")
    ratio = parts["study"] / block
    print(
        f"  wall / block                               {ratio:9.1f}   (target ≤ {TARGET_RATIO:g})"
    )
    us = 1e6
    print(f"  integration steps a case: block {block_steps:8.0f}, wall {parts['steps']:8.0f}")
    per_step = parts["integration"] / parts["steps"]
    print(f"  per step: block batched (whole case) {us * block / block_steps:6.3f} µs, "
          f"wall's compiled integration {us * per_step:6.3f} µs")  # fmt: skip
    check = parts["catalogue"] + parts["check"]
    print(f"  catalogue + code check, --jobs 2           {ms * check / 2:9.3f} ms   "
          f"(target ≤ {ms * TARGET_CHECK:g} ms)")  # fmt: skip


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 12)
