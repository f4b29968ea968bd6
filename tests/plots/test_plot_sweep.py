"""plot_sweep: the collapse map of a systemic study, on synthetic cases (the sweep calls it)."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from rockcli.plots import outcome, plot_sweep
from tests.plots.conftest import assert_png, assert_svg, needs_matplotlib

# The paper's first systemic grid (§3.3): R = 1.5, 3.5, 7, 10 m; α = 0.05 … 0.25 rad.
RS = (1.5, 3.5, 7.0, 10.0)
ALPHAS = (0.05, 0.10, 0.15, 0.25)
RECORDS = ("NVL", "MRN", "MOG0", "CAPEMEND", "AQV")


def synthetic_rows(with_k: bool = False) -> list[dict[str, object]]:
    """Every outcome appears: the code collapses the slender blocks, rocking only the small."""
    rows: list[dict[str, object]] = []
    ks = (0.0, 1e3) if with_k else (None,)
    for rec, R, alpha, K in itertools.product(RECORDS, RS, ALPHAS, ks):
        code = alpha <= 0.10
        rocking = alpha <= 0.05 and R < 5.0
        row: dict[str, object] = {
            "R": R, "alpha": alpha, "record": rec,
            "code_collapse": code, "rocking_collapse": rocking,
            "classification": "ignored by the plot",
        }  # fmt: skip
        if K is not None:
            row["K"] = K
        rows.append(row)
    rows[0]["code_collapse"] = False  # a rocking-only case (code unconservative)
    rows[1]["code_collapse"] = None  # a verdict missing
    return rows


@pytest.mark.parametrize(
    ("code", "rocking", "expected"),
    [
        (True, True, "both"),
        (True, False, "code"),
        (False, True, "rocking"),
        (False, False, "neither"),
        (None, False, "undetermined"),
        (True, None, "undetermined"),
    ],
)
def test_outcome(code: bool | None, rocking: bool | None, expected: str) -> None:
    assert outcome({"code_collapse": code, "rocking_collapse": rocking}) == expected


def test_sweep_map_png(tmp_path: Path) -> None:
    needs_matplotlib()
    out = tmp_path / "sweep.png"
    plot_sweep(synthetic_rows(), out)
    assert_png(out)


def test_sweep_map_by_stiffness_svg(tmp_path: Path) -> None:
    # One figure row per record, one column per K; several cases per cell are counted.
    needs_matplotlib()
    out = tmp_path / "sweep.svg"
    plot_sweep(synthetic_rows(with_k=True), out, by="K")
    assert_svg(out)


def test_sweep_map_several_cases_per_cell(tmp_path: Path) -> None:
    # Without `by`, the two K values share each cell: one marker per outcome with its count.
    needs_matplotlib()
    out = tmp_path / "sweep.png"
    plot_sweep(synthetic_rows(with_k=True), out)
    assert_png(out)


def test_sweep_rows_missing_a_key() -> None:
    rows = synthetic_rows()
    del rows[2]["rocking_collapse"]
    with pytest.raises(ValueError, match="case 2 has no rocking_collapse"):
        plot_sweep(rows, "sweep.png")


def test_sweep_without_rows() -> None:
    with pytest.raises(ValueError, match="no cases"):
        plot_sweep([], "sweep.png")
