"""The engine's inputs by kind (issue 35): ``Block`` is the paper's rectangle and nothing else;
a rigid body of another shape is a ``RigidBody``, a chain of bodies a ``Chain``; the rectangle
described as a rigid body of its own shape is the same system (its I_G = m(4b² + 4h²)/12 about
the centroid, Housner 1963)."""

from __future__ import annotations

import math
from dataclasses import fields

import pytest

from rockcli.dynamics import layout as L
from rockcli.dynamics.simulate import engine_kind
from rockcli.mechanics import (
    Block,
    Load,
    RigidBody,
    Rocker,
    collapse_rotations,
    impact_restitution,
    mirror_symmetric,
    mirrored,
    uplift_accelerations,
)

B, H, M = 0.25, 1.4, 800.0
R, ALPHA = math.hypot(B, H), math.atan2(B, H)


def as_body(**extra: object) -> RigidBody:
    """The rectangle B × H as a rigid body of its own shape."""
    i_g = M * (4 * B * B + 4 * H * H) / 12.0
    return RigidBody(R=R, alpha=ALPHA, mass=M, shape=(B, B, H, i_g), **extra)  # type: ignore[arg-type]


def test_block_is_the_rectangle_only() -> None:
    assert [f.name for f in fields(Block)] == [f.name for f in fields(Rocker)]
    assert "body" not in {f.name for f in fields(Block)}
    assert "chain" not in {f.name for f in fields(Block)}


def test_each_kind_names_its_equation() -> None:
    block = Block(R=R, alpha=ALPHA, mass=M)
    loaded = Block(R=R, alpha=ALPHA, mass=M, loads=(Load("roof", 1e3, B, B, 2 * H),))
    assert (block.kind, loaded.kind, as_body().kind) == ("rectangle", "points", "points")
    assert engine_kind(block) == L.K_RECTANGLE
    assert engine_kind(as_body()) == L.K_POINTS


def test_the_rectangle_as_a_body_is_the_same_system() -> None:
    block, body = Block(R=R, alpha=ALPHA, mass=M), as_body()
    assert body.inertia == pytest.approx(4.0 / 3.0 * M * R * R, rel=1e-13)
    assert body.p2 == pytest.approx(3 * 9.81 / (4 * R), rel=1e-13)
    for got, want in (
        (uplift_accelerations(body), (B / H, B / H)),
        (collapse_rotations(body), (ALPHA, ALPHA)),
        ((impact_restitution(body, 1), impact_restitution(body, -1)),
         (1 - 1.5 * math.sin(ALPHA) ** 2,) * 2),
    ):  # fmt: skip
        assert got == pytest.approx(want, rel=1e-12)
    assert impact_restitution(block, 1) == pytest.approx(impact_restitution(body, 1), rel=1e-12)


def test_a_body_off_centre_is_mirrored_by_its_shape() -> None:
    body = as_body()
    off = RigidBody(R=R, alpha=ALPHA, mass=M, shape=(B, 2 * B, H, 10.0))
    assert mirror_symmetric(body)
    assert not mirror_symmetric(off)
    assert mirrored(off).shape == (2 * B, B, H, 10.0)
    assert uplift_accelerations(mirrored(off)) == uplift_accelerations(off)[::-1]
