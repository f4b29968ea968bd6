"""Issue 7, items 9 and 13: the edges of a study run (resume, workers, a failing disk)."""

from __future__ import annotations

import errno
from pathlib import Path
from typing import Any

import pytest

from rockcli.errors import InputError
from rockcli.studies.sweep import output as sweep_output
from rockcli.studies.sweep.executor import local_executor
from rockcli.studies.sweep.run import run_sweep
from rockcli.studies.sweep.study import load_study
from tests.sweep.conftest import WriteStudy

N_CASES = 16  # conftest.STUDY: 2 R × 2 α × 2 K × 2 pulses


def test_resume_refuses_a_record_changed_at_the_same_size(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    # Before: the fingerprint hashed the record's name and size, so an edited record of the
    # same size resumed with the old rows. One digit changed, same byte count.
    study = write_study()
    out = tmp_path / "out"
    with local_executor(1) as lanes:
        run_sweep(load_study(str(study)), str(out), lanes)
    record = tmp_path / "records" / "ricker_Tp0.5s_0.5g.txt"
    text = record.read_text()
    lines = text.splitlines(keepends=True)
    k = next(
        i for i, line in enumerate(lines) if line.strip() and line[0].isdigit() and "1" in line
    )
    lines[k] = lines[k].replace("1", "2", 1)
    edited = "".join(lines)
    assert len(edited) == len(text) and edited != text
    record.write_text(edited)
    with local_executor(1) as lanes, pytest.raises(InputError, match="another study"):
        run_sweep(load_study(str(study)), str(out), lanes, resume=True)


def test_a_full_disk_mid_sweep_says_how_many_cases_are_saved(
    write_study: WriteStudy, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: list[int] = []
    original = sweep_output.Output.append

    def append_then_fail(self: Any, rows: Any) -> Any:
        calls.append(1)
        if len(calls) > 2:
            raise OSError(errno.ENOSPC, "No space left on device")
        return original(self, rows)

    monkeypatch.setattr(sweep_output.Output, "append", append_then_fail)
    with local_executor(1) as lanes, pytest.raises(InputError) as info:
        run_sweep(load_study(str(write_study())), str(tmp_path / "out"), lanes, chunk_size=2)
    text = str(info.value)
    assert f"No space left on device; 4 of {N_CASES} cases saved" in text  # 2 chunks of 2
    assert "rerun with --resume" in text


@pytest.mark.parametrize(
    ("jobs", "cpus", "cases", "expected", "note"),
    [
        (None, 2, 100, 2, None),
        (8, 2, 100, 2, "--jobs 8 capped to 2 (the CPU count)"),
        (4, 8, 3, 3, "--jobs 4 capped to 3 (the cases of the study)"),
        (2, 8, 100, 2, None),
    ],
)
def test_workers_are_capped_at_the_cpus_and_the_cases(
    jobs: int | None,
    cpus: int,
    cases: int,
    expected: int,
    note: str | None,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    from rockcli.cli import sweep as cli_sweep

    monkeypatch.setattr(cli_sweep.os, "cpu_count", lambda: cpus)
    assert cli_sweep.worker_count(jobs, cases) == expected
    err = capsys.readouterr().err
    assert (note in err) if note else err == ""


def test_an_element_of_an_array_the_base_lacks_is_one_error(write_study: WriteStudy) -> None:
    # Before: KeyError (set_path indexed a table created for the absent array).
    from tests.sweep.conftest import BASE, STUDY

    base = BASE.split("[[restrainers]]")[0] + '[ntc]\nedition = "2009"\nFC = 1.0\n'
    study = STUDY.split("[[axes]]\npath = [")[0] + STUDY.split("values = [0.0, 1e6]\n")[1]
    study = study.replace('path = "geometry.R"', 'path = "restrainers[0].k_pos"')
    with pytest.raises(InputError) as info:
        load_study(str(write_study(study, base=base)))
    assert "axes[0].path: restrainers[0] is not in the base model" in str(info.value)
