"""The wedge's impact loses energy, by the number a hand computation gives (docs/physics.md,
"One-sided impacts").

A one-storey façade H = 5 m high, t = 0.5 m thick, L = 4 m wide, dragging a wedge of one
return wall t_r = 0.4 m thick cracked at β = 30° from the vertical through the base corner at
the façade's inner face; 18 kN/m³, no masonry strength (the pivots at the section's edges: O at
x = 0, O′ at x = t). Its masses, centroids and inertias about the centroid, by hand:

- façade: m_f = γ·t·H·L/g, at (t/2, H/2), I_f = m_f·(t² + H²)/12 (a rectangle);
- wedge: the right triangle (t, 0), (t, H), (t + w, H) with w = H·tan β: m_w = γ·(H·w/2)·t_r/g,
  at (t + w/3, 2H/3), I_w = m_w·(w² + H²)/18 (a right triangle of legs w and H: m·(a² + b² +
  c²)/36 with c² = a² + b²).

Per unit rate about a pivot P at the base, v = ω × (r − P): D = Σ I_i + m_i·|r_i − O|², D′ =
Σ I_i + m_i·|r_i − O′|², N = Σ I_i + m_i·(r_i − O)·(r_i − O′). The wedge's centroid lies
inward of O′ (x > t), so Housner's e about O′, N/D′ = 1.0011, exceeds 1; it was clipped to 1 and
the one-sided wedge rebounded with all its energy. The one-sided impact keeps the energy
Housner's impact keeps, N²/(D·D′), and the wedge turns back about O with it:
e = N/√(D·D′) = 0.98731 (by hand below), and r_f = 1 loses 1 − e² = 2.5 % of the kinetic
energy at each impact. The same sums over a fine grid of the two bodies' mass check the
closed forms of the centroids and inertias, and a free-rocking run of the engine loses
(1 − e²)·V(θ0) at its one impact (the potential energy it was released with).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from rockcli.analyses.rocked import mechanism_block
from rockcli.dynamics.settings import SolverSettings
from rockcli.dynamics.simulate import simulate
from rockcli.model.derive_wall import to_wall
from rockcli.model.load import load_model
from tests.demand import SOIL_B

G = 9.81
GAMMA, H, T, L, T_R, BETA = 18e3, 5.0, 0.5, 4.0, 0.4, math.radians(30.0)

MODEL = (
    f"""
name = "One storey with one return-wall wedge"
kind = "wall"

[geometry]
width = {L}

[[geometry.storeys]]
height = {H}
thickness = {T}

[return_walls]
thickness = {T_R}

[mass]
unit_weight = {GAMMA / 1e3}

[[mechanisms]]
type = "wedge"
angle = 30.0
sides = 1

[ntc]
edition = "2019"
FC = 1.35
q = 2.0
soil = "B"
topography = "T1"
"""
    + SOIL_B
)


def bodies() -> list[tuple[float, float, float, float]]:
    """(m [kg], x [m], z [m], I_G [kg·m²]) of the façade and of the wedge, by hand."""
    m_f = GAMMA * T * H * L / G
    w = H * math.tan(BETA)
    m_w = GAMMA * (H * w / 2.0) * T_R / G
    return [
        (m_f, T / 2.0, H / 2.0, m_f * (T * T + H * H) / 12.0),
        (m_w, T + w / 3.0, 2.0 * H / 3.0, m_w * (w * w + H * H) / 18.0),
    ]


def sums(parts) -> tuple[float, float, float]:
    """(D about O, D′ about O′, N) over (m, x, z, I_G) parts; O at x = 0, O′ at x = T."""
    d = sum(i + m * (x * x + z * z) for m, x, z, i in parts)
    d_new = sum(i + m * ((x - T) ** 2 + z * z) for m, x, z, i in parts)
    n = sum(i + m * (x * (x - T) + z * z) for m, x, z, i in parts)
    return d, d_new, n


def grid(n: int) -> list[tuple[float, float, float, float]]:
    """The two bodies as n × n cells of point mass (I_G = 0): the façade's rectangle on a
    regular grid, the triangle row by row (each row's cells spread over its width)."""
    zf, xf = np.meshgrid((np.arange(n) + 0.5) * H / n, (np.arange(n) + 0.5) * T / n)
    cell_f = GAMMA * L * (T / n) * (H / n) / G
    rows = (np.arange(n) + 0.5) * H / n
    widths = rows * math.tan(BETA)  # the wedge's width at each row's mid-height
    u = (np.arange(n) + 0.5) / n
    xw = T + np.outer(widths, u)
    zw = np.repeat(rows[:, None], n, axis=1)
    cell_w = GAMMA * T_R * np.repeat((widths / n * H / n)[:, None], n, axis=1) / G
    return [
        *((cell_f, float(x), float(z), 0.0) for x, z in zip(xf.ravel(), zf.ravel(), strict=True)),
        *((float(m), float(x), float(z), 0.0)
          for m, x, z in zip(cell_w.ravel(), xw.ravel(), zw.ravel(), strict=True)),
    ]  # fmt: skip


@pytest.fixture(scope="module")
def wedge(tmp_path_factory):
    path = Path(tmp_path_factory.mktemp("wedge")) / "wedge.toml"
    path.write_text(MODEL, encoding="utf-8")
    model = load_model(str(path))
    assert model.analysis.g == G
    wall = to_wall(model)
    (spec,) = wall.mechanisms
    return mechanism_block(model, wall, spec)


def test_the_hand_sums_are_the_masses_sums() -> None:
    # Midpoint sums over 300 × 300 cells of each body: error O(1/n²) of the moments, and the
    # triangle's rows O(1/n²) too (each row's width at its mid-height): 1e-5 relative.
    by_hand, by_grid = sums(bodies()), sums(grid(300))
    for a, b in zip(by_hand, by_grid, strict=True):
        assert a == pytest.approx(b, rel=1e-5)


def test_the_wedge_keeps_less_than_its_energy_at_an_impact(wedge) -> None:
    d, d_new, n = sums(bodies())
    housner_about_inner_edge = n / d_new
    assert housner_about_inner_edge > 1.0  # 1.0011: why it was clipped
    expected = n / math.sqrt(d * d_new)
    assert expected == pytest.approx(0.98731, abs=5e-6)  # the docstring's number
    assert wedge.one_sided and wedge.free_side == 1 and wedge.rebound == 1.0
    # Both sides carry it (a one-sided impact is the same whichever way it is read).
    assert wedge.restitution(1) == pytest.approx(expected, rel=1e-12)
    assert wedge.restitution(-1) == pytest.approx(expected, rel=1e-12)
    # Kinetic energy after over before, one-sided about the same pivot: (r_f·e)² < 1.
    assert (wedge.rebound * wedge.e) ** 2 == pytest.approx(0.974783, abs=5e-6)
    assert (wedge.rebound * wedge.e) ** 2 < 1.0


def test_the_engine_loses_that_energy_at_the_impact(wedge) -> None:
    # Released at rest from θ0 on a still ground, the wedge reaches θ = 0 with the kinetic
    # energy V(θ0) = W·[x_G·sin θ0 + z_G·(cos θ0 − 1)] (its centroid's rise about O, by hand),
    # and loses (1 − e²) of it at the impact. The run stops before the second impact: the
    # fall takes about acosh(α/(α − θ0))/p (the linearised block), the rebound longer.
    parts = bodies()
    mass = sum(m for m, _, _, _ in parts)
    x_g = sum(m * x for m, x, _, _ in parts) / mass
    z_g = sum(m * z for m, _, z, _ in parts) / mass
    d, d_new, n = sums(parts)
    e = n / math.sqrt(d * d_new)
    alpha, r = math.atan2(x_g, z_g), math.hypot(x_g, z_g)
    theta0 = 0.5 * alpha
    fall = math.acosh(alpha / (alpha - theta0)) / math.sqrt(mass * G * r / d)
    time = np.arange(0.0, 2.0 * fall, 0.001)
    run = simulate(wedge, time, np.zeros_like(time), 0.001, theta0=theta0,
                   settings=SolverSettings(tail=0.0))  # fmt: skip
    assert run.impacts == 1
    energy = mass * G * (x_g * math.sin(theta0) + z_g * (math.cos(theta0) - 1.0))
    # The engine's rtol 1e-8 on the state; the loss is 2.5 % of the energy: 1e-5 relative.
    assert run.impact_loss == pytest.approx((1.0 - e * e) * energy, rel=1e-5)
    assert run.impact_loss > 0.0
