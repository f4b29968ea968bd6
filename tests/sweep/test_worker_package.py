"""The worker processes of `rock sweep --jobs N` import the rockcli the command imported.

Issue 34 item 7: run from a clone's root, the fork server (``python -c …``, the current folder
first on its sys.path) imported the working tree's ``rockcli`` instead of the installed one,
compiling the engine into the tree and running code that was not installed. Here the current
folder holds a fake ``rockcli`` that leaves a marker and refuses to import: the installed
`rock sweep --jobs 2` run from there must never import it, and every case must succeed.
"""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

import pytest

from rockcli.studies.parallel.executor import start_method
from tests.sweep.conftest import BASE, WriteStudy

#: Seconds a small study with a worker process takes at most (the kernels are cached).
TIME_LIMIT = 300

FAKE = """\
import os
here = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
with open(os.path.join(here, "imported.txt"), "a", encoding="utf-8") as marker:
    marker.write(f"{os.getpid()}\\n")
raise ImportError("the fake rockcli of the current folder")
"""

#: Four cases, one per chunk: the worker process takes some of them.
STUDY = """\
base = "wall.toml"
records_dir = "records"

[[axes]]
path = "geometry.alpha"
name = "alpha"
values = [0.1, 0.15, 0.2, 0.25]

[[records]]
path = "ricker_Tp0.5s_0.5g.txt"
name = "ricker"
"""


@pytest.mark.skipif(start_method() != "forkserver", reason="no fork server on this platform")
def test_workers_ignore_a_rockcli_in_the_current_folder(
    write_study: WriteStudy, tmp_path: Path
) -> None:
    rock = Path(sys.executable).with_name("rock")
    if not rock.exists():
        pytest.skip(f"no installed rock script next to {sys.executable}")
    study = write_study(STUDY, BASE)
    (tmp_path / "rockcli").mkdir()
    (tmp_path / "rockcli" / "__init__.py").write_text(FAKE, encoding="utf-8")
    out = tmp_path / "out"
    done = subprocess.run(
        [str(rock), "sweep", study.name, "--out", str(out), "--jobs", "2", "--chunk-size", "1",
         "--no-progress", "--format", "json"],
        cwd=tmp_path, capture_output=True, text=True, timeout=TIME_LIMIT,
    )  # fmt: skip
    assert not (tmp_path / "imported.txt").exists(), "a process imported the fake rockcli"
    assert done.returncode == 0, done.stderr
    with (out / "cases.csv").open(encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 4
    assert all(not row["error"] for row in rows), [row["error"] for row in rows]
