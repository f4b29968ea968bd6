"""The chain's table evaluates its grid of rotations at once (numpy arrays through the same
configuration function): every link state, and every row of the table, against the same
function called rotation by rotation — equal to rounding (numpy's sin and cos may differ from
math's in the last bit; the table's interpolation error is 1e-11)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.mechanics import versine
from rockcli.mechanisms.links import TwoBlock, versines
from rockcli.mechanisms.table import NODES, end_of, nodes, rows, slopes, terms

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "two-storey-facade.toml"
FIELDS = ("cx", "cz", "phi", "dcx", "dcz", "dphi", "ux", "uz")


@given(st.floats(-0.1, 0.1))
def test_versines_of_an_array_are_versine_of_each(a: float) -> None:
    grid = np.array([a, 0.029999, 0.03, 0.5 * a, 3.0 * a])
    out = versines(grid, np.cos(grid))
    assert [float(v) for v in out] == [versine(float(x), float(np.cos(x))) for x in grid]


@settings(max_examples=60, deadline=None)
@given(
    st.floats(0.15, 0.6),  # the hinge's x from the pivot (the section's far side)
    st.floats(1.0, 4.0),  # the hinge's height
    st.floats(0.0, 0.3),  # the top's x
    st.floats(0.5, 3.0),  # the top above the hinge
)
def test_two_block_states_of_a_grid_are_each_rotations(
    hx: float, hz: float, tx: float, above: float
) -> None:
    motion = TwoBlock(hx, hz, tx, hz + above)
    grid = np.linspace(0.0, 0.9 * motion.limit, 41)
    at_once = motion.states(grid)
    for k, theta in enumerate(grid):
        one = motion.states(float(theta))
        for link_all, link in zip(at_once, one, strict=True):
            for name in FIELDS:
                got, want = (
                    np.broadcast_to(getattr(link_all, name), grid.shape)[k],
                    getattr(link, name),
                )
                assert math.isclose(got, want, rel_tol=1e-12, abs_tol=1e-15), (name, theta)


def test_the_tables_rows_are_the_configuration_function_node_by_node() -> None:
    from rockcli.model.catalogue import catalogue
    from rockcli.model.load import load_model

    flexures = [
        m for m in catalogue(load_model(EXAMPLE)) if m.spec.type.value == "vertical-flexure"
    ]
    assert flexures
    for mech in flexures:
        plus, minus = mech.views
        end = end_of(plus, minus)
        table = np.array(rows(plus, end)).reshape(NODES, 10)
        grid = nodes(end)
        for k in (0, 1, 7, 300, 511, NODES - 2, NODES - 1):
            a = float(grid[k])
            values = terms(plus, a)
            node = [*values, *slopes(plus, a, values[4])]
            # G, H, T, M, M' and their slopes to rounding; M''s central difference (last
            # column) amplifies a last-bit difference of M' by 1/(2·3e-4)
            for col, want in enumerate(node):
                tol = 1e-8 if col == 9 else 1e-11
                assert math.isclose(table[k, col], want, rel_tol=tol, abs_tol=1e-9), (k, col)


def test_one_table_serves_every_rod() -> None:
    """A chain's table reads its weights, not its restrainers: sides that differ only by a
    member's stiffness (a retrofit's diameters) share one table."""
    from dataclasses import replace

    from rockcli.mechanisms.table import tabulate
    from rockcli.model.catalogue import catalogue, named
    from rockcli.model.load import load_model

    mech = named(catalogue(load_model(EXAMPLE)), "vertical flexure, storey 2")
    plus, minus = mech.views
    assert plus.restrainers, "the example's tie-rod is on the flexure of storey 2"

    def stiffer(side):
        return replace(side, restrainers=tuple(replace(r, k_pos=2 * r.k_pos, k_neg=2 * r.k_neg)
                                               for r in side.restrainers))  # fmt: skip

    other_plus, other_minus = stiffer(plus), stiffer(minus)
    assert other_plus != plus
    assert tabulate(other_plus, other_minus) is tabulate(plus, minus)
