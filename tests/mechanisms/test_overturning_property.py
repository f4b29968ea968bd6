"""Overturning of random one-storey walls (hypothesis): α0 by hand, and the mirror.

Sources: the Circolare's virtual work at θ = 0 (Circ. 617/2009 Eq. C8A.4.1; Circ. 7/2019
§C8.7.1.1) for one rigid body about the outer base edge: α0 = Σ P_i x_i / Σ P_i z_i over the
wall's weight at its centroid (t/2, h/2) and the loads (each bearing and moving); the
mirror through the wall's mid-plane (x → t − x) swaps the outer and inner base edges, so
side −1 of a wall is side 1 of its mirror, term by term.

Tolerance: the same few products summed in another order: 1e-12 relative (absolute 1e-12
of the sums' scale for terms that vanish).
"""

from __future__ import annotations

from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rockcli.codecheck.kinematic import Mechanism, alpha0, e_star, load_multiplier
from rockcli.mechanisms import catalogue
from rockcli.mechanisms.motion import generalised_mass, participation, potential_slope
from rockcli.mechanisms.wall import Storey, Wall, WallLoad

#: Cheap examples (a few sums each), kept bounded.
EXAMPLES = settings(max_examples=60, deadline=None)
G = 9.81
REL = 1e-12


@st.composite
def walls(draw: st.DrawFn) -> Wall:
    """A one-storey wall with up to three loads (bearing and moving) above its base."""
    h = draw(st.floats(1.0, 6.0))
    t = draw(st.floats(0.2, 0.9))
    n = draw(st.integers(0, 3))
    loads = tuple(
        WallLoad(
            f"P{i}",
            draw(st.floats(0.0, 1e5)),
            draw(st.floats(0.0, 1.0)) * t,
            draw(st.floats(0.05, 1.0)) * h,
        )  # fmt: skip
        for i in range(n)
    )
    return Wall(storeys=(Storey(h, t),), width=draw(st.floats(0.5, 5.0)),
                unit_weight=draw(st.floats(14e3, 22e3)), g=G, loads=loads)  # fmt: skip


def mirror(wall: Wall) -> Wall:
    """The wall seen through its mid-plane: every load at t − x."""
    t = wall.storeys[0].thickness
    return replace(wall, loads=tuple(replace(ld, x=t - ld.x) for ld in wall.loads))


@EXAMPLES
@given(walls())
def test_alpha0_by_hand(wall: Wall) -> None:
    s = wall.storeys[0]
    w = wall.unit_weight * s.thickness * s.height * wall.width
    num = w * s.thickness / 2 + sum(ld.weight * ld.x for ld in wall.loads)
    den = w * s.height / 2 + sum(ld.weight * ld.z for ld in wall.loads)
    side = catalogue.overturning(wall, 0.0, 1, "o")
    assert alpha0(Mechanism(side)) == pytest.approx(num / den, rel=REL)


@EXAMPLES
@given(walls(), st.floats(0.0, 1.2))
def test_mirror(wall: Wall, theta: float) -> None:
    inner = catalogue.overturning(wall, 0.0, -1, "o")
    outer = catalogue.overturning(mirror(wall), 0.0, 1, "o")
    m_in, m_out = Mechanism(inner), Mechanism(outer)
    assert alpha0(m_in) == pytest.approx(alpha0(m_out), rel=REL)
    assert e_star(m_in) == pytest.approx(e_star(m_out), rel=REL)
    # α(θ) passes through zero (order-one away from it): abs 1e-12 as well.
    assert load_multiplier(m_in, theta) == pytest.approx(load_multiplier(m_out, theta),
                                                         rel=REL, abs=REL)  # fmt: skip
    for f in (generalised_mass, participation):
        assert f(inner, theta) == pytest.approx(f(outer, theta), rel=REL)
    scale = sum(abs(v) for v in outer.work_terms(theta))
    assert potential_slope(inner, theta) == pytest.approx(potential_slope(outer, theta),
                                                          rel=REL, abs=REL * scale)  # fmt: skip
