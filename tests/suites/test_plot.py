"""`rock suite check --plot`: a PNG or an SVG that a reader accepts, written before the report."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.plots.conftest import assert_png, assert_svg, needs_matplotlib, run
from tests.suites.conftest import PULSES, write_suite


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_plot_is_written(tmp_path: Path, suffix: str) -> None:
    needs_matplotlib()
    suite = write_suite(tmp_path, [{"path": str(p)} for p in PULSES])
    out = tmp_path / f"suite{suffix}"
    code, stdout, stderr = run("suite", "check", str(suite), "--plot", str(out))
    assert code == 0, stderr
    assert f"wrote {out}" in stderr and "verdict:" in stdout
    (assert_png if suffix == ".png" else assert_svg)(out)


def test_existing_plot_needs_force(tmp_path: Path) -> None:
    suite = write_suite(tmp_path, [{"path": str(p)} for p in PULSES])
    out = tmp_path / "suite.png"
    out.write_bytes(b"keep")
    code, _, stderr = run("suite", "check", str(suite), "--plot", str(out))
    assert code == 2 and "--force" in stderr and out.read_bytes() == b"keep"
